// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Graphs of chosen bodies: one quantity (x, y, vx, vy, |v|, a, θ, ω, E_k, px, py, L) of
// bodies the user picks, against time, a curve per body named by it, and curves that sum the
// quantity over a set of bodies (p₁ + p₂ of two carts, E_k of a set). Values are measured in a
// frame of reference: the lab's, or the one moving with the centre of mass of some bodies,
// where the momenta of a collision are equal and opposite and sum to zero.
//
// The values come from the World's state alone (its public API); a BodyGraph feeds them to a
// PlotWidget point by point, so that the graph follows the timeline and exports as every plot
// does.

#include "plots/plot_widget.h"

#include "rigidlab/physics/world.h"

#include <QString>

#include <optional>
#include <vector>

namespace rigidlab::ui {

enum class BodyQuantity {
    X,               ///< centre of mass [m]
    Y,               ///< [m]
    Vx,              ///< [m/s]
    Vy,              ///< [m/s]
    Speed,           ///< |v| [m/s]
    Acceleration,    ///< |a|, from the change of v between two points of the graph [m/s²]
    AngleDegrees,    ///< θ [°]
    AngleRadians,    ///< θ [rad]
    AngularVelocity, ///< ω [rad/s]
    KineticEnergy,   ///< translation and rotation [J]
    Px,              ///< linear momentum [kg m/s]
    Py,              ///< [kg m/s]
    AngularMomentum, ///< about a point (the frame's origin) [kg m²/s]
};
inline constexpr int kBodyQuantityCount = 13;

/// The quantity in words, translated ("speed |v|").
QString quantityName(BodyQuantity q);
/// Its symbol as a CSV head writes it ("v_x", "E_k").
QString quantitySymbol(BodyQuantity q);
/// Its symbol on a plot's value axis ("vx", "θ").
QString quantityAxisName(BodyQuantity q);
/// Its SI unit ("m/s", "°").
QString quantityUnit(BodyQuantity q);

/// The frame the values are measured in: the lab's (no bodies), or the frame moving with the
/// centre of mass of `bodies` (their dynamic ones), with its origin there.
struct ReferenceFrame {
    std::vector<physics::BodyId> bodies;
    bool isLab() const { return bodies.empty(); }
};

/// Where the frame's origin is and how it moves, now.
struct FrameMotion {
    physics::Vec2 origin = physics::Vec2::Zero();   ///< [m]
    physics::Vec2 velocity = physics::Vec2::Zero(); ///< [m/s]
};
/// The lab frame is at rest at (0, 0); a centre-of-mass frame is at the bodies' centre of
/// mass, moving with it. Bodies without mass (static, kinematic) do not count; none with mass
/// is the lab frame.
FrameMotion frameMotion(const physics::World& world, const ReferenceFrame& frame);

/// Body `id`'s quantity in a frame moving as `motion` (positions from its origin, velocities
/// relative to it, L about its origin). Acceleration needs two moments: NaN here.
double bodyValue(const physics::World& world, physics::BodyId id, BodyQuantity q,
                 const FrameMotion& motion);

/// A quantity of bodies fed to a PlotWidget, a curve per body or set, named by it.
class BodyGraph {
public:
    BodyGraph(PlotWidget& plot, BodyQuantity quantity, ReferenceFrame frame);

    BodyQuantity quantity() const { return m_quantity; }
    const ReferenceFrame& frame() const { return m_frame; }
    /// A curve of one body, named `label`. Returns its series in the plot.
    int addBody(physics::BodyId id, const QString& label);
    /// A curve of the quantity summed over `ids`, named `label` ("p_x moving + at rest").
    int addSum(std::vector<physics::BodyId> ids, const QString& label);
    int curveCount() const { return static_cast<int>(m_curves.size()); }

    /// Adds the world's values at time t [s] (a t not later than the last goes back there).
    void record(const physics::World& world, double t);

private:
    struct Curve {
        int series = 0;
        std::vector<physics::BodyId> bodies;
        /// The last point, for the acceleration: time [s] and the velocities [m/s].
        std::optional<double> lastT;
        std::vector<physics::Vec2> lastV;
    };
    double valueOf(Curve& curve, const physics::World& world, const FrameMotion& motion,
                   double t) const;

    PlotWidget& m_plot;
    BodyQuantity m_quantity;
    ReferenceFrame m_frame;
    std::vector<Curve> m_curves;
};

} // namespace rigidlab::ui
