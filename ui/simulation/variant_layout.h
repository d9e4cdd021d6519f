// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Where worlds compared side by side (a lesson step) are drawn beside the main one.

#include "rigidlab/physics/world.h"

namespace rigidlab::ui {

/// The shift between compared worlds drawn beside each other: the lesson's `offset`, or,
/// where their floors and walls would overlap at it (a stack's floor is wider than the
/// shift), as far in the same direction as the main world's static bodies are long, plus a
/// gap. Never shorter than the lesson's. It only moves the drawing: the compared worlds run
/// where they are.
physics::Vec2 besideOffset(const physics::World& main, const physics::Vec2& offset);

} // namespace rigidlab::ui
