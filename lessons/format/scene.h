// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A scene as a file describes it: the world settings and the definitions of its bodies,
// springs and joints, ready to build a physics::World. See lessons/SCENE_FORMAT.md.

#include "rigidlab/physics/body.h"
#include "rigidlab/physics/forces.h"
#include "rigidlab/physics/world.h"

#include <QMap>
#include <QString>

#include <optional>
#include <vector>

namespace rigidlab::lessons {

/// A text the file gave in several languages: language code -> text. Empty when the file gave
/// a plain string (English), which Scene then keeps as it is.
using LocalTextMap = QMap<QString, QString>;

struct Scene {
    QString title;       ///< one line, for menus and window titles, in `language`
    QString description; ///< what a teacher reads before running it, in `language`
    /// Every language's title and description where the file gave an object of languages
    /// ({"en": ..., "cs": ...}), so that saving the scene keeps them all. `title` and
    /// `description` are the ones shown; when an editor changes them, the writer puts the new
    /// text in the language shown (scene_writer.h).
    LocalTextMap titles;
    LocalTextMap descriptions;
    /// The language the scene was read in (languages.h): the one `title` and `description`
    /// are in, when the file has it.
    QString language;
    physics::WorldDef world;
    /// In file order; a body's index here is its physics::BodyId in the built world.
    /// BodyDef::name holds the scene's id ("ball"), unique and non-empty.
    /// BodyDef::position is the body origin, the frame the shape's vertices are given in.
    std::vector<physics::BodyDef> bodies;
    /// Ends refer to bodies by index into `bodies`, or physics::kWorld.
    std::vector<physics::SpringDef> springs;
    std::vector<physics::PinJointDef> joints;
    /// Per body (parallel to `bodies`): the vertices the file gave for a polygon that was not
    /// convex and was replaced by its convex hull, body-local [m]; empty for every other body.
    /// The SAT lesson draws them to show where detection with the hull is wrong.
    std::vector<std::vector<physics::Vec2>> originalVertices;
    /// Per body (parallel to `bodies`, or shorter): the colour the file gives it, "#rrggbb" in
    /// lower case, or empty for the view's own colour. Read it through colourOf().
    std::vector<QString> colours;

    /// The index of the body with this id, or nullopt.
    std::optional<physics::BodyId> bodyIndex(const QString& id) const;
    /// The colour of body `index` ("#rrggbb"), or empty when it has none.
    QString colourOf(std::size_t index) const
    {
        return index < colours.size() ? colours[index] : QString();
    }
};

/// A world holding the scene's bodies (ids = indices into scene.bodies), springs and joints,
/// with the scene's settings.
physics::World buildWorld(const Scene& scene);

} // namespace rigidlab::lessons
