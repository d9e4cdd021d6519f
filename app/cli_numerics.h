// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// rigidlab-cli's numerical commands: error-vs-time (the work-precision sweep) and stress (the
// stiff and extreme cases). Argument handling only; the work is in rigidlab_lessons.

#include <QCoreApplication>
#include <QStringList>

#include <memory>

namespace rigidlab::cli {

int commandErrorVsTime(const QStringList& words);
int commandStress(const QStringList& words);
/// The conservation experiments (cli_conserve.cpp).
int commandConserve(const QStringList& words);

/// The application object: a QApplication on the offscreen platform for error-vs-time (its
/// --plot draws with the window's plot widget) and lesson (its --export too), a
/// QCoreApplication for everything else.
std::unique_ptr<QCoreApplication> makeApplication(int& argc, char** argv);

} // namespace rigidlab::cli
