// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The one message for a divergence (physics::Divergence is data only), for the window and the
// command line alike: translated (context DivergenceWords) where a translation is installed,
// English where none is (rigidlab-cli unless --lang asks), with numbers in the locale given:
// the C locale's decimal point for the command line, the user's in the window.

#include "rigidlab/physics/divergence.h"

#include <QCoreApplication>
#include <QLocale>
#include <QString>

namespace rigidlab::lessons {

/// The translation context of the words for a divergence.
struct DivergenceWords {
    Q_DECLARE_TR_FUNCTIONS(DivergenceWords)
};

/// The quantity as a noun: "position", "angular velocity", "total energy".
QString quantityName(physics::Divergence::Quantity quantity);

/// What went wrong: `body "ball": velocity is no longer finite`, or `the total energy grew to
/// 1e+06 J, past the bound of 1e+06 J (body "mass" holds the most kinetic energy)`.
/// `bodyLabel` names the body as the scene labels it; empty, by its id.
QString divergenceReason(const physics::Divergence& d, const QString& bodyLabel = {},
                         const QLocale& numbers = QLocale::c());

/// One line: `diverged at t = 0.125 s (step 125, dt = 0.001 s, euler): ` and the reason; for
/// a world crowded past its work budget, `stopped at t = 0 s, before step 1: `.
QString divergenceMessage(const physics::Divergence& d, const QString& bodyLabel = {},
                          const QLocale& numbers = QLocale::c());

} // namespace rigidlab::lessons
