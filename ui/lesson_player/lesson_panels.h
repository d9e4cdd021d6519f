// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Tables that lessons show beside the view: bounce heights against e² times the previous
// one, and a collision's before and after (velocities, momentum, kinetic energy, and the
// spin the impulse formula predicts with and without its rotational terms). Both fit the
// window's narrow right column (FittingTable) and export themselves as CSV.

#include "panels/fitting_table.h"

#include "rigidlab/physics/forces.h"

#include <QWidget>

#include <vector>

class QLabel;

namespace rigidlab::lessons {
struct CollisionEvent;
}
namespace rigidlab::physics {
struct Body;
}

namespace rigidlab::ui {

struct CollisionRows;

class RunView;
class ImpulseFormulaView;

class BouncePanel : public QWidget {
    Q_OBJECT
public:
    explicit BouncePanel(const RunView& controller, QWidget* parent = nullptr);
    FittingTable* table() const { return m_table; }
    /// Held: the measured heights and their ratios read "?" until the student has answered.
    void setHeightsHeld(bool held);

public slots:
    /// Fills the table, or, while the panel is out of sight, leaves it until it is shown.
    void refresh();

protected:
    /// Catches up with what changed while the panel was out of sight (its dock closed or
    /// behind another's tab): a run paused meanwhile changes nothing more to refresh it.
    void showEvent(QShowEvent* event) override;

private:
    /// Fills the table whether or not the panel is shown.
    void refreshNow();
    /// The tables' column headers; `heldTip` on those held back.
    static void setHeaders(TableText& wide, TableText& narrow, CsvTable& csv,
                           const QString& heldTip);

    const RunView& m_controller;
    FittingTable* m_table;
    bool m_heightsHeld = false;
    bool m_behind = false; ///< a refresh was skipped while out of sight
};

class CollisionPanel : public QWidget {
    Q_OBJECT
public:
    explicit CollisionPanel(const RunView& controller, QWidget* parent = nullptr);
    FittingTable* table() const { return m_table; }
    /// Which collision the table shows, and when ("Collision of … at t = … s").
    QLabel* title() const { return m_title; }
    /// Held: the "after" column reads "?" until the student has answered.
    void setAfterHeld(bool held);
    /// The bodies the lesson step names (lessons::namedBodies): the panel shows their
    /// collision (lessons::featuredCollision). Empty outside a lesson.
    void setNamedBodies(std::vector<physics::BodyId> bodies);

public slots:
    void refresh();

private:
    /// Body k's spin after the hit as the impulse formula predicts it, with and without its
    /// rotational terms, when the hit involves a spin.
    static void addPredictedSpins(CollisionRows& rows, const lessons::CollisionEvent& e, int k,
                                  const physics::Body& b, const QString& name);

    const RunView& m_controller;
    QLabel* m_title;
    FittingTable* m_table;
    ImpulseFormulaView* m_formula;        ///< j with the hit's numbers, under the table
    std::vector<physics::BodyId> m_named; ///< see setNamedBodies
    int m_shownCount = -1;
    bool m_afterHeld = false;
};

} // namespace rigidlab::ui
