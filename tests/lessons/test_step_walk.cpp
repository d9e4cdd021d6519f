// SPDX-License-Identifier: GPL-3.0-or-later
// The walk over the shipped lessons' steps that the window tests make (tests/step_walk.h): the
// Release pass walks every step, the sanitizer pass what the sanitizers add, and that shorter
// walk still shows everything any step shows.

#include "build_paths.h"
#include "step_walk.h"

#include "test_main.h"

#include "format/lesson.h"

#include <QDir>
#include <QtTest>

#include <vector>

// Built with AddressSanitizer (GCC says so by a macro, clang by a feature test).
#if defined(__SANITIZE_ADDRESS__)
#define RIGIDLAB_TEST_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define RIGIDLAB_TEST_ASAN 1
#endif
#endif
#ifndef RIGIDLAB_TEST_ASAN
#define RIGIDLAB_TEST_ASAN 0
#endif

namespace {

using rigidlab::test::StepWalk;

std::vector<rigidlab::lessons::Lesson> shippedLessons()
{
    const QDir dir(rigidlab::test::sourcePath(u"/lessons/lessons"));
    std::vector<rigidlab::lessons::Lesson> out;
    for (const QString& f : dir.entryList({QStringLiteral("*.json")}, QDir::Files, QDir::Name)) {
        const rigidlab::lessons::LessonLoadResult r =
            rigidlab::lessons::loadLessonFile(dir.filePath(f));
        if (!r.ok)
            qFatal("%s: %s", qPrintable(f), qPrintable(r.error));
        out.push_back(r.lesson);
    }
    return out;
}

} // namespace

class TestStepWalk : public QObject {
    Q_OBJECT
private slots:
    /// The walk CTest asks for is the build's: every step without the sanitizers (./lab test),
    /// what is new with them (./lab test-sanitize). A RIGIDLAB_STEP_WALK set by mistake for the
    /// Release tests fails here instead of thinning them silently.
    void theBuildsWalk()
    {
        qInfo("built %s AddressSanitizer; RIGIDLAB_STEP_WALK=\"%s\"",
              RIGIDLAB_TEST_ASAN ? "with" : "without",
              qPrintable(qEnvironmentVariable("RIGIDLAB_STEP_WALK")));
        QCOMPARE(StepWalk().everyStep(), !RIGIDLAB_TEST_ASAN);
    }

    /// Walking every step visits every step of every lesson.
    void everyStepWalksAll()
    {
        StepWalk walk(true);
        int steps = 0, visited = 0;
        for (const auto& lesson : shippedLessons())
            for (int i = 0; i < static_cast<int>(lesson.steps.size()); ++i, ++steps)
                visited += walk.visits(lesson.steps[static_cast<std::size_t>(i)], i) ? 1 : 0;
        QCOMPARE(visited, steps);
        QVERIFY2(steps >= 20, qPrintable(QString::number(steps)));
    }

    /// The sanitizer pass's walk: each lesson's first step, and between its steps everything
    /// that any step of any lesson shows (panel, plot, overlay, question kind, ...).
    void newWalkShowsEverything()
    {
        const std::vector<rigidlab::lessons::Lesson> lessons = shippedLessons();
        StepWalk walk(false);
        QSet<QString> all, shown;
        int steps = 0, visited = 0;
        for (const auto& lesson : lessons) {
            for (int i = 0; i < static_cast<int>(lesson.steps.size()); ++i, ++steps) {
                const auto& step = lesson.steps[static_cast<std::size_t>(i)];
                const QSet<QString> features = rigidlab::test::stepFeatures(step);
                all.unite(features);
                const bool visits = walk.visits(step, i);
                QVERIFY2(visits || i > 0, qPrintable(lesson.path));
                if (visits) {
                    ++visited;
                    shown.unite(features);
                }
            }
        }
        qInfo("the sanitizer pass walks %d of %d steps", visited, steps);
        QVERIFY2(visited >= static_cast<int>(lessons.size()) && visited <= steps,
                 qPrintable(QString::number(visited)));
        QStringList missing = (all - shown).values();
        missing.sort();
        QVERIFY2(missing.isEmpty(), qPrintable(missing.join(u' ')));
        QVERIFY(all.contains(QStringLiteral("panel:sat")) &&
                all.contains(QStringLiteral("question:1")));
    }

    /// A step that shows nothing new is left out; one that brings a new plot is visited.
    void newWalkSkipsTheSame()
    {
        rigidlab::lessons::LessonStep plain;
        plain.plots = {QStringLiteral("energy")};
        rigidlab::lessons::LessonStep more = plain;
        more.plots << QStringLiteral("momentum");
        StepWalk walk(false);
        QVERIFY(walk.visits(plain, 0));
        QVERIFY(!walk.visits(plain, 1));
        QVERIFY(walk.visits(more, 2));
        QVERIFY(!walk.visits(more, 3));
        QVERIFY(walk.visits(plain, 0)); // a lesson's first step always
    }
};

RIGIDLAB_TEST_GUILESS_MAIN(TestStepWalk)
#include "test_step_walk.moc"
