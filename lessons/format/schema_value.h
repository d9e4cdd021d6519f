// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A value of a schema row (scene_schema.h): what a scene field, a lesson step's setting and an
// edit of a run hold, in one type.

#include "rigidlab/physics/math.h"

#include <QString>

#include <variant>

namespace rigidlab::lessons::schema {

/// A field's value: unset (the default, the world's, absent), or one of the kinds' types.
using Value = std::variant<std::monostate, double, int, bool, physics::Vec2, QString>;

} // namespace rigidlab::lessons::schema
