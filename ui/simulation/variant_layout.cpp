// SPDX-License-Identifier: GPL-3.0-or-later
#include "simulation/variant_layout.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

namespace rigidlab::ui {

namespace {

/// The box [m] around a world's static bodies (floor, walls); empty when it has none.
/// corners: min x, min y, max x, max y.
std::optional<std::array<double, 4>> staticExtent(const physics::World& world)
{
    std::optional<std::array<double, 4>> box;
    auto add = [&box](const physics::Vec2& p) {
        if (!std::isfinite(p.x()) || !std::isfinite(p.y()))
            return;
        if (!box) {
            box = std::array<double, 4>{p.x(), p.y(), p.x(), p.y()};
            return;
        }
        auto& b = *box;
        b = {std::min(b[0], p.x()), std::min(b[1], p.y()), std::max(b[2], p.x()),
             std::max(b[3], p.y())};
    };
    for (const physics::Body& b : world.bodies()) {
        if (b.moves())
            continue;
        const physics::Transform t = b.transform();
        b.shape.visit(physics::Overloaded{[&](const physics::Circle& circle) {
                                              const physics::Vec2 c = t.apply(circle.center);
                                              const double r = circle.radius;
                                              add(c - physics::Vec2(r, r));
                                              add(c + physics::Vec2(r, r));
                                          },
                                          [&](const physics::Polygon& polygon) {
                                              for (const physics::Vec2& v : polygon.vertices)
                                                  add(t.apply(v));
                                          }});
    }
    return box;
}

} // namespace

physics::Vec2 besideOffset(const physics::World& main, const physics::Vec2& offset)
{
    const double length = offset.norm();
    const auto box = staticExtent(main);
    if (!(length > 0) || !std::isfinite(length) || !box)
        return offset;
    const auto& b = *box;
    const double w = b[2] - b[0], h = b[3] - b[1];
    const bool overlap = std::abs(offset.x()) < w && std::abs(offset.y()) < h;
    if (!overlap)
        return offset;
    // The box's length along the shift's direction, so that the shifted box clears it.
    const physics::Vec2 dir = offset / length;
    const double alongX = std::abs(dir.x()) > 1e-12 ? w / std::abs(dir.x()) : HUGE_VAL;
    const double alongY = std::abs(dir.y()) > 1e-12 ? h / std::abs(dir.y()) : HUGE_VAL;
    const double extent = std::min(alongX, alongY);
    const double gap = std::max(0.5, 0.1 * extent);
    return dir * std::max(length, extent + gap);
}

} // namespace rigidlab::ui
