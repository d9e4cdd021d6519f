// SPDX-License-Identifier: GPL-3.0-or-later
#include "panels/inspector_panel.h"

#include "common/calm_text.h"
#include "common/number_format.h"
#include "common/spoken_numbers.h"
#include "panels/forces_view.h"
#include "panels/number_field.h"
#include "simulation/simulation_controller.h"

#include "format/limits.h"
#include "format/scene_schema.h"

#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rigidlab::ui {

namespace {

// Digits are counted against each quantity's scale, so that its noise reads 0: a body at rest
// moves at 1e-19 m/s, a box lying flat is turned by 4e-7 rad (common/number_format.h).
constexpr int kDigits = 4;
/// [m]: positions to the millimetre.
constexpr double kLengthScale = 1.0;
/// [m/s]: velocities to the millimetre per second.
constexpr double kSpeedScale = 1.0;
/// Half a turn [rad] or [°]: angles to a thousandth of a radian or a tenth of a degree.
constexpr double kAngleScaleRad = std::numbers::pi;
constexpr double kAngleScaleDeg = 180.0;
/// [rad/s]: angular velocities to a thousandth of a radian per second.
constexpr double kTurnRateScaleRad = 1.0;
/// Kinetic energy gets more digits against the scene's energy scale, which may be large.
constexpr int kEnergyDigits = 6;

/// Whether `widget` is the field of the form's `row`, or lies in it.
bool isInRow(const QFormLayout& form, int row, const QWidget& widget)
{
    QLayoutItem* field = form.itemAt(row, QFormLayout::FieldRole);
    if (!field)
        return false;
    if (QWidget* w = field->widget())
        return w == &widget || w->isAncestorOf(&widget);
    if (QLayout* l = field->layout())
        return l->indexOf(&widget) >= 0;
    return false;
}

QString num(double v, double scale = 0)
{
    return formatReadable(v, kDigits, scale);
}

} // namespace

InspectorPanel::InspectorPanel(SimulationController& controller, QWidget* parent)
    : QWidget(parent), m_controller(controller), m_none(new QLabel(tr("No body selected"), this)),
      m_name(new QLabel(this)), m_mass(new QLabel(this)), m_massEdit(new NumberField(this)),
      m_massUnit(new QLabel(tr("kg"), this)), m_inertia(new QLabel(this)),
      m_position(new QLabel(this)), m_angle(new QLabel(this)), m_velocity(new QLabel(this)),
      m_speed(new QLabel(this)), m_omega(new QLabel(this)), m_angleUnit(new QComboBox(this)),
      m_energy(new QLabel(this)), m_restitution(new NumberField(this)),
      m_friction(new NumberField(this))
{
    // The mass: a field with its unit for a dynamic body, "infinite" for the others.
    auto* massRow = new QHBoxLayout;
    massRow->setContentsMargins(0, 0, 0, 0);
    massRow->addWidget(m_massEdit, 1);
    massRow->addWidget(m_massUnit);
    m_massUnit->setObjectName(QStringLiteral("massUnit"));
    massRow->addWidget(m_mass, 1);
    m_massEdit->setObjectName(QStringLiteral("mass"));
    m_massEdit->setRange(lessons::limits::kMass, tr("Mass m"));
    m_massEdit->setToolTip(tr("The body's mass; its moment of inertia scales with it"));
    m_massEdit->setUnitBeside(true);
    // The editable rows are the scene schema's (lessons/format/scene_schema.h): its label and
    // range, so that the inspector and the editor say the same.
    namespace schema = lessons::schema;
    const schema::Field& restitution = *schema::findField(schema::Object::Body, "restitution");
    const schema::Field& friction = *schema::findField(schema::Object::Body, "friction");
    m_restitution->setObjectName(QStringLiteral("bodyRestitution"));
    m_restitution->setRange(restitution.range, schema::label(restitution));
    m_friction->setObjectName(QStringLiteral("bodyFriction"));
    m_friction->setRange(friction.range, schema::label(friction));

    // Reached by Tab and read aloud: a reader says once that no body is chosen, and how to.
    m_none->setObjectName(QStringLiteral("noBody"));
    m_none->setFocusPolicy(Qt::TabFocus);
    m_none->setWordWrap(true);
    m_none->setAccessibleDescription(tr("Click a body in the scene, or select one there with ]"));
    auto* form = new QFormLayout(this);
    m_form = form;
    form->setRowWrapPolicy(QFormLayout::WrapLongRows); // labels above fields when narrow
    form->addRow(m_none);
    form->addRow(tr("Body"), m_name);
    form->addRow(tr("Mass m"), massRow);
    form->addRow(tr("Inertia I"), m_inertia);
    form->addRow(tr("Position"), m_position);
    form->addRow(tr("Angle θ"), m_angle);
    form->addRow(tr("Velocity v"), m_velocity);
    form->addRow(tr("Speed |v|"), m_speed);
    form->addRow(tr("Angular vel. ω"), m_omega);
    form->addRow(tr("Kinetic energy"), m_energy);
    form->addRow(angleUnitList());
    form->addRow(schema::label(restitution), m_restitution);
    form->addRow(schema::label(friction), m_friction);
    m_graph = new QPushButton(tr("Graph…"), this);
    m_graph->setObjectName(QStringLiteral("inspectorGraph"));
    m_graph->setToolTip(tr("A graph of this body's quantities against time"));
    connect(m_graph, &QPushButton::clicked, this, [this] {
        if (m_body >= 0)
            emit graphRequested(m_body);
    });
    labelRows(*form);
    form->addRow(m_graph);
    m_forces = new ForcesView(this);
    form->addRow(m_forces);
    for (QLabel* l :
         {m_name, m_mass, m_inertia, m_position, m_angle, m_velocity, m_speed, m_omega, m_energy}) {
        l->setTextInteractionFlags(Qt::TextSelectableByMouse);
        l->setWordWrap(true); // at its spaces, beside its label in a narrow column
    }
    connectEdits();
    connect(&m_controller, &SimulationController::worldChanged, this, &InspectorPanel::refresh);
    connect(&m_controller, &SimulationController::sceneLoaded, this, [this] {
        // The bodies are new: what was typed for the old one goes.
        for (NumberField* f : {m_massEdit, m_restitution, m_friction})
            f->revert();
        setBody(-1);
    });
    setBody(-1);
}

void InspectorPanel::connectEdits()
{
    // Each field sends only its own value: the other keeps the body's, not a stale text.
    connect(m_restitution, &NumberField::valueEdited, this, [this](double e) {
        if (m_body >= 0)
            m_controller.setBodyMaterial(m_body, e, m_controller.world().body(m_body).friction);
    });
    connect(m_friction, &NumberField::valueEdited, this, [this](double mu) {
        if (m_body >= 0)
            m_controller.setBodyMaterial(m_body, m_controller.world().body(m_body).restitution, mu);
    });
    connect(m_massEdit, &NumberField::valueEdited, this, [this](double m) {
        if (m_body >= 0)
            m_controller.setBodyMass(m_body, m);
    });
    for (NumberField* f : {m_massEdit, m_restitution, m_friction})
        connect(f, &NumberField::refused, this, &InspectorPanel::inputRefused);
}

void InspectorPanel::setBody(int id)
{
    const int count = static_cast<int>(m_controller.world().bodies().size());
    id = id >= 0 && id < count ? id : -1;
    // A value typed for the body shown goes to that body before another is shown.
    if (id != m_body && m_body >= 0 && m_body < count)
        for (NumberField* f : {m_massEdit, m_restitution, m_friction})
            if (f->isModified())
                f->commit();
    for (NumberField* f : {m_massEdit, m_restitution, m_friction})
        if (id != m_body)
            f->revert();
    m_body = id;
    // Filled in even out of sight: a choice of the student's, not a frame (the rows and their
    // names are there for whatever reads them, and the frames skip them until shown).
    m_shown = shownNow();
    fill();
}

InspectorPanel::Shown InspectorPanel::shownNow() const
{
    Shown now;
    now.body = m_body;
    now.step = m_controller.world().stepCount();
    now.degrees = anglesInDegrees();
    now.running = m_controller.isRunning();
    if (m_body >= 0) {
        const physics::Body& b = m_controller.world().body(m_body);
        now.numbers = {b.position.x(),
                       b.position.y(),
                       b.angle,
                       b.velocity.x(),
                       b.velocity.y(),
                       b.angularVelocity,
                       b.mass,
                       b.inertia,
                       b.restitution,
                       b.friction,
                       static_cast<double>(b.type)};
    }
    return now;
}

void InspectorPanel::refresh()
{
    // Out of sight in a window on screen: filled in when shown (a panel of its own, or in a
    // window not shown, as tests make them, is filled in at once).
    if (window()->isVisible() && !isVisible()) {
        m_shown.reset();
        return;
    }
    // A running clock's frame that took no step and left the body as it was changes nothing
    // here (a stopped clock's changes are the student's: a setting, a body's material).
    const Shown now = shownNow();
    if (now.running && m_shown == now)
        return;
    m_shown = now;
    fill();
}

void InspectorPanel::showEvent(QShowEvent* event)
{
    QWidget::showEvent(event);
    if (!m_shown)
        refresh();
}

void InspectorPanel::fill()
{
    ++m_fills;
    const bool has = m_body >= 0;
    showRows(has);
    if (!has) {
        m_forces->showNone();
        return;
    }
    const physics::Body& b = m_controller.world().body(m_body);
    m_name->setText(QStringLiteral("%1 (%2)").arg(m_controller.scene().bodyLabel(m_body),
                                                  lessons::schema::bodyTypeLabel(b.type)));
    m_massEdit->setVisible(b.isDynamic());
    m_massUnit->setVisible(b.isDynamic());
    m_mass->setVisible(!b.isDynamic());
    m_massEdit->setEnabled(b.isDynamic());
    if (b.isDynamic()) {
        m_massEdit->setValue(b.mass);
        m_mass->setText(tr("%1 kg").arg(num(b.mass)));
        m_inertia->setText(tr("%1 kg·m²").arg(num(b.inertia)));
    } else {
        m_mass->setText(tr("infinite"));
        m_inertia->setText(tr("infinite"));
    }
    const physics::Vec2 o = b.origin();
    const physics::Vec2 v = m_controller.world().originVelocity(m_body);
    m_position->setText(tr("(%1, %2) m").arg(num(o.x(), kLengthScale), num(o.y(), kLengthScale)));
    m_velocity->setText(tr("(%1, %2) m/s").arg(num(v.x(), kSpeedScale), num(v.y(), kSpeedScale)));
    m_speed->setText(tr("%1 m/s").arg(num(v.norm(), kSpeedScale)));
    if (anglesInDegrees()) {
        constexpr double kDeg = 180.0 / std::numbers::pi;
        m_angle->setText(tr("%1°").arg(num(b.angle * kDeg, kAngleScaleDeg)));
        m_omega->setText(tr("%1 °/s").arg(num(b.angularVelocity * kDeg, kTurnRateScaleRad * kDeg)));
    } else {
        m_angle->setText(tr("%1 rad").arg(num(b.angle, kAngleScaleRad)));
        m_omega->setText(tr("%1 rad/s").arg(num(b.angularVelocity, kTurnRateScaleRad)));
    }
    const double ke = b.isDynamic() ? 0.5 * b.mass * b.velocity.squaredNorm() +
                                          0.5 * b.inertia * b.angularVelocity * b.angularVelocity
                                    : 0.0;
    m_energy->setText(formatQuantity(ke, QStringLiteral("J"), kEnergyDigits,
                                     m_controller.recorder().energyScale()));
    m_forces->showBody(m_controller.world(), m_body);
    m_restitution->setValue(b.restitution);
    m_friction->setValue(b.friction);
    nameValues();
}

void InspectorPanel::resizeEvent(QResizeEvent* event)
{
    QWidget::resizeEvent(event);
    fitLabels();
}

void InspectorPanel::fitLabels()
{
    // Half of the width for the labels: "Moment setrvačnosti I" on two lines, its value
    // beside it. At least a short word's width, so that a label never breaks inside a word.
    const QMargins margins = m_form->contentsMargins();
    const int width = contentsRect().width() - margins.left() - margins.right();
    const int labels =
        std::max(fontMetrics().averageCharWidth() * 10,
                 static_cast<int>(0.5 * (width - std::max(0, m_form->horizontalSpacing()))));
    for (int row = 0; row < m_form->rowCount(); ++row) {
        QLayoutItem* item = m_form->itemAt(row, QFormLayout::LabelRole);
        auto* label = item ? qobject_cast<QLabel*>(item->widget()) : nullptr;
        if (!label)
            continue;
        // Only a label longer than that wraps: a short one wrapped too ("Mass" over "m") was
        // cut, its row no taller than its value.
        const bool wrap = label->fontMetrics().horizontalAdvance(label->text()) > labels;
        label->setWordWrap(wrap);
        // A wrapped label is as wide as that and as tall as its lines there: squeezed, the form
        // gave it its longest word's width and one line's height ("Velikost rychlosti" in
        // sight, "|v|" on a third line cut).
        const QSize most(wrap ? labels : QWIDGETSIZE_MAX, QWIDGETSIZE_MAX);
        const QSize least = wrap ? QSize(labels, label->heightForWidth(labels)) : QSize(0, 0);
        if (label->maximumSize() != most)
            label->setMaximumSize(most);
        if (label->minimumSize() != least)
            label->setMinimumSize(least);
    }
    // The rows' heights follow the labels' new wrap (the form keeps those it measured before).
    m_form->invalidate();
}

void InspectorPanel::labelRows(QFormLayout& form)
{
    const QList<QLabel*> values{m_name,     m_mass,  m_inertia, m_position, m_angle,
                                m_velocity, m_speed, m_omega,   m_energy};
    for (int row = 0; row < form.rowCount(); ++row) {
        QLayoutItem* labelItem = form.itemAt(row, QFormLayout::LabelRole);
        auto* label = labelItem ? qobject_cast<QLabel*>(labelItem->widget()) : nullptr;
        if (!label)
            continue;
        for (QLabel* value : values) {
            if (!isInRow(form, row, *value))
                continue;
            m_rowNames.append({value, label->text()});
            // QFormLayout gives no buddy to a row that is a layout (the mass: its field, or
            // "infinite").
            label->setBuddy(value == m_mass ? static_cast<QWidget*>(m_massEdit) : value);
        }
    }
}

void InspectorPanel::nameValues()
{
    // At a calm rate while the clock runs (the values change with every frame), at once for
    // what the student did; a negative value says "minus", which a reader never drops.
    const bool now = !m_controller.isRunning();
    for (const auto& [value, row] : std::as_const(m_rowNames))
        setCalmAccessibleName(
            *value, tr("%1: %2", "a value named by its row").arg(row, spokenSigns(value->text())),
            now);
}

void InspectorPanel::showRows(bool body)
{
    // Only when it changes: a row set visible shows every widget in it, the mass row's
    // "infinite" too, which fill() then hides for a dynamic body (shown and hidden at every
    // frame of a run, 110 times a second to a screen reader).
    if (m_rowsFor == body)
        return;
    m_rowsFor = body;
    // Rows of dashes read as "Angle θ: –" one by one; the values' rows and the controls with
    // nothing to edit, graph or turn into other units go, and one line says why.
    m_form->setRowVisible(0, !body);
    for (int row = 1; row < m_form->rowCount(); ++row)
        m_form->setRowVisible(row, body);
}

QWidget* InspectorPanel::angleUnitList()
{
    // Degrees first: the unit of a school's protractor. Radians for the formulas.
    m_angleUnit->addItem(tr("°", "angle unit: degrees"));
    m_angleUnit->addItem(tr("rad", "angle unit: radians"));
    m_angleUnit->setItemData(0, tr("degrees"), Qt::ToolTipRole);
    m_angleUnit->setItemData(1, tr("radians"), Qt::ToolTipRole);
    m_angleUnit->setObjectName(QStringLiteral("angleUnit"));
    m_angleUnit->setAccessibleName(tr("Unit of angles"));
    m_angleUnit->setToolTip(tr("Angles and angular velocities in degrees or in radians"));
    m_angleUnit->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    connect(m_angleUnit, &QComboBox::currentIndexChanged, this, &InspectorPanel::refresh);
    // Across the form's width, its label beside it: in the field column, under the long
    // labels of a narrow projector column, the list went below its label too.
    auto* row = new QWidget(this);
    auto* layout = new QHBoxLayout(row);
    layout->setContentsMargins(0, 0, 0, 0);
    auto* label = new QLabel(m_angleUnit->accessibleName(), row);
    label->setBuddy(m_angleUnit);
    // At its space when the column is narrow ("Jednotka úhlů" beside an eight-letter list
    // was wider than a projector's side column, which then scrolled sideways).
    label->setWordWrap(true);
    layout->addWidget(label);
    layout->addWidget(m_angleUnit);
    layout->addStretch(1);
    return row;
}

bool InspectorPanel::anglesInDegrees() const
{
    return m_angleUnit->currentIndex() != 1;
}

void InspectorPanel::setAnglesInDegrees(bool degrees)
{
    m_angleUnit->setCurrentIndex(degrees ? 0 : 1);
}

QString InspectorPanel::text() const
{
    // Out of sight the rows wait to be filled in (refresh); what the panel says is the world's
    // as it is now all the same (a copy, a test, a worksheet read it hidden too).
    if (!m_shown) {
        auto& self = const_cast<InspectorPanel&>(*this);
        self.m_shown = shownNow();
        self.fill();
    }
    if (m_body < 0)
        return m_none->text();
    QStringList parts;
    for (QLabel* l :
         {m_name, m_mass, m_inertia, m_position, m_angle, m_velocity, m_speed, m_omega, m_energy})
        parts << l->text();
    return parts.join(QLatin1Char('\n'));
}

} // namespace rigidlab::ui
