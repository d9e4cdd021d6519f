#pragma once
// The selected body, in numbers: mass, inertia, pose, velocities, energy; its restitution and
// friction can be edited.

#include <QWidget>

class QDoubleSpinBox;
class QLabel;

namespace rigidlab::ui {

class SimulationController;

class InspectorPanel : public QWidget {
    Q_OBJECT
public:
    explicit InspectorPanel(SimulationController& controller, QWidget* parent = nullptr);
    int body() const { return m_body; }
    QString text() const; ///< everything shown, for tests

public slots:
    void setBody(int id);
    void refresh();

private:
    SimulationController& m_controller;
    int m_body = -1;
    QLabel* m_name;
    QLabel* m_mass;
    QLabel* m_inertia;
    QLabel* m_position;
    QLabel* m_angle;
    QLabel* m_velocity;
    QLabel* m_omega;
    QLabel* m_energy;
    QDoubleSpinBox* m_restitution;
    QDoubleSpinBox* m_friction;
};

} // namespace rigidlab::ui
