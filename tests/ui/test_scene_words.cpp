// SPDX-License-Identifier: GPL-3.0-or-later
// What the scene says about its bodies to a screen reader, through QAccessible in process:
// the scene view's children are its bodies with their numbers, which change as the world runs;
// a contact found ahead of time is no touch; the narrator tells events through a live status
// at a calm rate; and the numbers are spoken in the locale, in the scene and the plots alike.
// (Names and roles of the controls are test_accessibility.cpp's, each announcement counted
// through a bridge test_accessibility_events.cpp's.)

#include "plots/plot_widget.h"
#include "simulation/simulation_controller.h"
#include "view/scene_narrator.h"
#include "view/world_view.h"
#include "view/world_view_accessible.h"
#include "window/main_window.h"

#include "rigidlab/physics/touching.h"

#include <QAccessible>
#include <QElapsedTimer>
#include <QRegularExpression>
#include <QScopeGuard>
#include <QtTest>

#include "projector_window.h"
#include "test_main.h"

using namespace rigidlab;
using rigidlab::test::shippedLessonFile;
using rigidlab::test::showOnProjector;
using rigidlab::ui::MainWindow;

class TestSceneWords : public QObject {
    Q_OBJECT
private slots:
    /// The scene's children are its bodies, with name, shape, mass, position and velocity,
    /// and their values change as the world runs.
    void sceneChildrenAreItsBodies()
    {
        MainWindow w;
        showOnProjector(w);
        QCOMPARE(w.openLesson(shippedLessonFile("restitution.json"), true), QString());
        QAccessibleInterface* scene = QAccessible::queryAccessibleInterface(&w.view());
        QVERIFY(scene);
        QVERIFY(!scene->text(QAccessible::Name).isEmpty());
        const auto& world = w.controller().world();
        const int bodies = static_cast<int>(world.bodies().size());
        QVERIFY(bodies >= 2);
        QCOMPARE(scene->childCount(), ui::WorldViewAccessible::FirstBody + bodies);
        const QString summary =
            scene->child(ui::WorldViewAccessible::Summary)->text(QAccessible::Description);
        QVERIFY2(summary.contains(QString::number(bodies - 1)) ||
                     summary.contains(QString::number(bodies)),
                 qPrintable(summary));
        QStringList before;
        for (int i = 0; i < bodies; ++i) {
            QAccessibleInterface* b = scene->child(ui::WorldViewAccessible::FirstBody + i);
            QVERIFY(b && b->isValid());
            QCOMPARE(b->parent(), scene);
            QCOMPARE(scene->indexOfChild(b), ui::WorldViewAccessible::FirstBody + i);
            QVERIFY2(b->text(QAccessible::Name).startsWith(w.controller().scene().bodyLabel(i)),
                     qPrintable(b->text(QAccessible::Name)));
            const QString value = b->text(QAccessible::Value);
            for (const char* word : {"mass", "position", "velocity"})
                QVERIFY2(value.contains(QLatin1String(word)), qPrintable(value));
            if (world.body(i).isDynamic())
                QVERIFY2(value.contains(QStringLiteral("kg")), qPrintable(value));
            before << value;
        }
        // Run half a second: a falling ball's position and velocity change.
        for (int k = 0; k < 50; ++k)
            w.controller().stepForward();
        int changed = 0;
        for (int i = 0; i < bodies; ++i)
            if (scene->child(ui::WorldViewAccessible::FirstBody + i)->text(QAccessible::Value) !=
                before[i])
                ++changed;
        int moving = 0;
        for (int i = 0; i < bodies; ++i)
            moving += world.body(i).isDynamic() ? 1 : 0;
        QCOMPARE(changed, moving);
    }

    /// At dt = 0.2 s the ball drop's balls, 1 m apart, get contacts ahead of time while they
    /// fall (continuous collision's look-ahead: between the balls a gap of 0.8 m): neither the
    /// scene's summary, nor a ball's value, nor the narrator says that anything touches.
    void lookAheadIsNoTouch()
    {
        MainWindow w;
        showOnProjector(w);
        QCOMPARE(
            w.openScene(QDir(MainWindow::scenesFolder()).filePath(QStringLiteral("ball_drop.json")),
                        true),
            QString());
        w.controller().setDt(0.2);
        QAccessibleInterface* scene = QAccessible::queryAccessibleInterface(&w.view());
        QVERIFY(scene);
        const auto& world = w.controller().world();
        int ahead = 0;
        for (int k = 0; k < 2; ++k) { // 0.4 s: the balls are still 1.2 m above the floor
            w.controller().stepForward();
            for (const physics::Contact& c : world.contacts())
                ahead += physics::touches(c) ? 0 : 1;
            QCoreApplication::processEvents();
            const QString summary =
                scene->child(ui::WorldViewAccessible::Summary)->text(QAccessible::Description);
            const QString ball =
                scene->child(ui::WorldViewAccessible::FirstBody + 1)->text(QAccessible::Value);
            for (const QString& text : {summary, ball, w.view().narrator().status()})
                QVERIFY2(!text.contains(QLatin1String("touch")), qPrintable(text));
        }
        QVERIFY(ahead > 0); // there were contacts ahead of time to be told apart
    }

    /// Events are told through the live status, merged and at a calm rate:
    /// a run of many frames gives a handful of updates, not one per frame.
    void eventsAreToldPolitely()
    {
        MainWindow w;
        showOnProjector(w);
        QCOMPARE(w.openLesson(shippedLessonFile("restitution.json"), true), QString());
        ui::SceneNarrator& narrator = w.view().narrator();
        QSignalSpy told(&narrator, &ui::SceneNarrator::told);
        const int changesBefore = narrator.statusChanges();
        int frames = 0;
        connect(&w.controller(), &ui::SimulationController::frameAdvanced, this, [&] { ++frames; });
        w.controller().setRunning(true);
        // The run's own clock, in real time: the balls fall and hit the floor.
        QElapsedTimer clock;
        clock.start();
        QTRY_VERIFY_WITH_TIMEOUT(w.controller().time() > 2.5, 20000);
        w.controller().setRunning(false);
        const auto seconds = clock.elapsed() / ui::SceneNarrator::kValueIntervalMs + 1;
        QVERIFY2(narrator.status().contains(QLatin1String("touch")), qPrintable(narrator.status()));
        const int changes = narrator.statusChanges() - changesBefore;
        QVERIFY2(changes >= 1 && changes <= seconds, qPrintable(QString::number(changes)));
        int statusTold = 0, bodyTold = 0;
        for (const QList<QVariant>& args : told) {
            const int child = args.at(0).toInt();
            statusTold += child == ui::WorldViewAccessible::Status ? 1 : 0;
            bodyTold += child >= ui::WorldViewAccessible::FirstBody ? 1 : 0;
        }
        QCOMPARE(statusTold, changes);
        const int bodies = static_cast<int>(w.controller().world().bodies().size());
        // At most one update of each body a second, however many frames ran.
        QVERIFY2(frames > 3 * seconds, qPrintable(QString::number(frames)));
        QVERIFY2(
            bodyTold >= bodies && bodyTold <= seconds * bodies,
            qPrintable(QStringLiteral("%1 body updates, %2 frames").arg(bodyTold).arg(frames)));
    }

    /// The scene's and the plots' texts say numbers in the locale: its decimal separator, a
    /// negative value as "minus" (never a sign a screen reader may drop), and coordinates
    /// separated by ", " after a decimal point, "; " after a decimal comma.
    void numbersAreSpokenInTheLocale_data()
    {
        QTest::addColumn<QString>("locale");
        QTest::newRow("en") << QStringLiteral("en_US");
        QTest::newRow("cs") << QStringLiteral("cs_CZ");
    }
    void numbersAreSpokenInTheLocale()
    {
        QFETCH(QString, locale);
        const QLocale before;
        QLocale::setDefault(QLocale(locale));
        const auto restore = qScopeGuard([&] { QLocale::setDefault(before); });
        const bool decimalComma = QLocale().decimalPoint() == QLatin1String(",");
        MainWindow w;
        showOnProjector(w);
        QCOMPARE(
            w.openScene(QDir(MainWindow::scenesFolder()).filePath(QStringLiteral("welcome.json")),
                        true),
            QString());
        for (int k = 0; k < 60; ++k) // the bodies fall: velocities below zero
            w.controller().stepForward();
        QStringList texts;
        QAccessibleInterface* scene = QAccessible::queryAccessibleInterface(&w.view());
        QVERIFY(scene);
        for (int i = ui::WorldViewAccessible::FirstBody; i < scene->childCount(); ++i)
            texts << scene->child(i)->text(QAccessible::Value);
        for (auto* plot : w.plots()) {
            plot->drain();
            texts << QAccessible::queryAccessibleInterface(plot)->text(QAccessible::Description);
        }
        const QString all = texts.join(QLatin1Char('\n'));
        const QRegularExpression sign(QStringLiteral("[-\u2212]\\d"));
        QVERIFY2(!sign.match(all).hasMatch(), qPrintable(sign.match(all).captured() + u'\n' + all));
        QVERIFY2(all.contains(QLatin1String("minus ")), qPrintable(all));
        const QRegularExpression decimal(decimalComma ? QStringLiteral("\\d,\\d")
                                                      : QStringLiteral("\\d\\.\\d"));
        QVERIFY2(decimal.match(all).hasMatch(), qPrintable(all));
        // Each body's position and velocity: two coordinates, the locale's separator between.
        const QString separator = decimalComma ? QStringLiteral("; ") : QStringLiteral(", ");
        const QRegularExpression pair(QStringLiteral("(position|velocity) \\(([^)]*)\\)"));
        int pairs = 0;
        for (auto m = pair.globalMatch(all); m.hasNext(); ++pairs) {
            const QString inside = m.next().captured(2);
            QVERIFY2(inside.split(separator).size() == 2, qPrintable(inside));
            // The other language's separator is not there as well.
            QVERIFY2(!inside.contains(decimalComma ? QStringLiteral(", ") : QStringLiteral(";")),
                     qPrintable(inside));
        }
        QVERIFY2(pairs >= 2, qPrintable(all));
    }
};

RIGIDLAB_TEST_MAIN(TestSceneWords)
#include "test_scene_words.moc"
