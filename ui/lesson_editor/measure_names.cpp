// SPDX-License-Identifier: GPL-3.0-or-later
#include "lesson_editor/measure_names.h"

#include <QCoreApplication>
#include <QJsonObject>
#include <QLocale>

namespace rigidlab::ui {

// In the lesson editor's words (its translation context), where they were written first.

/// The measures the player knows (LESSON_FORMAT.md, `measure`), in the order offered.
const std::array<MeasureName, 10> kMeasureNames{{
    {"apex", QT_TRANSLATE_NOOP("rigidlab::ui::QuestionEditor", "height of a bounce's top"), "m",
     true, false},
    {"speed", QT_TRANSLATE_NOOP("rigidlab::ui::QuestionEditor", "speed"), "m/s", true, true},
    {"velocity-x", QT_TRANSLATE_NOOP("rigidlab::ui::QuestionEditor", "velocity x"), "m/s", true,
     true},
    {"velocity-y", QT_TRANSLATE_NOOP("rigidlab::ui::QuestionEditor", "velocity y"), "m/s", true,
     true},
    {"angular-velocity", QT_TRANSLATE_NOOP("rigidlab::ui::QuestionEditor", "angular velocity"),
     "rad/s", true, true},
    {"position-x", QT_TRANSLATE_NOOP("rigidlab::ui::QuestionEditor", "position x"), "m", true,
     true},
    {"position-y", QT_TRANSLATE_NOOP("rigidlab::ui::QuestionEditor", "position y"), "m", true,
     true},
    {"energy-drift", QT_TRANSLATE_NOOP("rigidlab::ui::QuestionEditor", "energy drift"), "%", false,
     true},
    {"momentum-x", QT_TRANSLATE_NOOP("rigidlab::ui::QuestionEditor", "momentum x"), "kg m/s", false,
     true},
    {"momentum-y", QT_TRANSLATE_NOOP("rigidlab::ui::QuestionEditor", "momentum y"), "kg m/s", false,
     true},
}};

const MeasureName& measureName(const QString& id)
{
    for (const MeasureName& k : kMeasureNames)
        if (id == QLatin1String(k.id))
            return k;
    return kMeasureNames[0];
}

/// The question a new measured question asks, in the window's language, for what it measures:
/// it follows the kind, the body (by its label) and the time the teacher chooses.
QString defaultPrompt(const QJsonObject& measure, const QString& bodyName)
{
    const MeasureName& k = measureName(measure.value(u"kind").toString());
    const QString quantity = QCoreApplication::translate("rigidlab::ui::QuestionEditor", k.name);
    const QString time = QLocale().toString(measure.value(u"time").toDouble(), 'g', 4);
    if (!k.time)
        return QCoreApplication::translate("rigidlab::ui::QuestionEditor",
                                           "How high does %1 rise after its bounce %2?")
            .arg(bodyName)
            .arg(measure.value(u"n").toInt(1));
    if (!k.body)
        return QCoreApplication::translate("rigidlab::ui::QuestionEditor",
                                           "What is the %1 at t = %2\u00a0s?")
            .arg(quantity, time);
    return QCoreApplication::translate("rigidlab::ui::QuestionEditor",
                                       "What is the %1 of %2 at t = %3\u00a0s?")
        .arg(quantity, bodyName, time);
}

} // namespace rigidlab::ui
