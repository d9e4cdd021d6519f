// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The tools that draw a body by dragging: a circle from its centre, a box and the ground
// (a static box) corner to corner. Return adds one at the view's centre.

#include "editor/tools/drag_tool.h"

namespace rigidlab::lessons::edit {
struct EditResult;
}

namespace rigidlab::ui {

class CircleTool : public DragTool {
    Q_DECLARE_TR_FUNCTIONS(rigidlab::ui::EditTools)

public:
    using DragTool::DragTool;
    void paint(QPainter& painter, double zoom) const override;
    QString status() const override;

protected:
    void finish(const physics::Vec2& end, const physics::Vec2& raw) override;
    QString sizeText() const override;
    void addByKey() override;
};

class BoxTool : public DragTool {
    Q_DECLARE_TR_FUNCTIONS(rigidlab::ui::EditTools)

public:
    using DragTool::DragTool;
    void paint(QPainter& painter, double zoom) const override;
    QString status() const override;

protected:
    void finish(const physics::Vec2& end, const physics::Vec2& raw) override;
    QString sizeText() const override;
    void addByKey() override;
    /// Adds the box centred at `centre` [m], `size` [m] wide and high, and selects it.
    virtual void add(const physics::Vec2& centre, const physics::Vec2& size);
    /// The size Return gives it, in grid steps.
    virtual physics::Vec2 keySize() const { return {2.0, 1.0}; }
};

/// A static box: the ground, a wall, a ramp.
class GroundTool : public BoxTool {
    Q_DECLARE_TR_FUNCTIONS(rigidlab::ui::EditTools)

public:
    using BoxTool::BoxTool;
    QString status() const override;

protected:
    void add(const physics::Vec2& centre, const physics::Vec2& size) override;
    physics::Vec2 keySize() const override { return {10.0, 1.0}; }
};

} // namespace rigidlab::ui
