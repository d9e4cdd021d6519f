// SPDX-License-Identifier: GPL-3.0-or-later
#include "editor/tools/polygon_tool.h"

#include "editor/edit_tools.h"
#include "editor/overlay_paint.h"

#include "edit/scene_edits.h"

#include <QPainter>

namespace rigidlab::ui {

using physics::Vec2;
namespace edit = lessons::edit;

QString PolygonTool::status() const
{
    return tr("Polygon: click the vertices, then double-click or press Enter to close it; "
              "Backspace drops the last point; Enter with no points adds a triangle");
}

bool PolygonTool::press(const ToolPointer& pointer)
{
    m_points.push_back(m_tools.snapped(pointer.raw));
    m_pointer = m_points.back();
    if (const auto preview = edit::previewPolygon(m_points); !preview.warning.isEmpty()) {
        m_tools.say(tr("Not convex: it will be replaced by the convex hull shown"));
    } else {
        m_tools.say(tr("%n point(s); double-click or Enter closes the polygon, Escape drops it", "",
                       static_cast<int>(m_points.size())));
    }
    m_tools.refreshOverlay();
    return true;
}

bool PolygonTool::move(const ToolPointer& pointer)
{
    m_pointer = m_tools.snapped(pointer.raw);
    return false;
}

bool PolygonTool::doubleClick(const ToolPointer& pointer)
{
    // The double-click's point, unless its first click placed it already.
    const Vec2 p = m_tools.snapped(pointer.raw);
    if (m_points.empty() || m_points.back() != p) {
        m_points.push_back(p);
    }
    close();
    return true;
}

bool PolygonTool::wantsKey(int key) const
{
    return key == Qt::Key_Return || key == Qt::Key_Enter ||
           (key == Qt::Key_Backspace && !m_points.empty());
}

void PolygonTool::key(int key)
{
    if (key == Qt::Key_Backspace) {
        m_points.pop_back();
        m_tools.refreshOverlay();
        return;
    }
    if (!m_points.empty()) {
        close();
        return;
    }
    // A right triangle two grid steps on a side, its right angle below on the right.
    const Vec2 c = m_tools.viewCentre();
    const double g = m_tools.gridStep();
    add({c + Vec2(-g, -g), c + Vec2(g, -g), c + Vec2(g, g)});
}

void PolygonTool::close()
{
    if (m_points.empty()) {
        return;
    }
    const std::vector<Vec2> points = m_points;
    m_points.clear();
    add(points);
    m_tools.refreshOverlay();
}

void PolygonTool::add(const std::vector<Vec2>& points)
{
    const auto result = edit::addPolygon(m_tools.scene(), points);
    if (m_tools.apply(tr("Add polygon %1").arg(EditTools::bodyName(result.scene, result.body)),
                      result)) {
        m_tools.selectBody(result.body);
    }
}

void PolygonTool::paint(QPainter& painter, double zoom) const
{
    if (m_points.empty()) {
        return;
    }
    QPolygonF line;
    for (const Vec2& p : m_points) {
        line << overlay::at(p);
    }
    line << overlay::at(m_pointer);
    painter.drawPolyline(line);
    // The hull that will be accepted, dashed, once the outline is not convex.
    const auto preview = edit::previewPolygon(m_points);
    if (preview.ok && !preview.warning.isEmpty()) {
        QPolygonF hull;
        for (const Vec2& p : preview.hull) {
            hull << overlay::at(p);
        }
        painter.setPen(overlay::cosmetic(QColor(200, 100, 0), 2, Qt::DashLine));
        painter.drawPolygon(hull);
    }
    const double r = 3.0 / zoom;
    painter.setBrush(overlay::accent());
    for (const Vec2& p : m_points) {
        painter.drawEllipse(overlay::at(p), r, r);
    }
    painter.setBrush(Qt::NoBrush);
    overlay::label(painter, m_pointer,
                   QStringLiteral("(%1; %2) m")
                       .arg(m_tools.metres(m_pointer.x()), m_tools.metres(m_pointer.y())));
}

} // namespace rigidlab::ui
