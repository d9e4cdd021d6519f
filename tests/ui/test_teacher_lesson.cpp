// SPDX-License-Identifier: GPL-3.0-or-later
// A Czech teacher's own two-cart lesson (tests/lessons/data/two_carts, written in Czech only: a
// light cart runs into a heavy one on a 40 m ground), played in a Czech window: the collision
// panel reports the carts' hit, not the carts settling on the ground at the first step; the
// bodies are named by their Czech labels; the view frames the carts and where they go until
// the step's end time, not the whole ground; the run that reaches the step's end time, or a cart
// that runs off the end of the ground, stops with a message that says why (in the status bar
// and to a screen reader), and the lesson editor's checks warn of the fall; after the elastic hit
// the status bar says that nothing was dissipated, in the window's language and notation.

#include "build_paths.h"
#include "common/announcer.h"
#include "common/language.h"
#include "instruments/instruments.h"
#include "lesson_editor/step_checks.h"
#include "lesson_player/lesson_panels.h"
#include "lesson_player/lesson_player.h"
#include "panels/fitting_table.h"
#include "simulation/simulation_controller.h"
#include "view/world_view.h"
#include "window/main_window.h"

#include "format/lesson.h"
#include "run/featured_collision.h"
#include "run/off_stage.h"

#include "shipped_lessons.h"
#include "test_main.h"

#include <QComboBox>
#include <QDockWidget>
#include <QLabel>
#include <QMessageBox>
#include <QRegularExpression>
#include <QStatusBar>
#include <QtTest>

#include <atomic>

using namespace rigidlab;

namespace {

const QString kLesson =
    rigidlab::test::sourcePath(u"/tests/lessons/data/two_carts/dva_voziky.rlesson");

/// Steps the window's world until time `t` [s].
void stepUntil(ui::SimulationController& c, double t)
{
    while (c.world().time() < t)
        c.stepForward();
}

/// Empty when a screen reader was told what the status bar says (it reads no status bar), and
/// Play then runs on without `paused` (the pause's signal) coming again; else what went wrong.
QString toldAndRunsOn(ui::MainWindow& w, const QSignalSpy& paused)
{
    const QString shown = w.statusBar()->currentMessage();
    const QWidget* told = ui::announcer(w);
    if (!told || told->accessibleName() != shown.simplified())
        return QStringLiteral("told \"%1\", shown \"%2\"")
            .arg(told ? told->accessibleName() : QString(), shown);
    ui::SimulationController& c = w.controller();
    const auto before = paused.count();
    c.setRunning(true);
    for (int frame = 0; frame < 30; ++frame)
        c.advanceClock(1.0 / 60);
    const bool runs = c.isRunning();
    c.setRunning(false);
    return runs && paused.count() == before ? QString() : QStringLiteral("Play did not run on");
}

/// Shows `w` at 1024×768 with the lesson open: empty, or what went wrong.
QString showWithTheLesson(ui::MainWindow& w)
{
    w.setUnsavedAsker([] { return int(QMessageBox::Discard); });
    w.resize(1024, 768);
    w.show();
    if (!QTest::qWaitForWindowExposed(&w))
        return QStringLiteral("the window was not shown");
    return w.openLesson(kLesson, true);
}

} // namespace

class TestTeacherLesson : public QObject {
    Q_OBJECT
private slots:
    void init() { QVERIFY(ui::applyLanguage(QStringLiteral("cs"))); }
    void cleanupTestCase() { ui::applyLanguage(QStringLiteral("en")); }
    void collisionPanelShowsTheCarts();
    void bodiesByTheirLabels();
    void framingFitsTheCarts();
    void runStopsWhenACartFallsOff();
    void runSaysWhyItPausedAtTheEnd();
    void editorWarnsOfTheFall();
    void shippedStepsStayOnTheirStage();
    void elasticHitDissipatesNothing_data();
    void elasticHitDissipatesNothing();
};

void TestTeacherLesson::collisionPanelShowsTheCarts()
{
    ui::MainWindow w;
    w.setUnsavedAsker([] { return int(QMessageBox::Discard); });
    QCOMPARE(w.openLesson(kLesson, true), QString());
    ui::SimulationController& c = w.controller();
    stepUntil(c, 2.0);
    // The carts settled on the ground in the first step (recorded as contacts that began),
    // then hit each other: 1.6 m apart at 4 m/s, at about 0.4 s.
    const auto& events = c.lessonWatch().measurements().collisions();
    QVERIFY(events.size() >= 3);
    QVERIFY2(events.front().t < 0.01, qPrintable(QString::number(events.front().t)));
    const lessons::CollisionEvent* hit = lessons::featuredCollision(
        events, c.world(), lessons::namedBodies(w.lessonPlayer().lesson()->steps[0], c.scene()));
    QVERIFY(hit);
    QVERIFY2(std::abs(hit->t - 0.4) < 0.01, qPrintable(QString::number(hit->t)));
    const QString title = w.collisionPanel().title()->text();
    QVERIFY2(title.contains(QStringLiteral("lehký vozík")) &&
                 title.contains(QStringLiteral("těžký vozík")) &&
                 !title.contains(QStringLiteral("zem")),
             qPrintable(title));
    // Elastic, 1 kg against 3 kg at rest: the heavy cart leaves at 2·1/(1 + 3)·4 m/s = 2 m/s.
    const int heavy = hit->a == 2 ? 0 : 1;
    QVERIFY2(std::abs(hit->velocityAfter[heavy].x() - 2.0) < 0.02,
             qPrintable(QString::number(hit->velocityAfter[heavy].x())));
    // Without a body named by the step, the same hit: the first between two dynamic bodies.
    QCOMPARE(lessons::featuredCollision(events, c.world(), {}), hit);
}

void TestTeacherLesson::bodiesByTheirLabels()
{
    ui::MainWindow w;
    w.setUnsavedAsker([] { return int(QMessageBox::Discard); });
    QCOMPARE(w.openLesson(kLesson, true), QString());
    // The instruments' choosers name the carts as the class reads them, never by their id.
    QStringList items;
    for (const QComboBox* box : w.instruments().dock()->findChildren<QComboBox*>())
        for (int i = 0; i < box->count(); ++i)
            items << box->itemText(i);
    QVERIFY2(items.contains(QStringLiteral("lehký vozík")), qPrintable(items.join(u'|')));
    for (const char* id : {"box1", "box2", "ground"})
        QVERIFY2(!items.contains(QLatin1String(id)), qPrintable(items.join(u'|')));
    QVERIFY2(!w.windowTitle().contains(QStringLiteral("box")), qPrintable(w.windowTitle()));
}

void TestTeacherLesson::framingFitsTheCarts()
{
    ui::MainWindow w;
    QCOMPARE(showWithTheLesson(w), QString());
    ui::WorldView& view = w.view();
    const auto shown = [&] { return view.mapToScene(view.viewport()->rect()).boundingRect(); };
    // Until the end time (3 s) the light cart goes back to about −5 m and the heavy one on to
    // about 5 m: that is framed, with the ground under it, not the ground's whole 40 m.
    const QRectF framed = shown();
    QVERIFY2(framed.width() < 20, qPrintable(QString::number(framed.width())));
    QVERIFY2(framed.left() < -5 && framed.right() > 5,
             qPrintable(QStringLiteral("%1 to %2").arg(framed.left()).arg(framed.right())));
    // Fit does the same.
    view.zoomBy(0.1);
    QVERIFY(shown().width() > 40);
    view.fitScene();
    QVERIFY2(std::abs(shown().width() - framed.width()) < 0.5,
             qPrintable(QStringLiteral("%1 against %2").arg(shown().width()).arg(framed.width())));
}

void TestTeacherLesson::runStopsWhenACartFallsOff()
{
    ui::MainWindow w;
    w.setUnsavedAsker([] { return int(QMessageBox::Discard); });
    QCOMPARE(w.openLesson(kLesson, true), QString());
    ui::SimulationController& c = w.controller();
    QSignalSpy left(&c, &ui::SimulationController::leftStage);
    // Played past its end time (3 s), the light cart reaches the ground's end (−20 m) at about
    // 10 s going back at 2 m/s, and falls: the run pauses when it is 1 m below the ground.
    for (int round = 0; round < 2; ++round) {
        c.setRunning(true);
        for (int frame = 0; frame < 3000 && c.isRunning(); ++frame)
            c.advanceClock(1.0 / 60);
    }
    QVERIFY(!c.isRunning());
    QCOMPARE(left.count(), 1);
    QVERIFY(c.lessonWatch().leftStage());
    QCOMPARE(c.lessonWatch().leftStage()->body, 1); // the light cart
    QVERIFY2(c.world().time() > 9.5 && c.world().time() < 12,
             qPrintable(QString::number(c.world().time())));
    const QString message = w.statusBar()->currentMessage();
    QVERIFY2(message.contains(QStringLiteral("lehký vozík")), qPrintable(message));
    QCOMPARE(toldAndRunsOn(w, left), QString());
}

void TestTeacherLesson::runSaysWhyItPausedAtTheEnd()
{
    ui::MainWindow w;
    w.setUnsavedAsker([] { return int(QMessageBox::Discard); });
    QCOMPARE(w.openLesson(kLesson, true), QString());
    ui::SimulationController& c = w.controller();
    QSignalSpy ended(&c, &ui::SimulationController::endTimeReached);
    // The step's run ends at 3 s: it pauses there and says why, in Czech, in the status bar
    // and to a screen reader.
    c.setRunning(true);
    for (int frame = 0; frame < 600 && c.isRunning(); ++frame)
        c.advanceClock(1.0 / 60);
    QVERIFY(!c.isRunning());
    QCOMPARE(ended.count(), 1);
    QVERIFY2(std::abs(c.world().time() - 3.0) < 1e-9,
             qPrintable(QString::number(c.world().time())));
    const QString message = w.statusBar()->currentMessage();
    QVERIFY2(message.contains(QStringLiteral("t = 3 s")) &&
                 message.contains(QStringLiteral("krok")),
             qPrintable(message));
    QCOMPARE(toldAndRunsOn(w, ended), QString());
}

void TestTeacherLesson::editorWarnsOfTheFall()
{
    lessons::LessonLoadResult loaded =
        lessons::loadLessonFile(kLesson, lessons::LessonLoadOptions{QStringLiteral("cs")});
    QVERIFY2(loaded.ok, qPrintable(loaded.error));
    lessons::Lesson lesson = loaded.lesson;
    std::atomic_bool cancelled = false;
    // As written (end time 3 s): nothing falls before the run ends.
    std::vector<ui::StepFinding> findings = ui::runStepChecks(lesson, cancelled);
    QCOMPARE(findings.size(), std::size_t{1});
    QVERIFY(!findings[0].offStage);
    // Without an end time, over the export time of 15 s: the light cart falls off at ~10.6 s.
    lesson.steps[0].endTime.reset();
    lesson.steps[0].exportTime = 15;
    findings = ui::runStepChecks(lesson, cancelled);
    QVERIFY(findings[0].offStage);
    QCOMPARE(findings[0].offStage->body, 1);
    const QString lines = ui::stepCheckLines(findings[0]).join(u'\n');
    QVERIFY2(lines.contains(QStringLiteral("lehký vozík")), qPrintable(lines));
    // The same headless, from the step's world.
    const auto off =
        lessons::firstOffStage(lessons::buildStepWorlds(lesson.steps[0]).front(), 15, 100000);
    QVERIFY(off);
    QCOMPARE(off->time, findings[0].offStage->time);
}

void TestTeacherLesson::shippedStepsStayOnTheirStage()
{
    // No shipped step is stopped for a body leaving the stage during the run it frames (up to
    // its end or export time): a ball bouncing, a pendulum swinging, boxes sliding stay on.
    int steps = 0;
    for (const QString& path : test::shippedLessons()) {
        const lessons::LessonLoadResult loaded = lessons::loadLessonFile(path);
        QVERIFY2(loaded.ok, qPrintable(loaded.error));
        for (const lessons::LessonStep& step : loaded.lesson.steps) {
            const physics::World world = lessons::buildStepWorlds(step).front();
            const double until = std::min(step.exportTime, step.endTime.value_or(step.exportTime));
            const auto off = lessons::firstOffStage(world, until, 200000);
            QVERIFY2(!off, qPrintable(QStringLiteral("%1, %2: %3 at %4 s")
                                          .arg(path, step.title,
                                               off ? step.scene.bodyLabel(off->body) : QString())
                                          .arg(off ? off->time : 0)));
            ++steps;
        }
    }
    QVERIFY(steps > 20);
}

void TestTeacherLesson::elasticHitDissipatesNothing_data()
{
    QTest::addColumn<QString>("language");
    QTest::addColumn<QString>("said");
    QTest::newRow("cs") << QStringLiteral("cs") << QStringLiteral("energie");
    QTest::newRow("en") << QStringLiteral("en") << QStringLiteral("dissipated");
}

// e = 1 for both carts: what the soft contact took at the hit is a millionth of the scene's
// energy, round-off against it, and the status bar says 0 J, not "1,06E-05 J".
void TestTeacherLesson::elasticHitDissipatesNothing()
{
    QFETCH(QString, language);
    QFETCH(QString, said);
    QVERIFY(ui::applyLanguage(language));
    ui::MainWindow w;
    QCOMPARE(showWithTheLesson(w), QString());
    ui::SimulationController& c = w.controller();
    stepUntil(c, 3.0); // the step's end time, long after the hit at 0.4 s
    const double lost = c.recorder().dissipated(c.world());
    const double scale = c.recorder().energyScale();
    // Something was taken (the status bar says so), but less than a ten-thousandth of it.
    QVERIFY2(std::abs(lost) > 1e-9 && std::abs(lost) < 1e-4 * scale,
             qPrintable(QStringLiteral("%1 J of %2 J").arg(lost).arg(scale)));
    const QRegularExpression zero(said + QStringLiteral("[^|]* 0[\\x{a0} ]J"));
    QTRY_VERIFY2(zero.match(w.statusText()).hasMatch(), qPrintable(w.statusText()));
    const QRegularExpression exponent(QStringLiteral("\\d[eE][-+]?\\d"));
    QVERIFY2(!exponent.match(w.statusText()).hasMatch(), qPrintable(w.statusText()));
    // Nor does the collision table call the carts' spin, which round-off leaves a hair below 0,
    // "-0.000": a cart that never turned turns 0.
    QStringList cells;
    for (const QStringList& row : w.collisionPanel().table()->wideText().rows)
        cells << row;
    QVERIFY(!cells.isEmpty());
    const QRegularExpression negativeZero(QStringLiteral("-0[.,]0+(?!\\d*[1-9])"));
    QVERIFY2(!negativeZero.match(cells.join(u'|')).hasMatch(), qPrintable(cells.join(u'|')));
}

RIGIDLAB_TEST_MAIN(TestTeacherLesson)
#include "test_teacher_lesson.moc"
