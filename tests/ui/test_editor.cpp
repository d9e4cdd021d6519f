// SPDX-License-Identifier: GPL-3.0-or-later
// The scene editor, driven as a teacher drives it: Edit mode, the tools' actions,
// mouse drags and clicks on the view. Every edit is undone back to the scene as opened (field
// by field) and redone; refusals and warnings reach the status line with the loader's words.
// (The tools one by one: test_editor_tools.cpp; the editor in the window: test_editor_window.)

#include "editor_test_util.h"

#include "editor/colour_field.h"
#include "editor/velocity_arrow.h"
#include "panels/number_field.h"
#include "view/body_item.h"

#include "edit/scene_edits.h"
#include "rigidlab/physics/work_budget.h"

#include "near.h"
#include "test_main.h"

#include <QComboBox>
#include <QElapsedTimer>
#include <QSignalSpy>
#include <QToolButton>
#include <QUndoStack>

#include <numbers>
#include <optional>

using namespace rigidlab;
using namespace rigidlab::ui;
using namespace rigidlab::ui::test;
namespace edit = rigidlab::lessons::edit;

class TestEditor : public QObject {
    Q_OBJECT
private slots:
    void editModePausesAndRunsAsEdited();
    void drawsEveryKindAndUndoesBackToTheOpenedScene();
    void refusesDegenerateShapesWithTheirMessage();
    void warnsOfOverlapsAndHulls();
    void keysNudgeAndTurn();
    void velocityByDraggingTheArrow();
    void colourInTheProperties();
    void propertiesShowWhatMatters();
    void duplicatePastTheBudgetIsRefused();
};

void TestEditor::editModePausesAndRunsAsEdited()
{
    Rig rig;
    QVERIFY(rig.tools.editing());
    QVERIFY(rig.tools.editAction()->isChecked());
    QVERIFY(!rig.simulation.isRunning());
    QVERIFY(rig.tools.toolAction(EditTool::Circle)->isEnabled());
    rig.use(EditTool::Circle);
    rig.drag(rig.px(0, 4), rig.px(1, 4));
    QCOMPARE(rig.scene().bodies.size(), size_t(1));
    // The world shows the scene as edited, at its start.
    QCOMPARE(rig.simulation.world().bodies().size(), size_t(1));
    QCOMPARE(rig.simulation.world().time(), 0.0);
    // Run (Space's action) leaves Edit mode and runs the scene as edited.
    rig.simulation.setRunning(true);
    QVERIFY(!rig.tools.editing());
    QVERIFY(rig.simulation.isRunning());
    QVERIFY(!rig.tools.toolAction(EditTool::Circle)->isEnabled());
    QCOMPARE(rig.simulation.world().bodies().size(), size_t(1));
    rig.tools.editAction()->trigger();
    QVERIFY(rig.tools.editing());
    QVERIFY(!rig.simulation.isRunning());

    // Leaving Edit mode keeps the world paused at the start of the scene as edited: the class
    // predicts, then the teacher presses Run.
    rig.use(EditTool::Box);
    rig.drag(rig.px(3, 4), rig.px(5, 5));
    rig.tools.editAction()->trigger();
    QVERIFY(!rig.tools.editing());
    QVERIFY(!rig.simulation.isRunning());
    QCOMPARE(rig.simulation.world().time(), 0.0);
    QCOMPARE(rig.simulation.world().bodies().size(), size_t(2));
    rig.simulation.setRunning(true);
    QVERIFY(rig.simulation.isRunning());
}

namespace {

/// Draws a ground, a circle, a box, a polygon, a pendulum on a pin and a spring on `rig`.
void drawEveryKind(Rig& rig)
{
    const double g = rig.g;

    rig.use(EditTool::Ground);
    rig.drag(rig.px(-10, -1), rig.px(10, 0));
    QCOMPARE(rig.body("ground1").type, physics::BodyType::Static);
    QVERIFY(near(rig.body("ground1").position, Vec2(0.0, -0.5 * g)));

    rig.use(EditTool::Circle);
    rig.drag(rig.px(-4, 2), rig.px(-3, 2));
    QVERIFY(near(rig.body("circle1").position, Vec2(-4 * g, 2 * g)));
    RL_VERIFY_NEAR(rig.body("circle1").shape.asCircle()->radius, g, kTolerance, 0);

    rig.use(EditTool::Box);
    rig.drag(rig.px(2, 0), rig.px(4, 2));
    QVERIFY(near(rig.body("box1").position, Vec2(3 * g, g)));
    QVERIFY2(rig.tools.lastMessage().isEmpty(), qPrintable(rig.tools.lastMessage()));

    rig.use(EditTool::Polygon);
    rig.click(rig.px(6, 0));
    rig.click(rig.px(8, 0));
    rig.click(rig.px(7, 2));
    QCOMPARE(rig.tools.polygonPoints().size(), size_t(3));
    QTest::keyClick(&rig.view, Qt::Key_Return);
    QVERIFY(rig.index("polygon1") >= 0);
    QVERIFY(rig.tools.polygonPoints().empty());
    QVERIFY(std::abs(physics::computeMass(rig.body("polygon1").shape, 1.0).area - 2 * g * g) <
            1e-9);

    // A pendulum: a ball pinned to the world above its centre.
    rig.use(EditTool::Circle);
    rig.drag(rig.px(-8, 6), rig.px(-7, 6));
    rig.use(EditTool::Pin);
    rig.click(rig.px(-8, 6));  // the ball's centre
    rig.click(rig.px(-8, 12)); // empty space: the world
    QCOMPARE(rig.scene().joints.size(), size_t(1));
    QCOMPARE(rig.scene().joints[0].a, rig.index("circle2"));
    QCOMPARE(rig.scene().joints[0].b, physics::kWorld);
    QVERIFY(near(rig.scene().joints[0].anchorB, Vec2(-8 * g, 6 * g)));

    // A spring from the world down to the box's centre (snapped onto it).
    rig.use(EditTool::Spring);
    rig.drag(rig.px(3, 8), rig.px(3, 1));
    QCOMPARE(rig.scene().springs.size(), size_t(1));
    QCOMPARE(rig.scene().springs[0].a, physics::kWorld);
    QCOMPARE(rig.scene().springs[0].b, rig.index("box1"));
    RL_VERIFY_NEAR(rig.scene().springs[0].restLength, 7 * g, kTolerance, 0);
    QCOMPARE(rig.scene().springs[0].stiffness, EditTools::kSpringStiffness);
}

} // namespace

void TestEditor::drawsEveryKindAndUndoesBackToTheOpenedScene()
{
    Rig rig;
    const double g = rig.g;
    QUndoStack& undo = *rig.document.undoStack();
    drawEveryKind(rig);
    if (QTest::currentTestFailed()) {
        return;
    }

    // Move: one drag is one step of the history.
    rig.use(EditTool::Select);
    const int before = undo.count();
    rig.drag(rig.px(3, 1), rig.px(3, 3));
    QCOMPARE(undo.count(), before + 1);
    QVERIFY(near(rig.body("box1").position, Vec2(3 * g, 3 * g)));
    QCOMPARE(rig.tools.selectedBody(), rig.index("box1"));

    // Rotate by the handle: a quarter turn about the origin.
    rig.use(EditTool::Rotate);
    rig.drag(rig.px(3.8, 3), rig.px(3, 3.8));
    QVERIFY2(std::abs(rig.body("box1").angle - std::numbers::pi / 2) < 1e-9,
             qPrintable(QString::number(rig.body("box1").angle)));

    // Properties, typed into their fields: the box's mass, a spring's stiffness, gravity.
    rig.use(EditTool::Select);
    rig.click(rig.px(3, 3));
    QCOMPARE(rig.tools.selectedBody(), rig.index("box1"));
    NumberField* mass = rig.properties.field(QStringLiteral("mass"));
    QVERIFY(mass && mass->isVisibleTo(&rig.properties));
    type(mass, QStringLiteral("3"));
    QVERIFY(mass->commit());
    QCOMPARE(rig.body("box1").mass, 3.0);
    NumberField* restitution = rig.properties.field(QStringLiteral("restitution"));
    type(restitution, QStringLiteral("1.5"));
    QVERIFY(!restitution->commit()); // refused by the field, with the limits' range
    QVERIFY2(restitution->error().contains(QStringLiteral("1")), qPrintable(restitution->error()));
    QCOMPARE(rig.body("box1").restitution, -1.0); // the world's, as before
    rig.click(rig.px(3, 6)); // on the spring from (3, 8) down to the box at (3, 3)
    QCOMPARE(rig.tools.selectedSpring(), 0);
    QCOMPARE(rig.tools.selectedBody(), -1);
    NumberField* stiffness = rig.properties.field(QStringLiteral("stiffness"));
    QVERIFY(stiffness->isVisibleTo(&rig.properties));
    type(stiffness, QStringLiteral("120"));
    QVERIFY(stiffness->commit());
    QCOMPARE(rig.scene().springs[0].stiffness, 120.0);
    NumberField* gravity = rig.properties.field(QStringLiteral("gravityY"));
    type(gravity, QStringLiteral("-1.62"));
    QVERIFY(gravity->commit());
    QCOMPARE(rig.scene().world.gravity.y(), -1.62);
    QCOMPARE(rig.simulation.world().def().gravity.y(), -1.62); // the world follows the document

    // Duplicate the polygon, delete the first circle (the others' indices follow).
    rig.use(EditTool::Duplicate);
    rig.click(rig.px(7, 0.5));
    QVERIFY(rig.index("polygon2") >= 0);
    QVERIFY(rig.body("polygon2").position.x() > rig.body("polygon1").position.x());
    rig.use(EditTool::Delete);
    rig.click(rig.px(-4, 2));
    QCOMPARE(rig.index("circle1"), -1);
    QCOMPARE(rig.scene().joints[0].a, rig.index("circle2"));
    QCOMPARE(rig.scene().springs[0].b, rig.index("box1"));

    // Undo everything: the scene as opened, field by field; redo everything.
    const lessons::Scene edited = rig.scene();
    while (undo.canUndo()) {
        undo.undo();
    }
    QVERIFY2(difference(rig.scene(), rig.opened).isEmpty(),
             qPrintable(difference(rig.scene(), rig.opened)));
    QCOMPARE(rig.simulation.world().bodies().size(), size_t(0));
    while (undo.canRedo()) {
        undo.redo();
    }
    QVERIFY2(difference(rig.scene(), edited).isEmpty(),
             qPrintable(difference(rig.scene(), edited)));
    QCOMPARE(rig.simulation.world().bodies().size(), edited.bodies.size());
}

namespace {

/// A drag away from `at` and back to it before the release.
void dragOutAndBack(Rig& rig, QPoint at)
{
    QTest::mousePress(rig.viewport(), Qt::LeftButton, {}, at);
    QTest::mouseMove(rig.viewport(), at + QPoint(40, 30));
    QTest::mouseMove(rig.viewport(), at);
    QTest::mouseRelease(rig.viewport(), Qt::LeftButton, {}, at);
}

} // namespace

void TestEditor::refusesDegenerateShapesWithTheirMessage()
{
    Rig rig;
    rig.use(EditTool::Polygon);
    rig.click(rig.px(0, 0));
    rig.click(rig.px(2, 2));
    rig.click(rig.px(4, 4));
    QTest::keyClick(&rig.view, Qt::Key_Return);
    QVERIFY(rig.scene().bodies.empty());
    QVERIFY2(rig.tools.lastMessage().contains(QStringLiteral("the polygon has no area")),
             qPrintable(rig.tools.lastMessage()));

    rig.use(EditTool::Circle);
    dragOutAndBack(rig, rig.px(1, 1)); // a drag that ends where it began: no radius
    QVERIFY(rig.scene().bodies.empty());
    QVERIFY2(rig.tools.lastMessage().startsWith(QStringLiteral("circle1: shape.radius: must be")),
             qPrintable(rig.tools.lastMessage()));

    rig.use(EditTool::Box);
    rig.drag(rig.px(0, 0), rig.px(2, 2));
    rig.use(EditTool::Spring);
    dragOutAndBack(rig, rig.px(1, 1));
    QVERIFY(rig.scene().springs.empty());
    QVERIFY2(rig.tools.lastMessage().contains(QStringLiteral("zero length")),
             qPrintable(rig.tools.lastMessage()));

    rig.use(EditTool::Pin);
    rig.click(rig.px(1, 1));
    rig.click(rig.px(1.5, 1.5)); // the same box
    QVERIFY(rig.scene().joints.empty());
    QVERIFY2(rig.tools.lastMessage().endsWith(QStringLiteral("a pin joins two bodies")),
             qPrintable(rig.tools.lastMessage()));
    QCOMPARE(rig.document.undoStack()->count(), 1); // the box alone
}

void TestEditor::warnsOfOverlapsAndHulls()
{
    Rig rig;
    rig.use(EditTool::Polygon);
    for (const auto& [x, y] : {std::pair{0.0, 0.0}, {4.0, 0.0}, {2.0, 1.0}, {4.0, 4.0}}) {
        rig.click(rig.px(x, y));
    }
    QTest::mouseDClick(rig.viewport(), Qt::LeftButton, {}, rig.px(0, 4));
    QCOMPARE(rig.scene().bodies.size(), size_t(1));
    QCOMPARE(rig.scene().bodies[0].shape.asPolygon()->vertices.size(), size_t(4));
    QVERIFY2(rig.tools.lastMessage().contains(QStringLiteral("not convex")),
             qPrintable(rig.tools.lastMessage()));

    rig.use(EditTool::Circle);
    rig.drag(rig.px(4, 2), rig.px(5, 2));           // into the polygon's right edge
    QCOMPARE(rig.scene().bodies.size(), size_t(2)); // allowed...
    QVERIFY2(rig.tools.lastMessage().contains(QStringLiteral("polygon1 overlaps circle1")),
             qPrintable(rig.tools.lastMessage())); // ...but said
}

void TestEditor::keysNudgeAndTurn()
{
    Rig rig;
    rig.use(EditTool::Box);
    rig.drag(rig.px(0, 0), rig.px(2, 2));
    QCOMPARE(rig.tools.selectedBody(), 0);
    QUndoStack& undo = *rig.document.undoStack();
    rig.view.setFocus();
    QTest::keyClick(&rig.view, Qt::Key_Right);
    QTest::keyClick(&rig.view, Qt::Key_Up);
    QVERIFY(near(rig.body("box1").position, Vec2(2 * rig.g, 2 * rig.g)));
    QCOMPARE(undo.count(), 2); // the box, and one step for the run of arrow keys
    QTest::keyClick(&rig.view, Qt::Key_Q);
    RL_VERIFY_NEAR(rig.body("box1").angle, 5.0 * std::numbers::pi / 180.0, 1e-12, 0);
    QTest::keyClick(&rig.view, Qt::Key_E);
    QTest::keyClick(&rig.view, Qt::Key_E);
    RL_VERIFY_NEAR(rig.body("box1").angle + 5.0 * std::numbers::pi / 180.0, 0.0, 1e-12, 0);
    QCOMPARE(undo.count(), 3); // one step for the turns
    QCOMPARE(undo.text(2), QStringLiteral("Rotate box1"));
    undo.undo();
    QCOMPARE(rig.body("box1").angle, 0.0);
    // After an undo, a key starts a new step.
    QTest::keyClick(&rig.view, Qt::Key_E);
    QCOMPARE(undo.count(), 3);
    QTest::keyClick(&rig.view, Qt::Key_E);
    QCOMPARE(undo.count(), 3);
    undo.undo();
    QCOMPARE(rig.body("box1").angle, 0.0);
    rig.tools.deleteSelectionAction()->trigger();
    QVERIFY(rig.scene().bodies.empty());
}

// The Select tool's velocity arrow: one drag from the handle sets vx, vy (1 m of arrow is
// 1 m/s; on the grid, whole grid steps in m/s), one undo step, and the body runs with it.
void TestEditor::velocityByDraggingTheArrow()
{
    Rig rig;
    rig.document.apply(QStringLiteral("no gravity"),
                       edit::setWorldNumber(rig.scene(), edit::WorldNumber::GravityY, 0.0).scene);
    rig.use(EditTool::Circle);
    rig.drag(rig.px(0, 0), rig.px(1, 0));
    QCOMPARE(rig.tools.selectedBody(), 0);
    rig.use(EditTool::Select);
    const lessons::Scene before = rig.scene();
    const int steps = rig.document.undoStack()->count();

    // At rest the handle is a stub beyond the outline, not on the body (a press there moves it).
    const auto rest = velocityArrow(rig.body("circle1"), rig.view.zoom());
    QVERIFY(rest);
    QCOMPARE(rest->tip, rig.body("circle1").position);
    QVERIFY((rest->handle - rest->tail).norm() > rig.g);

    const Vec2 want(3 * rig.g, -2 * rig.g); // [m/s]
    const QPoint from = rig.view.mapFromScene(QPointF(rest->handle.x(), rest->handle.y()));
    const Vec2 end = rest->handle + want * kArrowSeconds;
    const QPoint to = rig.view.mapFromScene(QPointF(end.x(), end.y()));
    QTest::mousePress(rig.viewport(), Qt::LeftButton, {}, from);
    for (int k = 1; k <= 4; ++k) {
        QTest::mouseMove(rig.viewport(), from + (to - from) * k / 4);
    }
    // While dragging, the status line gives the velocity in m/s, in the locale's numbers.
    QVERIFY2(rig.tools.lastMessage().contains(QStringLiteral("m/s")),
             qPrintable(rig.tools.lastMessage()));
    QVERIFY2(rig.tools.lastMessage().contains(formatNumber(want.x(), 4)),
             qPrintable(rig.tools.lastMessage()));
    QTest::mouseRelease(rig.viewport(), Qt::LeftButton, {}, to);

    const physics::BodyDef& ball = rig.body("circle1");
    QVERIFY2(near(ball.velocity, want), qPrintable(rig.tools.lastMessage()));
    QCOMPARE(ball.position, before.bodies[0].position); // the body did not move
    QCOMPARE(rig.document.undoStack()->count(), steps + 1);
    // The Properties fields follow, and the arrow now ends at position + v * kArrowSeconds.
    QCOMPARE(rig.properties.field(QStringLiteral("velocityX"))->value(), ball.velocity.x());
    QCOMPARE(rig.properties.field(QStringLiteral("velocityY"))->value(), ball.velocity.y());
    const auto moving = velocityArrow(ball, rig.view.zoom());
    QVERIFY(moving && near(moving->tip, ball.position + want * kArrowSeconds));

    // Undo gives back the scene before the drag, bit for bit; redo the velocity.
    rig.document.undoStack()->undo();
    QCOMPARE(difference(rig.scene(), before), QString());
    QCOMPARE(rig.body("circle1").velocity, Vec2(0.0, 0.0));
    rig.document.undoStack()->redo();
    QVERIFY(near(rig.body("circle1").velocity, want));

    // A press beside the handle (on the body) moves the body, not its velocity.
    rig.drag(rig.px(0, 0), rig.px(0, 1));
    QVERIFY(near(rig.body("circle1").velocity, want));
    QVERIFY(near(rig.body("circle1").position, Vec2(0.0, rig.g)));

    // Run, without gravity: x(t) = x0 + v t.
    const Vec2 x0 = rig.body("circle1").position;
    rig.tools.setEditing(false);
    for (int k = 0; k < 25; ++k) {
        rig.simulation.stepForward();
    }
    const double t = rig.simulation.world().time();
    QVERIFY(t > 0.0);
    const Vec2 x = rig.simulation.world().bodies()[0].position;
    QVERIFY2(near(x, x0 + want * t),
             qPrintable(QStringLiteral("(%1, %2) at t = %3").arg(x.x()).arg(x.y()).arg(t)));
}

// The colour row: a swatch that opens a picker (injected here: no modal dialog offscreen), a
// "#rrggbb" field refused in the loader's words, Default; each one undo step; the view paints
// the body in it.
void TestEditor::colourInTheProperties()
{
    Rig rig;
    rig.use(EditTool::Box);
    rig.drag(rig.px(0, 0), rig.px(2, 1));
    QCOMPARE(rig.tools.selectedBody(), 0);
    const lessons::Scene drawn = rig.scene();
    const int steps = rig.document.undoStack()->count();
    ColourField* colour = rig.properties.colourField();
    QVERIFY(colour);
    QVERIFY(colour->colour().isEmpty());
    QVERIFY(!colour->defaultButton()->isEnabled());

    std::optional<QColor> picked = QColor(0xd0, 0x40, 0x30);
    QColor offered;
    colour->setPicker([&](const QColor& initial, QWidget*) {
        offered = initial;
        return picked;
    });
    QTest::mouseClick(colour->swatchButton(), Qt::LeftButton);
    QCOMPARE(offered, bodyColor(0)); // the picker starts from the colour shown
    QCOMPARE(rig.scene().colourOf(0), QStringLiteral("#d04030"));
    QCOMPARE(rig.document.undoStack()->count(), steps + 1);
    QCOMPARE(colour->textField()->text(), QStringLiteral("#d04030"));
    QVERIFY(rig.view.itemFor(0));
    QCOMPARE(rig.view.itemFor(0)->fill(), QColor(0xd0, 0x40, 0x30));
    // Cancelling the picker changes nothing; it started from the body's colour.
    picked.reset();
    QTest::mouseClick(colour->swatchButton(), Qt::LeftButton);
    QCOMPARE(offered, QColor(0xd0, 0x40, 0x30));
    QCOMPARE(rig.document.undoStack()->count(), steps + 1);

    // Typed, in either case; kept as the loader keeps it.
    type(colour->textField(), QStringLiteral("#00FF7F"));
    QTest::keyClick(colour->textField(), Qt::Key_Return);
    QCOMPARE(rig.scene().colourOf(0), QStringLiteral("#00ff7f"));
    QCOMPARE(rig.view.itemFor(0)->fill(), QColor(0x00, 0xff, 0x7f));

    // Not a colour: refused with the loader's message, the colour in force comes back.
    QSignalSpy refused(&rig.properties, &SceneProperties::refused);
    type(colour->textField(), QStringLiteral("red"));
    QTest::keyClick(colour->textField(), Qt::Key_Return);
    QCOMPARE(refused.count(), 1);
    QVERIFY2(refused.at(0).at(0).toString().startsWith(
                 QStringLiteral("box1: colour: must be a colour \"#rrggbb\"")),
             qPrintable(refused.at(0).at(0).toString()));
    QCOMPARE(rig.scene().colourOf(0), QStringLiteral("#00ff7f"));
    QCOMPARE(colour->textField()->text(), QStringLiteral("#00ff7f"));
    QCOMPARE(rig.document.undoStack()->count(), steps + 2);

    // Default takes it away: the view's own colour again.
    QVERIFY(colour->defaultButton()->isEnabled());
    QTest::mouseClick(colour->defaultButton(), Qt::LeftButton);
    QVERIFY(rig.scene().colourOf(0).isEmpty());
    QCOMPARE(rig.view.itemFor(0)->fill(), bodyColor(0));
    QCOMPARE(rig.document.undoStack()->count(), steps + 3);

    // Undo all three: the scene as drawn, bit for bit; redo them.
    for (int k = 0; k < 3; ++k) {
        rig.document.undoStack()->undo();
    }
    QCOMPARE(difference(rig.scene(), drawn), QString());
    QCOMPARE(rig.scene().colours, drawn.colours);
    for (int k = 0; k < 3; ++k) {
        rig.document.undoStack()->redo();
    }
    QVERIFY(rig.scene().colourOf(0).isEmpty());
    rig.document.undoStack()->undo();
    QCOMPARE(rig.scene().colourOf(0), QStringLiteral("#00ff7f"));
}

// Found by hand: a drawn ball's mass read "0,403417956328" (density times area, to twelve
// digits), and a static ramp offered a density and a mass that change nothing.
void TestEditor::propertiesShowWhatMatters()
{
    Rig rig;
    rig.use(EditTool::Circle);
    rig.drag(rig.px(0, 4), rig.px(1, 4));
    QCOMPARE(rig.tools.selectedBody(), rig.index("circle1"));
    const physics::BodyDef& ball = rig.body("circle1");
    NumberField* mass = rig.properties.field(QStringLiteral("mass"));
    NumberField* density = rig.properties.field(QStringLiteral("density"));
    const double area = std::numbers::pi * rig.g * rig.g;
    // The density is the scene's; the mass is computed from it, shown to four digits.
    QCOMPARE(density->text(), formatNumber(ball.density));
    QCOMPARE(mass->text(), formatNumber(ball.density * area, 4));
    QCOMPARE(mass->value(), ball.density * area); // the value itself is not rounded
    // Given a mass, the density becomes the computed one.
    type(mass, QLocale().toString(2.5));
    QVERIFY(mass->commit());
    QCOMPARE(rig.body("circle1").mass, 2.5);
    QCOMPARE(mass->text(), formatNumber(2.5));
    QCOMPARE(density->text(), formatNumber(2.5 / area, 4));
    // Static: no density, mass or velocity rows; restitution and friction stay.
    QComboBox* kind = rig.properties.findChild<QComboBox*>(QStringLiteral("type"));
    QVERIFY(kind);
    kind->setCurrentIndex(kind->findData(int(physics::BodyType::Static)));
    emit kind->activated(kind->currentIndex());
    QCOMPARE(rig.body("circle1").type, physics::BodyType::Static);
    QVERIFY(!mass->isVisibleTo(&rig.properties));
    QVERIFY(!density->isVisibleTo(&rig.properties));
    QVERIFY(!rig.properties.field(QStringLiteral("velocityX"))->isVisibleTo(&rig.properties));
    QVERIFY(rig.properties.field(QStringLiteral("friction"))->isVisibleTo(&rig.properties));
    // Kinematic: it moves at its velocity, whatever its mass.
    kind->setCurrentIndex(kind->findData(int(physics::BodyType::Kinematic)));
    emit kind->activated(kind->currentIndex());
    QVERIFY(!mass->isVisibleTo(&rig.properties));
    QVERIFY(rig.properties.field(QStringLiteral("velocityX"))->isVisibleTo(&rig.properties));
    rig.document.undoStack()->undo();
    rig.document.undoStack()->undo();
    QCOMPARE(rig.body("circle1").type, physics::BodyType::Dynamic);
    QVERIFY(mass->isVisibleTo(&rig.properties));
}

RIGIDLAB_TEST_MAIN(TestEditor)
#include "test_editor.moc"

// Duplicate clicked again and again on one ball puts every copy at one place beside it: past
// the engine's budget of pairs for a step the editor refuses the copy with a message in the
// status line, quickly, and the scene as it stands runs (or stops with its diagnosis): the
// window never freezes.
void TestEditor::duplicatePastTheBudgetIsRefused()
{
    Rig rig;
    rig.use(EditTool::Circle);
    rig.drag(rig.px(0, 4), rig.px(1, 4));
    rig.use(EditTool::Duplicate);
    QElapsedTimer clock;
    clock.start();
    std::size_t bodies = 0;
    int clicks = 0;
    for (; clicks < 200 && !rig.tools.lastMessage().contains(QStringLiteral("spread them out"));
         ++clicks) {
        bodies = rig.scene().bodies.size();
        rig.click(rig.px(0, 4)); // the first ball, every time
    }
    const qint64 ms = clock.elapsed();
    const QString message = rig.tools.lastMessage();
    QVERIFY2(
        message.contains(
            QStringLiteral("more than %1 pairs of bodies").arg(physics::pairBudget(bodies + 1))),
        qPrintable(message));
    QCOMPARE(rig.scene().bodies.size(), bodies); // the refused copy is not made
    qInfo("refused the copy after %d clicks (%zu bodies) in %lld ms", clicks, bodies, ms);
    RL_VERIFY_AT_MOST(ms, 5000);
    // Run the scene as it stands for a few frames: it runs, or stops with a diagnosis.
    rig.tools.editAction()->trigger();
    QVERIFY(!rig.tools.editing());
    clock.restart();
    for (int i = 0; i < 5; ++i)
        rig.simulation.stepForward();
    RL_VERIFY_AT_MOST(clock.elapsed(), 5000);
    const physics::World& world = rig.simulation.world();
    QVERIFY2(world.divergence() || world.stepCount() == 5,
             qPrintable(QString::number(world.stepCount())));
}
