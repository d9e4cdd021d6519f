// SPDX-License-Identifier: GPL-3.0-or-later
#include "editor/tools/click_tools.h"

#include "editor/edit_tools.h"

#include "edit/scene_edits.h"

#include <algorithm>
#include <cmath>

namespace rigidlab::ui {

using physics::Vec2;

namespace {

/// The body's width along x [m], for placing a duplicate beside it.
double bodyWidth(const physics::BodyDef& def)
{
    return def.shape.visit(
        physics::Overloaded{[](const physics::Circle& c) { return 2.0 * c.radius; },
                            [&def](const physics::Polygon& p) {
                                const physics::Rotation q(def.angle);
                                double lo = 0.0;
                                double hi = 0.0;
                                for (const Vec2& v : p.vertices) {
                                    lo = std::min(lo, q.apply(v).x());
                                    hi = std::max(hi, q.apply(v).x());
                                }
                                return hi - lo;
                            }});
}

} // namespace

QString DeleteTool::status() const
{
    return tr("Delete: click a body to delete it with its springs and pins; the Delete key "
              "deletes the selected body or spring");
}

bool DeleteTool::press(const ToolPointer& pointer)
{
    if (const int body = m_tools.bodyAt(pointer.raw); body >= 0) {
        m_tools.selectBody(body);
        m_tools.deleteSelected();
    }
    return true;
}

QString DuplicateTool::status() const
{
    return tr("Duplicate: click a body to place a copy beside it; Enter copies the selected "
              "body");
}

bool DuplicateTool::press(const ToolPointer& pointer)
{
    if (const int body = m_tools.bodyAt(pointer.raw); body >= 0) {
        duplicate(body);
    }
    return true;
}

bool DuplicateTool::wantsKey(int key) const
{
    return key == Qt::Key_Return || key == Qt::Key_Enter;
}

void DuplicateTool::key(int /*key*/)
{
    if (m_tools.selectedBody() < 0) {
        m_tools.say(tr("Select a body to duplicate it"));
        return;
    }
    duplicate(m_tools.selectedBody());
}

void DuplicateTool::duplicate(int body)
{
    const lessons::Scene& scene = m_tools.scene();
    const auto& def = scene.bodies[static_cast<size_t>(body)];
    const double width = bodyWidth(def);
    const double g = m_tools.gridStep();
    const double offset = m_tools.snapping() ? std::ceil(width / g) * g : width;
    const QString name = EditTools::bodyName(scene, body);
    const auto result = lessons::edit::duplicateBody(scene, body, Vec2(offset, 0.0));
    if (m_tools.apply(
            tr("Duplicate %1 as %2").arg(name, EditTools::bodyName(result.scene, result.body)),
            result)) {
        m_tools.selectBody(result.body);
    }
}

} // namespace rigidlab::ui
