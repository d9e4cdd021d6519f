// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Help › About: what RigidLab is, its version and licence, the paper it grows from, and the
// versions of the libraries it runs on.

#include <QString>

class QWidget;

namespace rigidlab::ui {

/// The About text (rich text): version, licence, the paper, Qt, QCustomPlot and Eigen.
QString aboutText();

/// Shows aboutText() in a dialog over `parent`.
void showAbout(QWidget* parent);

} // namespace rigidlab::ui
