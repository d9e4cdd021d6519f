// SPDX-License-Identifier: GPL-3.0-or-later
#include "panels/control_panel.h"

#include "common/accessible_names.h"
#include "common/display_names.h"
#include "panels/number_field.h"
#include "simulation/simulation_controller.h"

#include "format/limits.h"
#include "format/scene_loader.h"
#include "format/scene_schema.h"

#include <QCheckBox>
#include <QComboBox>
#include <QCoreApplication>
#include <QFormLayout>
#include <QSignalBlocker>

#include <utility>

namespace rigidlab::ui {

using physics::IntegratorKind;
using physics::SolverKind;

namespace {

/// A control named by the key of the run-time setting it changes (schema::settings()):
/// setAllowed finds it by that name.
template <class Widget, class... Args> Widget* named(const char* key, Args&&... args)
{
    auto* widget = new Widget(std::forward<Args>(args)...);
    widget->setObjectName(QLatin1String(key));
    return widget;
}

} // namespace

ControlPanel::ControlPanel(SimulationController& controller, QWidget* parent)
    : QWidget(parent), m_controller(controller), m_integrator(named<QComboBox>("integrator", this)),
      m_solver(named<QComboBox>("solver", this)),
      m_iterations(named<NumberField>("iterations", this)), m_dt(named<NumberField>("dt", this)),
      m_timeScale(named<NumberField>("timeScale", this)),
      m_restitution(named<NumberField>("restitution", this)),
      m_friction(named<NumberField>("friction", this)),
      m_gravity(named<QCheckBox>("gravity", tr("on"), this))
{
    // In words, from the one table of display names; the menus' order is physics'.
    for (const IntegratorKind kind : physics::kAllIntegrators)
        m_integrator->addItem(integratorDisplayName(kind), int(kind));
    m_integrator->setToolTip(tr("How positions and velocities are advanced in each step"));
    for (const SolverKind kind :
         {SolverKind::PaperImpulse, SolverKind::SequentialImpulse, SolverKind::SoftStep})
        m_solver->addItem(solverDisplayName(kind), int(kind));
    m_solver->setToolTip(tr("The paper's impulse: one impulse per contact, once.\n"
                            "Sequential impulse: iterated, clamped, warm started.\n"
                            "Soft step: springy contacts solved in small substeps; stiff stacks."));
    // Every range is a scene file's (lessons/limits.h): what a file may hold can be typed.
    namespace limits = lessons::limits;
    m_iterations->setRange(limits::kIterations, tr("Iterations"));
    m_iterations->setInteger(true);
    // dt in milliseconds reads better in class than 0.001 s.
    m_dt->setRange(NumberField::scaled(limits::kDt, 1e3), tr("dt"), tr("ms"));
    m_dt->setToolTip(tr("The fixed time step [ms]"));
    m_timeScale->setRange(limits::kTimeScale, tr("Time scale"), tr("×"));
    m_timeScale->setToolTip(tr("Slow motion below 1, fast forward above"));
    m_restitution->setRange(limits::kRestitution, tr("Restitution e"));
    m_restitution->setToolTip(
        tr("Coefficient of restitution e for every body: 0 sticks, 1 is elastic"));
    m_friction->setRange(limits::kFriction, tr("Friction μ"));
    m_friction->setToolTip(tr("Coulomb friction coefficient μ for every body"));

    auto* form = new QFormLayout(this);
    // In a narrow column (a 1024-pixel projector) each label goes above its field rather than
    // both being cut.
    form->setRowWrapPolicy(QFormLayout::WrapLongRows);
    form->addRow(tr("Integrator"), m_integrator);
    form->addRow(tr("Time step dt [ms]"), m_dt);
    form->addRow(tr("Solver"), m_solver);
    form->addRow(tr("Iterations"), m_iterations);
    form->addRow(tr("Time scale"), m_timeScale);
    form->addRow(tr("Restitution e"), m_restitution);
    form->addRow(tr("Friction μ"), m_friction);
    form->addRow(tr("Gravity"), m_gravity);
    m_gravity->setAccessibleName(tr("Gravity")); // not its box's word "on"
    addTableControls(*form);
    followRows(*form); // Tab down the rows; the lists named by their labels

    connect(m_integrator, &QComboBox::activated, this, [this] {
        m_controller.setIntegrator(IntegratorKind(m_integrator->currentData().toInt()));
    });
    connect(m_solver, &QComboBox::activated, this,
            [this] { m_controller.setSolver(SolverKind(m_solver->currentData().toInt())); });
    connect(m_iterations, &NumberField::valueEdited, this,
            [this](double n) { m_controller.setIterations(static_cast<int>(n)); });
    // Divided, not multiplied by 1e-3: 2.5 ms is then the double nearest 0.0025 s.
    connect(m_dt, &NumberField::valueEdited, this,
            [this](double ms) { m_controller.setDt(ms / 1e3); });
    connect(m_timeScale, &NumberField::valueEdited, &m_controller,
            &SimulationController::setTimeScale);
    connect(m_restitution, &NumberField::valueEdited, &m_controller,
            &SimulationController::setRestitution);
    connect(m_friction, &NumberField::valueEdited, &m_controller,
            &SimulationController::setFriction);
    for (NumberField* f : {m_iterations, m_dt, m_timeScale, m_restitution, m_friction})
        connect(f, &NumberField::refused, this, &ControlPanel::inputRefused);
    connect(m_gravity, &QCheckBox::toggled, &m_controller,
            &SimulationController::setGravityEnabled);
    connect(&m_controller, &SimulationController::settingsChanged, this, &ControlPanel::refresh);
    // Going back in time restores the settings that were in force then: the fields show them,
    // not the ones changed later (whose marks on the plots turn to ghosts).
    connect(&m_controller, &SimulationController::rewound, this, &ControlPanel::refresh);
    refresh();
}

void ControlPanel::addTableControls(QFormLayout& form)
{
    namespace schema = lessons::schema;
    // A setting of the world without a control of its own above gets one made from its world
    // row: adding a setting is a row of the table, and the controls follow.
    for (const schema::Field& setting : schema::settings()) {
        const schema::Field* row = schema::worldRowOf(setting);
        const QString key = QString::fromLatin1(setting.key.data(), qsizetype(setting.key.size()));
        if (row == nullptr || findChild<QWidget*>(key, Qt::FindDirectChildrenOnly))
            continue;
        const std::string_view k = row->key;
        QWidget* control = nullptr;
        if (row->kind == schema::Kind::Bool) {
            auto* box = new QCheckBox(tr("on"), this);
            connect(box, &QCheckBox::toggled, this,
                    [this, k](bool on) { m_controller.setSetting(k, on); });
            control = box;
        } else if (row->kind == schema::Kind::Choice) {
            auto* list = new QComboBox(this);
            for (const QString& option : row->options())
                list->addItem(methodDisplayName(option), option);
            connect(list, &QComboBox::activated, this, [this, k, list] {
                m_controller.setSetting(k, list->currentData().toString());
            });
            control = list;
        } else if (row->kind == schema::Kind::Number || row->kind == schema::Kind::Integer) {
            auto* field = new NumberField(this);
            const double scale = row->shownScale;
            field->setRange(NumberField::scaled(row->range, scale), schema::label(*row),
                            row->shownUnit
                                ? QCoreApplication::translate(schema::kContext, row->shownUnit)
                                : QString());
            const bool integer = row->kind == schema::Kind::Integer;
            field->setInteger(integer);
            connect(field, &NumberField::valueEdited, this, [this, k, scale, integer](double v) {
                m_controller.setSetting(k, integer ? schema::Value(static_cast<int>(v))
                                                   : schema::Value(v / scale));
            });
            connect(field, &NumberField::refused, this, &ControlPanel::inputRefused);
            control = field;
        } else {
            continue; // a pair or a text has no control made for it: give it one above
        }
        control->setObjectName(key);
        control->setAccessibleName(schema::label(*row));
        form.addRow(schema::label(*row), control);
        m_tableControls.emplace_back(k, control);
    }
}

void ControlPanel::refreshTableControls()
{
    namespace schema = lessons::schema;
    lessons::Scene now;
    now.world = m_controller.world().def();
    for (const auto& [key, control] : m_tableControls) {
        const schema::Field* row = schema::findField(schema::Object::World, key);
        const schema::Value v = row->get(now, 0);
        const QSignalBlocker block(control);
        if (auto* box = qobject_cast<QCheckBox*>(control))
            box->setChecked(std::get<bool>(v));
        else if (auto* list = qobject_cast<QComboBox*>(control))
            list->setCurrentIndex(list->findData(std::get<QString>(v)));
        else if (auto* field = qobject_cast<NumberField*>(control))
            field->setValue(std::holds_alternative<int>(v) ? std::get<int>(v)
                                                           : std::get<double>(v) * row->shownScale);
    }
}

void ControlPanel::setAllowed(const std::optional<QStringList>& allowed)
{
    // Every run-time setting has its control, named by the setting's key.
    for (const lessons::schema::Field& f : lessons::schema::settings()) {
        const QString name = QString::fromLatin1(f.key.data(), qsizetype(f.key.size()));
        QWidget* widget = findChild<QWidget*>(name, Qt::FindDirectChildrenOnly);
        if (widget == nullptr)
            continue;
        const bool on = !allowed || allowed->contains(name);
        widget->setEnabled(on);
        widget->setProperty("locked", !on);
        widget->setStatusTip(on ? QString() : tr("Fixed in this step of the lesson"));
    }
    refresh();
}

void ControlPanel::showIterationsMeaning(SolverKind solver)
{
    // What the number does under each solver, said where a greyed field leaves the student
    // guessing (tooltip and screen reader alike).
    QString meaning;
    switch (solver) {
    case SolverKind::PaperImpulse:
        meaning = tr("Not used: the paper's impulse solves each contact once, in one pass");
        break;
    case SolverKind::SequentialImpulse:
        meaning = tr("Velocity iterations of the sequential-impulse solver");
        break;
    case SolverKind::SoftStep:
        meaning = tr("Soft step: iterations of its bounce pass at the start of each step; the "
                     "resting contacts are solved in %n substeps instead",
                     nullptr, m_controller.world().contactSettings().soft.substeps);
        break;
    }
    m_iterations->setEnabled(solver != SolverKind::PaperImpulse &&
                             !m_iterations->property("locked").toBool());
    m_iterations->setToolTip(meaning);
    m_iterations->setAccessibleDescription(meaning);
}

void ControlPanel::refresh()
{
    const physics::WorldDef& d = m_controller.world().def();
    const QSignalBlocker b1(m_integrator), b2(m_solver), b3(m_gravity);
    m_integrator->setCurrentIndex(m_integrator->findData(int(d.integrator)));
    m_solver->setCurrentIndex(m_solver->findData(int(d.solver)));
    m_iterations->setValue(d.iterations);
    showIterationsMeaning(d.solver);
    // The value in force; a field being typed in keeps its text (NumberField::setValue).
    m_dt->setValue(d.dt * 1e3);
    m_timeScale->setValue(m_controller.timeScale());
    m_restitution->setValue(d.restitution);
    m_friction->setValue(d.friction);
    m_gravity->setChecked(d.gravity.squaredNorm() > 0);
    refreshTableControls();
}

} // namespace rigidlab::ui
