// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Makes the tool object for each of the editor's tools (the EditTool enum, toolbar order).

#include "editor/tools/tool.h"

#include <memory>

namespace rigidlab::ui {

enum class EditTool;

std::unique_ptr<Tool> makeTool(EditTool tool, EditTools& tools);

} // namespace rigidlab::ui
