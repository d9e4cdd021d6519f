// SPDX-License-Identifier: GPL-3.0-or-later
// The scene editor in the window: a teacher's scene drawn with the toolbar and run, the
// History dock, the view holding still under the pen, a new scene, and lesson steps that
// edit with locks on tools and properties.

#include "editor_test_util.h"

#include "editor/velocity_arrow.h"
#include "lesson_player/lesson_player.h"
#include "panels/number_field.h"
#include "window/main_window.h"

#include "edit/scene_edits.h"
#include "format/lesson.h"

#include "near.h"
#include "test_main.h"

#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QItemSelectionModel>
#include <QSignalSpy>
#include <QUndoStack>
#include <QUndoView>

#include "question_kinds.h"
#include <cmath>

using rigidlab::test::measuredOf;

using namespace rigidlab;
using namespace rigidlab::ui;
using namespace rigidlab::ui::test;
namespace edit = rigidlab::lessons::edit;

class TestEditorWindow : public QObject {
    Q_OBJECT
private slots:
    void teachersTaskInTheWindow();
    void historyListsEditsAndGoesBack();
    void viewHoldsStillWhileDrawing();
    void newSceneOpensEditModeAndTheWorldHolds();
    void lessonStepBuiltInTheEditorIsJudged();
    void lessonLocksProperties();
    void lessonLocksTheArrowAndTheColour();
    void returnHandsTheKeyboardBackToTheScene();
};

namespace {

/// The teacher's scene, drawn in the window with its toolbar's actions: a floor, a ramp with a
/// ball and a box on it, a pendulum on a pin and a box hung from a spring.
void drawTeachersScene(MainWindow& w)
{
    EditTools& tools = w.editTools();
    WorldView& view = w.view();
    const double g = tools.gridStep();
    const QPointF middle = view.mapToScene(view.viewport()->rect().center());
    const Vec2 c(std::round(middle.x() / g) * g, std::round(middle.y() / g) * g);
    const auto px = [&](double x, double y) {
        return view.mapFromScene(QPointF(c.x() + x * g, c.y() + y * g));
    };
    const auto drag = [&](QPoint a, QPoint b) {
        QTest::mousePress(view.viewport(), Qt::LeftButton, {}, a);
        QTest::mouseMove(view.viewport(), (a + b) / 2);
        QTest::mouseMove(view.viewport(), b);
        QTest::mouseRelease(view.viewport(), Qt::LeftButton, {}, b);
    };
    const auto key = [&](Qt::Key k, int times) {
        for (int i = 0; i < times; ++i) {
            QTest::keyClick(&view, k);
        }
    };
    const auto scene = [&]() -> const lessons::Scene& { return w.controller().scene(); };

    tools.toolAction(EditTool::Ground)->trigger();
    drag(px(-12, -6), px(12, -5)); // the floor
    drag(px(-9, -2), px(-1, -1));  // the ramp, turned down to the right by 20°
    key(Qt::Key_E, 4);
    tools.toolAction(EditTool::Circle)->trigger();
    drag(px(-7, 1), px(-6, 1));
    tools.toolAction(EditTool::Box)->trigger();
    drag(px(-5, 0), px(-4, 1));
    // The pendulum: a rod turned by 30°, pinned to the world at its upper end.
    drag(px(1, -1), px(2, 3));
    key(Qt::Key_E, 6);
    tools.snapAction()->setChecked(false);
    tools.toolAction(EditTool::Pin)->trigger();
    QTest::mouseClick(view.viewport(), Qt::LeftButton, {}, px(1.5 + 0.9, 1 + 1.56));
    QTest::mouseClick(view.viewport(), Qt::LeftButton, {}, px(2, 6));
    tools.snapAction()->setChecked(true);
    // The spring oscillator: a box hung from the world by a spring.
    tools.toolAction(EditTool::Box)->trigger();
    drag(px(6, -1), px(8, 0));
    tools.toolAction(EditTool::Spring)->trigger();
    drag(px(7, 4), px(7, -0.5));
    tools.toolAction(EditTool::Select)->trigger();
    tools.selectBody(scene().bodyIndex(QStringLiteral("box2")).value_or(-1));
}

} // namespace

void TestEditorWindow::teachersTaskInTheWindow()
{
    // A ramp with a ball and a box on it, a pendulum on a pin and a spring oscillator, drawn
    // in the window with its toolbar's actions, then run. With RIGIDLAB_EDITOR_SHOTS set to a
    // folder, the window is written there before and after the run (screenshots under Xvfb).
    MainWindow w;
    w.resize(1600, 1000);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.newScene());
    EditTools& tools = w.editTools();
    WorldView& view = w.view();
    QVERIFY(tools.editing()); // a new scene opens in Edit mode
    // The new scene's ground goes: this floor is drawn below.
    QCOMPARE(w.document()->scene().bodies.size(), size_t(1));
    tools.toolAction(EditTool::Delete)->trigger();
    QTest::mouseClick(view.viewport(), Qt::LeftButton, {}, view.mapFromScene(QPointF(0, -0.25)));
    QVERIFY(w.document()->scene().bodies.empty());
    drawTeachersScene(w);
    const auto scene = [&]() -> const lessons::Scene& { return w.controller().scene(); };
    QCOMPARE(scene().bodies.size(), size_t(6));
    QCOMPARE(scene().joints.size(), size_t(1));
    QCOMPARE(scene().springs.size(), size_t(1));
    QVERIFY2(edit::overlapMessage(scene()).isEmpty(), qPrintable(edit::overlapMessage(scene())));
    const QString shots = qEnvironmentVariable("RIGIDLAB_EDITOR_SHOTS");
    if (!shots.isEmpty()) {
        view.fitScene();
        QDir().mkpath(shots);
        QVERIFY(w.grab().save(QDir(shots).filePath(QStringLiteral("editor-edit.png"))));
    }

    const lessons::Scene edited = scene();
    tools.editAction()->trigger(); // leave: the scene as edited, paused for the class to predict
    QVERIFY(!tools.editing());
    QVERIFY(!w.controller().isRunning());
    QCOMPARE(w.controller().world().time(), 0.0);
    w.controller().setRunning(true); // the teacher presses Run
    QVERIFY(w.controller().isRunning());
    for (int i = 0; i < 1500; ++i) {
        w.controller().stepForward();
    }
    const auto& bodies = w.controller().world().bodies();
    const auto index = [&](const char* id) {
        return static_cast<size_t>(*edited.bodyIndex(QString::fromLatin1(id)));
    };
    QVERIFY(bodies[index("circle1")].position.x() > edited.bodies[index("circle1")].position.x());
    QVERIFY(bodies[index("box2")].angle != edited.bodies[index("box2")].angle); // it swings
    QVERIFY(bodies[index("box3")].position.y() < edited.bodies[index("box3")].position.y());
    if (!shots.isEmpty()) {
        QVERIFY(w.grab().save(QDir(shots).filePath(QStringLiteral("editor-run.png"))));
    }
}

namespace {

/// Draws a circle (the scene then is `withCircle`), a box, moves the box, types its friction
/// and hangs the circle from a spring, in the window.
void makeFiveEdits(MainWindow& w, lessons::Scene& withCircle)
{
    EditTools& tools = w.editTools();
    WorldView& view = w.view();
    const SceneDocument& document = *w.document();
    const double g = tools.gridStep();
    const auto px = [&view, g](double x, double y) {
        return view.mapFromScene(QPointF(x * g, y * g));
    };
    const auto drag = [&view](QPoint a, QPoint b) {
        QTest::mousePress(view.viewport(), Qt::LeftButton, {}, a);
        QTest::mouseMove(view.viewport(), (a + b) / 2);
        QTest::mouseMove(view.viewport(), b);
        QTest::mouseRelease(view.viewport(), Qt::LeftButton, {}, b);
    };
    tools.toolAction(EditTool::Circle)->trigger();
    drag(px(-2, 3), px(-1, 3));
    withCircle = document.scene();
    tools.toolAction(EditTool::Box)->trigger();
    drag(px(1, 2), px(2, 3));
    tools.toolAction(EditTool::Select)->trigger();
    drag(px(1.5, 2.5), px(3.5, 2.5));
    auto* properties = w.findChild<QDockWidget*>(QStringLiteral("propertiesDock"));
    QVERIFY(properties);
    auto* friction = properties->findChild<NumberField*>(QStringLiteral("friction"));
    QVERIFY(friction);
    type(friction, QStringLiteral("0.25"));
    QVERIFY(friction->commit());
    tools.toolAction(EditTool::Spring)->trigger();
    drag(px(-2, 8), px(-2, 3));
}

} // namespace

// The History dock lists every edit by name, shows in Edit mode only, and a click on an entry
// goes back to the scene as it was after that edit.
void TestEditorWindow::historyListsEditsAndGoesBack()
{
    MainWindow w;
    w.resize(1024, 768);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.newScene());
    auto* dock = w.findChild<QDockWidget*>(QStringLiteral("historyDock"));
    auto* history = w.findChild<QUndoView*>(QStringLiteral("historyView"));
    QVERIFY(dock && history);
    QCOMPARE(dock->windowTitle(), QStringLiteral("History"));
    EditTools& tools = w.editTools();
    if (!tools.editing()) {
        tools.editAction()->trigger();
    }
    QVERIFY(dock->isVisible());
    WorldView& view = w.view();
    const SceneDocument& document = *w.document();
    const lessons::Scene opened = document.scene();
    const QPoint origin = view.mapFromScene(QPointF(0, 0));
    const double zoom = view.zoom();

    lessons::Scene withCircle;
    makeFiveEdits(w, withCircle);
    if (QTest::currentTestFailed()) {
        return;
    }
    const QStringList expected{QStringLiteral("Scene as opened"),
                               QStringLiteral("Add circle circle1"),
                               QStringLiteral("Add box box1"),
                               QStringLiteral("Move box1"),
                               QStringLiteral("Set friction μ of box1"),
                               QStringLiteral("Add spring from the world to circle1")};
    QAbstractItemModel* model = history->model();
    QStringList shown;
    for (int row = 0; row < model->rowCount(); ++row) {
        shown << model->index(row, 0).data().toString();
    }
    QVERIFY2(shown == expected, qPrintable(shown.join(QStringLiteral(" | "))));
    // The view held still under the pen, though the circle was drawn outside the ground's
    // fitted area.
    QCOMPARE(view.mapFromScene(QPointF(0, 0)), origin);
    QCOMPARE(view.zoom(), zoom);
    // The scene as it is now is the entry shown chosen (the current item only while the list
    // has the focus: test_accessibility).
    QVERIFY(history->selectionModel()->isSelected(model->index(5, 0)));

    // A click on "Add circle circle1": back to the scene with the circle alone.
    const QModelIndex entry = model->index(1, 0);
    QTest::mouseClick(history->viewport(), Qt::LeftButton, {}, history->visualRect(entry).center());
    QCOMPARE(document.undoStack()->index(), 1);
    QVERIFY2(difference(document.scene(), withCircle).isEmpty(),
             qPrintable(difference(document.scene(), withCircle)));
    QCOMPARE(w.controller().scene().bodies.size(), withCircle.bodies.size());
    // The first entry: the scene as opened; the later edits stay, to redo.
    QTest::mouseClick(history->viewport(), Qt::LeftButton, {},
                      history->visualRect(model->index(0, 0)).center());
    QVERIFY(difference(document.scene(), opened).isEmpty());
    QCOMPARE(model->rowCount(), 6);
    QTest::mouseClick(history->viewport(), Qt::LeftButton, {},
                      history->visualRect(model->index(5, 0)).center());
    QCOMPARE(document.scene().springs.size(), size_t(1));

    tools.editAction()->trigger();
    QVERIFY(!dock->isVisible());
}

// Found by hand under Xvfb: the first body drawn above a new scene's floor made the view follow
// it (auto-fit), so the floor jumped and the next stroke landed elsewhere than aimed.
void TestEditorWindow::viewHoldsStillWhileDrawing()
{
    MainWindow w;
    w.resize(1024, 768);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.newScene());
    EditTools& tools = w.editTools();
    WorldView& view = w.view();
    if (!tools.editing())
        tools.editAction()->trigger();
    QVERIFY(tools.editing());
    const QPoint origin = view.mapFromScene(QPointF(0, 0));
    const double zoom = view.transform().m11();
    // A ball drawn well above the floor, outside what the fitted view was fitted to.
    const double g = tools.gridStep();
    const QPointF top = view.mapToScene(QPoint(view.viewport()->width() / 2, 40));
    const Vec2 centre(std::round(top.x() / g) * g, std::floor(top.y() / g) * g - g);
    QVERIFY2(centre.y() > 1.0, "the view shows room above the floor");
    tools.toolAction(EditTool::Circle)->trigger();
    const QPoint from = view.mapFromScene(QPointF(centre.x(), centre.y()));
    const QPoint to = view.mapFromScene(QPointF(centre.x() + g, centre.y()));
    QTest::mousePress(view.viewport(), Qt::LeftButton, {}, from);
    QTest::mouseMove(view.viewport(), (from + to) / 2);
    QTest::mouseMove(view.viewport(), to);
    QTest::mouseRelease(view.viewport(), Qt::LeftButton, {}, to);
    const auto& bodies = w.document()->scene().bodies;
    QCOMPARE(bodies.size(), size_t(2));
    QVERIFY(near(bodies.back().position, centre));
    QCOMPARE(view.mapFromScene(QPointF(0, 0)), origin);
    QCOMPARE(view.transform().m11(), zoom);
    // Leaving Edit mode, the view still shows the scene as it was drawn.
    tools.editAction()->trigger();
    QVERIFY(!tools.editing());
    QCOMPARE(view.mapFromScene(QPointF(0, 0)), origin);
    QCOMPARE(view.transform().m11(), zoom);
}

void TestEditorWindow::newSceneOpensEditModeAndTheWorldHolds()
{
    MainWindow w;
    w.resize(1024, 768);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    auto* step = w.findChild<QAction*>(QStringLiteral("step"));
    auto* back = w.findChild<QAction*>(QStringLiteral("back"));
    QVERIFY(step && back);
    const QString stepTip = step->toolTip();
    QVERIFY(!w.editTools().editing());
    QVERIFY(step->isEnabled());

    // New: straight into Edit mode, paused at the start, Step and Back off and saying why.
    QVERIFY(w.newScene());
    QVERIFY(w.editTools().editing());
    QVERIFY(!w.controller().isRunning());
    for (QAction* a : {step, back}) {
        QVERIFY2(!a->isEnabled(), qPrintable(a->objectName()));
        QVERIFY2(a->toolTip().contains(QStringLiteral("Edit mode")), qPrintable(a->toolTip()));
    }
    // Whatever asks, the world does not step: Step, Back, a seek, the clock's frames.
    step->trigger();
    w.controller().stepForward();
    w.controller().stepBack();
    w.controller().seek(10);
    w.controller().advanceFrame();
    QCOMPARE(w.controller().world().stepCount(), 0LL);
    QCOMPARE(w.controller().world().time(), 0.0);

    // Leaving Edit mode keeps the scene paused at its start; Step and Back are back with their
    // own tooltips.
    w.editTools().editAction()->trigger();
    QVERIFY(!w.editTools().editing());
    QVERIFY(!w.controller().isRunning());
    QVERIFY(step->isEnabled() && back->isEnabled());
    QCOMPARE(step->toolTip(), stepTip);
    w.controller().stepForward();
    QCOMPARE(w.controller().world().stepCount(), 1LL);
}

void TestEditorWindow::lessonStepBuiltInTheEditorIsJudged()
{
    // The shipped step "make the heavier ball the one at rest", done as a student does it in
    // the window: it opens in Edit mode with its locks; the resting ball's mass is typed in;
    // leaving Edit mode runs the scene as edited, and the question measures that run.
    MainWindow w;
    w.resize(1024, 768);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    const QString path =
        QDir(MainWindow::lessonsFolder()).filePath(QStringLiteral("billiards_momentum.json"));
    QCOMPARE(w.openLesson(path, true), QString());
    const lessons::Lesson& lesson = *w.lessonPlayer().lesson();
    int index = -1;
    for (size_t i = 0; i < lesson.steps.size(); ++i) {
        if (lesson.steps[i].editor) {
            index = static_cast<int>(i);
        }
    }
    QVERIFY(index >= 0);
    QVERIFY(!w.editTools().editing()); // the first step does not edit
    w.lessonPlayer().goToStep(index);
    const lessons::LessonStep& step = lesson.steps[static_cast<size_t>(index)];
    EditTools& tools = w.editTools();
    QVERIFY(tools.editing());
    QVERIFY(!w.controller().isRunning());
    QVERIFY(tools.locked(EditTool::Circle));
    QVERIFY(!tools.locked(EditTool::Select));
    auto* properties = w.findChild<SceneProperties*>();
    QVERIFY(properties);
    QVERIFY(!properties->field(QStringLiteral("density"))->isEnabled());
    QVERIFY(properties->field(QStringLiteral("mass"))->isEnabled());

    const int resting = *step.scene.bodyIndex(QStringLiteral("resting"));
    const auto& ball = step.scene.bodies[static_cast<size_t>(resting)];
    w.view().fitScene();
    QTest::mouseClick(w.view().viewport(), Qt::LeftButton, {},
                      w.view().mapFromScene(QPointF(ball.position.x(), ball.position.y())));
    QCOMPARE(tools.selectedBody(), resting);
    NumberField* mass = properties->field(QStringLiteral("mass"));
    type(mass, QStringLiteral("3"));
    QVERIFY(mass->commit());
    QCOMPARE(w.document()->scene().bodies[static_cast<size_t>(resting)].mass, 3.0);

    tools.editAction()->trigger(); // leave: the scene as edited runs
    QVERIFY(!tools.editing());
    QVERIFY(w.controller().isRunning());
    QCOMPARE(w.controller().scene().bodies[static_cast<size_t>(resting)].mass, 3.0);
    w.controller().setRunning(false);
    const lessons::Question& q = step.questions.front();
    while (w.controller().world().time() < 2.5) {
        w.controller().stepForward();
    }
    const auto measured =
        w.controller().lessonWatch().measurements().value(measuredOf(q).measure, step.scene);
    QVERIFY(measured);
    // Momentum and an elastic hit: v1 = (m1 - m2) / (m1 + m2) u = -u/2 for m2 = 3 m1.
    const auto& moving = step.scene.bodies[*step.scene.bodyIndex(QStringLiteral("moving"))];
    RL_VERIFY_NEAR(*measured, (-0.5 * moving.velocity.x()), 1e-3, 0);

    // Leaving the lesson unlocks the editor's properties.
    w.lessonPlayer().closeLesson();
    QVERIFY(!tools.propertyLocked(QStringLiteral("density")));
}

void TestEditorWindow::lessonLocksProperties()
{
    Rig rig;
    rig.use(EditTool::Circle);
    rig.drag(rig.px(0, 4), rig.px(1, 4));
    QCOMPARE(rig.tools.selectedBody(), rig.index("circle1"));
    rig.tools.setAllowedProperties(QStringList{QStringLiteral("mass")});
    QVERIFY(rig.tools.propertyLocked(QStringLiteral("density")));
    QVERIFY(!rig.tools.propertyLocked(QStringLiteral("mass")));
    NumberField* mass = rig.properties.field(QStringLiteral("mass"));
    NumberField* density = rig.properties.field(QStringLiteral("density"));
    NumberField* vx = rig.properties.field(QStringLiteral("velocityX"));
    QVERIFY(mass->isEnabled());
    // Every other field is locked, saying why: a body's, a vector's components, the world's.
    for (QWidget* locked : std::initializer_list<QWidget*>{
             density, vx, rig.properties.field(QStringLiteral("velocityY")),
             rig.properties.field(QStringLiteral("gravityY")), rig.properties.idField(),
             rig.properties.typeBox(),
             rig.properties.findChild<QComboBox*>(QStringLiteral("integrator"))}) {
        QVERIFY2(!locked->isEnabled(), qPrintable(locked->objectName()));
        QVERIFY2(locked->toolTip().contains(QStringLiteral("This lesson step locks the")),
                 qPrintable(locked->objectName() + QStringLiteral(": ") + locked->toolTip()));
    }
    QCOMPARE(density->toolTip(), QStringLiteral("This lesson step locks the Density property"));
    QCOMPARE(vx->toolTip(), QStringLiteral("This lesson step locks the Velocity vx property"));

    // The allowed field edits.
    type(mass, QStringLiteral("2.5"));
    QVERIFY(mass->commit());
    QCOMPARE(rig.body("circle1").mass, 2.5);
    // A locked field takes no typing...
    const lessons::Scene before = rig.scene();
    QTest::keyClicks(density, QStringLiteral("7"));
    QTest::keyClick(density, Qt::Key_Return);
    QCOMPARE(difference(rig.scene(), before), QString());
    // ...and a change that reaches it some other way is refused out loud; the value stays.
    QSignalSpy refused(&rig.properties, &SceneProperties::refused);
    emit vx->valueEdited(3.0);
    QCOMPARE(refused.size(), 1);
    QCOMPARE(refused.front().front().toString(),
             QStringLiteral("This lesson step locks the Velocity vx property"));
    QCOMPARE(rig.body("circle1").velocity, Vec2::Zero());
    QCOMPARE(vx->value(), 0.0);
    QCOMPARE(difference(rig.scene(), before), QString());

    // Unlocked: the fields edit again, with their own tooltips back.
    rig.tools.setAllowedProperties(std::nullopt);
    QVERIFY(density->isEnabled());
    QVERIFY(!density->toolTip().contains(QStringLiteral("locks")));
    type(density, QStringLiteral("7"));
    QVERIFY(density->commit());
    QCOMPARE(rig.body("circle1").density, 7.0);
}

// A step that locks velocity and colour: the arrow's handle does not drag (nor does the press
// move the body), the colour row's swatch, text and Default are all locked, saying so.
void TestEditorWindow::lessonLocksTheArrowAndTheColour()
{
    Rig rig;
    rig.use(EditTool::Circle);
    rig.drag(rig.px(0, 4), rig.px(1, 4));
    rig.use(EditTool::Select);
    rig.tools.setAllowedProperties(QStringList{QStringLiteral("mass")});
    const lessons::Scene before = rig.scene();
    const auto rest = velocityArrow(rig.body("circle1"), rig.view.zoom());
    QVERIFY(rest);
    const QPoint from = rig.view.mapFromScene(QPointF(rest->handle.x(), rest->handle.y()));
    rig.drag(from, from + QPoint(60, -40));
    QVERIFY(difference(rig.scene(), before).isEmpty());
    QVERIFY2(rig.tools.lastMessage().contains(QStringLiteral("locks")),
             qPrintable(rig.tools.lastMessage()));
    for (const char* part : {"colour", "colourPick", "colourDefault"}) {
        auto* w = rig.properties.findChild<QWidget*>(QLatin1String(part));
        QVERIFY2(w, part);
        QVERIFY2(!w->isEnabled(), part);
        QCOMPARE(w->toolTip(), QStringLiteral("This lesson step locks the Colour property"));
    }
    // Unlocked again, the arrow drags.
    rig.tools.setAllowedProperties(std::nullopt);
    QVERIFY(rig.properties.findChild<QWidget*>(QStringLiteral("colourPick"))->isEnabled());
    rig.drag(from, from + QPoint(60, -40));
    QVERIFY(rig.body("circle1").velocity.norm() > 0.0);
}

// A value typed into a property and taken with Return hands the keyboard back to the scene:
// Ctrl+Z then undoes the edit (it does not go into the field), and the tools' keys act.
void TestEditorWindow::returnHandsTheKeyboardBackToTheScene()
{
    MainWindow w;
    w.resize(1024, 768);
    w.show();
    QVERIFY(QTest::qWaitForWindowActive(&w));
    QVERIFY(w.newScene());
    EditTools& tools = w.editTools();
    WorldView& view = w.view();
    const double g = tools.gridStep();
    const auto px = [&view, g](double x, double y) {
        return view.mapFromScene(QPointF(x * g, y * g));
    };
    tools.toolAction(EditTool::Circle)->trigger();
    QTest::mousePress(view.viewport(), Qt::LeftButton, {}, px(-2, 3));
    QTest::mouseMove(view.viewport(), px(-1.5, 3));
    QTest::mouseMove(view.viewport(), px(-1, 3));
    QTest::mouseRelease(view.viewport(), Qt::LeftButton, {}, px(-1, 3));
    const auto circle = w.document()->scene().bodyIndex(QStringLiteral("circle1"));
    QVERIFY(circle);
    const lessons::Scene drawn = w.document()->scene();
    auto* properties = w.findChild<QDockWidget*>(QStringLiteral("propertiesDock"));
    QVERIFY(properties);
    properties->show();
    properties->raise();
    auto* friction = properties->findChild<NumberField*>(QStringLiteral("friction"));
    QVERIFY(friction);
    friction->setFocus(Qt::TabFocusReason);
    QCoreApplication::processEvents();
    QVERIFY(friction->hasFocus());
    friction->selectAll();
    QTest::keyClicks(friction, QStringLiteral("0.45"));
    QTest::keyClick(friction, Qt::Key_Return);
    QCOMPARE(w.document()->scene().bodies[static_cast<size_t>(*circle)].friction, 0.45);
    QVERIFY2(view.hasFocus(),
             qPrintable(QApplication::focusWidget() ? QApplication::focusWidget()->objectName()
                                                    : QStringLiteral("nothing")));
    // Ctrl+Z on the keyboard, where the focus is now: the edit goes, the field shows it.
    QTest::keyClick(QApplication::focusWidget(), Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(difference(w.document()->scene(), drawn), QString());
    QCOMPARE(w.document()->scene().bodies.size(), drawn.bodies.size());
}

RIGIDLAB_TEST_MAIN(TestEditorWindow)
#include "test_editor_window.moc"
