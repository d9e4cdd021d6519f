// SPDX-License-Identifier: GPL-3.0-or-later
// The Select tool's velocity arrow: drag its handle to set the selected body's initial
// velocity (one undo step a drag), refused with the loader's words when out of range.

#include "editor/edit_tools.h"
#include "editor/overlay_paint.h"
#include "editor/tools/select_tool.h"
#include "editor/velocity_arrow.h"

#include "edit/scene_edits.h"
#include "panels/number_field.h"

#include <algorithm>

namespace rigidlab::ui {

using physics::Vec2;
namespace edit = lessons::edit;

namespace {

/// A press this close to the arrow's handle grabs it [px].
constexpr double kHandleGrabPixels = 8.0;

} // namespace

bool SelectTool::pressVelocityHandle(const Vec2& raw)
{
    const auto arrow = m_tools.selectedArrow();
    if (!arrow || (arrow->handle - raw).norm() > m_tools.pixelsToMetres(kHandleGrabPixels)) {
        return false;
    }
    if (m_tools.propertyLocked(QStringLiteral("velocity"))) {
        m_tools.say(EditTools::propertyLockedMessage(tr("Velocity")));
        return true; // the press was on the arrow: it neither drags it nor moves the body
    }
    const int selected = m_tools.selectedBody();
    const auto& def = m_tools.scene().bodies[static_cast<size_t>(selected)];
    m_body = selected;
    m_velocity = true;
    m_press = raw;
    m_startVelocity = def.velocity;
    m_mergeId = m_tools.newMergeId();
    m_tools.say(velocityText(m_tools.scene(), selected));
    m_tools.refreshOverlay();
    return true;
}

void SelectTool::dragVelocity(const Vec2& raw)
{
    const lessons::Scene& scene = m_tools.scene();
    if (m_body < 0 || static_cast<size_t>(m_body) >= scene.bodies.size()) {
        return;
    }
    const double step = m_tools.snapping() ? m_tools.gridStep() / kArrowSeconds : 0.0;
    const Vec2 v = draggedVelocity(m_startVelocity, m_press, raw, step);
    const auto& def = scene.bodies[static_cast<size_t>(m_body)];
    if (v == def.velocity) {
        return;
    }
    const QString name = EditTools::bodyName(scene, m_body);
    if (m_tools.apply(tr("Set velocity of %1").arg(name), edit::setBodyVelocity(scene, m_body, v),
                      m_mergeId)) {
        m_tools.say(velocityText(m_tools.scene(), m_body));
    }
}

QString SelectTool::velocityText(const lessons::Scene& scene, int body)
{
    const physics::BodyDef& def = scene.bodies[static_cast<size_t>(body)];
    return tr("%1: v = (%2; %3) m/s, |v| = %4 m/s (arrow: the distance covered in %5 s)")
        .arg(EditTools::bodyName(scene, body), formatNumber(def.velocity.x(), 4),
             formatNumber(def.velocity.y(), 4), formatNumber(def.velocity.norm(), 4),
             formatNumber(kArrowSeconds, 3));
}

void SelectTool::paint(QPainter& painter, double /*zoom*/) const
{
    // The speed beside the handle while it is dragged (the overlay draws the arrow itself).
    if (m_body < 0 || !m_velocity) {
        return;
    }
    if (const auto arrow = m_tools.selectedArrow()) {
        const Vec2 v = (arrow->tip - arrow->tail) / kArrowSeconds;
        overlay::label(painter, arrow->handle,
                       QStringLiteral("v = %1 m/s").arg(formatNumber(v.norm(), 3)));
    }
}

} // namespace rigidlab::ui
