// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A question that asks the student to set something first ("set" in its file: "set e = 0
// and run again") is judged on the window's run only when that run is the one it asks for:
// the settings asked, from the start. Otherwise the student is told what to change, or,
// where the step does not let her change it, the question is judged by the asked run done
// without a window.

#include "simulation/setting_edit.h"

#include "format/lesson.h"

#include <QString>
#include <QStringList>

namespace rigidlab::ui {

struct AskedRun {
    /// The asked settings in words, "Restitution e = 0" (empty: the question asks none).
    QString asked;
    /// What differs in the window's run, in words; empty when it is the run asked for.
    QStringList differences;
    /// Whether the step lets the student make them (its controls shown, those settings
    /// allowed and not held back by this question).
    bool studentCanSet = true;
    bool matches() const { return differences.isEmpty(); }
};

/// How the run of `world` (with the hand-made `edits` of this run) stands to the run
/// `question` of `step` asks for.
AskedRun askedRun(const lessons::LessonStep& step, const lessons::Question& question,
                  const physics::World& world, const SettingEdits& edits);

/// What the student is told when the run is not the one asked for.
QString askedRunAdvice(const AskedRun& run);

} // namespace rigidlab::ui
