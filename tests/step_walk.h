// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Which steps of the shipped lessons a test that walks them visits.
//
// The Release pass (./lab test) walks every step of every lesson. The sanitizer pass
// (./lab test-sanitize) walks what the sanitizers add: every code path a step's content leads
// to, once. tests/CMakeLists.txt sets RIGIDLAB_STEP_WALK=new for every test of a
// RIGIDLAB_SANITIZE build, and nowhere else; a walk then visits each lesson's first step and
// each later step that shows something no step visited before it showed (stepFeatures below).
// The same paths again with other numbers are the Release pass's job; test_step_walk checks
// that the Release pass walks every step and that the shorter walk still shows every feature.
// docs/ci.md says what it saves.

#include "format/lesson.h"

#include <QSet>
#include <QString>
#include <QtGlobal>

namespace rigidlab::test {

/// True unless the environment asks for the sanitizer pass's walk (RIGIDLAB_STEP_WALK=new);
/// any other value than "new", "every" or none stops the test, saying so.
inline bool walkEveryStep()
{
    const QString walk = qEnvironmentVariable("RIGIDLAB_STEP_WALK");
    if (walk == QLatin1String("new"))
        return false;
    if (!walk.isEmpty() && walk != QLatin1String("every"))
        qFatal("RIGIDLAB_STEP_WALK=%s: expected \"every\" (every step, the default) or \"new\" "
               "(each lesson's first step and the steps that show something new)",
               qPrintable(walk));
    return true;
}

/// Whether a test that goes through every shipped lesson in each of `languages` languages takes
/// the `lesson`-th (0-based, in its order) in the `language`-th: every lesson in every language
/// in the Release pass; in the sanitizer pass each lesson once, the languages taking turns
/// (a language's code paths are the same in every lesson, and each is still taken).
inline bool walksLanguage(int lesson, int language, int languages)
{
    return walkEveryStep() || lesson % languages == language;
}

/// The least a count over a walk must reach: `every` when it walks every step (the Release
/// pass), `onlyNew` when it walks what is new (the sanitizer pass).
inline int atLeast(int every, int onlyNew)
{
    return walkEveryStep() ? every : onlyNew;
}

/// What a step shows that leads to code of its own: its panels, plots and overlays, compared
/// worlds, editor lock, SAT pair, locked controls, end time, a paused start, and its questions'
/// kinds, measures and what they hold back.
inline QSet<QString> stepFeatures(const lessons::LessonStep& step)
{
    QSet<QString> out;
    for (const QString& name : step.panels)
        out << QStringLiteral("panel:") + name;
    for (const QString& name : step.plots)
        out << QStringLiteral("plot:") + name;
    for (const QString& name : step.overlays)
        out << QStringLiteral("overlay:") + name;
    if (step.compare)
        out << QStringLiteral("compare");
    if (step.editor)
        out << QStringLiteral("editor");
    if (step.sat)
        out << QStringLiteral("sat");
    if (step.allow)
        out << QStringLiteral("allow");
    if (step.endTime)
        out << QStringLiteral("endTime");
    if (!step.autoplay)
        out << QStringLiteral("paused");
    for (const lessons::Question& q : step.questions) {
        out << QStringLiteral("question:%1").arg(q.kind.index());
        if (const auto* measured = q.as<lessons::MeasuredQuestion>()) {
            out << QStringLiteral("measure:%1").arg(static_cast<int>(measured->measure.kind));
            if (!measured->set.empty())
                out << QStringLiteral("asked-run");
        }
        for (const QString& held : q.holdBack)
            out << QStringLiteral("hold:") + held;
    }
    return out;
}

/// One walk over lessons' steps, in the order the test visits them.
class StepWalk {
public:
    /// every: walk every step; else what is new. By default as the environment says.
    explicit StepWalk(bool every = walkEveryStep()) : m_every(every) {}

    /// Whether the walk visits `step`, the `index`-th (0-based) of its lesson: always when
    /// walking every step; else when it is a lesson's first or shows something new.
    bool visits(const lessons::LessonStep& step, int index)
    {
        const QSet<QString> features = stepFeatures(step);
        const bool isNew = !m_seen.contains(features);
        m_seen.unite(features);
        return m_every || index == 0 || isNew;
    }
    bool everyStep() const { return m_every; }

private:
    bool m_every = true;
    QSet<QString> m_seen;
};

} // namespace rigidlab::test
