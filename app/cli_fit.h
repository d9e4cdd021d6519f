// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// rigidlab-cli fit: a scene's parameters fitted to a measured time series (or e to bounce
// times). Argument handling only; the work is in rigidlab_measure.

#include <QStringList>

namespace rigidlab::cli {

/// `fit SCENE MEASUREMENT.csv --param P [--param P]... --quantity Q:BODY [--bounce-times]
/// [--time-zero T] [--origin X,Y] [--time-unit U] [--length-unit U]`.
int commandFit(const QStringList& words);

} // namespace rigidlab::cli
