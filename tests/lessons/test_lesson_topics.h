// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The physics four lessons claim, checked on their own scenes against exact mechanics:
// rotation and moment of inertia, the force and torque accumulators
// (test_lesson_topics_forces.cpp), the impulse formula term by term and tunnelling
// (test_lesson_topics_collisions.cpp). Claims are pinned with the tolerances of the mechanics
// (α = τ / I, the impulse formula evaluated here, v·dt against the wall), not with hashes, so
// that a change inside the solver that keeps the mechanics keeps them passing.

#include "test_lesson.h"
#include "test_lesson_physics.h"

#include "near.h"

#include <QObject>

namespace rigidlab::test {

/// r × F in the plane [N m].
inline double crossZ(const physics::Vec2& r, const physics::Vec2& f)
{
    return r.x() * f.y() - r.y() * f.x();
}

/// Whether `answer` is judged right for question `q` of a step that has run far enough.
inline bool judgedRight(const lessons::LessonStep& step, std::size_t q, double answer,
                        const lessons::Measurements& m, QString* message)
{
    const lessons::Verdict v = lessons::judge(step.questions.at(q), answer, m, step.scene);
    *message = v.message;
    return v.measured && v.right;
}

} // namespace rigidlab::test

class TestLessonTopics : public QObject {
    Q_OBJECT

private slots:
    // test_lesson_topics_forces.cpp
    void rotationInertiaFromFormulas();
    void rotationAlphaIsTorqueOverInertia();
    void rotationQuestionsHaveTheirAnswers();
    void rotationOffCentrePullMovesAndTurns();
    void accumulatorsSumTheFourForces();
    void accumulatorQuestionsHaveTheirAnswers();
    void dragAloneDecaysExponentially();
    void forceForOneStepIsAnImpulse();

    // test_lesson_topics_collisions.cpp
    void impulseFormulaTermByTerm();
    void impulseShrinksAndSpinGrowsWithLeverArm();
    void tunnellingWhereVdtSkipsTheCatchZone();
    void tunnellingChoiceIsWhatTheRunDoes();
    void tunnellingSpeedSweepMatchesTheRule_data();
    void tunnellingSpeedSweepMatchesTheRule();
    void continuousCollisionContactsAheadOfTime();
};
