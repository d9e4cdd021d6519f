// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The scene in words, for a screen reader: what the scene view shows a sighted student, read
// from the run's world. Modelled on PhET's screen summary: what is on stage, what is
// happening now, what the student can do; then one line per body (its name, shape, mass,
// position and velocity). The scene view's accessible tree (world_view_accessible.h) and its
// announcements (scene_narrator.h) read these; nothing here changes the world.

#include "rigidlab/physics/body.h"
#include "rigidlab/physics/forces.h"

#include <QCoreApplication>
#include <QString>

#include <vector>

namespace rigidlab::ui {

class RunView;

namespace scene_words {

/// The translation context of the scene in words (and of the scene view's children).
struct SceneWords {
    Q_DECLARE_TR_FUNCTIONS(SceneWords)
};

/// The accessible name of the scene view ("Scene: Bouncing balls").
QString sceneName(const RunView& run);
/// What is on stage, what happens now and what the keys do, in three or four sentences.
QString summary(const RunView& run, int selectedBody);
/// A body's name as a class reads it, with its kind: "red ball (dynamic)".
QString bodyName(const RunView& run, physics::BodyId id);
/// A body's shape in words: "circle, radius 0.2 m", "box 1 m × 0.5 m", "polygon, 5 corners".
QString shapeText(const physics::Shape& shape);
/// A body's numbers now: shape, mass, position, velocity and what it touches.
QString bodyValue(const RunView& run, physics::BodyId id);
/// Per body, the bodies its contacts touch now, in the order of the world's contacts: one
/// pass over the contacts for every body (a pile of 5,000 boxes has 10,000 contacts).
std::vector<std::vector<physics::BodyId>> touchingBodies(const RunView& run);
/// bodyValue() with what the body touches taken from touchingBodies().
QString bodyValue(const RunView& run, physics::BodyId id,
                  const std::vector<physics::BodyId>& touches);

} // namespace scene_words
} // namespace rigidlab::ui
