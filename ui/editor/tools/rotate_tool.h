// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The Rotate tool: a drag turns a body (the one pressed, else the selected one) about its
// origin, in steps of 15° with the grid on. Q and E turn the selection by 5° (EditTools).

#include "editor/tools/tool.h"

namespace rigidlab::ui {

class RotateTool : public Tool {
    Q_DECLARE_TR_FUNCTIONS(rigidlab::ui::EditTools)

public:
    using Tool::Tool;
    bool press(const ToolPointer& pointer) override;
    bool move(const ToolPointer& pointer) override;
    bool release(const ToolPointer& pointer) override;
    bool wantsKey(int key) const override;
    void key(int key) override;
    QString status() const override;
    bool busy() const override { return m_body >= 0; }
    void cancel() override { m_body = -1; }
    bool marksSnaps() const override { return false; }

private:
    int m_body = -1;             ///< the body being turned, -1 when no drag is under way
    double m_startAngle = 0.0;   ///< the body's angle at the press [rad]
    double m_pointerAngle = 0.0; ///< the pointer's angle about the origin at the press [rad]
    int m_mergeId = -1;
};

} // namespace rigidlab::ui
