// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The stiff and extreme cases behind `rigidlab-cli stress`: each case builds its worlds, runs
// them and gives a verdict per row, beside the verdict it is documented to have
// (lessons/STRESS.md lists them):
//   stable          ran to the end, energy within bounds, nothing through anything
//   diverged at t   the world stopped itself (physics::Divergence): a non-finite state, or an
//                   energy grown to 10 times its scale (a tighter bound than the default)
//   tunnelled       a body ended on the far side of what it should have hit
//   jittering       bodies that should rest still move faster than 5 cm/s at the end
//   penetrating     bodies overlap by more than 1 cm (twice the allowed slop) at some step
// Where theory gives a stability limit (w dt < 2 for symplectic Euler and Verlet, 2.83 for
// RK4), the row gives it beside the largest stable dt found by a scan of steps.

#include <QByteArray>
#include <QString>
#include <QStringList>

#include <vector>

namespace rigidlab::lessons {

struct StressRow {
    QString caseName;
    QString setup; ///< what differs between the rows of a case ("k = 1e7", "rk4")
    QString integrator;
    QString verdict;         ///< "stable", "diverged at t = 0.012 s", "tunnelled", ...
    QString expected;        ///< the documented verdict's first word
    double energyGrowth = 1; ///< 1 + largest (E(t) - E(0)) / (kinetic + |potential| at start)
    double penetration = 0;  ///< largest overlap of two bodies over the run [m]
    QString limit;           ///< the theoretical limit, or empty
    QString largestStable;   ///< the largest stable dt found, or empty
    QString diagnosis;       ///< the divergence message, or empty
    bool asDocumented() const { return verdict.section(u' ', 0, 0) == expected; }
};

QStringList stressCaseNames();
/// Runs one case, or all for an empty name; an unknown name gives no rows.
std::vector<StressRow> runStress(const QString& caseName = {});
/// The rows as an aligned table for a terminal.
QString stressTable(const std::vector<StressRow>& rows);
QByteArray stressJson(const std::vector<StressRow>& rows);

} // namespace rigidlab::lessons
