// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The inspected body's force and torque accumulators, force by force
// (physics::forceBreakdown): a free-body diagram with an arrow for each force at the point it
// acts at and one for their sum at the centre of mass, each numbered, and a table of the
// numbers (force, point, torque about the centre) ending in the sums, the accumulators the
// next step starts from. Folded under the inspector until opened.

#include "rigidlab/physics/force_breakdown.h"

#include <QWidget>

class QLabel;
class QToolButton;

namespace rigidlab::ui {

class ForceDiagram;

class ForcesView : public QWidget {
    Q_OBJECT
public:
    explicit ForcesView(QWidget* parent = nullptr);
    /// Shows the forces on body `id` of `world` now.
    void showBody(const physics::World& world, physics::BodyId id);
    void showNone();
    void setOpen(bool open);
    /// The table as shown (rich text).
    QString text() const;

private:
    QToolButton* m_toggle;
    ForceDiagram* m_diagram;
    QLabel* m_table;
};

/// The table of the forces on `body` as rich text.
QString forcesTableText(const physics::ForceBreakdown& forces, const physics::Body& body);

} // namespace rigidlab::ui
