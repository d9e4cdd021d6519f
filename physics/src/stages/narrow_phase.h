// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Private: Stage::NarrowPhase (profile.h), the contacts of the pairs the broad phase found.

#include "rigidlab/physics/body.h"
#include "rigidlab/physics/contact.h"

#include "manifold.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace rigidlab::physics {

/// A contact's manifold as the full test of two polygons made it in the soft step, for
/// recycling it while the two bodies barely move (recycleManifold). Each point is kept as an
/// anchor on each body; the separation follows their motion. The world keeps one beside each
/// contact, at the same index (World::m_contactAnchors), out of the public Contact: only the
/// narrow phase reads them, and every other pass over the contacts reads fewer bytes.
struct ContactAnchors {
    bool valid = false;              ///< made by a full test in the soft step
    Vec2 centres = Vec2::Zero();     ///< B's centre of mass less A's then [m]
    Rotation qA, qB;                 ///< the bodies' rotations then
    double extentA = 0, extentB = 0; ///< farthest vertex from each centre of mass [m]
    std::array<Vec2, 2> anchorA{Vec2::Zero(), Vec2::Zero()}; ///< point less A's centre [m]
    std::array<Vec2, 2> anchorB{Vec2::Zero(), Vec2::Zero()}; ///< point less B's centre [m]
    std::array<double, 2> separation{0, 0};                  ///< then [m]
};

/// A pair of polygons that the SAT found farther apart than their margin, and the axis that
/// showed it (its index in the SAT's order: A's edges, then B's).
struct SeparatedPair {
    int a = 0, b = 0;
    int axis = -1;
};

/// A pair of polygons that the SAT found touching (closer than margin), the faces it chose,
/// and where each polygon was in the other's frame then.
struct TouchingPair {
    int a = 0, b = 0;
    FaceChoice choice;
    Vec2 bInA = Vec2::Zero();        ///< B's origin in A's frame [m]
    Vec2 aInB = Vec2::Zero();        ///< A's origin in B's frame [m]
    double turn = 0;                 ///< B's angle less A's [rad]
    double radiusA = 0, radiusB = 0; ///< the farthest vertex from each origin [m]
};

/// The narrow phase's buffers, kept in the world's scratch from step to step. They save work
/// and change no result: a fresh cache gives the same contacts, bit for bit.
struct NarrowPhaseCache {
    WorldPolygons placed; ///< this step's polygons placed in the world, each once
    /// The pairs found apart this step and last step, in pair order: last step's separating
    /// axis is tried first (collidePlacedPolygons), and a pair that has not come closer is
    /// settled by one axis instead of all of them.
    std::vector<SeparatedPair> separated, previousSeparated;
    /// The pairs found touching, in pair order: a pair that has moved too little since the
    /// SAT chose its faces to change that choice is clipped from the same faces without the
    /// SAT (the same manifold, bit for bit: the SAT would choose them again).
    std::vector<TouchingPair> touching, previousTouching;
    bool reuseFaces = true; ///< off: every pair gets the whole SAT (to test that it is the same)
    int reused = 0;         ///< pairs clipped from kept faces in the last call
    /// The room of the ring where last step's contacts not yet read, with their anchors, are
    /// moved out of the way of this step's as these are written over them
    /// (fast/contact_rewrite.h); what it holds between steps is not read.
    std::vector<Contact> spill;
    std::vector<ContactAnchors> spillAnchors;
    /// Forgets what was kept (the plain path keeps nothing).
    void clear()
    {
        separated.clear();
        previousSeparated.clear();
        touching.clear();
        previousTouching.clear();
        reused = 0;
    }
};

/// Last step's records of pairs (contacts, separated pairs), looked up pair by pair in
/// increasing order: both lists are sorted, so one cursor walks through them once.
template <typename Record> class PreviousPairs {
public:
    explicit PreviousPairs(const std::vector<Record>& records) : m_records(records) {}
    /// Last step's record of the pair (a, b), or null. Calls come in increasing (a, b).
    const Record* find(int a, int b)
    {
        while (m_next < m_records.size() &&
               std::pair(m_records[m_next].a, m_records[m_next].b) < std::pair(a, b))
            ++m_next;
        if (m_next < m_records.size() && m_records[m_next].a == a && m_records[m_next].b == b)
            return &m_records[m_next];
        return nullptr;
    }

private:
    const std::vector<Record>& m_records;
    size_t m_next = 0;
};

/// Static, or dynamic and asleep: it does not move this step.
inline bool rests(const Body& body)
{
    return body.type == BodyType::Static || (body.isDynamic() && !body.awake);
}

/// A body's swept margin this step [m] (continuous.cpp); `sweep` is empty when no body is fast.
inline double sweptMargin(const std::vector<double>& sweep, int body)
{
    return sweep.empty() ? 0.0 : sweep[static_cast<size_t>(body)];
}

/// How a pair moved since its manifold's anchors were kept (ContactAnchors): each body's turn
/// since then, and the shift of B's centre of mass less A's [m].
struct AnchorMotion {
    Rotation dqA, dqB;
    Vec2 shift = Vec2::Zero();
};
/// Whether `previous` (last step's contact of the pair a, b), with its anchors `kept`, may be
/// recycled: kept by a full test, and the pair moved less than `recycle` against each other
/// since [m] (the centres' shift, plus the turns times the extents): recycleManifold's first
/// test. The motion into `motion`.
bool mayRecycle(const Contact& previous, const ContactAnchors& kept, const Body& a,
                const Transform& xfA, const Body& b, const Transform& xfB, double recycle,
                AnchorMotion& motion);
/// The points of `previous`'s manifold (last step's contact of the pair a, b, with its anchors
/// `kept`) carried to where a and b are now (recycleManifold's test and points), into
/// `points`; false when the manifold is not to be recycled.
bool recycledPoints(const Contact& previous, const ContactAnchors& kept, const Body& a,
                    const Transform& xfA, const Body& b, const Transform& xfB, double recycle,
                    double margin, std::array<ContactPoint, 2>& points);
/// The manifold of `previous` (last step's contact of the pair a, b, with its anchors `kept`)
/// carried to where a and b are now, when it was kept (keepAnchors) and they moved less than
/// `recycle` against each other since [m] (their centres' shift, plus their turns times their
/// extents), and no point ends farther apart than margin: then into c, its anchors into
/// `anchors`, and true.
bool recycleManifold(const Contact& previous, const ContactAnchors& kept, const Body& a,
                     const Transform& xfA, const Body& b, const Transform& xfB, double recycle,
                     double margin, Contact& c, ContactAnchors& anchors);
/// Keeps `manifold`, of the polygons pa and pb just made by the full test, into `anchors` for
/// recycling.
void keepAnchors(const Body& a, const Polygon& pa, const Transform& xfA, const Body& b,
                 const Polygon& pb, const Transform& xfB, const Manifold& manifold,
                 ContactAnchors& anchors);

/// Last step's contacts and this step's, each with its anchors at the same index.
struct ContactLists {
    const std::vector<Contact>& previous;
    const std::vector<ContactAnchors>& previousAnchors;
    std::vector<Contact>& contacts;
    std::vector<ContactAnchors>& anchors;
    /// Set when a contact carried over holds a bounce (StepScratch::bounceHeld): a new or
    /// recycled contact holds none.
    bool& bounceKept;
    /// Last step's contact `kept` (found in previous) carried over whole, with its anchors.
    void keep(const Contact& kept)
    {
        contacts.push_back(kept);
        anchors.push_back(previousAnchors[static_cast<size_t>(&kept - previous.data())]);
        bounceKept = bounceKept || kept.bounceImpulse[0] > 0 || kept.bounceImpulse[1] > 0;
    }
    /// The anchors of last step's contact `p` (found in previous).
    const ContactAnchors& anchorsOf(const Contact& p) const
    {
        return previousAnchors[static_cast<size_t>(&p - previous.data())];
    }
};

/// The contacts of `pairs` (a < b, sorted), in their order: each pair's manifold
/// (collideShapes, manifold.cpp) for shapes closer than margin plus both bodies' swept margins
/// (`sweep`, per body [m], empty when no body is fast: continuous.cpp), with the pair's mixed
/// material and the impulses that `lists.previous` (last step's contacts, sorted) held for the
/// same features. Two resting bodies (asleep, or asleep on a static one) keep last step's
/// contact. `xf`: each body's placement now. recycle > 0 (the soft step): two polygons that
/// barely moved, neither fast, keep last step's manifold (recycleManifold), and every other
/// pair of polygons keeps its anchors for that. Into lists.contacts and, at the same index,
/// lists.anchors. The plain path (narrow_phase.cpp).
void narrowPhase(const std::vector<Body>& bodies, const std::vector<Transform>& xf,
                 const std::vector<std::pair<int, int>>& pairs, double margin,
                 const std::vector<double>& sweep, double recycle, ContactLists lists);
class ContactRewrite;
/// The same contacts as narrowPhase, bit for bit, keeping work in `cache` from step to step
/// (fast/kept_faces.cpp; see NarrowPhaseCache), written from last step's by `contacts`
/// (fast/contact_rewrite.h: over them, in the same arrays, when nothing reads them after the
/// narrow phase). `bounceKept`: as ContactLists::bounceKept.
void narrowPhaseFast(const std::vector<Body>& bodies, const std::vector<Transform>& xf,
                     const std::vector<std::pair<int, int>>& pairs, double margin,
                     const std::vector<double>& sweep, double recycle, NarrowPhaseCache& cache,
                     ContactRewrite& contacts, bool& bounceKept);

/// The material of a contact from its two bodies': restitution the larger of the two (a ball
/// bounces off a rubber floor as the floor makes it), friction the geometric mean (Box2D's
/// b2MixFriction: either surface being frictionless makes the pair frictionless). Inline: the
/// recycled pairs of a pile call it for every contact of every step.
inline void mixMaterials(const Body& a, const Body& b, Contact& c)
{
    c.restitution = std::max(a.restitution, b.restitution);
    c.friction = std::sqrt(a.friction * b.friction);
}

/// Warm start: gives each point of `c` the impulses of the point of `previous` (the same pair
/// last step) that the same features made (ContactPoint::id).
void carryImpulses(const Contact& previous, Contact& c);

/// A contact with its manifold made: its mixed material and last step's impulses.
void finishContact(const Body& a, const Body& b, PreviousPairs<Contact>& before, Contact& c);

} // namespace rigidlab::physics
