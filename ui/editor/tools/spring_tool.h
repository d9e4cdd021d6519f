// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The spring tool: drag from one point to another, each end on a body or on the world; its
// rest length is the length drawn. Return hangs the selected body from the world by one.

#include "editor/tools/drag_tool.h"

#include "rigidlab/physics/forces.h"

namespace rigidlab::ui {

class SpringTool : public DragTool {
    Q_DECLARE_TR_FUNCTIONS(rigidlab::ui::EditTools)

public:
    using DragTool::DragTool;
    bool press(const ToolPointer& pointer) override;
    void paint(QPainter& painter, double zoom) const override;
    QString status() const override;

    /// How far above the selected body Return hangs it from [grid steps].
    static constexpr double kKeyLength = 3.0;

protected:
    void finish(const physics::Vec2& end, const physics::Vec2& raw) override;
    QString sizeText() const override;
    void addByKey() override;

private:
    void add(physics::BodyId a, const physics::Vec2& pointA, physics::BodyId b,
             const physics::Vec2& pointB);

    physics::BodyId m_bodyA = physics::kWorld; ///< the first end's body
};

} // namespace rigidlab::ui
