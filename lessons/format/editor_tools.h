// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The names of the scene editor's tools: one list, read by a lesson step's "editor" key
// (lesson_step.cpp, LESSON_FORMAT.md) and by the editor's toolbar, which enables only what a
// step unlocks.

#include <array>
#include <string_view>

namespace rigidlab::lessons {

/// The editor's tools, in the toolbar's order.
inline constexpr std::array<std::string_view, 10> kEditorToolNames{
    "select", "rotate", "circle", "box",    "polygon",
    "ground", "pin",    "spring", "delete", "duplicate"};

/// The properties a step may lock are the schema's: schema::editorPropertyNames()
/// (scene_schema.h).

} // namespace rigidlab::lessons
