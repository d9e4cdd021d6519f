// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The simulation's run-time settings (lessons::schema::settings()) as controls: integrator,
// solver, iterations, dt, time scale, global restitution and friction, gravity, each made by
// hand, and any other setting of the table made from its row. The number fields take a value
// on Enter or on leaving them, and refuse what is outside the ranges of lessons/limits.h out
// loud.

#include <QStringList>
#include <QWidget>

#include <optional>
#include <string_view>
#include <utility>
#include <vector>

class QCheckBox;
class QComboBox;
class QFormLayout;

namespace rigidlab::physics {
enum class SolverKind;
}

namespace rigidlab::ui {

class NumberField;
class SimulationController;

class ControlPanel : public QWidget {
    Q_OBJECT
public:
    explicit ControlPanel(SimulationController& controller, QWidget* parent = nullptr);

    NumberField* restitutionField() const { return m_restitution; }
    NumberField* frictionField() const { return m_friction; }
    QCheckBox* gravityBox() const { return m_gravity; }

    /// Which controls the student may change (the settings' keys, a step's "allow"); nullopt:
    /// all of them.
    void setAllowed(const std::optional<QStringList>& allowed);

signals:
    /// A typed value was refused; `message` names the allowed range (for the status bar).
    void inputRefused(const QString& message);

public slots:
    /// Shows the controller's current settings.
    void refresh();

private:
    /// Greys the iterations field where the solver has none, and says what it means under
    /// each solver (tooltip and accessible description).
    void showIterationsMeaning(physics::SolverKind solver);
    /// Makes a control for each setting of the table that has none of its own.
    void addTableControls(QFormLayout& form);
    void refreshTableControls();

    SimulationController& m_controller;
    QComboBox* m_integrator;
    QComboBox* m_solver;
    NumberField* m_iterations;
    NumberField* m_dt;
    NumberField* m_timeScale;
    NumberField* m_restitution;
    NumberField* m_friction;
    QCheckBox* m_gravity;
    /// The controls made from the table's rows, by setting key.
    std::vector<std::pair<std::string_view, QWidget*>> m_tableControls;
};

} // namespace rigidlab::ui
