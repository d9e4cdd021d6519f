// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The measures the lesson editor offers for a measured question, with their names, units and
// what each needs (a body, a time), and the question it writes for one.

#include <QJsonObject>
#include <QString>

#include <array>

namespace rigidlab::ui {

struct MeasureName {
    const char* id;   ///< its "kind" in a question's "measure"
    const char* name; ///< QT_TRANSLATE_NOOP in the editor's context
    const char* unit;
    bool body; ///< it measures a body
    bool time; ///< it is read at a time (an apex is not)
};

/// The measures the player knows (LESSON_FORMAT.md, `measure`), in the order offered.
extern const std::array<MeasureName, 10> kMeasureNames;
/// The measure with this id; the first for one it does not know.
const MeasureName& measureName(const QString& id);

/// The question a new measured question asks, in the window's language, for what it measures:
/// it follows the kind, the body (by its label) and the time the teacher chooses.
QString defaultPrompt(const QJsonObject& measure, const QString& bodyName);

} // namespace rigidlab::ui
