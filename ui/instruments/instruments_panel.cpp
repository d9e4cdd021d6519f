// SPDX-License-Identifier: GPL-3.0-or-later
#include "instruments/instruments_panel.h"

#include "common/number_format.h"
#include "simulation/run_view.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QTabWidget>
#include <QVBoxLayout>

#include <cmath>

namespace rigidlab::ui {

namespace {

/// A coordinate field: typed, or nudged by a centimetre with the arrow keys [m].
QDoubleSpinBox* coordinateField(QWidget* parent, const QString& accessibleName)
{
    auto* field = new QDoubleSpinBox(parent);
    field->setRange(-1e4, 1e4);
    field->setDecimals(3);
    field->setSingleStep(0.01);
    field->setSuffix(QStringLiteral("\u00a0m"));
    field->setAccessibleName(accessibleName);
    field->setToolTip(accessibleName);
    field->setKeyboardTracking(false); // a value typed counts when it is complete
    return field;
}

/// A reading: large, selectable, and what a screen reader reads.
QLabel* readingLabel(QWidget* parent, const QString& accessibleName)
{
    auto* label = new QLabel(parent);
    label->setTextInteractionFlags(Qt::TextSelectableByMouse | Qt::TextSelectableByKeyboard);
    label->setFocusPolicy(Qt::StrongFocus); // reached by Tab, read aloud
    label->setAccessibleName(accessibleName);
    QFont f = label->font();
    f.setPointSizeF(f.pointSizeF() * 1.3);
    f.setBold(true);
    label->setFont(f);
    return label;
}

/// A row "x [field] y [field]" for one point.
QWidget* pointRow(QWidget* parent, QDoubleSpinBox* x, QDoubleSpinBox* y)
{
    auto* row = new QWidget(parent);
    auto* layout = new QHBoxLayout(row);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(new QLabel(QStringLiteral("x"), row));
    layout->addWidget(x, 1);
    layout->addWidget(new QLabel(QStringLiteral("y"), row));
    layout->addWidget(y, 1);
    return row;
}

} // namespace

InstrumentsPanel::InstrumentsPanel(const RunView& run, QWidget* parent)
    : QWidget(parent), m_run(run), m_tabs(new QTabWidget(this))
{
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_tabs);
    m_tabs->addTab(makeRulerTab(), tr("Ruler"));
    m_tabs->addTab(makeProtractorTab(), tr("Protractor"));
    m_tabs->addTab(makeStopwatchTab(), tr("Stopwatch"));
    m_tabs->addTab(makeProbeTab(), tr("Probe"));
    m_tabs->addTab(makeFrameTab(), tr("Frame"));
    m_tabs->setAccessibleName(tr("Instruments"));
    connect(m_tabs, &QTabWidget::currentChanged, this, &InstrumentsPanel::refresh);
    connect(&m_run, &RunView::sceneLoaded, this, [this] {
        m_stopwatch.reset();
        fillBodyLists();
        refresh();
    });
    connect(&m_run, &RunView::worldChanged, this, [this] {
        m_stopwatch.observe(m_run.world());
        refresh();
    });
    fillBodyLists();
    showPoints();
    refresh();
}

QString InstrumentsPanel::num(double v, const QString& unit, double scale) const
{
    return formatQuantity(v, unit, 4, scale);
}

QWidget* InstrumentsPanel::makeRulerTab()
{
    auto* tab = new QWidget(this);
    auto* form = new QFormLayout(tab);
    m_rulerFields[0] = coordinateField(tab, tr("Ruler start x"));
    m_rulerFields[1] = coordinateField(tab, tr("Ruler start y"));
    m_rulerFields[2] = coordinateField(tab, tr("Ruler end x"));
    m_rulerFields[3] = coordinateField(tab, tr("Ruler end y"));
    form->addRow(tr("Start"), pointRow(tab, m_rulerFields[0], m_rulerFields[1]));
    form->addRow(tr("End"), pointRow(tab, m_rulerFields[2], m_rulerFields[3]));
    m_snap = new QCheckBox(tr("Snap to centres and corners"), tab);
    m_snap->setChecked(true);
    m_snap->setToolTip(tr("An end near a body's centre of mass or corner goes exactly there"));
    form->addRow(m_snap);
    m_rulerReading = readingLabel(tab, tr("Length measured by the ruler"));
    form->addRow(tr("Length"), m_rulerReading);
    auto* hint = new QLabel(tr("Drag on the scene with Shift held to lay the ruler; drag its "
                               "ends to move them."),
                            tab);
    hint->setWordWrap(true);
    form->addRow(hint);
    for (QDoubleSpinBox* f : m_rulerFields)
        connect(f, &QDoubleSpinBox::valueChanged, this, &InstrumentsPanel::pointsTyped);
    return tab;
}

QWidget* InstrumentsPanel::makeProtractorTab()
{
    auto* tab = new QWidget(this);
    auto* form = new QFormLayout(tab);
    m_protractorMode = new QComboBox(tab);
    m_protractorMode->addItem(tr("Angle of a body"));
    m_protractorMode->addItem(tr("Angle between two lines"));
    m_protractorMode->setAccessibleName(tr("What the protractor measures"));
    form->addRow(tr("Measure"), m_protractorMode);
    m_protractorBody = new QComboBox(tab);
    m_protractorBody->setAccessibleName(tr("Body the protractor measures"));
    form->addRow(tr("Body"), m_protractorBody);
    const QString names[6] = {tr("Vertex x"),
                              tr("Vertex y"),
                              tr("First line through x"),
                              tr("First line through y"),
                              tr("Second line through x"),
                              tr("Second line through y")};
    for (int i = 0; i < 6; ++i)
        m_angleFields[i] = coordinateField(tab, names[i]);
    form->addRow(tr("Vertex"), pointRow(tab, m_angleFields[0], m_angleFields[1]));
    form->addRow(tr("First line"), pointRow(tab, m_angleFields[2], m_angleFields[3]));
    form->addRow(tr("Second line"), pointRow(tab, m_angleFields[4], m_angleFields[5]));
    m_protractorReading = readingLabel(tab, tr("Angle measured by the protractor"));
    form->addRow(tr("Angle"), m_protractorReading);
    for (QDoubleSpinBox* f : m_angleFields)
        connect(f, &QDoubleSpinBox::valueChanged, this, &InstrumentsPanel::pointsTyped);
    connect(m_protractorMode, &QComboBox::currentIndexChanged, this, [this] {
        const bool lines = protractorMode() == ProtractorMode::Lines;
        m_protractorBody->setEnabled(!lines);
        for (QDoubleSpinBox* f : m_angleFields)
            f->setEnabled(lines);
        refresh();
    });
    connect(m_protractorBody, &QComboBox::currentIndexChanged, this, &InstrumentsPanel::refresh);
    m_protractorMode->setCurrentIndex(1);
    m_protractorMode->setCurrentIndex(0);
    return tab;
}

void InstrumentsPanel::setSnapping(bool on)
{
    m_snap->setChecked(on);
}

bool InstrumentsPanel::snapping() const
{
    return m_snap->isChecked();
}

void InstrumentsPanel::setRuler(const physics::Vec2& a, const physics::Vec2& b)
{
    const physics::World& w = m_run.world();
    m_rulerA = snapping() ? instruments::snapPoint(w, a, m_snapRadius).point : a;
    m_rulerB = snapping() ? instruments::snapPoint(w, b, m_snapRadius).point : b;
    showPoints();
    refresh();
}

QString InstrumentsPanel::rulerText() const
{
    return num(rulerLength(), QStringLiteral("m"));
}

void InstrumentsPanel::setProtractorMode(ProtractorMode mode)
{
    m_protractorMode->setCurrentIndex(mode == ProtractorMode::Lines ? 1 : 0);
}

InstrumentsPanel::ProtractorMode InstrumentsPanel::protractorMode() const
{
    return m_protractorMode->currentIndex() == 1 ? ProtractorMode::Lines : ProtractorMode::Body;
}

void InstrumentsPanel::setProtractorBody(int id)
{
    m_protractorBody->setCurrentIndex(id);
}

int InstrumentsPanel::protractorBody() const
{
    return m_protractorBody->currentIndex();
}

void InstrumentsPanel::setProtractorLines(const physics::Vec2& vertex, const physics::Vec2& a,
                                          const physics::Vec2& b)
{
    const physics::World& w = m_run.world();
    const auto snap = [&](const physics::Vec2& p) {
        return snapping() ? instruments::snapPoint(w, p, m_snapRadius).point : p;
    };
    m_vertex = snap(vertex);
    m_armA = snap(a);
    m_armB = snap(b);
    showPoints();
    refresh();
}

double InstrumentsPanel::protractorDegrees() const
{
    if (protractorMode() == ProtractorMode::Lines)
        return instruments::angleBetweenDegrees(m_vertex, m_armA, m_armB);
    const int id = protractorBody();
    const physics::World& w = m_run.world();
    if (id < 0 || id >= static_cast<int>(w.bodies().size()))
        return std::nan("");
    return instruments::bodyAngleDegrees(w.body(id));
}

QString InstrumentsPanel::protractorText() const
{
    return formatReadable(protractorDegrees(), 4, 180.0) + QStringLiteral("°");
}

void InstrumentsPanel::showPoints()
{
    // Setting a field must not send it back as typed (it would snap the other points).
    m_showing = true;
    const physics::Vec2 ruler[2] = {m_rulerA, m_rulerB};
    for (int i = 0; i < 4; ++i)
        m_rulerFields[i]->setValue(ruler[i / 2][i % 2]);
    const physics::Vec2 angle[3] = {m_vertex, m_armA, m_armB};
    for (int i = 0; i < 6; ++i)
        m_angleFields[i]->setValue(angle[i / 2][i % 2]);
    m_showing = false;
}

void InstrumentsPanel::pointsTyped()
{
    if (m_showing)
        return;
    const auto at = [](QDoubleSpinBox* const* f, int i) {
        return physics::Vec2(f[2 * i]->value(), f[2 * i + 1]->value());
    };
    // A typed point is where the student put it: snapping is for the hand's imprecision.
    m_rulerA = at(m_rulerFields, 0);
    m_rulerB = at(m_rulerFields, 1);
    m_vertex = at(m_angleFields, 0);
    m_armA = at(m_angleFields, 1);
    m_armB = at(m_angleFields, 2);
    refresh();
}

void InstrumentsPanel::refresh()
{
    // Only what is in sight is read: a hidden panel (its dock closed or behind another's tab)
    // reads nothing, the open tab only its own readings (the probe walks all of the world's
    // contacts, every frame of a running world). Each is read when it comes into sight
    // (showEvent, the tabs' currentChanged).
    if (!m_frame || !isVisible()) // the tabs are still being made, or nothing shows
        return;
    const auto read = [](QLabel* label, const auto& text) {
        if (label->isVisible())
            label->setText(text());
    };
    read(m_rulerReading, [this] { return rulerText(); });
    read(m_protractorReading, [this] { return protractorText(); });
    read(m_watchReading, [this] { return stopwatchText(); });
    read(m_watchState, [this] { return stopwatchStateText(); });
    read(m_probeReading, [this] { return probeText(); });
    emit changed();
}

void InstrumentsPanel::showEvent(QShowEvent* event)
{
    QWidget::showEvent(event);
    refresh();
}

} // namespace rigidlab::ui
