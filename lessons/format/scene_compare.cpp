// SPDX-License-Identifier: GPL-3.0-or-later
#include "format/scene_compare.h"
#include "format/scene_schema.h"

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

/// Every field of `object` the schema lists, the shape aside (compareShape), and the texts of
/// every language.
void compareFields(Differ& d, schema::Object object, const Scene& a, const Scene& b, std::size_t i)
{
    const QString place = schema::placeOf(object, i);
    for (const schema::Field& f : schema::fields(object)) {
        if (f.kind == schema::Kind::Shape || f.kind == schema::Kind::Size)
            continue;
        const QString key = QString::fromLatin1(f.key.data(), qsizetype(f.key.size()));
        const QString at = place.isEmpty() ? key : place + u'.' + key;
        const schema::Value x = f.get(a, i);
        const schema::Value y = f.get(b, i);
        if (!(x == y))
            d.note(at, schema::text(x) + QStringLiteral(" vs ") + schema::text(y));
        if (f.texts)
            d.field(at + QStringLiteral(" (every language)"), f.texts(a, i), f.texts(b, i));
    }
}

void compareShape(Differ& d, std::size_t i, const Scene& sa, const Scene& sb)
{
    const physics::Shape& a = sa.bodies[i].shape;
    const physics::Shape& b = sb.bodies[i].shape;
    const auto original = [](const Scene& s, std::size_t k) {
        return k < s.originalVertices.size() ? s.originalVertices[k] : std::vector<Vec2>{};
    };
    d.field(at("bodies", i, "shape (as the file gave it)"), original(sa, i), original(sb, i));
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

} // namespace

QString sceneDifference(const Scene& a, const Scene& b)
{
    using schema::Object;
    Differ d;
    compareFields(d, Object::Scene, a, b, 0);
    // dopri5's relative tolerance: the file has one tolerance for both, the row the absolute.
    d.field(QStringLiteral("world.tolerance.relative"), a.world.tolerances.relative,
            b.world.tolerances.relative);
    compareFields(d, Object::World, a, b, 0);
    for (const Object object : {Object::Body, Object::Spring, Object::Joint}) {
        const std::size_t n = schema::count(a, object);
        d.field(schema::placeOf(object, 0).section(u'[', 0, 0) + QStringLiteral(" (count)"),
                static_cast<int>(n), static_cast<int>(schema::count(b, object)));
        for (std::size_t i = 0; i < n && i < schema::count(b, object); ++i) {
            compareFields(d, object, a, b, i);
            if (object == Object::Body)
                compareShape(d, i, a, b);
        }
    }
    return d.first();
}

} // namespace rigidlab::lessons
