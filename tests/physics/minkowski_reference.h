// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The SAT's reference in test_sat: whether two convex polygons meet, how deep and along which
// normal, found by another method than the separating axis test.
//
// Independent method. D = B (+) (-A) is the convex hull of all differences vB - vA of world
// vertices (built here by gift wrapping, not by the engine's convexHull). A and B intersect
// iff the origin lies in D. With D's faces written n_f . x <= c_f (n_f outward, unit):
//   - the origin is inside iff every c_f >= 0, and max_f(-c_f) is the SAT's largest gap;
//   - the penetration depth is min_f c_f (the distance from the origin to D's nearest face);
//   - moving B by -c_f n_f pushes the origin out through that face, so the normal from A to
//     B is -n_f of the nearest face (n_f itself is the outward normal of A - B's face).
//
//          D = B - A                       origin inside D, nearest face on the left:
//        +-----------+                      n_f = (-1, 0), c_f = depth, B must move +x
//   n_f  | o         |
//   <--  |           |
//        +-----------+

#include "physics_test_util.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace rigidlab::test {

/// The faces of the Minkowski difference B - A, from world vertices.
struct Minkowski {
    std::vector<Vec2> normals; ///< outward unit normals of D's faces
    std::vector<double> c;     ///< offsets: n . x <= c on D
    double maxGap = 0;         ///< max(-c): > 0 separated, < 0 intersecting
    int nearest = -1;          ///< face of least c
    double secondC = INFINITY; ///< the next least c (of a face with another normal)
};

inline bool minkowski(const std::vector<Vec2>& a, const std::vector<Vec2>& b, Minkowski& out)
{
    std::vector<Vec2> diff;
    for (const Vec2& vb : b) {
        for (const Vec2& va : a) {
            diff.push_back(vb - va);
        }
    }
    const std::vector<Vec2> hull = giftWrapHull(diff);
    if (hull.size() < 3) {
        return false;
    }
    out = Minkowski{};
    out.maxGap = -INFINITY;
    double best = INFINITY;
    for (std::size_t i = 0; i < hull.size(); ++i) {
        const Vec2 e = hull[(i + 1) % hull.size()] - hull[i];
        if (e.norm() < 1e-12) {
            continue; // a sliver face has no reliable normal; its neighbours bound it anyway
        }
        const Vec2 n = Vec2(e.y(), -e.x()).normalized(); // outward for a CCW hull
        const double c = n.dot(hull[i]);
        out.normals.push_back(n);
        out.c.push_back(c);
        out.maxGap = std::max(out.maxGap, -c);
        if (c < best) {
            best = c;
            out.nearest = static_cast<int>(out.c.size()) - 1;
        }
    }
    for (std::size_t i = 0; i < out.c.size(); ++i) {
        if (static_cast<int>(i) != out.nearest &&
            out.normals[i].dot(out.normals[out.nearest]) < 1.0 - 1e-9) {
            out.secondC = std::min(out.secondC, out.c[i]);
        }
    }
    return true;
}

/// Support of world vertices along d: the largest projection.
inline double maxAlong(const std::vector<Vec2>& v, const Vec2& d)
{
    double m = -INFINITY;
    for (const Vec2& p : v) {
        m = std::max(m, p.dot(d));
    }
    return m;
}
inline double minAlong(const std::vector<Vec2>& v, const Vec2& d)
{
    return -maxAlong(v, -d);
}

} // namespace rigidlab::test
