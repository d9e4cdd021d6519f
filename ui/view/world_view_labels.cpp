// SPDX-License-Identifier: GPL-3.0-or-later
// WorldView's body labels: the scene's own name of each body that moves ("ball 1"), drawn
// above it, so that bodies which differ only in colour (the restitution lesson's four balls)
// are told apart by a word as well (WCAG 1.4.1, use of colour). Drawn for a few bodies only:
// a billiards break of sixteen labels would hide the table.
#include "view/world_view.h"

#include "common/theme.h"
#include "simulation/simulation_controller.h"
#include "view/body_item.h"

#include <QPainter>

namespace rigidlab::ui {

namespace {
/// More moving bodies with labels than this, and none is labelled on the scene.
constexpr int kMostBodyLabels = 8;
} // namespace

void WorldView::drawBodyLabels(QPainter* painter) const
{
    const lessons::Scene& scene = m_controller.scene();
    const auto& bodies = m_controller.world().bodies();
    std::vector<int> labelled;
    for (std::size_t i = 0; i < bodies.size(); ++i)
        if (bodies[i].moves() && scene.hasLabel(static_cast<physics::BodyId>(i)))
            labelled.push_back(static_cast<int>(i));
    if (labelled.empty() || labelled.size() > static_cast<std::size_t>(kMostBodyLabels))
        return;
    const QFontMetrics fm(legendFont());
    for (const int id : labelled) {
        const BodyItem* item = itemFor(id);
        if (!item || !item->isVisible())
            continue;
        const QRect body = mapFromScene(item->sceneBoundingRect()).boundingRect();
        const QString text = scene.bodyLabel(id);
        QRect box = fm.boundingRect(text).adjusted(-3, -1, 3, 1);
        box.moveCenter(QPoint(body.center().x(), body.top() - 4 - box.height() / 2));
        if (!viewport()->rect().intersects(box))
            continue;
        painter->fillRect(box, theme::worldLabelBox());
        painter->setPen(theme::worldText());
        painter->drawText(box, Qt::AlignCenter, text);
    }
}

} // namespace rigidlab::ui
