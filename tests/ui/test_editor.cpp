// SPDX-License-Identifier: GPL-3.0-or-later
// The scene editor (issue 15), driven as a teacher drives it: Edit mode, the tools' actions,
// mouse drags and clicks on the view. Every edit is undone back to the scene as opened (field
// by field) and redone; refusals and warnings reach the status line with the loader's words.

#include "editor/edit_tools.h"
#include "editor/scene_document.h"
#include "simulation/simulation_controller.h"
#include "view/world_view.h"

#include "format/scene.h"

#include "test_main.h"

#include <QAction>
#include <QTest>
#include <QUndoStack>

#include <cmath>
#include <numbers>

using namespace rigidlab;
using namespace rigidlab::ui;
using physics::Vec2;

namespace {

constexpr double kTolerance = 1e-9;

/// Where two scenes differ, the first field found; empty when they are the same.
QString difference(const lessons::Scene& a, const lessons::Scene& b)
{
    if (a.title != b.title || a.description != b.description) {
        return QStringLiteral("title or description");
    }
    const auto& wa = a.world;
    const auto& wb = b.world;
    if (wa.gravity != wb.gravity || wa.dt != wb.dt || wa.integrator != wb.integrator ||
        wa.solver != wb.solver || wa.iterations != wb.iterations ||
        wa.restitution != wb.restitution || wa.friction != wb.friction) {
        return QStringLiteral("world");
    }
    if (a.bodies.size() != b.bodies.size()) {
        return QStringLiteral("body count %1 vs %2").arg(a.bodies.size()).arg(b.bodies.size());
    }
    for (size_t i = 0; i < a.bodies.size(); ++i) {
        const auto& x = a.bodies[i];
        const auto& y = b.bodies[i];
        const bool same =
            x.name == y.name && x.type == y.type && x.position == y.position &&
            x.angle == y.angle && x.velocity == y.velocity &&
            x.angularVelocity == y.angularVelocity && x.density == y.density && x.mass == y.mass &&
            x.restitution == y.restitution && x.friction == y.friction && x.collide == y.collide &&
            x.shape.geometry.index() == y.shape.geometry.index() &&
            (x.shape.asCircle() ? x.shape.asCircle()->radius == y.shape.asCircle()->radius
                                : x.shape.asPolygon()->vertices == y.shape.asPolygon()->vertices);
        if (!same) {
            return QStringLiteral("bodies[%1]").arg(i);
        }
    }
    if (a.springs.size() != b.springs.size() || a.joints.size() != b.joints.size() ||
        a.originalVertices != b.originalVertices) {
        return QStringLiteral("springs, joints or original vertices");
    }
    for (size_t i = 0; i < a.springs.size(); ++i) {
        const auto& x = a.springs[i];
        const auto& y = b.springs[i];
        if (x.a != y.a || x.b != y.b || x.anchorA != y.anchorA || x.anchorB != y.anchorB ||
            x.stiffness != y.stiffness || x.damping != y.damping || x.restLength != y.restLength) {
            return QStringLiteral("springs[%1]").arg(i);
        }
    }
    for (size_t i = 0; i < a.joints.size(); ++i) {
        const auto& x = a.joints[i];
        const auto& y = b.joints[i];
        if (x.a != y.a || x.b != y.b || x.anchorA != y.anchorA || x.anchorB != y.anchorB) {
            return QStringLiteral("joints[%1]").arg(i);
        }
    }
    return {};
}

/// An editor on a view of its own, on an empty scene.
struct Rig {
    SimulationController simulation;
    SceneDocument document;
    WorldView view{simulation};
    EditTools tools{view, simulation, document};
    lessons::Scene opened;
    double g = 0; ///< the grid step [m]; every point below is on the grid

    Rig()
    {
        opened.title = QStringLiteral("Empty");
        opened.world.gravity = Vec2(0.0, -9.81);
        document.reset(opened, {});
        simulation.loadScene(opened, {});
        view.resize(900, 700);
        view.show();
        tools.setEditing(true);
        g = tools.gridStep();
    }

    const lessons::Scene& scene() const { return document.scene(); }
    QWidget* viewport() { return view.viewport(); }
    QPoint px(double x, double y) const { return view.mapFromScene(QPointF(x * g, y * g)); }
    void use(EditTool tool) { tools.toolAction(tool)->trigger(); }
    void drag(QPoint from, QPoint to)
    {
        QTest::mousePress(viewport(), Qt::LeftButton, {}, from);
        QTest::mouseMove(viewport(), (from + to) / 2);
        QTest::mouseMove(viewport(), to);
        QTest::mouseRelease(viewport(), Qt::LeftButton, {}, to);
    }
    void click(QPoint at) { QTest::mouseClick(viewport(), Qt::LeftButton, {}, at); }
    int index(const char* id) const
    {
        const auto found = scene().bodyIndex(QString::fromLatin1(id));
        return found ? *found : -1;
    }
    const physics::BodyDef& body(const char* id) const
    {
        return scene().bodies[static_cast<size_t>(index(id))];
    }
};

bool near(const Vec2& a, const Vec2& b)
{
    return (a - b).norm() <= kTolerance;
}

} // namespace

class TestEditor : public QObject {
    Q_OBJECT
private slots:
    void editModePausesAndRunsAsEdited();
    void drawsEveryKindAndUndoesBackToTheOpenedScene();
    void refusesDegenerateShapesWithTheirMessage();
    void warnsOfOverlapsAndHulls();
    void keysNudgeAndTurn();
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
}

void TestEditor::drawsEveryKindAndUndoesBackToTheOpenedScene()
{
    Rig rig;
    const double g = rig.g;
    QUndoStack& undo = *rig.document.undoStack();

    rig.use(EditTool::Ground);
    rig.drag(rig.px(-10, -1), rig.px(10, 0));
    QCOMPARE(rig.body("ground1").type, physics::BodyType::Static);
    QVERIFY(near(rig.body("ground1").position, Vec2(0.0, -0.5 * g)));

    rig.use(EditTool::Circle);
    rig.drag(rig.px(-4, 2), rig.px(-3, 2));
    QVERIFY(near(rig.body("circle1").position, Vec2(-4 * g, 2 * g)));
    QVERIFY(std::abs(rig.body("circle1").shape.asCircle()->radius - g) < kTolerance);

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
    QVERIFY(std::abs(rig.scene().springs[0].restLength - 7 * g) < kTolerance);
    QCOMPARE(rig.scene().springs[0].stiffness, EditTools::kSpringStiffness);

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
    rig.click(rig.px(1, 1)); // no drag: no radius
    QVERIFY(rig.scene().bodies.empty());
    QVERIFY2(rig.tools.lastMessage().startsWith(QStringLiteral("circle1: shape.radius: must be")),
             qPrintable(rig.tools.lastMessage()));

    rig.use(EditTool::Box);
    rig.drag(rig.px(0, 0), rig.px(2, 2));
    rig.use(EditTool::Spring);
    rig.click(rig.px(1, 1));
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
    rig.view.setFocus();
    QTest::keyClick(&rig.view, Qt::Key_Right);
    QTest::keyClick(&rig.view, Qt::Key_Up);
    QVERIFY(near(rig.body("box1").position, Vec2(2 * rig.g, 2 * rig.g)));
    QTest::keyClick(&rig.view, Qt::Key_Q);
    QVERIFY(std::abs(rig.body("box1").angle - 5.0 * std::numbers::pi / 180.0) < 1e-12);
    QTest::keyClick(&rig.view, Qt::Key_E);
    QTest::keyClick(&rig.view, Qt::Key_E);
    QVERIFY(std::abs(rig.body("box1").angle + 5.0 * std::numbers::pi / 180.0) < 1e-12);
    rig.tools.deleteSelectionAction()->trigger();
    QVERIFY(rig.scene().bodies.empty());
}

RIGIDLAB_TEST_MAIN(TestEditor)
#include "test_editor.moc"
