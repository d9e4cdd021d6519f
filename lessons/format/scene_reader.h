// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The scene loader's reader (scene_loader.h), private to the loader: one reader per file, which
// stops at the first problem. Its parts by job: the scene's texts, world and bodies with their
// shapes (scene_loader.cpp), and what joins the bodies, springs and pin joints: their ends by
// body id and their anchors where the bodies stand at load (scene_links_reader.cpp).

#include "format/json_reader.h"
#include "format/local_text.h"
#include "format/scene_loader.h"
#include "format/scene_schema.h"

#include "rigidlab/physics/shape.h"

#include <QHash>
#include <QJsonObject>
#include <QJsonValue>
#include <QString>

#include <cstddef>
#include <vector>

namespace rigidlab::lessons::detail {

class SceneReader {
public:
    SceneReader(const QString& sourceName, const SceneLoadOptions& options)
        : m_in(sourceName),
          m_texts(m_in, options.language,
                  FileMessages::tr("no %1 text (\"%2\") in the whole scene: it will show in %3"))
    {
    }

    SceneLoadResult read(const QJsonObject& root);

private:
    /// A title or description: "..." or {"en": "...", "cs": "..."}, kept in the chosen language;
    /// `all` gets every language's text of the object form.
    bool readText(const QJsonObject& root, QStringView key, QString& out, LocalTextMap& all);
    /// A body's "colour": "#rrggbb", kept in lower case; absent: empty.
    bool readColour(const QJsonObject& body, const QString& place, QString& out);
    /// Every row of `object` (scene_schema.h) in file order: the plain kinds through
    /// readPlainField, the others here.
    bool readFields(schema::Object object, const QJsonObject& json, const QString& place,
                    std::size_t index);
    bool readField(const schema::Field& field, const QJsonObject& json, const QString& place,
                   std::size_t index);
    bool readId(const QJsonObject& body, const QString& place, std::size_t index);
    bool readWorld(const QJsonObject& root);
    bool readBodies(const QJsonObject& root);
    bool readBody(const QJsonValue& value, const QString& place, std::size_t index);
    /// A body's optional "label": a name a class reads, in every language it has.
    bool readLabel(const QJsonObject& body, const QString& place, QString& label,
                   LocalTextMap& all);
    /// Reads a shape; `original` gets the file's vertices of a polygon replaced by its hull.
    bool readShape(const QJsonValue& value, const QString& place, physics::Shape& shape,
                   std::vector<physics::Vec2>& original);
    bool readSprings(const QJsonObject& root);
    bool readSpring(const QJsonValue& value, const QString& place);
    bool readJoints(const QJsonObject& root);
    bool readJoint(const QJsonValue& value, const QString& place);
    /// Reads a body reference: an id string, or null (and, when allowed, absent) for the world.
    bool readEnd(const QJsonObject& object, QStringView key, const QString& place,
                 physics::BodyId& out, bool worldAllowed);
    /// Where a body-local anchor (or, for the world, a world point) is at load [m].
    physics::Vec2 worldPoint(physics::BodyId body, const physics::Vec2& anchor) const;

    JsonReader m_in;
    detail::LocalTexts m_texts; ///< reads through m_in, declared after it
    Scene m_scene;
    QHash<QString, physics::BodyId> m_ids; // lookup only, never iterated: order comes from m_scene
};

} // namespace rigidlab::lessons::detail
