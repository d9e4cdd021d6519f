// SPDX-License-Identifier: GPL-3.0-or-later
#include "view/scene_words.h"

#include "common/shortcuts.h"
#include "common/spoken_numbers.h"
#include "simulation/run_view.h"

#include "format/scene_schema.h"

#include "rigidlab/physics/touching.h"

#include <QStringList>

#include <algorithm>
#include <cmath>

namespace rigidlab::ui::scene_words {

namespace {

QString metres(double v)
{
    return spokenQuantity(v, QStringLiteral("m"), 3, 1.0);
}

QString pair(double x, double y, const QString& unit)
{
    return spokenPair(x, y, unit, 3, 1.0);
}

/// Whether the polygon is a rectangle: four corners, each edge at a right angle to the next.
bool isBox(const physics::Polygon& p)
{
    if (p.normals.size() != 4)
        return false;
    for (std::size_t i = 0; i < 4; ++i)
        if (std::abs(p.normals[i].dot(p.normals[(i + 1) % 4])) > 1e-9)
            return false;
    return true;
}

/// The names of the bodies `touches`, each name once.
QStringList touchingNames(const std::vector<physics::BodyId>& touches, const RunView& run)
{
    QStringList names;
    for (const physics::BodyId other : touches) {
        const QString name = run.scene().bodyLabel(other);
        if (!names.contains(name))
            names << name;
    }
    return names;
}

} // namespace

QString sceneName(const RunView& run)
{
    const QString title = run.scene().title;
    return title.isEmpty() ? SceneWords::tr("Scene") : SceneWords::tr("Scene: %1").arg(title);
}

QString summary(const RunView& run, int selectedBody)
{
    const physics::World& world = run.world();
    int moving = 0;
    for (const physics::Body& b : world.bodies())
        moving += b.moves() ? 1 : 0;
    const int fixed = static_cast<int>(world.bodies().size()) - moving;
    QStringList parts;
    parts << SceneWords::tr("On stage: %n moving body(ies)", nullptr, moving) +
                 SceneWords::tr(", %n fixed body(ies).", nullptr, fixed);
    const QString t = spokenQuantity(run.time(), QStringLiteral("s"), 3, 1.0);
    if (world.divergence())
        parts << SceneWords::tr("The simulation stopped at %1: it diverged.").arg(t);
    else if (run.isRunning())
        parts << SceneWords::tr("Running, time %1.").arg(t);
    else
        parts << SceneWords::tr("Paused at time %1.").arg(t);
    // Only pairs that touch: not a contact the step made ahead (physics/touching.h).
    const auto touching =
        std::count_if(world.contacts().begin(), world.contacts().end(),
                      [](const physics::Contact& c) { return physics::touches(c); });
    if (touching > 0)
        parts << SceneWords::tr("%n pair(s) of bodies touch.", nullptr, static_cast<int>(touching));
    if (selectedBody >= 0 && selectedBody < static_cast<int>(world.bodies().size()))
        parts << SceneWords::tr("Selected: %1.").arg(run.scene().bodyLabel(selectedBody));
    parts << SceneWords::tr(
                 "%1 runs or pauses; %2 and %3 select a body; arrows move it, Shift+arrows change "
                 "its velocity, Enter shows its numbers.")
                 .arg(controlKeysText("play"), controlKeysText("selectNextBody"),
                      controlKeysText("selectPreviousBody"));
    return parts.join(QLatin1Char(' '));
}

QString bodyName(const RunView& run, physics::BodyId id)
{
    const physics::Body& b = run.world().body(id);
    // The kind is an adjective of "body" (the schema's word for the editor's list), which a
    // language with genders says with its noun: Czech "podlaha (statické těleso)", never
    // "podlaha (statické)" after a feminine name.
    return SceneWords::tr("%1 (%2)", "a body's name, then its kind: static, dynamic or kinematic")
        .arg(run.scene().bodyLabel(id), lessons::schema::bodyTypeLabel(b.type));
}

QString shapeText(const physics::Shape& shape)
{
    if (const physics::Circle* c = shape.asCircle())
        return SceneWords::tr("circle, radius %1").arg(metres(c->radius));
    const physics::Polygon* p = shape.asPolygon();
    if (!p)
        return {};
    if (isBox(*p)) {
        const auto& v = p->vertices;
        return SceneWords::tr("box %1 × %2")
            .arg(metres((v[1] - v[0]).norm()), metres((v[2] - v[1]).norm()));
    }
    return SceneWords::tr("polygon, %n corner(s)", nullptr, static_cast<int>(p->vertices.size()));
}

std::vector<std::vector<physics::BodyId>> touchingBodies(const RunView& run)
{
    const physics::World& world = run.world();
    std::vector<std::vector<physics::BodyId>> touches(world.bodies().size());
    for (const physics::Contact& c : world.contacts()) {
        if (!physics::touches(c))
            continue;
        touches[static_cast<std::size_t>(c.a)].push_back(c.b);
        touches[static_cast<std::size_t>(c.b)].push_back(c.a);
    }
    return touches;
}

QString bodyValue(const RunView& run, physics::BodyId id)
{
    std::vector<physics::BodyId> touches;
    for (const physics::Contact& c : run.world().contacts())
        if ((c.a == id || c.b == id) && physics::touches(c))
            touches.push_back(c.a == id ? c.b : c.a);
    return bodyValue(run, id, touches);
}

QString bodyValue(const RunView& run, physics::BodyId id,
                  const std::vector<physics::BodyId>& touches)
{
    const physics::World& world = run.world();
    const physics::Body& b = world.body(id);
    QStringList parts;
    parts << shapeText(b.shape);
    parts << (b.isDynamic()
                  ? SceneWords::tr("mass %1").arg(spokenQuantity(b.mass, QStringLiteral("kg"), 3))
                  : SceneWords::tr("mass infinite"));
    const physics::Vec2 o = b.origin();
    parts << SceneWords::tr("position %1").arg(pair(o.x(), o.y(), QStringLiteral("m")));
    const physics::Vec2 v = world.originVelocity(id);
    parts << SceneWords::tr("velocity %1, speed %2")
                 .arg(pair(v.x(), v.y(), QStringLiteral("m/s")),
                      spokenQuantity(v.norm(), QStringLiteral("m/s"), 3, 1.0));
    if (const QStringList t = touchingNames(touches, run); !t.isEmpty())
        parts << SceneWords::tr("touches %1").arg(t.join(QStringLiteral(", ")));
    return parts.join(QStringLiteral("; "));
}

} // namespace rigidlab::ui::scene_words
