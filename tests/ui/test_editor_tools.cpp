// SPDX-License-Identifier: GPL-3.0-or-later
// The scene editor's tools one by one: sizes drawn on the grid are grid sizes, a click is not a
// drawing, every tool draws from the keyboard too and says what a click and a drag do, points
// snap onto other bodies, a lesson locks tools; a new scene's ground and file name.

#include "editor_test_util.h"

#include "edit/scene_edits.h"
#include "format/scene_loader.h"
#include "format/scene_schema.h"

#include "near.h"
#include "test_main.h"

#include <QUndoStack>

#include <algorithm>
#include <numbers>

using namespace rigidlab;
using namespace rigidlab::ui;
using namespace rigidlab::ui::test;
namespace edit = rigidlab::lessons::edit;

class TestEditorTools : public QObject {
    Q_OBJECT
private slots:
    void thinBoxOnTheGridKeepsOneStep();
    void gridDrawnSizesAreExact();
    void aClickDrawsNothing();
    void keyboardDrawsWithEveryTool();
    void snapsToOtherBodiesEdges();
    void movedBodyRestsOnARamp();
    void lessonLocksTools();
    void newSceneGroundHoldsACart();
    void safeFileNames();
    void undoTextsNameBodiesByLabel();
};

// A ramp drawn thinner than the grid: both its long edges snap to one grid line, and it keeps
// one grid step across instead of being refused as flat (found drawing by hand under Xvfb).
void TestEditorTools::thinBoxOnTheGridKeepsOneStep()
{
    Rig rig;
    rig.use(EditTool::Ground);
    rig.drag(rig.px(-3, 3), rig.px(3, 3.2));
    QVERIFY2(rig.index("ground1") >= 0, qPrintable(rig.tools.lastMessage()));
    const physics::Polygon* box = rig.body("ground1").shape.asPolygon();
    QVERIFY(box);
    const auto [lo, hi] =
        std::minmax_element(box->vertices.begin(), box->vertices.end(),
                            [](const Vec2& a, const Vec2& b) { return a.y() < b.y(); });
    RL_VERIFY_NEAR((hi->y() - lo->y()), rig.g, kTolerance, 0);
}

namespace {

/// A scene with a new scene's floor: a long static box, its top at y = 0.
lessons::Scene onTheFloor()
{
    lessons::Scene scene = SceneDocument::newScene(QStringLiteral("Floor"));
    scene.world.gravity = Vec2(0.0, -9.81);
    return scene;
}

/// The extent of a polygon body along x and y [m].
Vec2 extent(const physics::BodyDef& def)
{
    const physics::Polygon& poly = *def.shape.asPolygon();
    Vec2 lo = poly.vertices.front();
    Vec2 hi = lo;
    for (const Vec2& v : poly.vertices) {
        lo = lo.cwiseMin(v);
        hi = hi.cwiseMax(v);
    }
    return hi - lo;
}

QString text(const Vec2& v)
{
    return QStringLiteral("(%1, %2)").arg(v.x(), 0, 'g', 17).arg(v.y(), 0, 'g', 17);
}

/// Whether `got` is `want` but for the last bits of rounding; else says both.
bool exactly(const Vec2& got, const Vec2& want)
{
    if ((got - want).norm() <= 1e-12 * std::max(1.0, want.norm())) {
        return true;
    }
    qWarning("got %s, want %s", qPrintable(text(got)), qPrintable(text(want)));
    return false;
}

} // namespace

// Found in a lesson hour: boxes drawn corner to corner on the 1 m grid from the floor's surface
// came out 1.99 m wide, the floor's edge snapping beating the grid. A person's pointer lands a
// few pixels off the grid point, within reach of the floor's edge; the size is whole steps.
void TestEditorTools::gridDrawnSizesAreExact()
{
    Rig rig(onTheFloor());
    // Framed as a new scene is first shown: the floor's middle, on a grid of a metre or so.
    rig.view.fitRect(SceneDocument::newSceneFrame(), 20);
    rig.g = rig.tools.gridStep();
    const double g = rig.g;
    QVERIFY2(g <= 1.0, qPrintable(QString::number(g)));
    const QPoint off(3, -3); // 3 px right of the grid point and 3 px above the floor
    rig.use(EditTool::Box);
    rig.drag(rig.px(-1, 0) + off, rig.px(1, 1) + QPoint(-2, 2));
    QVERIFY2(rig.index("box1") >= 0, qPrintable(rig.tools.lastMessage()));
    QVERIFY(exactly(extent(rig.body("box1")), Vec2(2 * g, g)));
    QVERIFY(exactly(rig.body("box1").position, Vec2(0.0, 0.5 * g)));

    // A second box beside it, from the floor's surface again: whole steps, on the grid.
    rig.drag(rig.px(3, 0) + off, rig.px(6, 2) + off);
    QVERIFY(exactly(extent(rig.body("box2")), Vec2(3 * g, 2 * g)));

    // A circle from the surface: its centre on the grid point, on the floor.
    rig.use(EditTool::Circle);
    rig.drag(rig.px(-5, 0) + off, rig.px(-4, 0) + QPoint(0, -12));
    QVERIFY(exactly(rig.body("circle1").position, Vec2(-5 * g, 0.0)));

    // A box moved along the floor, set down a few pixels above it: on the floor, on the grid.
    rig.use(EditTool::Select);
    const QPoint grab = rig.px(0, 0.5);
    rig.drag(grab, grab + (rig.px(9, 0) - rig.px(0, 0)) + QPoint(4, -3));
    QVERIFY(exactly(rig.body("box1").position, Vec2(9 * g, 0.5 * g)));
}

// Found in a lesson hour: one click with the box tool still active added a 1 m box. A click
// draws nothing with the drawing tools (not even with a pixel or two of jitter) and the status
// line says what a click and a drag do.
void TestEditorTools::aClickDrawsNothing()
{
    Rig rig(onTheFloor());
    const int steps = rig.document.undoStack()->count();
    for (EditTool tool : {EditTool::Box, EditTool::Circle, EditTool::Ground, EditTool::Spring}) {
        rig.use(tool);
        const QString status = rig.tools.lastMessage();
        QVERIFY2(status.contains(QStringLiteral("a click draws nothing")), qPrintable(status));
        rig.tools.say({});
        rig.click(rig.px(2, 3) + QPoint(5, 4));
        QTest::mousePress(rig.viewport(), Qt::LeftButton, {}, rig.px(-3, 4));
        QTest::mouseMove(rig.viewport(), rig.px(-3, 4) + QPoint(2, 1));
        QTest::mouseRelease(rig.viewport(), Qt::LeftButton, {}, rig.px(-3, 4) + QPoint(2, 1));
        QCOMPARE(rig.scene().bodies.size(), size_t(1)); // the floor alone
        QVERIFY(rig.scene().springs.empty());
        QCOMPARE(rig.document.undoStack()->count(), steps);
        QCOMPARE(rig.tools.lastMessage(), status); // said again, after the click
    }
    // A drag still draws.
    rig.use(EditTool::Box);
    rig.drag(rig.px(2, 3), rig.px(3, 4));
    QCOMPARE(rig.scene().bodies.size(), size_t(2));
}

// Everything the mouse draws, the keyboard draws too: Enter adds the tool's shape at the view's
// centre, or acts on the selected body; every tool's status says what a click and a drag do.
void TestEditorTools::keyboardDrawsWithEveryTool()
{
    Rig rig;
    const double g = rig.g;
    const Vec2 centre = rig.tools.viewCentre();
    const auto enter = [&rig](EditTool tool) {
        rig.use(tool);
        rig.view.setFocus();
        QTest::keyClick(&rig.view, Qt::Key_Return);
    };
    enter(EditTool::Ground);
    QCOMPARE(rig.body("ground1").type, physics::BodyType::Static);
    QVERIFY(near(extent(rig.body("ground1")), Vec2(10 * g, g)));
    enter(EditTool::Circle);
    QVERIFY(near(rig.body("circle1").position, centre));
    QCOMPARE(rig.body("circle1").shape.asCircle()->radius, g);
    enter(EditTool::Box);
    QVERIFY(near(extent(rig.body("box1")), Vec2(2 * g, g)));
    QCOMPARE(rig.tools.selectedBody(), rig.index("box1"));
    enter(EditTool::Spring); // hangs the selected box from the world
    QCOMPARE(rig.scene().springs.size(), size_t(1));
    QCOMPARE(rig.scene().springs[0].a, physics::kWorld);
    QCOMPARE(rig.scene().springs[0].b, rig.index("box1"));
    enter(EditTool::Pin); // pins it to the world at its centre
    QCOMPARE(rig.scene().joints.size(), size_t(1));
    QCOMPARE(rig.scene().joints[0].b, physics::kWorld);
    enter(EditTool::Duplicate);
    QVERIFY(rig.index("box2") >= 0);
    enter(EditTool::Polygon); // no points: a triangle
    QVERIFY(rig.index("polygon1") >= 0);
    QVERIFY(std::abs(physics::computeMass(rig.body("polygon1").shape, 1.0).area - 2 * g * g) <
            1e-9);
    QTest::keyClick(&rig.view, Qt::Key_Delete); // the selected triangle
    QCOMPARE(rig.index("polygon1"), -1);
    // Select and Rotate: Enter selects body after body, then the keys move and turn it.
    rig.use(EditTool::Select);
    rig.tools.selectBody(-1);
    QTest::keyClick(&rig.view, Qt::Key_Return);
    QCOMPARE(rig.tools.selectedBody(), 0);
    QTest::keyClick(&rig.view, Qt::Key_Return);
    QCOMPARE(rig.tools.selectedBody(), 1);
    rig.use(EditTool::Rotate);
    QTest::keyClick(&rig.view, Qt::Key_Return);
    QCOMPARE(rig.tools.selectedBody(), 2);
    QTest::keyClick(&rig.view, Qt::Key_Q);
    RL_VERIFY_NEAR(rig.scene().bodies[2].angle, 5.0 * std::numbers::pi / 180.0, 1e-12, 0);

    for (int i = 0; i < kEditToolCount; ++i) {
        rig.use(static_cast<EditTool>(i));
        const QString status = rig.tools.lastMessage();
        QVERIFY2(status.contains(QStringLiteral("click")), qPrintable(status));
    }
}

// A new scene's ground (found in a lesson hour: 10 m, and a 4 m/s cart drove off it in about
// a second): a cart pushed at 4 m/s from the middle is still on it after 4 s.
void TestEditorTools::newSceneGroundHoldsACart()
{
    lessons::Scene scene = SceneDocument::newScene(QStringLiteral("Carts"));
    QCOMPARE(scene.title, QStringLiteral("Carts"));
    QCOMPARE(scene.bodies.size(), size_t(1));
    QCOMPARE(scene.bodies[0].type, physics::BodyType::Static);
    // Its top at y = 0, and long enough for 4 s at 4 m/s either way from the middle with a
    // 1 m cart's half beyond.
    const physics::BodyDef& ground = scene.bodies[0];
    const Vec2 size = extent(ground);
    QCOMPARE(ground.position.y() + 0.5 * size.y(), 0.0);
    QVERIFY2(std::abs(ground.position.x()) + 4.0 * 4.0 + 0.5 <= 0.5 * size.x(),
             qPrintable(text(size)));
    // What the view shows first: the ground's middle at a drawing zoom, not all of it.
    const QRectF frame = SceneDocument::newSceneFrame();
    QVERIFY(frame.contains(QPointF(0.0, 0.0)) && frame.width() < SceneDocument::kNewGroundLength);
}

// Names proposed for a new scene's file survive school shares and USB sticks: ASCII only.
void TestEditorTools::safeFileNames()
{
    const QList<std::pair<QString, QString>> cases{
        {QStringLiteral("Nová scéna"), QStringLiteral("nova_scena.json")},
        {QStringLiteral("Srážka vozíků"), QStringLiteral("srazka_voziku.json")},
        {QStringLiteral("  Žluťoučký kůň — úpěl!  "), QStringLiteral("zlutoucky_kun_upel.json")},
        {QStringLiteral("Straße in Łódź"), QStringLiteral("strasse_in_lodz.json")},
        {QStringLiteral("My ramp 2"), QStringLiteral("my_ramp_2.json")},
        {QStringLiteral("Наклонная"), QStringLiteral("scene.json")},
        {QString(), QStringLiteral("scene.json")}};
    for (const auto& [title, expected] : cases) {
        const QString name = lessons::schema::safeFileName(title);
        QCOMPARE(name, expected);
        for (const QChar c : name) {
            QVERIFY2(c.unicode() < 128, qPrintable(name));
        }
    }
    QVERIFY(lessons::schema::safeFileName(QString(200, QLatin1Char('a'))).size() <= 65);
}

// A ramp turned by 20° (its sides off the grid): a circle drawn from a few pixels beside its
// surface has its centre exactly on it, a point near a corner takes the corner, and the pointer
// shows where it snaps before the press.
void TestEditorTools::snapsToOtherBodiesEdges()
{
    Rig rig;
    rig.use(EditTool::Ground);
    rig.drag(rig.px(-4, -1), rig.px(4, 0));
    rig.view.setFocus();
    for (int i = 0; i < 4; ++i) {
        QTest::keyClick(&rig.view, Qt::Key_E);
    }
    const Side top = topSide(rig.body("ground1"));
    RL_VERIFY_NEAR(top.normal.y(), std::cos(20.0 * std::numbers::pi / 180.0), 1e-12, 0);
    const double pixel = 1.0 / rig.view.zoom(); // [m]
    const auto toView = [&rig](const Vec2& p) {
        return rig.view.mapFromScene(QPointF(p.x(), p.y()));
    };

    // 3 px outside the surface, a third of the way along: off the grid and off the side.
    const Vec2 beside = top.a + 0.37 * top.length * top.along + 3.0 * pixel * top.normal;
    rig.use(EditTool::Circle);
    QTest::mouseMove(rig.viewport(), toView(beside));
    QVERIFY(rig.tools.bodySnap().has_value()); // the marker shows where it will go
    QCOMPARE(rig.tools.bodySnap()->kind, Snap::Kind::Edge);
    QCOMPARE(rig.tools.bodySnap()->body, rig.index("ground1"));
    rig.drag(toView(beside), toView(beside + 2.0 * rig.g * top.normal));
    QVERIFY2(rig.index("circle1") >= 0, qPrintable(rig.tools.lastMessage()));
    const Vec2 centre = rig.body("circle1").position;
    QVERIFY2(std::abs(top.distance(centre)) < kTolerance,
             qPrintable(QString::number(top.distance(centre))));
    const double along = (centre - top.a).dot(top.along);
    QVERIFY(along > 0.3 * top.length && along < 0.45 * top.length);
    // Its radius: to the point released (on the grid), about two grid steps out.
    const double radius = rig.body("circle1").shape.asCircle()->radius;
    QVERIFY(radius > rig.g && radius < 3.0 * rig.g);

    // Near both a corner and the side: the corner wins.
    const Vec2 corner = top.a + 3.0 * pixel * top.along + 2.0 * pixel * top.normal;
    rig.use(EditTool::Box);
    rig.drag(toView(corner), toView(top.a + Vec2(-2.0 * rig.g, 2.0 * rig.g)));
    QVERIFY2(rig.index("box1") >= 0, qPrintable(rig.tools.lastMessage()));
    const auto* box = rig.body("box1").shape.asPolygon();
    const physics::Transform xf(rig.body("box1").position, rig.body("box1").angle);
    QVERIFY(std::any_of(box->vertices.begin(), box->vertices.end(),
                        [&](const Vec2& v) { return near(xf.apply(v), top.a); }));

    // With snapping off, nothing snaps and no marker shows.
    rig.tools.snapAction()->setChecked(false);
    rig.use(EditTool::Circle);
    QTest::mouseMove(rig.viewport(), toView(beside));
    QVERIFY(!rig.tools.bodySnap().has_value());
}

// A box dragged by its middle until its corner is a few pixels above a 20° ramp is set down
// with that corner on the ramp's surface; a ball dragged near it rests on it, touching.
void TestEditorTools::movedBodyRestsOnARamp()
{
    Rig rig;
    rig.use(EditTool::Ground);
    rig.drag(rig.px(-6, -1), rig.px(6, 0));
    rig.view.setFocus();
    for (int i = 0; i < 4; ++i) {
        QTest::keyClick(&rig.view, Qt::Key_E);
    }
    const Side top = topSide(rig.body("ground1"));
    const double pixel = 1.0 / rig.view.zoom();
    const auto toView = [&rig](const Vec2& p) {
        return rig.view.mapFromScene(QPointF(p.x(), p.y()));
    };
    const auto fromView = [&rig](QPoint p) {
        const QPointF q = rig.view.mapToScene(p);
        return Vec2(q.x(), q.y());
    };

    rig.use(EditTool::Box);
    rig.drag(rig.px(2, 8), rig.px(4, 10)); // 2 by 2 grid steps, centred at (3, 9)
    rig.use(EditTool::Circle);
    rig.drag(rig.px(-4, 9), rig.px(-3, 9)); // radius one grid step
    rig.use(EditTool::Select);

    // The box's lowest corner (its lower left one, the ramp going down to the right) 4 px
    // above the middle of the surface.
    const Vec2 grab = fromView(rig.px(3, 9));
    const Vec2 grabOffset = rig.body("box1").position - grab;
    const Vec2 lowerLeft(-rig.g, -rig.g);
    const Vec2 onSurface = top.a + 0.5 * top.length * top.along;
    const Vec2 target = onSurface + 4.0 * pixel * top.normal - lowerLeft - grabOffset;
    rig.drag(toView(grab), toView(target));
    const auto& box = rig.body("box1");
    QCOMPARE(box.angle, 0.0);
    const Vec2 corner = box.position + lowerLeft;
    QVERIFY2(std::abs(top.distance(corner)) < kTolerance,
             qPrintable(QString::number(top.distance(corner))));
    QVERIFY(((corner - onSurface).norm()) < 3.0 * pixel); // where it was set down
    QVERIFY2(!rig.tools.lastMessage().contains(QStringLiteral("overlaps")),
             qPrintable(rig.tools.lastMessage()));
    QVERIFY(!rig.tools.bodySnap().has_value()); // the marker goes with the release

    // The ball, its surface 5 px above the ramp's, lower down the slope: it rests on it.
    const Vec2 ballGrab = fromView(rig.px(-4, 9));
    const Vec2 ballOffset = rig.body("circle1").position - ballGrab;
    const Vec2 below = top.a + 0.8 * top.length * top.along;
    const Vec2 ballTarget = below + (rig.g + 5.0 * pixel) * top.normal - ballOffset;
    rig.drag(toView(ballGrab), toView(ballTarget));
    const Vec2 ball = rig.body("circle1").position;
    QVERIFY2(std::abs(top.distance(ball) - rig.g) < kTolerance,
             qPrintable(QString::number(top.distance(ball) - rig.g)));
    QVERIFY2(edit::overlapMessage(rig.scene()).isEmpty(),
             qPrintable(edit::overlapMessage(rig.scene())));
}

void TestEditorTools::lessonLocksTools()
{
    Rig rig;
    rig.tools.setAllowedTools(QStringList{QStringLiteral("select"), QStringLiteral("circle")});
    QVERIFY(rig.tools.locked(EditTool::Box));
    QVERIFY(!rig.tools.locked(EditTool::Circle));
    QVERIFY(!rig.tools.toolAction(EditTool::Box)->isEnabled());
    QVERIFY(rig.tools.toolAction(EditTool::Circle)->isEnabled());
    QVERIFY2(rig.tools.toolAction(EditTool::Box)->toolTip().contains(QStringLiteral("locks")),
             qPrintable(rig.tools.toolAction(EditTool::Box)->toolTip()));
    // The locked tool's key is refused out loud; the tool in use stays.
    rig.view.setFocus();
    QTest::keyClick(&rig.view, Qt::Key_X);
    QCOMPARE(rig.tools.tool(), EditTool::Select);
    QVERIFY2(rig.tools.lastMessage().contains(QStringLiteral("locks the Box tool")),
             qPrintable(rig.tools.lastMessage()));
    rig.tools.setTool(EditTool::Spring);
    QCOMPARE(rig.tools.tool(), EditTool::Select);
    rig.use(EditTool::Circle);
    QCOMPARE(rig.tools.tool(), EditTool::Circle);
    rig.tools.setAllowedTools(std::nullopt);
    QVERIFY(rig.tools.toolAction(EditTool::Box)->isEnabled());
}

// The History names a body as the rest of the window does: by its label ("light ball"), not
// its id ("b1"); a body without a label by its id.
void TestEditorTools::undoTextsNameBodiesByLabel()
{
    const lessons::SceneLoadResult loaded = lessons::loadSceneJson(
        R"({"rigidlab": 1, "title": "labels", "bodies": [
            {"id": "b1", "label": "light ball", "shape": {"type": "circle", "radius": 0.5}},
            {"id": "b2", "shape": {"type": "circle", "radius": 0.5}, "position": [3, 0]}]})",
        QStringLiteral("labels.json"));
    QVERIFY2(loaded.ok, qPrintable(loaded.error));
    Rig rig(loaded.scene);
    const QUndoStack& undo = *rig.document.undoStack();
    rig.tools.selectBody(0);
    rig.tools.nudgeSelected(Vec2(rig.g, 0.0));
    QCOMPARE(undo.text(undo.index() - 1), QStringLiteral("Move light ball"));
    rig.tools.rotateSelected(0.1);
    QCOMPARE(undo.text(undo.index() - 1), QStringLiteral("Rotate light ball"));
    rig.tools.deleteSelected();
    QCOMPARE(undo.text(undo.index() - 1), QStringLiteral("Delete light ball"));
    rig.tools.selectBody(0); // b2, now the first
    rig.tools.nudgeSelected(Vec2(rig.g, 0.0));
    QCOMPARE(undo.text(undo.index() - 1), QStringLiteral("Move b2"));
}

RIGIDLAB_TEST_MAIN(TestEditorTools)
#include "test_editor_tools.moc"
