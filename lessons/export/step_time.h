// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The time of a step as a person writes it. A run's clock is a sum of steps in binary, so
// step 9 of 1 ms is at 0.009000000000000001 s; a table, a plot and a file should say 0.009.
// The rule, for every place that writes a time (the plots' samples, every CSV):
//   - dt a decimal of up to 9 places (0.001, 0.003, 0.0025): k dt worked out in decimal,
//     (k m) / 10^d with dt = m / 10^d: step 9 of 0.003 s is 0.027;
//   - 1/dt a whole rate (1/60 s, 1/240 s): k / rate: step 9 of 1/60 s is 0.15;
//   - anything else: k * dt.
// The result is the double nearest the exact time, so its shortest round-trip text is the
// one a person writes.

namespace rigidlab::lessons {

/// The time of step k of a run on a fixed dt [s], as the double nearest the exact product.
double stepTime(long long k, double dt);

/// The time a run's summed clock `summed` [s] stands for after k steps of dt: stepTime(k, dt)
/// when the sum is within rounding of it (a run on one dt since t = 0), else the sum itself
/// (a dt changed mid-run, a run that did not start at 0).
double stepTime(long long k, double dt, double summed);

} // namespace rigidlab::lessons
