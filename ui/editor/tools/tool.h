// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One of the editor's tools, behind the small interface EditTools dispatches to: what a press,
// a move and a release of the left button do, the keys it takes, what it draws over the world
// while it is in use and what the status line says it does.
//
// A tool holds only its own gesture (the shape being dragged, the polygon's points, the pin's
// first end). The scene, the selection, snapping and the history are EditTools', reached
// through the reference every tool keeps: a tool never touches a world, it hands scene edits
// of lessons/edit/ to EditTools::apply.

#include "rigidlab/physics/math.h"

#include <QCoreApplication>
#include <QPoint>
#include <QString>

class QPainter;

namespace rigidlab::ui {

class EditTools;

/// The pointer, as a tool sees it.
struct ToolPointer {
    physics::Vec2 raw = physics::Vec2::Zero(); ///< under the pointer [m], not snapped
    QPoint pixel;                              ///< in the view's viewport [px]
};

class Tool {
    // The tools speak in the words EditTools always used (one context for the translators);
    // each tool class declares it again, so that lupdate files its strings there too.
    Q_DECLARE_TR_FUNCTIONS(rigidlab::ui::EditTools)
public:
    explicit Tool(EditTools& tools) : m_tools(tools) {}
    virtual ~Tool() = default;
    Tool(const Tool&) = delete;
    Tool& operator=(const Tool&) = delete;

    /// The left button went down; returns whether the tool took it (else the view pans).
    virtual bool press(const ToolPointer& pointer) = 0;
    /// The pointer moved, the button down or not; returns whether the tool took the move.
    virtual bool move(const ToolPointer& /*pointer*/) { return false; }
    /// The left button came up; returns whether the tool took it.
    virtual bool release(const ToolPointer& /*pointer*/) { return false; }
    /// A double-click (its second press); by default a press.
    virtual bool doubleClick(const ToolPointer& pointer) { return press(pointer); }
    /// Whether the tool takes this key now (Return, Escape, Backspace...), before the
    /// window's shortcuts do.
    virtual bool wantsKey(int /*key*/) const { return false; }
    /// The key, when wantsKey said so.
    virtual void key(int /*key*/) {}
    /// What the tool draws over the world while in use, in world coordinates; `zoom` [px/m].
    virtual void paint(QPainter& /*painter*/, double /*zoom*/) const {}
    /// For the status line: what a click and a drag do (and a key, where one does).
    virtual QString status() const = 0;
    /// A gesture is under way (a drag, a polygon's points, a pin's first end).
    virtual bool busy() const = 0;
    /// Drops the gesture under way.
    virtual void cancel() = 0;
    /// Whether the pointer shows where it snaps to other bodies while it hovers.
    virtual bool marksSnaps() const { return true; }

protected:
    EditTools& m_tools;
};

} // namespace rigidlab::ui
