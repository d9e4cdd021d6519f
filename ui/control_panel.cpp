#include "control_panel.h"

#include "simulation_controller.h"

#include "rigidlab/lessons/limits.h"
#include "rigidlab/lessons/scene_loader.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QSignalBlocker>
#include <QSpinBox>

#include <array>

namespace rigidlab::ui {

using physics::IntegratorKind;
using physics::SolverKind;

ControlPanel::ControlPanel(SimulationController& controller, QWidget* parent)
    : QWidget(parent), m_controller(controller), m_integrator(new QComboBox(this)),
      m_solver(new QComboBox(this)), m_iterations(new QSpinBox(this)),
      m_dt(new QDoubleSpinBox(this)), m_timeScale(new QDoubleSpinBox(this)),
      m_restitution(new QDoubleSpinBox(this)), m_friction(new QDoubleSpinBox(this)),
      m_gravity(new QCheckBox(tr("on"), this))
{
    m_integrator->addItem(tr("Explicit Euler"), int(IntegratorKind::Euler));
    m_integrator->addItem(tr("Symplectic Euler"), int(IntegratorKind::SymplecticEuler));
    m_integrator->addItem(tr("Velocity Verlet"), int(IntegratorKind::Verlet));
    m_integrator->addItem(tr("Runge-Kutta 4"), int(IntegratorKind::RK4));
    m_integrator->addItem(tr("Dormand-Prince 5(4), adaptive"), int(IntegratorKind::DormandPrince));
    m_integrator->addItem(tr("Implicit midpoint"), int(IntegratorKind::ImplicitMidpoint));
    m_integrator->setToolTip(tr("How positions and velocities are advanced in each step"));
    m_solver->addItem(tr("Seed impulse"), int(SolverKind::SeedImpulse));
    m_solver->addItem(tr("Sequential impulse"), int(SolverKind::SequentialImpulse));
    m_solver->setToolTip(tr("Seed impulse: one impulse per contact, once (the paper's method).\n"
                            "Sequential impulse: iterated, clamped, warm started."));
    // Every range is a scene file's (lessons/limits.h): what a file may hold can be typed.
    m_iterations->setRange(1, lessons::kMaxIterations);
    m_iterations->setToolTip(tr("Velocity iterations of the sequential-impulse solver"));
    // dt in milliseconds reads better in class than 0.001 s.
    m_dt->setRange(lessons::kMinDt * 1e3, lessons::kMaxDt * 1e3);
    m_dt->setDecimals(4);
    m_dt->setSingleStep(0.5);
    m_dt->setSuffix(tr(" ms"));
    m_dt->setToolTip(tr("The fixed time step"));
    m_timeScale->setRange(lessons::limits::kTimeScale.min, lessons::limits::kTimeScale.max);
    m_timeScale->setSingleStep(0.1);
    m_timeScale->setDecimals(1);
    m_timeScale->setSuffix(tr(" ×"));
    m_timeScale->setToolTip(tr("Slow motion below 1, fast forward above"));
    m_restitution->setRange(0.0, 1.0);
    m_restitution->setSingleStep(0.05);
    m_restitution->setDecimals(2);
    m_restitution->setToolTip(
        tr("Coefficient of restitution e for every body: 0 sticks, 1 is elastic"));
    m_friction->setRange(lessons::limits::kFriction.min, lessons::limits::kFriction.max);
    m_friction->setSingleStep(0.05);
    m_friction->setDecimals(2);
    m_friction->setToolTip(tr("Coulomb friction coefficient μ for every body"));

    auto* form = new QFormLayout(this);
    form->addRow(tr("Integrator"), m_integrator);
    form->addRow(tr("Time step dt"), m_dt);
    form->addRow(tr("Solver"), m_solver);
    form->addRow(tr("Iterations"), m_iterations);
    form->addRow(tr("Time scale"), m_timeScale);
    form->addRow(tr("Restitution e"), m_restitution);
    form->addRow(tr("Friction μ"), m_friction);
    form->addRow(tr("Gravity"), m_gravity);

    connect(m_integrator, &QComboBox::activated, this, [this] {
        m_controller.setIntegrator(IntegratorKind(m_integrator->currentData().toInt()));
    });
    connect(m_solver, &QComboBox::activated, this,
            [this] { m_controller.setSolver(SolverKind(m_solver->currentData().toInt())); });
    connect(m_iterations, &QSpinBox::valueChanged, &m_controller,
            &SimulationController::setIterations);
    connect(m_dt, &QDoubleSpinBox::valueChanged, this,
            [this](double ms) { m_controller.setDt(ms * 1e-3); });
    connect(m_timeScale, &QDoubleSpinBox::valueChanged, &m_controller,
            &SimulationController::setTimeScale);
    connect(m_restitution, &QDoubleSpinBox::valueChanged, &m_controller,
            &SimulationController::setRestitution);
    connect(m_friction, &QDoubleSpinBox::valueChanged, &m_controller,
            &SimulationController::setFriction);
    connect(m_gravity, &QCheckBox::toggled, &m_controller,
            &SimulationController::setGravityEnabled);
    connect(&m_controller, &SimulationController::settingsChanged, this, &ControlPanel::refresh);
    refresh();
}

void ControlPanel::setAllowed(const std::optional<QStringList>& allowed)
{
    const std::array<std::pair<const char*, QWidget*>, 8> controls{{
        {"integrator", m_integrator},
        {"dt", m_dt},
        {"solver", m_solver},
        {"iterations", m_iterations},
        {"timeScale", m_timeScale},
        {"restitution", m_restitution},
        {"friction", m_friction},
        {"gravity", m_gravity},
    }};
    for (const auto& [name, widget] : controls) {
        const bool on = !allowed || allowed->contains(QLatin1String(name));
        widget->setEnabled(on);
        widget->setProperty("locked", !on);
        widget->setStatusTip(on ? QString() : tr("Fixed in this step of the lesson"));
    }
    refresh();
}

void ControlPanel::refresh()
{
    const physics::WorldDef& d = m_controller.world().def();
    const QSignalBlocker b1(m_integrator), b2(m_solver), b3(m_iterations), b4(m_dt),
        b5(m_timeScale), b6(m_restitution), b7(m_friction), b8(m_gravity);
    m_integrator->setCurrentIndex(m_integrator->findData(int(d.integrator)));
    m_solver->setCurrentIndex(m_solver->findData(int(d.solver)));
    m_iterations->setValue(d.iterations);
    m_iterations->setEnabled(d.solver == SolverKind::SequentialImpulse &&
                             !m_iterations->property("locked").toBool());
    m_dt->setValue(d.dt * 1e3);
    m_timeScale->setValue(m_controller.timeScale());
    m_restitution->setValue(d.restitution);
    m_friction->setValue(d.friction);
    m_gravity->setChecked(d.gravity.squaredNorm() > 0);
}

} // namespace rigidlab::ui
