// SPDX-License-Identifier: GPL-3.0-or-later
// WorldView's body labels: the scene's own name of each body that moves ("ball 1"), drawn
// above it, so that bodies which differ only in colour (the restitution lesson's four balls)
// are told apart by a word as well (WCAG 1.4.1, use of colour). Drawn for a few bodies only:
// a billiards break of sixteen labels would hide the table. Where they go is label_layout.h's:
// inside the view, and below the body or a row further out where another label is.
#include "view/world_view.h"

#include "common/theme.h"
#include "simulation/run_view.h"
#include "view/body_item.h"
#include "view/label_layout.h"

#include <QPainter>

namespace rigidlab::ui {

namespace {
/// More moving bodies with labels than this, and none is labelled on the scene.
constexpr int kMostBodyLabels = 8;
} // namespace

std::vector<std::pair<int, QRect>> WorldView::bodyLabelRects() const
{
    const lessons::Scene& scene = m_run.scene();
    const auto& bodies = m_run.world().bodies();
    std::vector<int> labelled;
    for (std::size_t i = 0; i < bodies.size(); ++i)
        if (bodies[i].moves() && scene.hasLabel(static_cast<physics::BodyId>(i)))
            labelled.push_back(static_cast<int>(i));
    if (labelled.empty() || labelled.size() > static_cast<std::size_t>(kMostBodyLabels))
        return {};
    const QFontMetrics fm(legendFont());
    const QRect area = viewport()->rect();
    std::vector<int> shown;
    std::vector<LabelWish> wishes;
    for (const int id : labelled) {
        const BodyItem* item = itemFor(id);
        if (!item || !item->isVisible())
            continue;
        const QRect body = mapFromScene(item->sceneBox()).boundingRect();
        if (!area.intersects(body)) // out of sight: a label at the edge would point nowhere
            continue;
        shown.push_back(id);
        wishes.push_back(
            {fm.boundingRect(scene.bodyLabel(id)).adjusted(-3, -1, 3, 1).size(), body});
    }
    // The legend of compared worlds and the "… stopped" labels are there first.
    std::vector<QRect> taken;
    for (const QRect& r : legendLayout())
        taken.push_back(r.adjusted(-30, -1, 3, 1)); // with its colour swatch, as drawn
    for (const QRect& r : stoppedLabelRects())
        taken.push_back(r);
    const std::vector<QRect> boxes = placeLabels(wishes, area, std::move(taken));
    std::vector<std::pair<int, QRect>> placed;
    for (std::size_t i = 0; i < shown.size(); ++i)
        placed.emplace_back(shown[i], boxes[i]);
    return placed;
}

void WorldView::drawBodyLabels(QPainter* painter) const
{
    const lessons::Scene& scene = m_run.scene();
    for (const auto& [id, box] : bodyLabelRects()) {
        painter->fillRect(box, theme::worldLabelBox());
        painter->setPen(theme::worldText());
        painter->drawText(box, Qt::AlignCenter, scene.bodyLabel(id));
    }
}

} // namespace rigidlab::ui
