// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The Select tool: a click selects a body or a spring, a drag moves a body (snapping onto
// other bodies and the grid), a drag of the selected body's velocity arrow sets its initial
// velocity. The arrow keys, Q, E and Delete act on the selection in every tool (EditTools).

#include "editor/tools/tool.h"

namespace rigidlab::lessons {
struct Scene;
}

namespace rigidlab::ui {

class SelectTool : public Tool {
    Q_DECLARE_TR_FUNCTIONS(rigidlab::ui::EditTools)

public:
    using Tool::Tool;
    bool press(const ToolPointer& pointer) override;
    bool move(const ToolPointer& pointer) override;
    bool release(const ToolPointer& pointer) override;
    bool wantsKey(int key) const override;
    void key(int key) override;
    void paint(QPainter& painter, double zoom) const override;
    QString status() const override;
    bool busy() const override { return m_body >= 0; }
    void cancel() override { m_body = -1; }
    bool marksSnaps() const override { return false; } // a drag marks where the body snaps

private:
    /// Starts dragging the selected body's velocity arrow when `raw` [m] is on its handle
    /// (select_tool_velocity.cpp); true when the press was on the handle.
    bool pressVelocityHandle(const physics::Vec2& raw);
    /// Sets the velocity as the arrow's handle is dragged to `raw` [m]; one undo step a drag.
    void dragVelocity(const physics::Vec2& raw);
    /// "ball: v = (1,5; −2) m/s, |v| = 2,5 m/s", in the locale.
    static QString velocityText(const lessons::Scene& scene, int body);

    int m_body = -1;         ///< the body being dragged, -1 when no drag is under way
    bool m_velocity = false; ///< dragging its velocity arrow rather than the body
    physics::Vec2 m_press = physics::Vec2::Zero();         ///< where the press was [m]
    physics::Vec2 m_grabOffset = physics::Vec2::Zero();    ///< body origin minus the press [m]
    physics::Vec2 m_startVelocity = physics::Vec2::Zero(); ///< at the press [m/s]
    int m_mergeId = -1;
};

} // namespace rigidlab::ui
