// SPDX-License-Identifier: GPL-3.0-or-later
// The instruments panel's stopwatch, probe and frame tabs.
#include "instruments/instruments_panel.h"

#include "common/number_format.h"
#include "simulation/run_view.h"
#include "simulation/sample_recorder.h"

#include <QApplication>
#include <QClipboard>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QVBoxLayout>

#include <numbers>

namespace rigidlab::ui {

namespace {

void addTriggers(QComboBox* box, bool start)
{
    box->addItem(start ? InstrumentsPanel::tr("Start button") : InstrumentsPanel::tr("Stop button"),
                 static_cast<int>(instruments::Trigger::Hand));
    box->addItem(InstrumentsPanel::tr("first contact of the body"),
                 static_cast<int>(instruments::Trigger::FirstContact));
    box->addItem(InstrumentsPanel::tr("the body passing the line"),
                 static_cast<int>(instruments::Trigger::PassesLine));
    box->addItem(InstrumentsPanel::tr("the body coming to rest"),
                 static_cast<int>(instruments::Trigger::AtRest));
}

QLabel* readout(QWidget* parent, const QString& accessibleName)
{
    auto* label = new QLabel(parent);
    label->setTextInteractionFlags(Qt::TextSelectableByMouse | Qt::TextSelectableByKeyboard);
    label->setFocusPolicy(Qt::StrongFocus);
    label->setAccessibleName(accessibleName);
    return label;
}

} // namespace

QWidget* InstrumentsPanel::makeStopwatchTab()
{
    auto* tab = new QWidget(this);
    auto* form = new QFormLayout(tab);
    m_watchReading = readout(tab, tr("Time on the stopwatch"));
    QFont f = m_watchReading->font();
    f.setPointSizeF(f.pointSizeF() * 1.6);
    f.setBold(true);
    m_watchReading->setFont(f);
    form->addRow(tr("Time"), m_watchReading);
    m_watchState = readout(tab, tr("Stopwatch state"));
    form->addRow(tr("State"), m_watchState);
    auto* buttons = new QHBoxLayout;
    auto* start = new QPushButton(tr("Start"), tab);
    auto* stop = new QPushButton(tr("Stop"), tab);
    auto* reset = new QPushButton(tr("Reset"), tab);
    for (QPushButton* b : {start, stop, reset})
        buttons->addWidget(b);
    form->addRow(buttons);
    m_startOn = new QComboBox(tab);
    m_stopOn = new QComboBox(tab);
    addTriggers(m_startOn, true);
    addTriggers(m_stopOn, false);
    m_startOn->setAccessibleName(tr("What starts the stopwatch"));
    m_stopOn->setAccessibleName(tr("What stops the stopwatch"));
    form->addRow(tr("Starts on"), m_startOn);
    form->addRow(tr("Stops on"), m_stopOn);
    m_watchBody = new QComboBox(tab);
    m_watchBody->setAccessibleName(tr("Body the stopwatch watches"));
    form->addRow(tr("Body"), m_watchBody);
    m_lineY = new QDoubleSpinBox(tab);
    m_lineY->setRange(-1e4, 1e4);
    m_lineY->setDecimals(3);
    m_lineY->setSingleStep(0.01);
    m_lineY->setSuffix(QStringLiteral("\u00a0m"));
    m_lineY->setAccessibleName(tr("Height of the line"));
    m_lineY->setToolTip(tr("The horizontal line y = h that the body's centre passes"));
    form->addRow(tr("Line at height y"), m_lineY);
    connect(start, &QPushButton::clicked, this, &InstrumentsPanel::startStopwatch);
    connect(stop, &QPushButton::clicked, this, &InstrumentsPanel::stopStopwatch);
    connect(reset, &QPushButton::clicked, this, &InstrumentsPanel::resetStopwatch);
    for (QComboBox* box : {m_startOn, m_stopOn, m_watchBody})
        connect(box, &QComboBox::currentIndexChanged, this, &InstrumentsPanel::triggersChanged);
    connect(m_lineY, &QDoubleSpinBox::valueChanged, this, &InstrumentsPanel::triggersChanged);
    return tab;
}

instruments::TriggerSpec InstrumentsPanel::triggerFrom(QComboBox* kind) const
{
    instruments::TriggerSpec spec;
    spec.kind = static_cast<instruments::Trigger>(kind->currentData().toInt());
    spec.body = std::max(0, m_watchBody->currentIndex());
    spec.lineY = m_lineY->value();
    return spec;
}

void InstrumentsPanel::triggersChanged()
{
    m_stopwatch.setStart(triggerFrom(m_startOn));
    m_stopwatch.setStop(triggerFrom(m_stopOn));
    emit changed();
}

void InstrumentsPanel::setStartTrigger(const instruments::TriggerSpec& spec)
{
    m_watchBody->setCurrentIndex(spec.body);
    m_lineY->setValue(spec.lineY);
    m_startOn->setCurrentIndex(m_startOn->findData(static_cast<int>(spec.kind)));
    triggersChanged();
}

void InstrumentsPanel::setStopTrigger(const instruments::TriggerSpec& spec)
{
    m_watchBody->setCurrentIndex(spec.body);
    m_lineY->setValue(spec.lineY);
    m_stopOn->setCurrentIndex(m_stopOn->findData(static_cast<int>(spec.kind)));
    triggersChanged();
}

void InstrumentsPanel::startStopwatch()
{
    m_stopwatch.press(m_run.world());
    refresh();
}

void InstrumentsPanel::stopStopwatch()
{
    m_stopwatch.halt(m_run.world());
    refresh();
}

void InstrumentsPanel::resetStopwatch()
{
    m_stopwatch.reset();
    refresh();
}

double InstrumentsPanel::stopwatchSeconds() const
{
    return m_stopwatch.reading(m_run.world());
}

QString InstrumentsPanel::stopwatchText() const
{
    // Digits to the step: dt = 0.001 s shows milliseconds.
    const double dt = m_run.world().def().dt;
    const int decimals = std::clamp(static_cast<int>(std::ceil(-std::log10(dt) - 1e-9)), 0, 6);
    return QLocale().toString(stopwatchSeconds(), 'f', decimals) + QStringLiteral("\u00a0s");
}

QString InstrumentsPanel::stopwatchStateText() const
{
    switch (m_stopwatch.state()) {
    case instruments::Stopwatch::State::Idle:
        return tr("ready");
    case instruments::Stopwatch::State::Armed:
        return tr("waiting for the start event");
    case instruments::Stopwatch::State::Running:
        return tr("running");
    case instruments::Stopwatch::State::Stopped:
        return tr("stopped");
    }
    return {};
}

QWidget* InstrumentsPanel::makeProbeTab()
{
    auto* tab = new QWidget(this);
    auto* form = new QFormLayout(tab);
    m_probeBody = new QComboBox(tab);
    m_probeBody->setAccessibleName(tr("Body the probe reads"));
    form->addRow(tr("Body"), m_probeBody);
    m_probeReading = readout(tab, tr("Probe reading"));
    m_probeReading->setWordWrap(true);
    form->addRow(m_probeReading);
    auto* buttons = new QHBoxLayout;
    auto* copy = new QPushButton(tr("Copy"), tab);
    copy->setToolTip(tr("Puts the probe's numbers on the clipboard"));
    auto* plot = new QPushButton(tr("Plot…"), tab);
    plot->setToolTip(tr("A graph of this body's quantities against time"));
    buttons->addWidget(copy);
    buttons->addWidget(plot);
    form->addRow(buttons);
    connect(m_probeBody, &QComboBox::currentIndexChanged, this, &InstrumentsPanel::refresh);
    connect(copy, &QPushButton::clicked, this, &InstrumentsPanel::copyProbe);
    connect(plot, &QPushButton::clicked, this, [this] {
        if (probeBody() >= 0)
            emit plotRequested(probeBody());
    });
    return tab;
}

void InstrumentsPanel::setProbeBody(int id)
{
    m_probeBody->setCurrentIndex(id);
}

int InstrumentsPanel::probeBody() const
{
    return m_probeBody->currentIndex();
}

instruments::ProbeReading InstrumentsPanel::probeReading() const
{
    return instruments::probeBody(m_run.world(), probeBody());
}

QStringList InstrumentsPanel::probeLines() const
{
    const int id = probeBody();
    if (id < 0 || id >= static_cast<int>(m_run.world().bodies().size()))
        return {tr("no body chosen")};
    const instruments::ProbeReading r = probeReading();
    const auto vec = [this](const physics::Vec2& v, const QString& unit) {
        return QStringLiteral("(%1; %2)")
                   .arg(formatReadable(v.x(), 4, 1.0), formatReadable(v.y(), 4, 1.0)) +
               QChar(0x00a0) + unit;
    };
    const double scale = m_run.recorder().energyScale();
    return {
        tr("x = %1").arg(num(r.position.x(), QStringLiteral("m"))),
        tr("y = %1").arg(num(r.position.y(), QStringLiteral("m"))),
        tr("v = %1").arg(vec(r.velocity, QStringLiteral("m/s"))),
        tr("|v| = %1").arg(num(r.speed, QStringLiteral("m/s"))),
        tr("ω = %1").arg(num(r.angularVelocity, QStringLiteral("rad/s"))),
        tr("E_k = %1").arg(formatQuantity(r.kinetic, QStringLiteral("J"), 6, scale)),
        tr("p = %1").arg(vec(r.momentum, QStringLiteral("kg·m/s"))),
        tr("L = %1").arg(num(r.angularMomentum, QStringLiteral("kg·m²/s"))),
        tr("weight = %1").arg(vec(r.weight, QStringLiteral("N"))),
        tr("contact force = %1").arg(vec(r.contactForce, QStringLiteral("N"))),
    };
}

void InstrumentsPanel::copyProbe()
{
    const QString body = m_run.scene().bodyLabel(std::max(0, probeBody()));
    QApplication::clipboard()->setText(
        tr("%1 at t = %2 s").arg(body, QLocale().toString(m_run.time())) + QLatin1Char('\n') +
        probeText());
}

QWidget* InstrumentsPanel::makeFrameTab()
{
    auto* tab = new QWidget(this);
    auto* layout = new QVBoxLayout(tab);
    m_frame = new QComboBox(tab);
    m_frame->addItem(tr("Lab frame"));
    m_frame->addItem(tr("Centre-of-mass frame of the bodies ticked"));
    m_frame->setAccessibleName(tr("Frame of reference"));
    layout->addWidget(m_frame);
    m_frameBodies = new QListWidget(tab);
    m_frameBodies->setAccessibleName(tr("Bodies of the centre-of-mass frame"));
    layout->addWidget(m_frameBodies, 1);
    auto* plot = new QPushButton(tr("Plot momenta in this frame…"), tab);
    layout->addWidget(plot);
    const auto changed = [this] {
        const std::vector<physics::BodyId> ids = frameBodies();
        emit frameChanged(ids);
        emit this->changed();
    };
    connect(m_frame, &QComboBox::currentIndexChanged, this, changed);
    connect(m_frameBodies, &QListWidget::itemChanged, this, changed);
    connect(plot, &QPushButton::clicked, this, [this] {
        std::vector<physics::BodyId> ids;
        for (int i = 0; i < m_frameBodies->count(); ++i)
            if (m_frameBodies->item(i)->checkState() == Qt::Checked)
                ids.push_back(i);
        emit frameMomentumRequested(ids);
    });
    return tab;
}

std::vector<physics::BodyId> InstrumentsPanel::frameBodies() const
{
    std::vector<physics::BodyId> ids;
    if (m_frame->currentIndex() != 1)
        return ids;
    for (int i = 0; i < m_frameBodies->count(); ++i)
        if (m_frameBodies->item(i)->checkState() == Qt::Checked)
            ids.push_back(i);
    return ids;
}

void InstrumentsPanel::setFrameBodies(const std::vector<physics::BodyId>& ids)
{
    const QSignalBlocker block(m_frameBodies);
    for (int i = 0; i < m_frameBodies->count(); ++i)
        m_frameBodies->item(i)->setCheckState(
            std::find(ids.begin(), ids.end(), i) != ids.end() ? Qt::Checked : Qt::Unchecked);
    m_frame->setCurrentIndex(ids.empty() ? 0 : 1);
    emit frameChanged(frameBodies());
    emit changed();
}

void InstrumentsPanel::fillBodyLists()
{
    const auto count = static_cast<int>(m_run.world().bodies().size());
    for (QComboBox* box : {m_protractorBody, m_watchBody, m_probeBody}) {
        const QSignalBlocker block(box);
        box->clear();
        for (int i = 0; i < count; ++i)
            box->addItem(m_run.scene().bodyLabel(i));
    }
    const QSignalBlocker block(m_frameBodies);
    m_frameBodies->clear();
    for (int i = 0; i < count; ++i) {
        auto* item = new QListWidgetItem(m_run.scene().bodyLabel(i), m_frameBodies);
        item->setFlags(item->flags() | Qt::ItemIsUserCheckable);
        item->setCheckState(m_run.world().body(i).isDynamic() ? Qt::Checked : Qt::Unchecked);
    }
    m_frame->setCurrentIndex(0);
    triggersChanged();
}

} // namespace rigidlab::ui
