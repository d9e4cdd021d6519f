// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Edits of a scene as pure functions: each takes a scene and returns an edited copy, or the
// reason it refuses, in the scene loader's words and ranges (format/limits.h,
// format/scene_rules.h), so that a scene built by hand is one the loader would read. Nothing
// here knows about windows or undo: the editor (ui/editor/) hands the copy to its document.
//
// Points are in world coordinates [m] unless a name says body-local. Bodies are named by their
// index in scene.bodies (physics::BodyId); physics::kWorld stands for the world.

#include "format/scene.h"
#include "format/scene_schema.h"

#include <QCoreApplication>
#include <QString>

#include <utility>
#include <vector>

namespace rigidlab::lessons::edit {

/// The translation context of the editor's own refusals (the loader's are FileMessages).
struct EditMessages {
    Q_DECLARE_TR_FUNCTIONS(EditMessages)
};

/// An edited scene, or why not.
struct EditResult {
    bool ok = false;
    Scene scene;     ///< the edited copy when ok
    QString error;   ///< one line when !ok: `ID: PLACE: what is wrong` or what to do
    QString warning; ///< when ok: what was changed to make it valid (a polygon's hull)
    /// The body added or duplicated, or the one edited; kWorld otherwise.
    physics::BodyId body = physics::kWorld;
};

/// `stem` followed by the smallest whole number >= 1 that no body of `scene` has: "circle1".
QString uniqueId(const Scene& scene, const QString& stem);

/// A circle of `radius` [m] centred at `center`.
EditResult addCircle(const Scene& scene, const physics::Vec2& center, double radius,
                     physics::BodyType type = physics::BodyType::Dynamic);
/// An axis-aligned box `width` x `height` [m] centred at `center`.
EditResult addBox(const Scene& scene, const physics::Vec2& center, double width, double height,
                  physics::BodyType type = physics::BodyType::Dynamic);
/// A static box: ground, a wall, a ramp once rotated. Its id is "groundN".
EditResult addGround(const Scene& scene, const physics::Vec2& center, double width, double height);
/// A polygon through `points`, its origin at its centroid. Fewer than 3 distinct points or no
/// area is refused; a non-convex outline becomes its convex hull with the loader's warning,
/// and the outline drawn is kept in scene.originalVertices, as the loader keeps a file's.
EditResult addPolygon(const Scene& scene, const std::vector<physics::Vec2>& points,
                      physics::BodyType type = physics::BodyType::Dynamic);
/// The convex polygon addPolygon would make of `points` (world), or its refusal; ok() with no
/// scene change, for showing the hull before it is accepted.
struct PolygonPreview {
    bool ok = false;
    std::vector<physics::Vec2> hull; ///< world points, counter-clockwise
    QString error;
    QString warning;
};
PolygonPreview previewPolygon(const std::vector<physics::Vec2>& points);

/// Places the body's origin at `position`. A pin holding the body to the world moves with it
/// (it stays at its point of the body); a spring's world end stays where it is.
EditResult moveBody(const Scene& scene, physics::BodyId body, const physics::Vec2& position);
/// Turns the body to `angle` [rad] about its origin; its pins to the world turn with it.
EditResult rotateBody(const Scene& scene, physics::BodyId body, double angle);
/// Removes the body with the springs and pins that name it; later bodies move down one index
/// and every spring and pin is renumbered to match.
EditResult deleteBody(const Scene& scene, physics::BodyId body);
/// A copy of the body moved by `offset` [m], with a new id, added last.
EditResult duplicateBody(const Scene& scene, physics::BodyId body, const physics::Vec2& offset);
/// Removes spring `index` / pin `index`.
EditResult deleteSpring(const Scene& scene, int index);
EditResult deletePin(const Scene& scene, int index);

/// A pin holding body `a` at `point` to body `b` (or the world) where they are now.
EditResult addPin(const Scene& scene, physics::BodyId a, physics::BodyId b,
                  const physics::Vec2& point);
/// A spring from `pointA` on `a` to `pointB` on `b` (either may be the world), its rest
/// length the distance drawn, with stiffness [N/m] and damping [N s/m].
EditResult addSpring(const Scene& scene, physics::BodyId a, const physics::Vec2& pointA,
                     physics::BodyId b, const physics::Vec2& pointB, double stiffness,
                     double damping = 0.0);

/// Sets the field `key` of object `index` of `object` (scene_schema.h) to `value`: for a pair,
/// `component` 0 or 1 sets that component alone (a number), -1 the whole pair. Checked with
/// the loader's rules and words; a body's pins to the world follow its position and angle.
/// Setting density lets the mass follow from it again; an unset value (std::monostate) gives
/// an optional field back to its default (a body's restitution: the world's).
EditResult setField(const Scene& scene, schema::Object object, std::size_t index,
                    std::string_view key, const schema::Value& value, int component = -1);

/// A number of a body, by name (setField with its key and component).
enum class BodyNumber {
    PositionX,       ///< [m]
    PositionY,       ///< [m]
    Angle,           ///< [rad]
    Density,         ///< [kg/m^2]; the body's mass then follows from it
    Mass,            ///< [kg]; overrides the density
    Restitution,     ///< 0 to 1
    Friction,        ///< >= 0
    VelocityX,       ///< [m/s]
    VelocityY,       ///< [m/s]
    AngularVelocity, ///< [rad/s]
};
EditResult setBodyNumber(const Scene& scene, physics::BodyId body, BodyNumber what, double value);
EditResult setBodyType(const Scene& scene, physics::BodyId body, physics::BodyType type);
/// Sets the body's initial velocity [m/s], both components at once (the editor's arrow).
EditResult setBodyVelocity(const Scene& scene, physics::BodyId body, const physics::Vec2& velocity);
/// Gives the body its own colour, "#rrggbb" (either case; kept in lower case, as the loader
/// keeps it), or, for an empty `colour`, takes it away so that the view colours it itself.
EditResult setBodyColour(const Scene& scene, physics::BodyId body, const QString& colour);
/// Renames a body; springs and pins refer to it by index and follow.
EditResult setBodyId(const Scene& scene, physics::BodyId body, const QString& id);

enum class SpringNumber {
    Stiffness,  ///< [N/m]
    Damping,    ///< [N s/m]
    RestLength, ///< [m]
};
EditResult setSpringNumber(const Scene& scene, int spring, SpringNumber what, double value);

enum class WorldNumber {
    GravityX,   ///< [m/s^2]
    GravityY,   ///< [m/s^2]
    Dt,         ///< [s]
    Iterations, ///< whole number
};
EditResult setWorldNumber(const Scene& scene, WorldNumber what, double value);
EditResult setIntegrator(const Scene& scene, physics::IntegratorKind kind);
EditResult setSolver(const Scene& scene, physics::SolverKind kind);

/// The most overlapping pairs the editor lists (a heap of duplicates has millions).
inline constexpr std::size_t kMaxListedOverlaps = 100;
/// Pairs of bodies (i < j) that overlap as placed, in index order, at most kMaxListedOverlaps.
/// Touching is not overlapping; pairs that never collide (two static bodies, a body that
/// passes through all) are left out.
std::vector<std::pair<physics::BodyId, physics::BodyId>> overlappingPairs(const Scene& scene);
/// "circle1 overlaps box2; overlapping bodies are pushed apart when the scene runs", or empty.
QString overlapMessage(const Scene& scene);

} // namespace rigidlab::lessons::edit
