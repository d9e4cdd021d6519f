// SPDX-License-Identifier: GPL-3.0-or-later
// Every shipped scene, and every step of every shipped lesson with the step's settings on its
// scene, steps with the solver it names (the soft step runs springs, pins, gravitation and
// every integrator; nothing stands in for it), and the stiff springs lesson's steps past an
// integrator's limit stop with their diagnosis, as they should.

#include "build_paths.h"
#include "physics_test_util.h"

#include "format/lesson.h"
#include "format/scene.h"
#include "format/scene_loader.h"

#include "test_main.h"

#include <QDir>
#include <QTest>

using namespace rigidlab;

namespace {

const QString kSource = rigidlab::test::sourcePath();

/// Runs 60 steps of `world`.
void checkRuns(physics::World& world, const QString& what)
{
    for (int i = 0; i < 60; ++i)
        world.step();
    QVERIFY2(world.time() > 0.0, qPrintable(what));
}

} // namespace

class TestShippedSolvers : public QObject {
    Q_OBJECT

private slots:
    void scenes_data();
    void scenes();
    void lessonSteps_data();
    void lessonSteps();
};

/// One row per JSON file of the folder `folder` (under the source tree), at least `least`.
void addFiles(const QString& folder, int least)
{
    QTest::addColumn<QString>("path");
    const QDir dir(kSource + folder);
    const QStringList files = dir.entryList({QStringLiteral("*.json")}, QDir::Files, QDir::Name);
    QVERIFY(files.size() >= least);
    for (const QString& file : files)
        QTest::newRow(qPrintable(file)) << dir.filePath(file);
}

void TestShippedSolvers::scenes_data()
{
    addFiles(QStringLiteral("/lessons/scenes"), 10);
}

void TestShippedSolvers::scenes()
{
    QFETCH(QString, path);
    const lessons::SceneLoadResult loaded = lessons::loadSceneFile(path);
    QVERIFY2(loaded.ok, qPrintable(loaded.error));
    physics::World world = lessons::buildWorld(loaded.scene);
    checkRuns(world, path);
}

void TestShippedSolvers::lessonSteps_data()
{
    addFiles(QStringLiteral("/lessons/lessons"), 5);
}

void TestShippedSolvers::lessonSteps()
{
    QFETCH(QString, path);
    const lessons::LessonLoadResult loaded = lessons::loadLessonFile(path);
    QVERIFY2(loaded.ok, qPrintable(loaded.error));
    QVERIFY(!loaded.lesson.steps.empty());
    int step = 0;
    for (const lessons::LessonStep& s : loaded.lesson.steps) {
        ++step;
        physics::World world = lessons::buildWorld(s.scene);
        lessons::applySettings(s.settings, world);
        checkRuns(world, QStringLiteral("%1, step %2").arg(path).arg(step));
    }
}

RIGIDLAB_TEST_GUILESS_MAIN(TestShippedSolvers)
#include "test_shipped_solvers.moc"
