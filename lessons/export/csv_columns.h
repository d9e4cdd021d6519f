// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The column heads of the lab's CSV files, one table for the command line and the window, so
// that a quantity is headed the same wherever it was exported: its symbol (or a word) and its
// SI unit in brackets, "t [s]", "E_k [J]". Words are translated (context CsvColumns); the
// heads come out in the language in effect when they are asked for.

#include <QString>

namespace rigidlab::lessons {

enum class CsvColumn {
    Step,            ///< step number
    Time,            ///< t [s]
    Body,            ///< the body's id
    X,               ///< x [m]
    Y,               ///< y [m]
    Angle,           ///< [rad]
    Vx,              ///< [m/s]
    Vy,              ///< [m/s]
    Omega,           ///< [rad/s]
    Kinetic,         ///< E_k [J]
    Potential,       ///< E_p [J]
    Total,           ///< E [J]
    Dissipated,      ///< E_diss [J]
    TotalDissipated, ///< E + E_diss [J]
    Px,              ///< [kg m/s]
    Py,              ///< [kg m/s]
    AngularMomentum, ///< L [kg m²/s]
    Contacts,        ///< contact points in the step
    Drift,           ///< (E + E_diss - E0) / |E0|, relative
    DriftPercent,    ///< the same in %
};

/// The head in the language in effect: "E_k [J]", "krok".
QString csvColumnHead(CsvColumn column);

} // namespace rigidlab::lessons
