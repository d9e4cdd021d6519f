// SPDX-License-Identifier: GPL-3.0-or-later
#include "question_kinds/measured_page.h"
#include "question_kinds/editor_parts.h"
#include "question_kinds/measure_names.h"

#include "common/accessible_names.h"
#include "common/language.h"

#include "format/lesson_rows.h"
#include "format/question_kinds/measured.h"

#include <QComboBox>
#include <QCoreApplication>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLineEdit>

namespace rigidlab::ui {

namespace {

namespace keys = lessons::schema::question_keys;
using lessons::schema::jsonKey;

/// A measure's name in the window's language (kMeasureNames marks them in this context).
QString titleOf(const MeasureName& k)
{
    return QCoreApplication::translate("MeasuredQuestion", k.name);
}

} // namespace

MeasuredPage::MeasuredPage(QWidget* parent) : KindPage(parent)
{
    auto* form = new QFormLayout(this);
    form->setContentsMargins(0, 0, 0, 0);
    m_kind = new QComboBox(this);
    m_kind->setObjectName(QStringLiteral("questionKind"));
    m_kind->setAccessibleName(QCoreApplication::translate("MeasuredQuestion", "What is measured"));
    for (const MeasureName& k : kMeasureNames)
        m_kind->addItem(titleOf(k), QLatin1String(k.id));
    m_body = new QComboBox(this);
    m_body->setObjectName(QStringLiteral("questionBody"));
    m_body->setAccessibleName(QCoreApplication::translate("MeasuredQuestion", "Body measured"));
    m_time = new QDoubleSpinBox(this);
    m_time->setObjectName(QStringLiteral("questionTime"));
    m_time->setRange(0, 3600);
    m_time->setDecimals(2);
    m_time->setSuffix(QStringLiteral("\u00a0s"));
    nameWithUnit(*m_time,
                 QCoreApplication::translate("MeasuredQuestion", "Time of the measurement"));
    m_unit = new QLineEdit(this);
    m_unit->setObjectName(QStringLiteral("questionUnit"));
    m_unit->setAccessibleName(
        QCoreApplication::translate("MeasuredQuestion", "Unit of the answer"));
    m_tolerance = new QDoubleSpinBox(this);
    m_tolerance->setObjectName(QStringLiteral("questionTolerance"));
    m_tolerance->setRange(0.1, 100);
    m_tolerance->setDecimals(1);
    m_tolerance->setSuffix(QStringLiteral("\u00a0%"));
    nameWithUnit(*m_tolerance,
                 QCoreApplication::translate("MeasuredQuestion", "Tolerance of the answer"));
    form->addRow(QCoreApplication::translate("MeasuredQuestion", "Measu&red"), m_kind);
    form->addRow(QCoreApplication::translate("MeasuredQuestion", "&Body"), m_body);
    form->addRow(QCoreApplication::translate("MeasuredQuestion", "&At time"), m_time);
    form->addRow(QCoreApplication::translate("MeasuredQuestion", "&Unit"), m_unit);
    form->addRow(QCoreApplication::translate("MeasuredQuestion", "Toleran&ce"), m_tolerance);
    const auto changed = [this] {
        if (edited)
            edited();
    };
    connect(m_kind, &QComboBox::activated, this, changed);
    connect(m_body, &QComboBox::activated, this, changed);
    connect(m_time, &QDoubleSpinBox::valueChanged, this, changed);
    connect(m_unit, &QLineEdit::textEdited, this, changed);
    connect(m_tolerance, &QDoubleSpinBox::valueChanged, this, changed);
}

void MeasuredPage::showQuestion(const QJsonObject& q, const QJsonObject& scene)
{
    m_scene = scene;
    // The bodies of the step's scene that move, by their labels (the id where there is none),
    // each kept by its id.
    const QJsonObject measure = q.value(jsonKey(keys::kMeasure)).toObject();
    m_body->clear();
    for (const auto& [id, name] : movingBodies(scene))
        m_body->addItem(name, id);
    const QString body = measure.value(u"body").toString();
    if (!body.isEmpty() && m_body->findData(body) < 0)
        m_body->addItem(
            QCoreApplication::translate("MeasuredQuestion", "%1 (not in the scene)").arg(body),
            body);
    m_body->setCurrentIndex(m_body->findData(body));
    const MeasureName& k = measureName(measure.value(u"kind").toString());
    m_kind->setCurrentIndex(m_kind->findData(QLatin1String(k.id)));
    m_body->setEnabled(k.body);
    m_time->setEnabled(k.time);
    m_time->setValue(measure.value(u"time").toDouble());
    showText(m_unit, q.value(jsonKey(keys::kUnit)).toString());
    m_tolerance->setValue(q.value(jsonKey(keys::kTolerance)).toDouble(0.05) * 100.0);
}

void MeasuredPage::applyTo(QJsonObject& q) const
{
    const MeasureName& k = measureName(m_kind->currentData().toString());
    QJsonObject measure{{QStringLiteral("kind"), QLatin1String(k.id)}};
    const QJsonObject old = q.value(jsonKey(keys::kMeasure)).toObject();
    if (k.body && m_body->currentIndex() >= 0)
        measure.insert(QStringLiteral("body"), m_body->currentData().toString());
    if (k.time)
        measure.insert(QStringLiteral("time"), m_time->value());
    else // an apex keeps its bounce and floor
        for (const char* key : {"n", "above"})
            if (old.contains(QLatin1String(key)) && old.value(u"kind").toString() == u"apex")
                measure.insert(QLatin1String(key), old.value(QLatin1String(key)));
    q.insert(jsonKey(keys::kMeasure), measure);
    if (old.value(u"kind").toString() != QLatin1String(k.id) &&
        m_unit->text() == measureName(old.value(u"kind").toString()).unit)
        m_unit->setText(QLatin1String(k.unit)); // the new quantity's unit, unless typed
    q.insert(jsonKey(keys::kUnit), m_unit->text());
    q.insert(jsonKey(keys::kTolerance), m_tolerance->value() / 100.0);
    followMeasure(old, q);
}

void MeasuredPage::followMeasure(const QJsonObject& was, QJsonObject& q) const
{
    // The prompt the editor wrote follows what is measured, until the teacher writes their own.
    const QJsonObject now = q.value(jsonKey(keys::kMeasure)).toObject();
    if (was == now || now.isEmpty())
        return;
    const QString language = currentLanguage();
    const QJsonValue prompt = q.value(jsonKey(keys::kPrompt));
    if (writtenText(prompt, language) !=
        defaultPrompt(was, bodyName(m_scene, was.value(u"body").toString())))
        return;
    q.insert(jsonKey(keys::kPrompt),
             withWrittenText(prompt, language,
                             defaultPrompt(now, bodyName(m_scene, now.value(u"body").toString()))));
}

} // namespace rigidlab::ui
