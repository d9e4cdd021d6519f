// SPDX-License-Identifier: GPL-3.0-or-later
#include "plots/body_series.h"

#include <cmath>
#include <limits>
#include <numbers>

namespace rigidlab::ui {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// What a quantity is worth in a teaching scene, in its unit: a change below a billionth of it
/// is rounding noise and the plot draws it flat (plot_range.h).
double quantityScale(BodyQuantity q)
{
    switch (q) {
    case BodyQuantity::AngleDegrees:
        return 180.0;
    case BodyQuantity::AngleRadians:
        return std::numbers::pi;
    default:
        return 1.0;
    }
}

physics::Vec2 velocityOf(const physics::World& world, physics::BodyId id, const FrameMotion& m)
{
    return world.body(id).velocity - m.velocity;
}

} // namespace

QString quantityName(BodyQuantity q)
{
    switch (q) {
    case BodyQuantity::X:
        return PlotWidget::tr("position x");
    case BodyQuantity::Y:
        return PlotWidget::tr("position y");
    case BodyQuantity::Vx:
        return PlotWidget::tr("velocity vx");
    case BodyQuantity::Vy:
        return PlotWidget::tr("velocity vy");
    case BodyQuantity::Speed:
        return PlotWidget::tr("speed |v|");
    case BodyQuantity::Acceleration:
        return PlotWidget::tr("acceleration |a|");
    case BodyQuantity::AngleDegrees:
        return PlotWidget::tr("angle θ in degrees");
    case BodyQuantity::AngleRadians:
        return PlotWidget::tr("angle θ in radians");
    case BodyQuantity::AngularVelocity:
        return PlotWidget::tr("angular velocity ω");
    case BodyQuantity::KineticEnergy:
        return PlotWidget::tr("kinetic energy E_k");
    case BodyQuantity::Px:
        return PlotWidget::tr("momentum px");
    case BodyQuantity::Py:
        return PlotWidget::tr("momentum py");
    case BodyQuantity::AngularMomentum:
        return PlotWidget::tr("angular momentum L");
    }
    return {};
}

QString quantitySymbol(BodyQuantity q)
{
    static const char* const kSymbols[kBodyQuantityCount] = {
        "x", "y", "v_x", "v_y", "|v|", "|a|", "theta", "theta", "omega", "E_k", "p_x", "p_y", "L"};
    return QString::fromLatin1(kSymbols[static_cast<int>(q)]);
}

QString quantityAxisName(BodyQuantity q)
{
    // Short, as the standard plots' axes are ("energy E", "p"): a narrow plot keeps them whole.
    static const char* const kAxis[kBodyQuantityCount] = {"x", "y", "vx",  "vy", "|v|", "|a|", "θ",
                                                          "θ", "ω", "E_k", "px", "py",  "L"};
    return QString::fromUtf8(kAxis[static_cast<int>(q)]);
}

QString quantityUnit(BodyQuantity q)
{
    static const char* const kUnits[kBodyQuantityCount] = {
        "m",   "m",     "m/s", "m/s",    "m/s",    "m/s²",   "°",
        "rad", "rad/s", "J",   "kg m/s", "kg m/s", "kg m²/s"};
    return QString::fromUtf8(kUnits[static_cast<int>(q)]);
}

FrameMotion frameMotion(const physics::World& world, const ReferenceFrame& frame)
{
    // The centre of mass R = Σ m r / Σ m and its velocity V = Σ m v / Σ m.
    double mass = 0.0;
    physics::Vec2 moment = physics::Vec2::Zero(), momentum = physics::Vec2::Zero();
    const auto count = static_cast<physics::BodyId>(world.bodies().size());
    for (physics::BodyId id : frame.bodies) {
        if (id < 0 || id >= count || !world.body(id).isDynamic())
            continue;
        const physics::Body& b = world.body(id);
        mass += b.mass;
        moment += b.mass * b.position;
        momentum += b.mass * b.velocity;
    }
    if (mass <= 0.0)
        return {};
    return {moment / mass, momentum / mass};
}

double bodyValue(const physics::World& world, physics::BodyId id, BodyQuantity q,
                 const FrameMotion& motion)
{
    if (id < 0 || id >= static_cast<physics::BodyId>(world.bodies().size()))
        return kNaN;
    const physics::Body& b = world.body(id);
    const physics::Vec2 r = b.position - motion.origin;
    const physics::Vec2 v = velocityOf(world, id, motion);
    switch (q) {
    case BodyQuantity::X:
        return r.x();
    case BodyQuantity::Y:
        return r.y();
    case BodyQuantity::Vx:
        return v.x();
    case BodyQuantity::Vy:
        return v.y();
    case BodyQuantity::Speed:
        return v.norm();
    case BodyQuantity::Acceleration:
        return kNaN;
    case BodyQuantity::AngleDegrees:
        return b.angle * 180.0 / std::numbers::pi;
    case BodyQuantity::AngleRadians:
        return b.angle;
    case BodyQuantity::AngularVelocity:
        return b.angularVelocity;
    case BodyQuantity::KineticEnergy:
        return 0.5 * b.mass * v.squaredNorm() +
               0.5 * b.inertia * b.angularVelocity * b.angularVelocity;
    case BodyQuantity::Px:
        return b.mass * v.x();
    case BodyQuantity::Py:
        return b.mass * v.y();
    case BodyQuantity::AngularMomentum:
        // Spin about the centre of mass plus the orbit of the centre of mass: I ω + m r × v.
        return b.inertia * b.angularVelocity + b.mass * physics::cross(r, v);
    }
    return kNaN;
}

BodyGraph::BodyGraph(PlotWidget& plot, BodyQuantity quantity, ReferenceFrame frame)
    : m_plot(plot), m_quantity(quantity), m_frame(std::move(frame))
{
    m_plot.setYAxisLabel(quantityAxisName(quantity), quantityUnit(quantity));
    m_plot.model().setValueScale(YAxis::Left, quantityScale(quantity));
}

int BodyGraph::addBody(physics::BodyId id, const QString& label)
{
    return addSum({id}, label);
}

int BodyGraph::addSum(std::vector<physics::BodyId> ids, const QString& label)
{
    // Told apart by line style as well as by colour.
    const int index = curveCount();
    const int series = m_plot.addSeries(label, plotColor(index));
    m_plot.setSeriesPen(series, plotPenStyle(index));
    m_plot.model().setSeriesColumn(
        series, QStringLiteral("%1 %2 [%3]")
                    .arg(quantitySymbol(m_quantity), label, quantityUnit(m_quantity)));
    Curve curve;
    curve.series = series;
    curve.bodies = std::move(ids);
    m_curves.push_back(std::move(curve));
    return series;
}

void BodyGraph::record(const physics::World& world, double t)
{
    const FrameMotion motion = frameMotion(world, m_frame);
    for (Curve& curve : m_curves)
        m_plot.model().appendPoint(curve.series, t, valueOf(curve, world, motion, t));
}

double BodyGraph::valueOf(Curve& curve, const physics::World& world, const FrameMotion& motion,
                          double t) const
{
    if (m_quantity != BodyQuantity::Acceleration) {
        double sum = 0.0;
        for (physics::BodyId id : curve.bodies)
            sum += bodyValue(world, id, m_quantity, motion);
        return sum;
    }
    // |a| = |Δv| / Δt between this point and the last one of the curve (a backward
    // difference); the first point, or one after going back in time, has none.
    std::vector<physics::Vec2> v;
    const auto count = static_cast<physics::BodyId>(world.bodies().size());
    for (physics::BodyId id : curve.bodies)
        v.push_back(id >= 0 && id < count ? velocityOf(world, id, motion)
                                          : physics::Vec2(kNaN, kNaN));
    double value = kNaN;
    if (curve.lastT && t > *curve.lastT && curve.lastV.size() == v.size()) {
        value = 0.0;
        for (std::size_t i = 0; i < v.size(); ++i)
            value += (v[i] - curve.lastV[i]).norm() / (t - *curve.lastT);
    }
    curve.lastT = t;
    curve.lastV = std::move(v);
    return value;
}

} // namespace rigidlab::ui
