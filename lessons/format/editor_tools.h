// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The names of the scene editor's tools and of the properties it edits: one list, read by a
// lesson step's "editor" key (lesson_step.cpp, LESSON_FORMAT.md) and by the editor's toolbar
// and inspector, which enable only what a step unlocks.

#include <array>
#include <string_view>

namespace rigidlab::lessons {

/// The editor's tools, in the toolbar's order.
inline constexpr std::array<std::string_view, 10> kEditorToolNames{
    "select", "rotate", "circle", "box",    "polygon",
    "ground", "pin",    "spring", "delete", "duplicate"};

/// The properties the editor's inspector edits: a body's, a spring's, the world's.
inline constexpr std::array<std::string_view, 17> kEditorPropertyNames{
    "id",       "type",       "density",         "mass",   "restitution",
    "friction", "velocity",   "angularVelocity", "colour", "stiffness",
    "damping",  "restLength", "gravity",         "dt",     "integrator",
    "solver",   "iterations"};

} // namespace rigidlab::lessons
