// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What the scene edits share (scene_edits.cpp, scene_field_edits.cpp, scene_overlaps.cpp):
// their results, and the loader's words for what they refuse.

#include "edit/scene_edits.h"
#include "format/limits.h"

namespace rigidlab::lessons::edit::support {

EditResult refused(const QString& error);
/// The edited scene, or the refusal when its bodies crowd past the engine's work budget
/// (checkCrowding).
EditResult accepted(Scene scene, physics::BodyId body = physics::kWorld,
                    const QString& warning = {});
/// `source: place: must be from MIN to MAX UNIT, got V`, the loader's words, or empty.
QString rangeError(const QString& source, const QString& place, double value,
                   const limits::Range& range);
/// `source: place: what`, as the loader joins them.
QString placedError(const QString& source, const QString& place, const QString& what);
bool validBody(const Scene& scene, physics::BodyId body);
QString noSuchBody(physics::BodyId body);
QString bodyId(const physics::BodyDef& def);
/// Empty, or why `def` may not stand in a scene: its placement out of range, or its mass.
QString bodyProblem(const physics::BodyDef& def);
/// An anchor as the scene format holds it, checked against limits::kCoordinate.
QString anchorError(const QString& source, const QString& key, const physics::Vec2& anchor);
/// After `body` was moved or turned: each pin holding it to the world keeps its point on the
/// body, so its world anchor goes with the body (a pendulum's pivot moves with its bob, as in
/// Algodoo). Springs are left alone: their world ends stay, and the spring stretches. Returns
/// the loader's words when a moved anchor leaves limits::kCoordinate.
QString carryWorldPins(Scene& scene, physics::BodyId body);

} // namespace rigidlab::lessons::edit::support
