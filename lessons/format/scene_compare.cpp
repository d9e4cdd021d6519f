// SPDX-License-Identifier: GPL-3.0-or-later
#include "format/scene_compare.h"

#include "rigidlab/physics/contact.h"
#include "rigidlab/physics/integrator.h"
#include "rigidlab/physics/shape.h"

#include <QStringList>

#include <string_view>

namespace rigidlab::lessons {

namespace {

using physics::Vec2;

QString text(double x)
{
    return QString::number(x, 'g', 17);
}

QString text(const Vec2& v)
{
    return QStringLiteral("[%1, %2]").arg(text(v.x()), text(v.y()));
}

QString text(const QString& s)
{
    return u'"' + s + u'"';
}

QString text(std::string_view s)
{
    return text(QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size())));
}

QString text(const std::string& s)
{
    return text(std::string_view(s));
}

QString text(bool b)
{
    return b ? QStringLiteral("true") : QStringLiteral("false");
}

QString text(int i)
{
    return QString::number(i);
}

QString text(const LocalTextMap& m)
{
    QStringList parts;
    for (auto it = m.cbegin(); it != m.cend(); ++it)
        parts << it.key() + QStringLiteral(": ") + text(it.value());
    return u'{' + parts.join(QStringLiteral(", ")) + u'}';
}

QString text(const std::optional<bool>& b)
{
    return b ? text(*b) : QStringLiteral("unset");
}

QString text(const std::vector<Vec2>& list)
{
    QStringList parts;
    for (const Vec2& v : list)
        parts << text(v);
    return u'[' + parts.join(QStringLiteral(", ")) + u']';
}

/// Collects the first difference.
class Differ {
public:
    template <class T> void field(const QString& place, const T& a, const T& b)
    {
        if (m_first.isEmpty() && !(a == b))
            m_first = place + QStringLiteral(": ") + text(a) + QStringLiteral(" vs ") + text(b);
    }
    void note(const QString& place, const QString& what)
    {
        if (m_first.isEmpty())
            m_first = place + QStringLiteral(": ") + what;
    }
    const QString& first() const { return m_first; }

private:
    QString m_first;
};

QString at(const char* list, std::size_t i, const char* key)
{
    return QStringLiteral("%1[%2].%3").arg(QLatin1String(list)).arg(i).arg(QLatin1String(key));
}

void compareWorld(Differ& d, const physics::WorldDef& a, const physics::WorldDef& b)
{
    d.field(QStringLiteral("world.gravity"), a.gravity, b.gravity);
    d.field(QStringLiteral("world.dt"), a.dt, b.dt);
    d.field(QStringLiteral("world.integrator"), physics::integratorName(a.integrator),
            physics::integratorName(b.integrator));
    d.field(QStringLiteral("world.solver"), physics::solverName(a.solver),
            physics::solverName(b.solver));
    d.field(QStringLiteral("world.iterations"), a.iterations, b.iterations);
    d.field(QStringLiteral("world.restitution"), a.restitution, b.restitution);
    d.field(QStringLiteral("world.friction"), a.friction, b.friction);
    d.field(QStringLiteral("world.gravitation"), a.gravitation, b.gravitation);
    d.field(QStringLiteral("world.drag"), a.drag, b.drag);
    d.field(QStringLiteral("world.tolerance.absolute"), a.tolerances.absolute,
            b.tolerances.absolute);
    d.field(QStringLiteral("world.tolerance.relative"), a.tolerances.relative,
            b.tolerances.relative);
    d.field(QStringLiteral("world.continuous"), a.continuous, b.continuous);
    d.field(QStringLiteral("world.sleep"), a.sleep, b.sleep);
}

void compareShape(Differ& d, std::size_t i, const physics::Shape& a, const physics::Shape& b)
{
    const physics::Circle* ca = a.asCircle();
    const physics::Circle* cb = b.asCircle();
    if (!ca != !cb) {
        d.note(at("bodies", i, "shape"), QStringLiteral("a circle vs a polygon"));
        return;
    }
    if (ca) {
        d.field(at("bodies", i, "shape.center"), ca->center, cb->center);
        d.field(at("bodies", i, "shape.radius"), ca->radius, cb->radius);
        return;
    }
    d.field(at("bodies", i, "shape.vertices"), a.asPolygon()->vertices, b.asPolygon()->vertices);
    d.field(at("bodies", i, "shape.normals"), a.asPolygon()->normals, b.asPolygon()->normals);
}

void compareBody(Differ& d, std::size_t i, const physics::BodyDef& a, const physics::BodyDef& b)
{
    d.field(at("bodies", i, "id"), a.name, b.name);
    d.field(at("bodies", i, "type"), static_cast<int>(a.type), static_cast<int>(b.type));
    compareShape(d, i, a.shape, b.shape);
    d.field(at("bodies", i, "position"), a.position, b.position);
    d.field(at("bodies", i, "angle"), a.angle, b.angle);
    d.field(at("bodies", i, "velocity"), a.velocity, b.velocity);
    d.field(at("bodies", i, "angularVelocity"), a.angularVelocity, b.angularVelocity);
    d.field(at("bodies", i, "density"), a.density, b.density);
    d.field(at("bodies", i, "mass"), a.mass, b.mass);
    d.field(at("bodies", i, "restitution"), a.restitution, b.restitution);
    d.field(at("bodies", i, "friction"), a.friction, b.friction);
    d.field(at("bodies", i, "collide"), a.collide, b.collide);
}

} // namespace

QString sceneDifference(const Scene& a, const Scene& b)
{
    Differ d;
    d.field(QStringLiteral("title"), a.title, b.title);
    d.field(QStringLiteral("description"), a.description, b.description);
    d.field(QStringLiteral("title (every language)"), a.titles, b.titles);
    d.field(QStringLiteral("description (every language)"), a.descriptions, b.descriptions);
    compareWorld(d, a.world, b.world);
    d.field(QStringLiteral("bodies (count)"), static_cast<int>(a.bodies.size()),
            static_cast<int>(b.bodies.size()));
    for (std::size_t i = 0; i < a.bodies.size() && i < b.bodies.size(); ++i) {
        compareBody(d, i, a.bodies[i], b.bodies[i]);
        const auto original = [](const Scene& s, std::size_t k) {
            return k < s.originalVertices.size() ? s.originalVertices[k] : std::vector<Vec2>{};
        };
        d.field(at("bodies", i, "shape (as the file gave it)"), original(a, i), original(b, i));
        d.field(at("bodies", i, "colour"), a.colourOf(i), b.colourOf(i));
    }
    d.field(QStringLiteral("springs (count)"), static_cast<int>(a.springs.size()),
            static_cast<int>(b.springs.size()));
    for (std::size_t i = 0; i < a.springs.size() && i < b.springs.size(); ++i) {
        const physics::SpringDef& x = a.springs[i];
        const physics::SpringDef& y = b.springs[i];
        d.field(at("springs", i, "a"), static_cast<int>(x.a), static_cast<int>(y.a));
        d.field(at("springs", i, "anchorA"), x.anchorA, y.anchorA);
        d.field(at("springs", i, "b"), static_cast<int>(x.b), static_cast<int>(y.b));
        d.field(at("springs", i, "anchorB"), x.anchorB, y.anchorB);
        d.field(at("springs", i, "stiffness"), x.stiffness, y.stiffness);
        d.field(at("springs", i, "damping"), x.damping, y.damping);
        d.field(at("springs", i, "restLength"), x.restLength, y.restLength);
    }
    d.field(QStringLiteral("joints (count)"), static_cast<int>(a.joints.size()),
            static_cast<int>(b.joints.size()));
    for (std::size_t i = 0; i < a.joints.size() && i < b.joints.size(); ++i) {
        const physics::PinJointDef& x = a.joints[i];
        const physics::PinJointDef& y = b.joints[i];
        d.field(at("joints", i, "a"), static_cast<int>(x.a), static_cast<int>(y.a));
        d.field(at("joints", i, "anchorA"), x.anchorA, y.anchorA);
        d.field(at("joints", i, "b"), static_cast<int>(x.b), static_cast<int>(y.b));
        d.field(at("joints", i, "anchorB"), x.anchorB, y.anchorB);
    }
    return d.first();
}

} // namespace rigidlab::lessons
