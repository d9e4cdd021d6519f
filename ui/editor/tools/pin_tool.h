// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The Pin tool: click a point of a body, then a second body or empty space (the world).
// Enter pins the selected body (or the point clicked first) to the world.

#include "editor/tools/tool.h"

#include "rigidlab/physics/forces.h"

#include <optional>
#include <utility>

namespace rigidlab::ui {

class PinTool : public Tool {
    Q_DECLARE_TR_FUNCTIONS(rigidlab::ui::EditTools)

public:
    using Tool::Tool;
    bool press(const ToolPointer& pointer) override;
    bool wantsKey(int key) const override;
    void key(int key) override;
    void paint(QPainter& painter, double zoom) const override;
    QString status() const override;
    bool busy() const override { return m_start.has_value(); }
    void cancel() override { m_start.reset(); }

private:
    /// Pins the first end to `body` (-1: the world).
    void pinTo(physics::BodyId body);

    /// The pin being placed: its body and point [m], after the first click.
    std::optional<std::pair<physics::BodyId, physics::Vec2>> m_start;
};

} // namespace rigidlab::ui
