// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What the scene editor's tests share: an editor on a view of its own (Rig), gestures on it,
// and a field-by-field comparison of scenes that names the first difference.

#include "editor/edit_tools.h"
#include "editor/scene_document.h"
#include "editor/scene_properties.h"
#include "simulation/simulation_controller.h"
#include "view/world_view.h"

#include "format/scene.h"

#include <QAction>
#include <QLineEdit>
#include <QTest>

#include <cmath>

namespace rigidlab::ui::test {

using physics::Vec2;

inline constexpr double kTolerance = 1e-9;

/// Where two scenes differ, the first field found; empty when they are the same.
inline QString difference(const lessons::Scene& a, const lessons::Scene& b)
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
    SceneProperties properties{tools, document};
    lessons::Scene opened;
    double g = 0; ///< the grid step [m]; every point below is on the grid

    Rig() : Rig(empty()) {}
    explicit Rig(const lessons::Scene& scene) : opened(scene)
    {
        document.reset(opened, {});
        simulation.loadScene(opened, {});
        view.resize(900, 700);
        view.show();
        tools.setEditing(true);
        g = tools.gridStep();
    }

    static lessons::Scene empty()
    {
        lessons::Scene scene;
        scene.title = QStringLiteral("Empty");
        scene.world.gravity = Vec2(0.0, -9.81);
        return scene;
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

/// Types `text` into a field as a person does, replacing what it shows.
inline void type(QLineEdit* field, const QString& text)
{
    field->clear();
    QTest::keyClicks(field, text);
}

inline bool near(const Vec2& a, const Vec2& b)
{
    return (a - b).norm() <= kTolerance;
}

/// A side of a polygon body in the world: its first vertex, its outward normal, its length.
struct Side {
    Vec2 a = Vec2::Zero();
    Vec2 normal = Vec2::Zero();
    Vec2 along = Vec2::Zero(); ///< unit, from a to the next vertex
    double length = 0.0;       ///< [m]
    /// Signed distance of p from the side's line [m], positive outside.
    double distance(const Vec2& p) const { return normal.dot(p - a); }
};

/// The side of `def` whose outward normal points most nearly up (a ramp's surface).
inline Side topSide(const physics::BodyDef& def)
{
    const physics::Polygon& poly = *def.shape.asPolygon();
    const physics::Transform xf(def.position, def.angle);
    Side best;
    best.normal = Vec2(0.0, -2.0);
    for (size_t i = 0; i < poly.vertices.size(); ++i) {
        const Vec2 n = xf.q.apply(poly.normals[i]);
        if (n.y() > best.normal.y()) {
            const Vec2 a = xf.apply(poly.vertices[i]);
            const Vec2 b = xf.apply(poly.vertices[(i + 1) % poly.vertices.size()]);
            best = Side{a, n, (b - a).normalized(), (b - a).norm()};
        }
    }
    return best;
}

} // namespace rigidlab::ui::test
