#pragma once
// The simulation's settings as controls: integrator, solver, iterations, dt, time scale,
// global restitution and friction, gravity. Every field is range-checked by its widget.

#include <QStringList>
#include <QWidget>

#include <optional>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QSpinBox;

namespace rigidlab::ui {

class SimulationController;

class ControlPanel : public QWidget {
    Q_OBJECT
public:
    explicit ControlPanel(SimulationController& controller, QWidget* parent = nullptr);

    QComboBox* integratorBox() const { return m_integrator; }
    QComboBox* solverBox() const { return m_solver; }
    QDoubleSpinBox* dtBox() const { return m_dt; }
    QDoubleSpinBox* timeScaleBox() const { return m_timeScale; }
    QDoubleSpinBox* restitutionBox() const { return m_restitution; }
    QDoubleSpinBox* frictionBox() const { return m_friction; }
    QCheckBox* gravityBox() const { return m_gravity; }

    /// Which controls the student may change (names: integrator, dt, solver, iterations,
    /// timeScale, restitution, friction, gravity); nullopt: all of them.
    void setAllowed(const std::optional<QStringList>& allowed);

public slots:
    /// Shows the controller's current settings.
    void refresh();

private:
    SimulationController& m_controller;
    QComboBox* m_integrator;
    QComboBox* m_solver;
    QSpinBox* m_iterations;
    QDoubleSpinBox* m_dt;
    QDoubleSpinBox* m_timeScale;
    QDoubleSpinBox* m_restitution;
    QDoubleSpinBox* m_friction;
    QCheckBox* m_gravity;
};

} // namespace rigidlab::ui
