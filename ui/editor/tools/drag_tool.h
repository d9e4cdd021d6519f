// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A tool that draws by dragging from one point to another (a circle, a box, the ground, a
// spring). A click is not a drawing: a press released within a few pixels of where it went
// down adds nothing and says what the tool does instead; only a drag draws.

#include "editor/tools/tool.h"

namespace rigidlab::ui {

class DragTool : public Tool {
    Q_DECLARE_TR_FUNCTIONS(rigidlab::ui::EditTools)

public:
    using Tool::Tool;

    bool press(const ToolPointer& pointer) override;
    bool move(const ToolPointer& pointer) override;
    bool release(const ToolPointer& pointer) override;
    bool wantsKey(int key) const override;
    void key(int key) override;
    bool busy() const override { return m_active; }
    void cancel() override { m_active = false; }

protected:
    /// The drag is over: it ends at `end` [m] (snapped), the pointer at `raw`.
    virtual void finish(const physics::Vec2& end, const physics::Vec2& raw) = 0;
    /// The size being drawn, for the status line while dragging.
    virtual QString sizeText() const = 0;
    /// Return: the tool's shape at the view's centre, drawn without the mouse.
    virtual void addByKey() = 0;
    /// Whether the pointer travelled far enough from the press to be a drag.
    bool dragged(const ToolPointer& pointer) const;

    physics::Vec2 m_start = physics::Vec2::Zero();   ///< where the press was [m], snapped
    physics::Vec2 m_current = physics::Vec2::Zero(); ///< [m], snapped
    QPoint m_pressPixel;
    bool m_active = false;
    bool m_dragged = false; ///< the pointer went beyond a click's reach since the press
};

} // namespace rigidlab::ui
