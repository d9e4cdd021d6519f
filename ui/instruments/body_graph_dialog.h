// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Choosing a graph of bodies: the quantity, the bodies (a curve each), whether a curve sums
// them, and the frame of reference. Every choice is a labelled control the keyboard reaches.

#include "plots/body_series.h"

#include <QDialog>

class QCheckBox;
class QComboBox;
class QListWidget;

namespace rigidlab::ui {

/// What a graph of bodies shows.
struct BodyGraphSpec {
    BodyQuantity quantity = BodyQuantity::Y;
    std::vector<physics::BodyId> bodies; ///< a curve each (when `eachBody`)
    bool eachBody = true;
    bool sum = false;     ///< one more curve: the sum over `bodies`
    ReferenceFrame frame; ///< the lab's, or the centre of mass of its bodies
};

class BodyGraphDialog : public QDialog {
    Q_OBJECT
public:
    /// `labels`: the bodies' names in id order; `initial` ticks its bodies and picks its
    /// quantity.
    BodyGraphDialog(const QStringList& labels, const BodyGraphSpec& initial, QWidget* parent);
    BodyGraphSpec spec() const;

private:
    QComboBox* m_quantity;
    QListWidget* m_bodies;
    QCheckBox* m_each;
    QCheckBox* m_sum;
    QCheckBox* m_centreOfMass;
};

} // namespace rigidlab::ui
