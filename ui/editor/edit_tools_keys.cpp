// SPDX-License-Identifier: GPL-3.0-or-later
// EditTools' keys for what the mouse does to the view in Edit mode: Insert opens a choice of
// the bodies to add at the view's centre (through the tools' own Enter, one undo step each),
// + and − zoom about the middle of the view as the wheel does about the pointer, 0 fits the
// scene, and Ctrl+arrows pan as dragging empty space does.

#include "editor/edit_tools.h"

#include "view/world_view.h"

#include <QAction>
#include <QKeyEvent>
#include <QMenu>
#include <QTimer>

#include <array>

namespace rigidlab::ui {

namespace {

/// One key press zooms by this factor, as one step of the wheel does.
constexpr double kZoomStep = 1.2;
/// One Ctrl+arrow moves the view by this share of its width or height.
constexpr double kPanShare = 0.1;

/// The tools that add a body with Enter, in the order the Insert menu offers them.
constexpr std::array kAddingTools{EditTool::Circle, EditTool::Box, EditTool::Polygon,
                                  EditTool::Ground};

bool isArrow(int key)
{
    return key == Qt::Key_Left || key == Qt::Key_Right || key == Qt::Key_Up || key == Qt::Key_Down;
}

} // namespace

bool EditTools::isViewKey(const QKeyEvent& event)
{
    const Qt::KeyboardModifiers mods =
        event.modifiers() & ~(Qt::KeypadModifier | Qt::ShiftModifier);
    if (mods == Qt::ControlModifier)
        return isArrow(event.key());
    if (mods != Qt::NoModifier)
        return false;
    switch (event.key()) {
    case Qt::Key_Insert:
    case Qt::Key_Plus:
    case Qt::Key_Equal:
    case Qt::Key_Minus:
    case Qt::Key_0:
        return true;
    default:
        return false;
    }
}

bool EditTools::viewKey(const QKeyEvent& event)
{
    if (!isViewKey(event))
        return false;
    const QSize size = m_view.viewport()->size();
    const int dx = static_cast<int>(kPanShare * size.width());
    const int dy = static_cast<int>(kPanShare * size.height());
    switch (event.key()) {
    case Qt::Key_Insert:
        chooseBodyToAdd();
        break;
    case Qt::Key_Plus:
    case Qt::Key_Equal:
        m_view.zoomBy(kZoomStep);
        break;
    case Qt::Key_Minus:
        m_view.zoomBy(1.0 / kZoomStep);
        break;
    case Qt::Key_0:
        m_view.fitScene();
        break;
    case Qt::Key_Left:
        m_view.panBy({-dx, 0});
        break;
    case Qt::Key_Right:
        m_view.panBy({dx, 0});
        break;
    case Qt::Key_Up:
        m_view.panBy({0, -dy});
        break;
    case Qt::Key_Down:
        m_view.panBy({0, dy});
        break;
    default:
        return false;
    }
    refreshOverlay();
    return true;
}

void EditTools::chooseBodyToAdd()
{
    auto* menu = new QMenu(&m_view);
    menu->setAttribute(Qt::WA_DeleteOnClose);
    menu->setObjectName(QStringLiteral("addBodyMenu"));
    menu->setTitle(tr("Add a body at the view's centre"));
    menu->setAccessibleName(menu->title());
    for (const EditTool tool : kAddingTools) {
        QAction* a = menu->addAction(toolAction(tool)->text(), this,
                                     [this, tool] { addBodyAtCentre(tool); });
        a->setEnabled(!locked(tool));
    }
    // Under the middle of the view, where the body goes; the first choice ready for Enter.
    menu->popup(m_view.viewport()->mapToGlobal(m_view.viewport()->rect().center()));
    for (QAction* a : menu->actions())
        if (a->isEnabled()) {
            menu->setActiveAction(a);
            break;
        }
}

void EditTools::addBodyAtCentre(EditTool tool)
{
    setTool(tool); // says why not when a lesson step locks it
    if (m_tool != tool)
        return;
    Tool& t = current();
    if (t.wantsKey(Qt::Key_Return))
        t.key(Qt::Key_Return); // the tool's own body at the view's centre
    // The keys go on in the scene, on the new body: once the menu has closed and the panels
    // that show the edit have changed, which may take the focus.
    QTimer::singleShot(0, &m_view, [view = &m_view] { view->setFocus(Qt::OtherFocusReason); });
}

} // namespace rigidlab::ui
