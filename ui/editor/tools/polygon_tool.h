// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The Polygon tool: click the vertices; a double-click or Enter closes the polygon (its convex
// hull, said when the outline is not convex), Backspace drops the last point. Enter with no
// points adds a triangle (a small ramp) at the view's centre.

#include "editor/tools/tool.h"

#include <vector>

namespace rigidlab::ui {

class PolygonTool : public Tool {
    Q_DECLARE_TR_FUNCTIONS(rigidlab::ui::EditTools)

public:
    using Tool::Tool;
    bool press(const ToolPointer& pointer) override;
    bool move(const ToolPointer& pointer) override;
    bool doubleClick(const ToolPointer& pointer) override;
    bool wantsKey(int key) const override;
    void key(int key) override;
    void paint(QPainter& painter, double zoom) const override;
    QString status() const override;
    bool busy() const override { return !m_points.empty(); }
    void cancel() override { m_points.clear(); }

    /// Adds the polygon of the points clicked, and selects it.
    void close();
    const std::vector<physics::Vec2>& points() const { return m_points; }

private:
    void add(const std::vector<physics::Vec2>& points);

    std::vector<physics::Vec2> m_points;             ///< of the polygon being drawn [m]
    physics::Vec2 m_pointer = physics::Vec2::Zero(); ///< last pointer position [m], snapped
};

} // namespace rigidlab::ui
