// SPDX-License-Identifier: GPL-3.0-or-later
// What WorldView draws under and over the bodies: the grid, the scale bar, the legend of the
// compared worlds, the labels of stopped worlds, and their tooltips.

#include "view/world_view.h"

#include "common/divergence_text.h"
#include "common/number_format.h"
#include "common/theme.h"
#include "plots/plot_widget.h"
#include "simulation/run_view.h"
#include "view/body_item.h"

#include <QHelpEvent>
#include <QLocale>
#include <QPainter>
#include <QToolTip>

#include <algorithm>
#include <array>
#include <cmath>

namespace rigidlab::ui {

void WorldView::drawBackground(QPainter* painter, const QRectF& rect)
{
    // In device pixels and without antialiasing: a solid fill and whole-pixel lines are the
    // raster engine's fast paths (through the view's flipped, scaled transform with
    // antialiasing, this took more of a frame than all the bodies of a 820-box pyramid).
    const QTransform toDevice = painter->worldTransform();
    painter->save();
    painter->resetTransform();
    painter->setRenderHint(QPainter::Antialiasing, false);
    const QRect device = toDevice.mapRect(rect).toAlignedRect();
    painter->fillRect(device, theme::worldBackground());
    // A light grid, 1 m apart (10 m when zoomed far out), so that distances can be read.
    const double step = zoom() < 12 ? 10.0 : (zoom() > 400 ? 0.1 : 1.0);
    painter->setPen(QPen(theme::worldGrid(), 0));
    const double x0 = std::floor(rect.left() / step) * step;
    const double y0 = std::floor(rect.top() / step) * step;
    for (double x = x0; x <= rect.right(); x += step) {
        const int px = qRound(toDevice.map(QPointF(x, 0)).x());
        painter->drawLine(px, device.top(), px, device.bottom());
    }
    for (double y = y0; y <= rect.bottom(); y += step) {
        const int py = qRound(toDevice.map(QPointF(0, y)).y());
        painter->drawLine(device.left(), py, device.right(), py);
    }
    painter->restore();
}

int WorldView::worldCount() const
{
    return static_cast<int>(m_run.variantLabels().size());
}

bool WorldView::stoppedWorld(int world) const
{
    const physics::World& w = world == 0 ? m_run.world() : m_run.variant(world - 1);
    return w.divergence().has_value();
}

QString WorldView::legendLine(int world) const
{
    const QString name = m_run.variantLabels().value(world);
    const physics::World& w = world == 0 ? m_run.world() : m_run.variant(world - 1);
    // A stopped world gets one short line, readable from the back of the room; the numbers
    // (how far the energy grew, which body) are in legendDetail, the line's tooltip.
    if (const auto& d = w.divergence()) {
        const QString time = formatReadable(d->time, 3);
        if (d->kind == physics::Divergence::Kind::EnergyGrowth)
            return tr("%1 — blew up at t = %2 s").arg(name, time);
        return tr("%1 — stopped at t = %2 s: %3").arg(name, time, divergenceShort(*d));
    }
    return world == 0 ? tr("%1 (solid)").arg(name) : tr("%1 (outline)").arg(name);
}

QString WorldView::legendDetail(int world) const
{
    const QString name = m_run.variantLabels().value(world);
    const physics::World& w = world == 0 ? m_run.world() : m_run.variant(world - 1);
    if (const auto& d = w.divergence()) {
        // The variants are copies of the scene's world: the same bodies, the same labels.
        const QString detail = divergenceLabel(*d, m_run.scene().bodyLabel(d->body));
        return world == 0 ? tr("%1 (solid): %2").arg(name, detail)
                          : tr("%1 (outline): %2").arg(name, detail);
    }
    return legendLine(world);
}

bool WorldView::viewportEvent(QEvent* event)
{
    if (event->type() == QEvent::ToolTip) {
        // The legend's short lines: the full diagnosis of a stopped world.
        const auto* help = static_cast<QHelpEvent*>(event);
        const std::vector<QRect> lines = legendLayout();
        for (int i = 0; i < static_cast<int>(lines.size()); ++i) {
            const QRect box = lines[static_cast<std::size_t>(i)].adjusted(-30, -1, 3, 1);
            if (box.contains(help->pos())) {
                QToolTip::showText(help->globalPos(), legendDetail(i), viewport(), box);
                return true;
            }
        }
        QToolTip::hideText();
        event->ignore();
        return true;
    }
    return QGraphicsView::viewportEvent(event);
}

void WorldView::drawForeground(QPainter* painter, const QRectF&)
{
    // A scale bar in screen space, bottom left: a round length of about 120 px.
    painter->save();
    painter->resetTransform();
    const double metres = 120.0 / zoom();
    const double exp10 = std::pow(10.0, std::floor(std::log10(metres)));
    double nice = exp10;
    for (double m : {1.0, 2.0, 5.0})
        if (m * exp10 <= metres)
            nice = m * exp10;
    const int len = static_cast<int>(nice * zoom());
    const QPoint o(16, viewport()->height() - 18);
    painter->setPen(QPen(theme::worldText(), 2));
    painter->drawLine(o, o + QPoint(len, 0));
    painter->drawLine(o + QPoint(0, -5), o + QPoint(0, 5));
    painter->drawLine(o + QPoint(len, -5), o + QPoint(len, 5));
    const QFont f = legendFont();
    painter->setFont(f);
    const QString label = nice >= 1 ? tr("%1 m").arg(QLocale().toString(nice))
                                    : tr("%1 cm").arg(QLocale().toString(nice * 100));
    painter->drawText(o + QPoint(len + 8, 5), label);
    const QFontMetrics fm(legendFont());

    // Which colour is which world, when worlds are compared; a stopped one says why. Each line
    // on a box of the background's colour: the grid (or a body) behind it does not lower its
    // contrast.
    const std::vector<QRect> lines = legendLayout();
    for (int i = 0; i < static_cast<int>(lines.size()); ++i) {
        const QRect& box = lines[static_cast<std::size_t>(i)];
        painter->fillRect(box.adjusted(-30, -1, 3, 1), theme::worldLabelBox());
        painter->fillRect(QRect(14, box.top() + 2, 22, fm.ascent() - 4), plotColor(i));
        painter->setPen(stoppedWorld(i) ? theme::worldAlertText() : theme::worldText());
        painter->drawText(box, Qt::TextWordWrap, legendLine(i));
    }
    // Beside each stopped ghost, in a box of the background's colour (it may lie over bodies
    // or off the view, so it is kept inside), below the one before where they would meet.
    const std::vector<QRect> labels = stoppedLabelRects();
    int k = 0;
    for (int v = 0; v < m_run.variantCount(); ++v) {
        if (!m_run.variant(v).divergence() || !ghostOf(v))
            continue;
        const QRect& box = labels[static_cast<std::size_t>(k++)];
        painter->fillRect(box, theme::worldLabelBox());
        painter->setPen(theme::worldAlertText());
        painter->drawText(box, Qt::AlignCenter, stoppedLabel(v));
        // A cross over the frozen body: this one no longer moves.
        const QPoint c = mapFromScene(ghostOf(v)->sceneBox().center());
        const int r = std::max(6, fm.ascent() / 2);
        painter->setPen(QPen(theme::worldAlertText(), theme::lineWidth(2.5)));
        painter->drawLine(c + QPoint(-r, -r), c + QPoint(r, r));
        painter->drawLine(c + QPoint(-r, r), c + QPoint(r, -r));
    }
    drawBodyLabels(painter);
    painter->restore();
}

QFont WorldView::legendFont() const
{
    QFont f = font();
    f.setPointSizeF(f.pointSizeF() * 1.1);
    return f;
}

std::vector<QRect> WorldView::legendLayout() const
{
    const QFontMetrics fm(legendFont());
    const int width = std::max(120, viewport()->width() - 56);
    std::vector<QRect> out;
    int y = 12;
    for (int i = 0; i < worldCount(); ++i) {
        const QRect box =
            fm.boundingRect(QRect(42, y, width, 10000), Qt::TextWordWrap, legendLine(i));
        out.push_back(box);
        y = box.bottom() + 3;
    }
    return out;
}

int WorldView::legendHeight() const
{
    const std::vector<QRect> lines = legendLayout();
    return lines.empty() ? 0 : lines.back().bottom() + 4;
}

int WorldView::stoppedCount() const
{
    int n = m_run.world().divergence() ? 1 : 0;
    for (int v = 0; v < m_run.variantCount(); ++v)
        n += m_run.variant(v).divergence() ? 1 : 0;
    return n;
}

const BodyItem* WorldView::ghostOf(int variant) const
{
    const auto ghost = std::find_if(m_ghosts.begin(), m_ghosts.end(),
                                    [variant](const Ghost& g) { return g.variant == variant; });
    return ghost == m_ghosts.end() ? nullptr : ghost->item.get();
}

QString WorldView::stoppedLabel(int variant) const
{
    return tr("%1 stopped").arg(m_run.variantLabels().value(variant + 1));
}

std::vector<QRect> WorldView::stoppedLabelRects() const
{
    const QFontMetrics fm(legendFont());
    const QRect inside = viewport()->rect().adjusted(4, legendHeight(), -4, -30);
    std::vector<QRect> out;
    for (int v = 0; v < m_run.variantCount(); ++v) {
        const BodyItem* ghost = ghostOf(v);
        if (!m_run.variant(v).divergence() || !ghost)
            continue;
        const QRect label = fm.boundingRect(stoppedLabel(v)).adjusted(-4, -2, 4, 2);
        const QRect body = mapFromScene(ghost->sceneBox()).boundingRect();
        // Beside the stopped body where the label covers no body (a long label pushed back
        // from the edge lay over the ball it names): above right, above left, below right,
        // below left, right, left; the first one clear, else the first.
        const auto keepInside = [&inside](QRect box) {
            box.moveLeft(std::clamp(box.left(), inside.left(),
                                    std::max(inside.left(), inside.right() - box.width())));
            box.moveTop(std::clamp(box.top(), inside.top(),
                                   std::max(inside.top(), inside.bottom() - box.height())));
            return box;
        };
        const auto coversBody = [this](const QRect& box) {
            for (const auto& item : m_items)
                if (item && item->isVisible() &&
                    mapFromScene(item->sceneBox()).boundingRect().intersects(box))
                    return true;
            for (const Ghost& g : m_ghosts)
                if (g.item && g.item->isVisible() &&
                    mapFromScene(g.item->sceneBox()).boundingRect().intersects(box))
                    return true;
            return false;
        };
        const int w = label.width(), h = label.height();
        const std::array<QPoint, 6> corners{QPoint(body.right() + 6, body.top() - h),
                                            QPoint(body.left() - 6 - w, body.top() - h),
                                            QPoint(body.right() + 6, body.bottom() + 3),
                                            QPoint(body.left() - 6 - w, body.bottom() + 3),
                                            QPoint(body.right() + 6, body.center().y() - h / 2),
                                            QPoint(body.left() - 6 - w, body.center().y() - h / 2)};
        QRect box = keepInside(QRect(corners.front(), label.size()));
        for (const QPoint& corner : corners) {
            const QRect candidate = keepInside(QRect(corner, label.size()));
            if (!coversBody(candidate)) {
                box = candidate;
                break;
            }
        }
        // Stacked below any label it would meet (a ghost that flew off is pinned to an edge,
        // where the others are too).
        for (bool moved = true; moved;) {
            moved = false;
            for (const QRect& other : out)
                if (box.intersects(other)) {
                    box.moveTop(other.bottom() + 3);
                    moved = true;
                }
        }
        out.push_back(box);
    }
    return out;
}

} // namespace rigidlab::ui
