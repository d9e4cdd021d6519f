// SPDX-License-Identifier: GPL-3.0-or-later
#include "editor/tools/spring_tool.h"

#include "editor/edit_tools.h"
#include "editor/overlay_paint.h"

#include "edit/scene_edits.h"

#include <QPainter>

namespace rigidlab::ui {

using physics::Vec2;
namespace edit = lessons::edit;

QString SpringTool::status() const
{
    return tr("Spring: drag from one point to another (a body or empty space, the world, at "
              "each end); a click draws nothing; Enter hangs the selected body from the world");
}

bool SpringTool::press(const ToolPointer& pointer)
{
    m_bodyA = m_tools.bodyAtOrSnapped(pointer.raw);
    return DragTool::press(pointer);
}

QString SpringTool::sizeText() const
{
    return tr("Spring: length %1 m").arg(m_tools.metres((m_current - m_start).norm()));
}

void SpringTool::finish(const Vec2& end, const Vec2& raw)
{
    add(m_bodyA, m_start, m_tools.bodyAtOrSnapped(raw), end);
}

void SpringTool::addByKey()
{
    const int body = m_tools.selectedBody();
    if (body < 0) {
        m_tools.say(tr("Select a body to hang it from a spring"));
        return;
    }
    const Vec2 centre = m_tools.scene().bodies[static_cast<size_t>(body)].position;
    add(physics::kWorld, centre + Vec2(0.0, kKeyLength * m_tools.gridStep()), body, centre);
}

void SpringTool::add(physics::BodyId a, const Vec2& pointA, physics::BodyId b, const Vec2& pointB)
{
    const lessons::Scene& scene = m_tools.scene();
    const auto result = edit::addSpring(scene, a, pointA, b, pointB, EditTools::kSpringStiffness);
    QString what = tr("Add spring from %1 to %2");
    if (result.ok) {
        const auto& spring = result.scene.springs.back();
        what = what.arg(EditTools::bodyName(scene, spring.a), EditTools::bodyName(scene, spring.b));
    }
    m_tools.apply(what, result);
}

void SpringTool::paint(QPainter& painter, double /*zoom*/) const
{
    if (!m_active) {
        return;
    }
    painter.drawLine(overlay::at(m_start), overlay::at(m_current));
    overlay::label(painter, m_current,
                   QStringLiteral("%1 m").arg(m_tools.metres((m_current - m_start).norm())));
}

} // namespace rigidlab::ui
