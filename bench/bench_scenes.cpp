// SPDX-License-Identifier: GPL-3.0-or-later
// The benchmark scenes, engine-neutral. Every engine builds exactly these bodies.

#include "bench.h"

#include <cmath>
#include <numbers>

namespace rigidlab::bench {

using physics::Vec2;

namespace {

constexpr double kFriction = 0.6;

BenchBody box(double w, double h, const Vec2& position, double density = 1.0)
{
    BenchBody b;
    b.shape.kind = BenchShapeKind::Box;
    b.shape.width = w;
    b.shape.height = h;
    b.position = position;
    b.density = density;
    b.friction = kFriction;
    return b;
}

BenchBody ground(double halfWidth)
{
    // The top face at y = 0.
    BenchBody g = box(2.0 * halfWidth, 2.0, Vec2(0.0, -1.0));
    g.isStatic = true;
    return g;
}

/// A regular polygon of n vertices and circumradius r, centred on its centroid.
BenchShape regularPolygon(int n, double r)
{
    BenchShape s;
    s.kind = BenchShapeKind::Polygon;
    for (int i = 0; i < n; ++i) {
        const double a = 2.0 * std::numbers::pi * i / n + std::numbers::pi / 2.0;
        s.vertices.emplace_back(r * std::cos(a), r * std::sin(a));
    }
    return s;
}

/// Pyramid of 1 m boxes as in Box2D's large-pyramid benchmark: row i (from the bottom), box j
/// (i <= j < base) at x = (i + 1) 0.5 + (j - i) - 0.5 base, y = (2 i + 1) 0.5.
BenchScene pyramid(int base)
{
    BenchScene s;
    s.name = "pyramid-" + std::to_string(base);
    s.description = "pyramid of 1 m boxes, base " + std::to_string(base);
    s.bodies.push_back(ground(2.0 * base));
    for (int i = 0; i < base; ++i)
        for (int j = i; j < base; ++j)
            s.bodies.push_back(
                box(1.0, 1.0, Vec2((i + 1) * 0.5 + (j - i) - 0.5 * base, (2 * i + 1) * 0.5)));
    s.topBody = static_cast<int>(s.bodies.size()) - 1;
    return s;
}

/// n boxes of 1 m, one on another, with the densities given from the bottom up.
BenchScene stack(std::string name, std::string description, const std::vector<double>& densities)
{
    BenchScene s;
    s.name = std::move(name);
    s.description = std::move(description);
    s.bodies.push_back(ground(20.0));
    for (size_t i = 0; i < densities.size(); ++i)
        s.bodies.push_back(box(1.0, 1.0, Vec2(0.0, 0.5 + static_cast<double>(i)), densities[i]));
    s.topBody = static_cast<int>(s.bodies.size()) - 1;
    return s;
}

/// 1000 bodies (boxes, circles, triangles, hexagons in turn) on a grid above an open box
/// 24 m wide, all let go at once.
BenchScene rain()
{
    BenchScene s;
    s.name = "rain-1000";
    s.description = "1000 polygons and circles rained into a box";
    s.check = BenchCheck::Rain;
    const double halfWidth = 12.0, wallHeight = 60.0;
    s.bodies.push_back(ground(halfWidth + 1.0));
    for (double side : {-1.0, 1.0}) {
        BenchBody wall = box(1.0, wallHeight, Vec2(side * (halfWidth + 0.5), 0.5 * wallHeight));
        wall.isStatic = true;
        s.bodies.push_back(wall);
    }
    s.containerLo = Vec2(-halfWidth, 0.0);
    s.containerHi = Vec2(halfWidth, wallHeight);
    const int columns = 20, rows = 50;
    const double spacing = 1.0;
    for (int row = 0; row < rows; ++row) {
        for (int col = 0; col < columns; ++col) {
            const int k = row * columns + col;
            const double x = -0.5 * spacing * (columns - 1) + spacing * col + 0.25 * (row % 2);
            const Vec2 p(x, 2.0 + spacing * row);
            BenchBody b;
            switch (k % 4) {
            case 0:
                b = box(0.5, 0.5, p);
                break;
            case 1:
                b.shape.kind = BenchShapeKind::Circle;
                b.shape.radius = 0.25;
                break;
            case 2:
                b.shape = regularPolygon(3, 0.35);
                break;
            default:
                b.shape = regularPolygon(6, 0.3);
                break;
            }
            b.position = p;
            b.angle = 0.37 * k; // varied, the same in every engine
            b.friction = kFriction;
            s.bodies.push_back(b);
        }
    }
    return s;
}

} // namespace

int BenchScene::dynamicCount() const
{
    int n = 0;
    for (const BenchBody& b : bodies)
        n += b.isStatic ? 0 : 1;
    return n;
}

std::vector<std::string> benchSceneNames()
{
    return {"pyramid-20", "pyramid-40", "pyramid-100", "rain-1000", "stack-12", "mass-ratio"};
}

std::optional<BenchScene> makeBenchScene(std::string_view name)
{
    if (name == "pyramid-20")
        return pyramid(20);
    if (name == "pyramid-40")
        return pyramid(40);
    if (name == "pyramid-100")
        return pyramid(100);
    if (name == "rain-1000")
        return rain();
    if (name == "stack-12")
        return stack("stack-12", "12 boxes of 1 m, one on another", std::vector<double>(12, 1.0));
    if (name == "mass-ratio")
        return stack("mass-ratio", "a box of 1 kg under one of 100 kg", {1.0, 100.0});
    return std::nullopt;
}

} // namespace rigidlab::bench
