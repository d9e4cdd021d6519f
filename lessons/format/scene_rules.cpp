// SPDX-License-Identifier: GPL-3.0-or-later
#include "format/scene_rules.h"

#include "format/json_reader.h"
#include "format/limits.h"
#include "format/scene_loader.h"

#include "rigidlab/physics/shape.h"

#include <QRegularExpression>

#include <cmath>

namespace rigidlab::lessons::rules {

using detail::FileMessages;

std::optional<MassProblem> checkMass(const physics::BodyDef& def)
{
    // Sizes and densities are each finite, but their products need not be.
    const physics::MassProperties unit = physics::computeMass(def.shape, 1.0);
    if (!(std::isfinite(unit.area) && unit.area > 0 && std::isfinite(unit.inertia))) {
        return MassProblem{QStringLiteral("shape"),
                           FileMessages::tr("too large or too small: its area works out as %1 m^2")
                               .arg(detail::formatNumber(unit.area))};
    }
    const double mass = def.mass > 0 ? def.mass : def.density * unit.area;
    if (!(std::isfinite(mass) && limits::kMass.contains(mass))) {
        return MassProblem{
            QStringLiteral("density"),
            FileMessages::tr("the mass works out as %1 kg (density times area); it "
                             "must be %2")
                .arg(detail::formatNumber(mass), detail::describeRange(limits::kMass))};
    }
    return std::nullopt;
}

QString idProblem(const QString& id)
{
    if (id.isEmpty()) {
        return FileMessages::tr("must not be empty");
    }
    if (id.size() > kMaxBodyIdLength) {
        return FileMessages::tr("longer than %1 characters").arg(kMaxBodyIdLength);
    }
    for (QChar c : id) {
        if (c.category() == QChar::Other_Control) {
            return FileMessages::tr("must not hold control characters");
        }
    }
    return {};
}

QString duplicateId(const QString& id, int otherIndex)
{
    return FileMessages::tr("duplicate id \"%1\" (bodies[%2] has it already)")
        .arg(id, QString::number(otherIndex));
}

QString polygonVertexCount(qsizetype count)
{
    return FileMessages::tr("a polygon needs 3 to %1 vertices, got %2")
        .arg(kMaxPolygonVertices)
        .arg(count);
}

QString springBothInWorld()
{
    return FileMessages::tr("both ends are fixed in the world (a and b are "
                            "null): a spring needs a body at one end");
}

QString springSameBody()
{
    return FileMessages::tr("the same body as \"a\": a spring joins two bodies");
}

QString pinSameBody()
{
    return FileMessages::tr("the same body as \"a\": a pin joins two bodies");
}

QString colourProblem(const QString& text)
{
    static const QRegularExpression rgb(QStringLiteral("^#[0-9A-Fa-f]{6}$"));
    if (rgb.match(text).hasMatch()) {
        return {};
    }
    return FileMessages::tr(
               "must be a colour \"#rrggbb\" (six hexadecimal digits, as \"#d04030\"), "
               "got \"%1\"")
        .arg(text.left(kMaxBodyIdLength));
}

} // namespace rigidlab::lessons::rules
