// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Whether two scenes are the same, field by field and bit for bit: what a saved scene must be
// when it is read back, and what undoing every edit must give.

#include "format/scene.h"

#include <QString>

namespace rigidlab::lessons {

/// The first field in which the scenes differ, as "bodies[2].position: [0, 1] vs [0, 1.5]",
/// or empty when they are equal in every field (numbers compared exactly).
QString sceneDifference(const Scene& a, const Scene& b);

} // namespace rigidlab::lessons
