// SPDX-License-Identifier: GPL-3.0-or-later
#include "editor/tools/shape_tools.h"

#include "editor/edit_tools.h"
#include "editor/overlay_paint.h"

#include "edit/scene_edits.h"

#include <QPainter>

#include <cmath>

namespace rigidlab::ui {

using physics::Vec2;
namespace edit = lessons::edit;

namespace {

/// Applies an edit that adds a body ("Add circle %1", the new body's id filled in) and
/// selects the body.
void addBody(EditTools& tools, const QString& what, const edit::EditResult& result)
{
    if (tools.apply(result.ok ? what.arg(EditTools::bodyName(result.scene, result.body)) : what,
                    result)) {
        tools.selectBody(result.body);
    }
}

} // namespace

QString CircleTool::status() const
{
    return tr("Circle: drag from the centre outwards to draw one; a click draws nothing; "
              "Enter adds one at the view's centre");
}

QString CircleTool::sizeText() const
{
    return tr("Circle: centre (%1; %2) m, radius %3 m")
        .arg(m_tools.metres(m_start.x()), m_tools.metres(m_start.y()),
             m_tools.metres((m_current - m_start).norm()));
}

void CircleTool::finish(const Vec2& end, const Vec2& /*raw*/)
{
    addBody(m_tools, tr("Add circle %1"),
            edit::addCircle(m_tools.scene(), m_start, (end - m_start).norm()));
}

void CircleTool::addByKey()
{
    addBody(m_tools, tr("Add circle %1"),
            edit::addCircle(m_tools.scene(), m_tools.viewCentre(), m_tools.gridStep()));
}

void CircleTool::paint(QPainter& painter, double /*zoom*/) const
{
    if (!m_active) {
        return;
    }
    const double r = (m_current - m_start).norm();
    painter.drawEllipse(overlay::at(m_start), r, r);
    painter.drawLine(overlay::at(m_start), overlay::at(m_current));
    overlay::label(painter, m_current, QStringLiteral("r = %1 m").arg(m_tools.metres(r)));
}

QString BoxTool::status() const
{
    return tr("Box: drag from corner to corner to draw one; a click draws nothing; Enter adds "
              "one at the view's centre");
}

QString BoxTool::sizeText() const
{
    const Vec2 size = (m_current - m_start).cwiseAbs();
    return tr("%1 × %2 m").arg(m_tools.metres(size.x()), m_tools.metres(size.y()));
}

void BoxTool::finish(const Vec2& snappedEnd, const Vec2& raw)
{
    Vec2 end = snappedEnd;
    if (m_tools.snapping()) {
        // A thin box whose two edges snap to one grid line keeps one grid step across, the way
        // it was dragged, instead of being refused as flat (a ramp drawn on a 1 m grid).
        for (int k = 0; k < 2; ++k) {
            if (end[k] == m_start[k] && raw[k] != m_start[k]) {
                end[k] =
                    m_start[k] + (raw[k] > m_start[k] ? m_tools.gridStep() : -m_tools.gridStep());
            }
        }
    }
    add(0.5 * (m_start + end), (end - m_start).cwiseAbs());
}

void BoxTool::addByKey()
{
    add(m_tools.viewCentre(), keySize() * m_tools.gridStep());
}

void BoxTool::add(const Vec2& centre, const Vec2& size)
{
    addBody(m_tools, tr("Add box %1"), edit::addBox(m_tools.scene(), centre, size.x(), size.y()));
}

void BoxTool::paint(QPainter& painter, double /*zoom*/) const
{
    if (!m_active) {
        return;
    }
    painter.drawRect(QRectF(overlay::at(m_start), overlay::at(m_current)).normalized());
    overlay::label(painter, m_current,
                   QStringLiteral("%1 × %2 m")
                       .arg(m_tools.metres(std::abs(m_current.x() - m_start.x())),
                            m_tools.metres(std::abs(m_current.y() - m_start.y()))));
}

QString GroundTool::status() const
{
    return tr("Ground: drag from corner to corner to draw static ground or a wall; a click "
              "draws nothing; Enter adds a floor at the view's centre");
}

void GroundTool::add(const Vec2& centre, const Vec2& size)
{
    addBody(m_tools, tr("Add ground %1"),
            edit::addGround(m_tools.scene(), centre, size.x(), size.y()));
}

} // namespace rigidlab::ui
