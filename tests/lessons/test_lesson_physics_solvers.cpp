// SPDX-License-Identifier: GPL-3.0-or-later
// Which solver the shipped scenes and lessons use: the soft step, except where a lesson shows
// another on purpose.

#include "test_lesson.h"

#include "format/scene_loader.h"

#include <QFileInfo>

#include <map>

using namespace rigidlab;
using namespace rigidlab::test;

// The soft step is the default: WorldDef's, so the editor's New scene's, and every shipped
// scene's and lesson step's, except the ones listed here, each with the reason it shows
// another solver. A new scene or step that names another solver must be added with its reason.
void TestLesson::shippedScenesUseTheSoftStep()
{
    QVERIFY(physics::WorldDef{}.solver == physics::SolverKind::SoftStep);
    // Scene files that name another solver, and why.
    const std::map<QString, QString> scenes = {
        {QStringLiteral("newtons_cradle.json"),
         QStringLiteral("the balls hang on pins, where the sequential solver would stand in for "
                        "the soft step; the paper's impulse passes the blow pair by pair along "
                        "the 1 mm gaps, as the description tells")},
        {QStringLiteral("lab_vs_measurement.json"),
         QStringLiteral("the same as measure/samples/ball_floor.json, from which the shipped "
                        "sample measurements were made: the lesson fits e to them with the "
                        "solver that made them")},
    };
    // Lessons whose steps name or compare other solvers, and why.
    const std::map<QString, QString> lessons = {
        {QStringLiteral("stacks.json"),
         QStringLiteral("compares the paper's impulse with sequential impulses on stacks, shows "
                        "warm starting with one sequential iteration, and the soft step against "
                        "sequential impulses on the pyramid")},
        {QStringLiteral("billiards_momentum.json"),
         QStringLiteral("computes the break with the paper's impulse and sequential impulses "
                        "side by side: momentum is kept by both")},
    };
    const QStringList sceneFiles =
        QDir(kScenesDir).entryList({QStringLiteral("*.json")}, QDir::Files, QDir::Name);
    QVERIFY(sceneFiles.size() >= 20);
    for (const QString& name : sceneFiles) {
        const lessons::SceneLoadResult r = lessons::loadSceneFile(QDir(kScenesDir).filePath(name));
        QVERIFY2(r.ok, qPrintable(r.error));
        const bool soft = r.scene.world.solver == physics::SolverKind::SoftStep;
        QVERIFY2(soft != scenes.contains(name),
                 qPrintable(name + (soft ? QStringLiteral(" is listed as differing but uses the "
                                                          "soft step")
                                         : QStringLiteral(" names another solver without a "
                                                          "reason listed here"))));
    }
    const QStringList lessonFiles =
        QDir(kLessonsDir).entryList({QStringLiteral("*.json")}, QDir::Files, QDir::Name);
    for (const QString& name : lessonFiles) {
        const lessons::LessonLoadResult r =
            lessons::loadLessonFile(QDir(kLessonsDir).filePath(name));
        QVERIFY2(r.ok, qPrintable(r.error));
        bool other = false;
        for (const lessons::LessonStep& step : r.lesson.steps) {
            other = other ||
                    (step.settings.has("solver") &&
                     physics::solverFromName(step.settings.get<QString>("solver")->toStdString()) !=
                         physics::SolverKind::SoftStep);
            if (step.compare)
                for (physics::SolverKind k : step.compare->solvers)
                    other = other || k != physics::SolverKind::SoftStep;
            // A step's world is the soft step's unless the step says otherwise.
            if (!step.settings.has("solver") && !step.compare && !step.scenePath.isEmpty())
                QVERIFY2(step.scene.world.solver == physics::SolverKind::SoftStep ||
                             scenes.contains(QFileInfo(step.scenePath).fileName()),
                         qPrintable(name + QStringLiteral(": ") + step.scenePath));
        }
        QVERIFY2(other == lessons.contains(name),
                 qPrintable(name + (other ? QStringLiteral(" shows another solver without a "
                                                           "reason listed here")
                                          : QStringLiteral(" is listed but shows only the soft "
                                                           "step"))));
    }
}
