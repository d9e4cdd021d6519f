// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The impulse formula of one collision with its numbers substituted, each term named:
//   j = −(1 + e) (v_A − v_B)·n / (1/m_A + 1/m_B + (r_A × n)²/I_A + (r_B × n)²/I_B)
// read from the lab's record of the hit (lessons::CollisionEvent), with n written from B to A
// as the lessons write it. Shown under the collision table, folded until opened (a narrow
// column keeps its table in sight); j itself gives the velocities after the hit away, so it
// reads "?" while they are held back.

#include "run/measurements.h"

#include "rigidlab/physics/body.h"

#include <QWidget>

class QLabel;
class QToolButton;

namespace rigidlab::ui {

class ImpulseFormulaView : public QWidget {
    Q_OBJECT
public:
    explicit ImpulseFormulaView(QWidget* parent = nullptr);
    /// The formula as shown (rich text), whether or not it is unfolded.
    QString text() const;
    /// Unfolds (or folds) the formula, as its button does.
    void setOpen(bool open);

    /// Shows the formula for `hit` between bodies `a` and `b` (hit.a and hit.b, named
    /// `nameA` and `nameB`); `held`: j reads "?".
    void showHit(const lessons::CollisionEvent& hit, const physics::Body& a, const physics::Body& b,
                 const QString& nameA, const QString& nameB, bool held);
    /// No collision yet: the formula without numbers.
    void showNone();

private:
    QToolButton* m_toggle;
    QLabel* m_formula;
};

/// The substituted formula as rich text (what the view shows), for a test to read.
QString impulseFormulaText(const lessons::CollisionEvent& hit, const physics::Body& a,
                           const physics::Body& b, const QString& nameA, const QString& nameB,
                           bool held);

} // namespace rigidlab::ui
