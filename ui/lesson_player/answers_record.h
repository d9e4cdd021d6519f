// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What the session remembers of the student's work: who the student is, and the lesson last
// opened with every step's tries and the settings its world ran with. It outlives the lesson
// player (a language switch makes the window anew; the same lesson opened again goes on with
// its record); another lesson starts a new record. Hand in writes it.

#include "format/answers_file.h"
#include "format/lesson.h"
#include "rigidlab/physics/settings.h"

#include <QString>

#include <cstddef>
#include <vector>

namespace rigidlab::ui {

class AnswersRecord {
public:
    /// The one record of the session.
    static AnswersRecord& session();

    QString student;
    QString className;

    /// Starts the record of `lesson`, unless the record is of it already.
    void start(const lessons::Lesson& lesson);
    /// Whether the record is of `lesson`.
    bool isOf(const lessons::Lesson& lesson) const;
    /// Keeps the tries at question i of `step`, one of its `questions` (the record is of the
    /// lesson); the other questions' stay as kept.
    void keepTries(int step, std::size_t questions, std::size_t i,
                   const std::vector<lessons::AnswerTry>& tries);
    /// Keeps the settings the world of `step` runs with.
    void keepSettings(int step, const physics::WorldDef& def);
    /// Each question's tries at `step`, as kept.
    std::vector<std::vector<lessons::AnswerTry>> tries(int step) const;
    /// The work on `lesson` so far, every step visited, with who and when (`language`: the
    /// one it is played in).
    lessons::Answers answers(const lessons::Lesson& lesson, const QString& language) const;

private:
    QString m_lessonPath;
    std::vector<lessons::StepAnswers> m_steps;
};

} // namespace rigidlab::ui
