// SPDX-License-Identifier: GPL-3.0-or-later
#include "measure/exact_flights.h"

#include "measure/fit.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rigidlab::measure {

namespace {

/// Impacts slower than this rest [m/s]: the lab's rest threshold as its step goes to zero
/// (physics::restitutionThreshold).
constexpr double kRestSpeed = 0.01;
/// More bounces than this before the last time asked: the model gives up (e within 1e-7 of 1
/// over hours), and the lab's run answers instead.
constexpr long long kMaxModelBounces = 10'000'000;

struct Extent {
    double left = std::numeric_limits<double>::infinity();
    double right = -std::numeric_limits<double>::infinity();
    double top = -std::numeric_limits<double>::infinity();
};

/// A static body's horizontal extent and top in the world; `flatTop` whether its top is one
/// horizontal edge (an unrotated box, or any polygon with a level top edge).
Extent extentOf(const physics::BodyDef& b, bool& flatTop)
{
    Extent e;
    flatTop = false;
    const physics::Transform pose(b.position, b.angle);
    if (const physics::Circle* c = b.shape.asCircle()) {
        const physics::Vec2 p = pose.apply(c->center);
        return {p.x() - c->radius, p.x() + c->radius, p.y() + c->radius};
    }
    std::vector<physics::Vec2> world;
    for (const physics::Vec2& v : b.shape.asPolygon()->vertices) {
        world.push_back(pose.apply(v));
        e.left = std::min(e.left, world.back().x());
        e.right = std::max(e.right, world.back().x());
        e.top = std::max(e.top, world.back().y());
    }
    int atTop = 0;
    for (const physics::Vec2& w : world)
        atTop += std::abs(w.y() - e.top) <= 1e-12 * std::max(1.0, std::abs(e.top)) ? 1 : 0;
    flatTop = atTop >= 2;
    return e;
}

/// The ball's flights: its centre's height and vertical speed from the start of a flight.
struct Flights {
    double g = 0;      ///< downward acceleration [m/s²]
    double c = 0;      ///< the centre's height on the floor [m]
    double e = 0;      ///< of the contact
    double t0 = 0;     ///< start of the current flight [s]
    double y0 = 0;     ///< centre height then [m]
    double v0 = 0;     ///< upward speed then [m/s]
    bool rest = false; ///< on the floor for good
    long long bounces = 0;

    double hitTime() const { return t0 + (v0 + std::sqrt(v0 * v0 + 2 * g * (y0 - c))) / g; }

    /// Flies on to the flight that holds time t; false when that takes too many bounces.
    bool advanceTo(double t)
    {
        while (!rest && t > hitTime()) {
            const double u = std::sqrt(v0 * v0 + 2 * g * (y0 - c)), hit = hitTime();
            const double up = e * u;
            y0 = c;
            t0 = hit;
            v0 = up;
            rest = up < kRestSpeed;
            if (!rest && e == 1.0) { // a period of its own for ever: skip whole flights
                const double period = 2 * up / g;
                t0 += std::floor(std::max(0.0, t - t0) / period) * period;
            }
            if (++bounces > kMaxModelBounces)
                return false;
        }
        return true;
    }
};

} // namespace

std::optional<std::vector<double>> exactFlightsAt(const lessons::Scene& scene, const Target& target,
                                                  const std::vector<double>& times)
{
    const physics::WorldDef& w = scene.world;
    if (!scene.springs.empty() || !scene.joints.empty() || w.gravitation != 0 || w.drag != 0 ||
        w.gravity.x() != 0 || !(w.gravity.y() < 0))
        return std::nullopt;
    const auto ballIndex = static_cast<std::size_t>(target.body);
    const physics::BodyDef& ball = scene.bodies[ballIndex];
    const physics::Circle* circle = ball.shape.asCircle();
    if (ball.type != physics::BodyType::Dynamic || circle == nullptr || !ball.collide ||
        ball.velocity.x() != 0 || ball.angularVelocity != 0)
        return std::nullopt;
    const physics::Vec2 centre =
        physics::Transform(ball.position, ball.angle).apply(circle->center);
    const double r = circle->radius, x = centre.x();
    // One floor under the ball; nothing else it could touch on its way up and down.
    const physics::BodyDef* floor = nullptr;
    for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
        const physics::BodyDef& b = scene.bodies[i];
        if (i == ballIndex || !b.collide)
            continue;
        if (b.type != physics::BodyType::Static)
            return std::nullopt;
        bool flatTop = false;
        const Extent extent = extentOf(b, flatTop);
        if (extent.right <= x - r || extent.left >= x + r)
            continue; // beside the ball's path
        if (floor != nullptr || !flatTop || !(extent.left < x && x < extent.right))
            return std::nullopt;
        floor = &b;
    }
    if (floor == nullptr)
        return std::nullopt;
    bool flatTop = false;
    const double top = extentOf(*floor, flatTop).top;
    Flights f;
    f.g = -w.gravity.y();
    f.c = top + r;
    f.y0 = centre.y();
    f.v0 = ball.velocity.y();
    if (f.y0 < f.c)
        return std::nullopt; // starts inside the floor
    f.e = std::max(physics::resolvedMaterial(ball.restitution, w.restitution),
                   physics::resolvedMaterial(floor->restitution, w.restitution));
    f.rest = f.y0 == f.c && f.v0 <= 0;
    const double offset = ball.position.y() - centre.y(); // origin below or above the centre
    std::vector<double> out;
    out.reserve(times.size());
    for (const double t : times) {
        if (!f.advanceTo(t))
            return std::nullopt;
        const double tau = f.rest ? 0.0 : t - f.t0;
        const double y = f.rest ? f.c : f.y0 + f.v0 * tau - 0.5 * f.g * tau * tau;
        const double vy = f.rest ? 0.0 : f.v0 - f.g * tau;
        switch (target.quantity) {
        case Quantity::X:
            out.push_back(ball.position.x());
            break;
        case Quantity::Y:
            out.push_back(y + offset);
            break;
        case Quantity::Vx:
            out.push_back(0.0);
            break;
        case Quantity::Vy:
            out.push_back(vy);
            break;
        case Quantity::Speed:
            out.push_back(std::abs(vy));
            break;
        default:
            return std::nullopt;
        }
    }
    return out;
}

} // namespace rigidlab::measure
