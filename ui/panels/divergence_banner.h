// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A red banner over the window when the world diverged: the diagnosis in words (which body,
// which quantity, when, with which dt and integrator) and two ways on: "Reset" and "Halve dt"
// (reset with half the step).

#include <QWidget>

class QLabel;

namespace rigidlab::ui {

class SimulationController;

class DivergenceBanner : public QWidget {
    Q_OBJECT
public:
    explicit DivergenceBanner(SimulationController& controller, QWidget* parent = nullptr);
    QString text() const;

public slots:
    /// Shows the banner while the world is diverged, hides it otherwise; stops the run.
    void refresh();

private:
    SimulationController& m_controller;
    QLabel* m_text;
};

} // namespace rigidlab::ui
