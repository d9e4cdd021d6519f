// SPDX-License-Identifier: GPL-3.0-or-later
#include "editor/tools/all_tools.h"

#include "editor/edit_tools.h"
#include "editor/tools/click_tools.h"
#include "editor/tools/pin_tool.h"
#include "editor/tools/polygon_tool.h"
#include "editor/tools/rotate_tool.h"
#include "editor/tools/select_tool.h"
#include "editor/tools/shape_tools.h"
#include "editor/tools/spring_tool.h"

namespace rigidlab::ui {

std::unique_ptr<Tool> makeTool(EditTool tool, EditTools& tools)
{
    switch (tool) {
    case EditTool::Select:
        return std::make_unique<SelectTool>(tools);
    case EditTool::Rotate:
        return std::make_unique<RotateTool>(tools);
    case EditTool::Circle:
        return std::make_unique<CircleTool>(tools);
    case EditTool::Box:
        return std::make_unique<BoxTool>(tools);
    case EditTool::Polygon:
        return std::make_unique<PolygonTool>(tools);
    case EditTool::Ground:
        return std::make_unique<GroundTool>(tools);
    case EditTool::Pin:
        return std::make_unique<PinTool>(tools);
    case EditTool::Spring:
        return std::make_unique<SpringTool>(tools);
    case EditTool::Delete:
        return std::make_unique<DeleteTool>(tools);
    case EditTool::Duplicate:
        return std::make_unique<DuplicateTool>(tools);
    }
    return nullptr;
}

} // namespace rigidlab::ui
