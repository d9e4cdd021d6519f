// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The measures the lesson editor offers for a measured question (measured.h), with their names,
// units and what each needs (a body, a time), the bodies of a step's scene it may measure, and
// the question it writes for one.

#include <QJsonObject>
#include <QList>
#include <QString>

#include <array>
#include <utility>

namespace rigidlab::ui {

struct MeasureName {
    const char* id;   ///< its "kind" in a question's "measure"
    const char* name; ///< QT_TRANSLATE_NOOP in the context "MeasuredQuestion"
    const char* unit;
    bool body; ///< it measures a body
    bool time; ///< it is read at a time (an apex is not)
};

/// The measures the player knows (LESSON_FORMAT.md, `measure`), in the order offered.
extern const std::array<MeasureName, 10> kMeasureNames;
/// The measure with this id; the first for one it does not know.
const MeasureName& measureName(const QString& id);

/// The bodies of a step's `scene` (as the lesson's JSON holds it) that move: (id, label or id),
/// in the scene's order. Read from the JSON, so that they are listed even while the lesson has
/// an error.
QList<std::pair<QString, QString>> movingBodies(const QJsonObject& scene);
/// A body's label in `scene` (its id where it has none, or where it is not a moving body).
QString bodyName(const QJsonObject& scene, const QString& id);

/// The question a new measured question asks, in the window's language, for what it measures:
/// it follows the kind, the body (by its label) and the time the teacher chooses.
QString defaultPrompt(const QJsonObject& measure, const QString& bodyName);

} // namespace rigidlab::ui
