// SPDX-License-Identifier: GPL-3.0-or-later
// The Select tool's velocity arrow: drag its handle to set the selected body's initial
// velocity (one undo step a drag), refused with the loader's words when out of range.

#include "editor/edit_tools.h"

#include "editor/scene_document.h"

#include "edit/scene_edits.h"
#include "panels/number_field.h"
#include "view/world_view.h"

#include <QAction>

#include <algorithm>

namespace rigidlab::ui {

using physics::Vec2;
namespace edit = lessons::edit;

namespace {

/// A press this close to the arrow's handle grabs it [px].
constexpr double kHandleGrabPixels = 8.0;

} // namespace

std::optional<VelocityArrow> EditTools::selectedArrow() const
{
    const lessons::Scene& scene = m_document.scene();
    if (m_selected < 0 || static_cast<size_t>(m_selected) >= scene.bodies.size()) {
        return std::nullopt;
    }
    return velocityArrow(scene.bodies[static_cast<size_t>(m_selected)], m_view.zoom());
}

bool EditTools::pressVelocityHandle(const Vec2& raw)
{
    const auto arrow = selectedArrow();
    const double reach = kHandleGrabPixels / std::max(m_view.zoom(), 1e-9);
    if (!arrow || (arrow->handle - raw).norm() > reach) {
        return false;
    }
    if (propertyLocked(QStringLiteral("velocity"))) {
        say(propertyLockedMessage(tr("Velocity")));
        return true; // the press was on the arrow: it neither drags it nor moves the body
    }
    const auto& def = m_document.scene().bodies[static_cast<size_t>(m_selected)];
    m_drag.active = true;
    m_drag.velocity = true;
    m_drag.body = m_selected;
    m_drag.start = raw;
    m_drag.startVelocity = def.velocity;
    m_drag.mergeId = m_nextMergeId++;
    say(velocityText(def));
    refreshOverlay();
    return true;
}

void EditTools::dragVelocity(const Vec2& raw)
{
    const lessons::Scene& scene = m_document.scene();
    if (m_drag.body < 0 || static_cast<size_t>(m_drag.body) >= scene.bodies.size()) {
        return;
    }
    const double step = m_snapAction->isChecked() ? gridStep() / kArrowSeconds : 0.0;
    const Vec2 v = draggedVelocity(m_drag.startVelocity, m_drag.start, raw, step);
    const auto& def = scene.bodies[static_cast<size_t>(m_drag.body)];
    if (v == def.velocity) {
        return;
    }
    const QString name = QString::fromStdString(def.name);
    if (apply(tr("Set velocity of %1").arg(name), edit::setBodyVelocity(scene, m_drag.body, v),
              m_drag.mergeId)) {
        say(velocityText(m_document.scene().bodies[static_cast<size_t>(m_drag.body)]));
    }
}

QString EditTools::velocityText(const physics::BodyDef& def) const
{
    return tr("%1: v = (%2; %3) m/s, |v| = %4 m/s (arrow: the distance covered in %5 s)")
        .arg(QString::fromStdString(def.name), formatNumber(def.velocity.x(), 4),
             formatNumber(def.velocity.y(), 4), formatNumber(def.velocity.norm(), 4),
             formatNumber(kArrowSeconds, 3));
}

} // namespace rigidlab::ui
