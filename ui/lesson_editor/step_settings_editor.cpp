// SPDX-License-Identifier: GPL-3.0-or-later
#include "lesson_editor/step_settings_editor.h"
#include "lesson_editor/lesson_draft.h"

#include "common/accessible_names.h"
#include "common/step_part_names.h"
#include "plots/plot_table.h"

#include "format/lesson.h"
#include "format/lesson_schema.h"
#include "format/scene_schema.h"

#include <QCheckBox>
#include <QCoreApplication>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QJsonArray>
#include <QLabel>
#include <QVBoxLayout>

namespace rigidlab::ui {

namespace {

QString qs(std::string_view s)
{
    return QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size()));
}

/// The step's plots or panels in words, as the window titles them (one table for both).
template <std::size_t N>
std::vector<std::pair<std::string_view, QString>>
partNames(const std::array<StepPartName, N>& table)
{
    std::vector<std::pair<std::string_view, QString>> out;
    for (const StepPartName& part : table)
        out.emplace_back(part.name, stepPartText(part.title));
    return out;
}

/// The step's plots in words, as the window titles them (their rows, plot_table.h).
std::vector<std::pair<std::string_view, QString>> plotNames()
{
    std::vector<std::pair<std::string_view, QString>> out;
    for (const PlotRow& plot : kPlotRows)
        out.emplace_back(plot.name, plotTitle(plot));
    return out;
}

/// The settings a step may allow, named by the schema's own labels.
std::vector<std::pair<std::string_view, QString>> controlNames()
{
    std::vector<std::pair<std::string_view, QString>> out;
    for (const lessons::schema::Field& f : lessons::schema::settings()) {
        const QString label =
            f.label ? QCoreApplication::translate(lessons::schema::kContext, f.label) : qs(f.key);
        out.emplace_back(f.key, label);
    }
    return out;
}

} // namespace

StepSettingsEditor::StepSettingsEditor(LessonDraft& draft, QWidget* parent)
    : QWidget(parent), m_draft(draft)
{
    setObjectName(QStringLiteral("stepSettings"));
    setAccessibleName(tr("What the step shows and lets the student change"));
    auto* layout = new QVBoxLayout(this);
    auto* row = new QHBoxLayout;
    row->addWidget(group(tr("Plots shown"), QStringLiteral("plots"), plotNames()));
    row->addWidget(
        group(tr("Panels shown"), QStringLiteral("panels"), partNames(kStepPanelTitles)));
    row->addWidget(group(tr("The student may change (unticked: locked)"), QStringLiteral("allow"),
                         controlNames()));
    layout->addLayout(row);
    auto* form = new QFormLayout;
    m_exportTime = new QDoubleSpinBox(this);
    m_exportTime->setObjectName(QStringLiteral("stepExportTime"));
    const lessons::schema::StepField& exportRow = *lessons::schema::findStepField("exportTime");
    m_exportTime->setRange(0.1, exportRow.value.range.max);
    m_exportTime->setDecimals(2);
    m_exportTime->setSuffix(QStringLiteral("\u00a0s"));
    nameWithUnit(*m_exportTime, tr("Plots exported at"));
    m_exportTime->setAccessibleDescription(
        tr("The simulated time at which the step's plots are exported, 0.1 to 600 s"));
    auto* label = new QLabel(
        QCoreApplication::translate(lessons::schema::kContext, exportRow.value.label), this);
    label->setBuddy(m_exportTime);
    form->addRow(label, m_exportTime);
    connect(m_exportTime, &QDoubleSpinBox::editingFinished, this, [this] {
        if (m_refreshing || m_step < 0)
            return;
        const QJsonValue now = m_draft.value(m_step, QStringLiteral("exportTime"));
        if (now.isDouble() && now.toDouble() == m_exportTime->value())
            return;
        m_draft.setValue(m_step, QStringLiteral("exportTime"), m_exportTime->value(),
                         tr("export time"));
    });
    m_endTime = new QDoubleSpinBox(this);
    m_endTime->setObjectName(QStringLiteral("stepEndTime"));
    m_endTime->setRange(0, lessons::schema::findStepField("endTime")->value.range.max);
    m_endTime->setDecimals(2);
    m_endTime->setSuffix(QStringLiteral("\u00a0s"));
    m_endTime->setSpecialValueText(tr("runs on"));
    nameWithUnit(*m_endTime, tr("The run stops at"));
    m_endTime->setAccessibleDescription(
        tr("The simulated time at which the step's run stops, so that nothing runs off the "
           "stage; 0: it runs on"));
    auto* endLabel = new QLabel(tr("The run st&ops at"), this);
    endLabel->setBuddy(m_endTime);
    form->addRow(endLabel, m_endTime);
    connect(m_endTime, &QDoubleSpinBox::editingFinished, this, [this] {
        if (m_refreshing || m_step < 0)
            return;
        const double t = m_endTime->value();
        const QJsonValue value = t > 0 ? QJsonValue(t) : QJsonValue();
        if (value == m_draft.value(m_step, QStringLiteral("endTime")))
            return;
        m_draft.setValue(m_step, QStringLiteral("endTime"), value, tr("end of the run"));
    });
    m_waitForPlay = new QCheckBox(tr("Wait for &Play: the step opens paused, so that the class "
                                     "reads and predicts first"),
                                  this);
    m_waitForPlay->setObjectName(QStringLiteral("stepWaitForPlay"));
    connect(m_waitForPlay, &QCheckBox::toggled, this, [this](bool wait) {
        if (m_refreshing || m_step < 0)
            return;
        // Written either way: a step without the key starts at once, as the format's default.
        if (m_draft.value(m_step, QStringLiteral("autoplay")) == QJsonValue(!wait))
            return;
        m_draft.setValue(m_step, QStringLiteral("autoplay"), !wait, tr("wait for Play"));
    });
    form->addRow(m_waitForPlay);
    layout->addLayout(form);
    layout->addStretch(1);
    setStep(-1);
}

QGroupBox* StepSettingsEditor::group(const QString& title, const QString& key,
                                     const std::vector<std::pair<std::string_view, QString>>& names)
{
    auto* box = new QGroupBox(title, this);
    box->setAccessibleName(title);
    auto* column = new QVBoxLayout(box);
    for (const auto& [name, words] : names) {
        auto* tick = new QCheckBox(words, box);
        tick->setObjectName(key + u'_' + qs(name));
        tick->setAccessibleName(title + QStringLiteral(": ") + words);
        connect(tick, &QCheckBox::toggled, this, [this, key] { ticked(key); });
        column->addWidget(tick);
        m_rows.push_back({key, qs(name), tick});
    }
    column->addStretch(1);
    return box;
}

QCheckBox* StepSettingsEditor::box(const QString& key, const QString& name) const
{
    for (const Row& r : m_rows)
        if (r.key == key && r.name == name)
            return r.box;
    return nullptr;
}

void StepSettingsEditor::setStep(int step)
{
    m_step = step;
    refresh();
}

void StepSettingsEditor::refresh()
{
    const bool was = m_refreshing;
    m_refreshing = true;
    const bool on = m_step >= 0 && m_step < m_draft.stepCount();
    for (const Row& r : m_rows) {
        const QJsonValue v = on ? m_draft.value(m_step, r.key) : QJsonValue();
        // Plots and panels: only those named are shown. Controls: all may change unless the
        // step names those that may.
        const bool ticked = v.isArray() ? v.toArray().contains(QJsonValue(r.name))
                                        : (r.key == QStringLiteral("allow"));
        r.box->setChecked(on && ticked);
        r.box->setEnabled(on);
    }
    const QJsonValue t = on ? m_draft.value(m_step, QStringLiteral("exportTime")) : QJsonValue();
    m_exportTime->setValue(t.isDouble() ? t.toDouble() : lessons::LessonStep{}.exportTime);
    m_exportTime->setEnabled(on);
    const QJsonValue end = on ? m_draft.value(m_step, QStringLiteral("endTime")) : QJsonValue();
    m_endTime->setValue(end.isDouble() ? end.toDouble() : 0.0);
    m_endTime->setEnabled(on);
    const QJsonValue autoplay =
        on ? m_draft.value(m_step, QStringLiteral("autoplay")) : QJsonValue();
    m_waitForPlay->setChecked(on && !autoplay.toBool(lessons::LessonStep{}.autoplay));
    m_waitForPlay->setEnabled(on);
    m_refreshing = was;
}

void StepSettingsEditor::ticked(const QString& key)
{
    if (m_refreshing || m_step < 0)
        return;
    QJsonArray names;
    bool all = true;
    for (const Row& r : m_rows) {
        if (r.key != key)
            continue;
        if (r.box->isChecked())
            names.append(r.name);
        else
            all = false;
    }
    // Every control allowed is what a step without "allow" means: the file stays as it was.
    const QJsonValue value = (key == QStringLiteral("allow") && all) ||
                                     (key != QStringLiteral("allow") && names.isEmpty())
                                 ? QJsonValue()
                                 : QJsonValue(names);
    if (value == m_draft.value(m_step, key))
        return;
    const QString name = key == QStringLiteral("allow")   ? tr("what the student may change")
                         : key == QStringLiteral("plots") ? tr("plots shown")
                                                          : tr("panels shown");
    m_draft.setValue(m_step, key, value, name);
}

} // namespace rigidlab::ui
