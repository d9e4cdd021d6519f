// SPDX-License-Identifier: GPL-3.0-or-later
// Islands and sleeping. Bodies that touch (a contact with points), or that a pin or a spring
// joins, form an island; static and kinematic bodies belong to none (a pile on the ground is
// one island, not glued to every other pile by the ground). An island whose bodies have all
// been nearly still for kTimeToSleep goes to sleep: its velocities are set to zero, and it is
// neither integrated nor solved, and its contacts are not recomputed, until
//   - an awake body touches it (the whole island wakes at the next step),
//   - a force or torque is applied to one of its bodies (the user pulling it),
//   - a moving kinematic body touches it,
//   - World::wakeBody, setBodyOrigin or setBodyVelocity names one of its bodies, or a
//     change of gravity, restitution or friction wakes everything.
// The thresholds are Box2D's (b2_linearSleepTolerance, b2_angularSleepTolerance,
// b2_timeToSleep).
//
// Sleeping is a choice of the scene (WorldDef::sleep): it changes the physics a little (a
// body moving slower than 1 cm/s for half a second is stopped), so a lesson about one body's
// energy keeps it off; unset, it is on in large scenes only (kLargeSceneBodies).

#include "rigidlab/physics/world.h"

#include "stages.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace rigidlab::physics {

namespace {

constexpr double kLinearSleepTolerance = 0.01;                            ///< [m/s]
constexpr double kAngularSleepTolerance = 2.0 * 3.14159265358979 / 180.0; ///< [rad/s]
constexpr double kTimeToSleep = 0.5;                                      ///< [s]

int findRoot(std::vector<int>& parent, int i)
{
    while (parent[static_cast<size_t>(i)] != i) {
        int& p = parent[static_cast<size_t>(i)];
        p = parent[static_cast<size_t>(p)]; // path halving
        i = p;
    }
    return i;
}

void unite(std::vector<int>& parent, int a, int b)
{
    a = findRoot(parent, a);
    b = findRoot(parent, b);
    if (a == b)
        return;
    // The smaller index becomes the root: the result does not depend on the order of calls.
    if (b < a)
        std::swap(a, b);
    parent[static_cast<size_t>(b)] = a;
}

bool touchesAsMoving(const Body& kinematic)
{
    return kinematic.type == BodyType::Kinematic &&
           (kinematic.velocity != Vec2::Zero() || kinematic.angularVelocity != 0.0);
}

void wake(Body& b)
{
    b.awake = true;
    b.sleepTime = 0.0;
}

} // namespace

void wakeIslands(StepContext& ctx)
{
    StageTimer timer(ctx.profile, Stage::Islands);
    StepScratch& s = ctx.scratch;
    const size_t n = ctx.bodies.size();
    // Nothing awake, nothing pushed, no kinematic body moving: nothing can wake (contacts
    // between sleeping bodies are last step's, unchanged). The whole check is this loop.
    bool anyAwake = false;
    for (const Body& b : ctx.bodies) {
        if ((b.isDynamic() && (b.awake || b.force != Vec2::Zero() || b.torque != 0.0)) ||
            touchesAsMoving(b)) {
            anyAwake = true;
            break;
        }
    }
    s.islandParent.resize(n);
    std::iota(s.islandParent.begin(), s.islandParent.end(), 0);
    ctx.plan.anyAwake = anyAwake;
    if (!anyAwake)
        return;

    std::vector<int>& parent = s.islandParent;
    for (const Contact& c : ctx.contacts) {
        const Body& a = ctx.bodies[static_cast<size_t>(c.a)];
        const Body& b = ctx.bodies[static_cast<size_t>(c.b)];
        if (a.isDynamic() && b.isDynamic())
            unite(parent, c.a, c.b);
        else if (touchesAsMoving(a) && b.isDynamic())
            wake(ctx.bodies[static_cast<size_t>(c.b)]);
        else if (touchesAsMoving(b) && a.isDynamic())
            wake(ctx.bodies[static_cast<size_t>(c.a)]);
    }
    auto joined = [&](BodyId a, BodyId b) {
        if (a != kWorld && b != kWorld && ctx.bodies[static_cast<size_t>(a)].isDynamic() &&
            ctx.bodies[static_cast<size_t>(b)].isDynamic())
            unite(parent, a, b);
    };
    for (const PinJointDef& j : ctx.joints)
        joined(j.a, j.b);
    for (const SpringDef& sp : ctx.springs)
        joined(sp.a, sp.b);

    // A pushed body wakes; an island with an awake body wakes whole.
    std::vector<double>& islandAwake = s.islandRest; // per root: 1 if awake
    islandAwake.assign(n, 0.0);
    for (size_t i = 0; i < n; ++i) {
        Body& b = ctx.bodies[i];
        if (!b.isDynamic())
            continue;
        if (b.force != Vec2::Zero() || b.torque != 0.0)
            wake(b);
        if (b.awake)
            islandAwake[static_cast<size_t>(findRoot(parent, static_cast<int>(i)))] = 1.0;
    }
    for (size_t i = 0; i < n; ++i) {
        Body& b = ctx.bodies[i];
        if (b.isDynamic() && !b.awake &&
            islandAwake[static_cast<size_t>(findRoot(parent, static_cast<int>(i)))] != 0.0)
            wake(b);
    }
}

void sleepIslands(StepContext& ctx)
{
    StageTimer timer(ctx.profile, Stage::Sleep);
    StepScratch& s = ctx.scratch;
    const size_t n = ctx.bodies.size();
    std::vector<int>& parent = s.islandParent; // from wakeIslands(): the contacts are the same
    const double h = ctx.dt;

    // Each awake body's time at rest; the least over its island decides.
    std::vector<double>& rest = s.islandRest; // per root: the island's least rest time
    constexpr double kUnseen = std::numeric_limits<double>::infinity();
    rest.assign(n, kUnseen);
    for (size_t i = 0; i < n; ++i) {
        Body& b = ctx.bodies[i];
        if (!b.isDynamic()) {
            continue;
        }
        if (!b.awake) {
            ++ctx.profile.asleep;
            continue;
        }
        ++ctx.profile.awake;
        const bool still =
            b.velocity.squaredNorm() <= kLinearSleepTolerance * kLinearSleepTolerance &&
            std::abs(b.angularVelocity) <= kAngularSleepTolerance;
        b.sleepTime = still ? b.sleepTime + h : 0.0;
        double& r = rest[static_cast<size_t>(findRoot(parent, static_cast<int>(i)))];
        if (r == kUnseen)
            ++ctx.profile.islands; // the first awake body seen of this island
        r = std::min(r, b.sleepTime);
    }
    // A moving kinematic body keeps what it touches awake.
    for (const Contact& c : ctx.contacts) {
        const Body& a = ctx.bodies[static_cast<size_t>(c.a)];
        const Body& b = ctx.bodies[static_cast<size_t>(c.b)];
        if (touchesAsMoving(a) && b.isDynamic())
            rest[static_cast<size_t>(findRoot(parent, c.b))] = 0.0;
        else if (touchesAsMoving(b) && a.isDynamic())
            rest[static_cast<size_t>(findRoot(parent, c.a))] = 0.0;
    }
    for (size_t i = 0; i < n; ++i) {
        Body& b = ctx.bodies[i];
        if (!b.isActive() ||
            rest[static_cast<size_t>(findRoot(parent, static_cast<int>(i)))] < kTimeToSleep)
            continue;
        b.awake = false;
        b.velocity = Vec2::Zero();
        b.angularVelocity = 0.0;
        --ctx.profile.awake;
        ++ctx.profile.asleep;
    }
}

} // namespace rigidlab::physics
