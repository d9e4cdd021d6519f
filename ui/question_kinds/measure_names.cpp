// SPDX-License-Identifier: GPL-3.0-or-later
#include "question_kinds/measure_names.h"
#include "common/number_format.h"
#include "question_kinds/editor_parts.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonObject>
#include <QLocale>

namespace rigidlab::ui {

// In the measured kind's words (its translation context, as in measured.h).

/// The measures the player knows (LESSON_FORMAT.md, `measure`), in the order offered.
const std::array<MeasureName, 10> kMeasureNames{{
    {"apex", QT_TRANSLATE_NOOP("MeasuredQuestion", "height of a bounce's top"), "m", true, false},
    {"speed", QT_TRANSLATE_NOOP("MeasuredQuestion", "speed"), "m/s", true, true},
    {"velocity-x", QT_TRANSLATE_NOOP("MeasuredQuestion", "velocity x"), "m/s", true, true},
    {"velocity-y", QT_TRANSLATE_NOOP("MeasuredQuestion", "velocity y"), "m/s", true, true},
    {"angular-velocity", QT_TRANSLATE_NOOP("MeasuredQuestion", "angular velocity"), "rad/s", true,
     true},
    {"position-x", QT_TRANSLATE_NOOP("MeasuredQuestion", "position x"), "m", true, true},
    {"position-y", QT_TRANSLATE_NOOP("MeasuredQuestion", "position y"), "m", true, true},
    {"energy-drift", QT_TRANSLATE_NOOP("MeasuredQuestion", "energy drift"), "%", false, true},
    {"momentum-x", QT_TRANSLATE_NOOP("MeasuredQuestion", "momentum x"), "kg m/s", false, true},
    {"momentum-y", QT_TRANSLATE_NOOP("MeasuredQuestion", "momentum y"), "kg m/s", false, true},
}};

const MeasureName& measureName(const QString& id)
{
    for (const MeasureName& k : kMeasureNames)
        if (id == QLatin1String(k.id))
            return k;
    return kMeasureNames[0];
}

QList<std::pair<QString, QString>> movingBodies(const QJsonObject& scene)
{
    QList<std::pair<QString, QString>> out;
    for (const QJsonValue b : scene.value(u"bodies").toArray()) {
        const QJsonObject body = b.toObject();
        const QString id = body.value(u"id").toString();
        if (id.isEmpty() || body.value(u"type").toString() == u"static")
            continue;
        const QString label = shownText(body.value(u"label"));
        out.append({id, label.isEmpty() ? id : label});
    }
    return out;
}

QString bodyName(const QJsonObject& scene, const QString& id)
{
    for (const auto& [bodyId, name] : movingBodies(scene))
        if (bodyId == id)
            return name;
    return id;
}

QString defaultPrompt(const QJsonObject& measure, const QString& bodyName)
{
    const MeasureName& k = measureName(measure.value(u"kind").toString());
    const QString quantity = QCoreApplication::translate("MeasuredQuestion", k.name);
    const QString time = formatReadable(measure.value(u"time").toDouble(), 4);
    if (!k.time)
        return QCoreApplication::translate("MeasuredQuestion",
                                           "How high does %1 rise after its bounce %2?")
            .arg(bodyName)
            .arg(measure.value(u"n").toInt(1));
    if (!k.body)
        return QCoreApplication::translate("MeasuredQuestion", "What is the %1 at t = %2\u00a0s?")
            .arg(quantity, time);
    return QCoreApplication::translate("MeasuredQuestion", "What is the %1 of %2 at t = %3\u00a0s?")
        .arg(quantity, bodyName, time);
}

} // namespace rigidlab::ui
