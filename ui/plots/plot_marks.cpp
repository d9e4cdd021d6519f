// SPDX-License-Identifier: GPL-3.0-or-later
// PlotWidget's marks: a dashed vertical line where a setting changed mid-run, with a short
// label above the plot ("dt = 5 ms"). Labels that would overlap are stacked on rows above one
// another; marks closer than a few pixels share one label:
//
//    dt = 5 ms  Runge–Kutta 4         row 1
//   e = 0.5, μ = 0.3 |  dt = 2 ms     row 0
//   |             |  |  |
//   |             |  |  |             the lines stay where the changes were

#include "plots/plot_widget.h"

#include <qcustomplot.h>

#include <QFontMetricsF>

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <limits>
#include <vector>

namespace rigidlab::ui {

namespace {

constexpr double kMarkLabelPt = 10;
constexpr double kLabelGapPx = 6; // between labels on one row
const QMargins kLabelPadding(3, 0, 3, 1);
const QColor kInk(0x20, 0x20, 0x20);
const QColor kLine(0x60, 0x60, 0x60);
constexpr int kGhostAlpha = 100; // of 255: a mark in the run's abandoned future

QFont markFont(const QFont& base)
{
    QFont f = base;
    f.setPointSizeF(kMarkLabelPt);
    return f;
}

/// Marks close together on screen, sharing one label.
struct MarkGroup {
    std::size_t first = 0; ///< the mark whose label shows the group's
    QStringList texts;
    double x = 0; ///< [px] of the first mark
    double lastX = 0;
};

/// Where a group's label goes.
struct PlacedLabel {
    double left = 0; ///< [px]
    bool leftwards = false;
    std::size_t row = 0;
};

QString groupText(const MarkGroup& g)
{
    return g.texts.join(QStringLiteral(", "));
}

/// The marks in `range` in groups: marks within kMergePx of the one before share its label.
template <class Pixel>
std::vector<MarkGroup> groupMarks(const std::deque<PlotMark>& marks, const QCPRange& range,
                                  Pixel pixel)
{
    std::vector<MarkGroup> groups;
    for (std::size_t i = 0; i < marks.size(); ++i) {
        const PlotMark& mark = marks[i];
        if (!range.contains(mark.t))
            continue;
        const double x = pixel(mark.t);
        if (!groups.empty() && x - groups.back().lastX < PlotWidget::kMergePx &&
            marks[groups.back().first].ghost == mark.ghost) {
            MarkGroup& g = groups.back();
            if (!mark.text.isEmpty() && !g.texts.contains(mark.text))
                g.texts.append(mark.text);
            g.lastX = x;
            continue;
        }
        groups.push_back({i, mark.text.isEmpty() ? QStringList() : QStringList{mark.text}, x, x});
    }
    return groups;
}

/// Each group's label on the lowest of `rows` rows where it overlaps nothing. A label that
/// finds no row is merged into the label before it, and the rows are laid out again (the
/// groups only get fewer, so this ends).
std::vector<PlacedLabel> placeLabels(std::vector<MarkGroup>& groups, const QFontMetricsF& metrics,
                                     double axisPx, std::size_t rows, double rightMarginPx)
{
    std::vector<PlacedLabel> placed;
    for (;;) {
        placed.clear();
        std::vector<double> rowEnd(rows, -std::numeric_limits<double>::infinity());
        std::size_t crowded = 0; // the first group with no room, 0 if none
        for (std::size_t k = 0; k < groups.size() && crowded == 0; ++k) {
            const MarkGroup& g = groups[k];
            const double w = metrics.horizontalAdvance(groupText(g)) + kLabelPadding.left() +
                             kLabelPadding.right();
            // Near the right edge the label reads leftwards from its line, not cut off.
            const bool leftwards = g.x + w > axisPx + rightMarginPx && g.x - w >= 0;
            const double left = leftwards ? g.x - w : g.x;
            std::size_t row = 0;
            while (row < rowEnd.size() && rowEnd[row] + kLabelGapPx > left)
                ++row;
            if (row == rowEnd.size() && k > 0) {
                crowded = k;
                break;
            }
            row = std::min(row, rowEnd.size() - 1);
            rowEnd[row] = left + w;
            placed.push_back({left, leftwards, row});
        }
        if (crowded == 0)
            return placed;
        MarkGroup& into = groups[crowded - 1];
        for (const QString& text : groups[crowded].texts)
            if (!into.texts.contains(text))
                into.texts.append(text);
        into.lastX = groups[crowded].lastX;
        groups.erase(groups.begin() + static_cast<std::ptrdiff_t>(crowded));
    }
}

} // namespace

void PlotWidget::syncMarks()
{
    for (const MarkItems& items : m_markItems) {
        m_plot->removeItem(items.label); // first: it hangs from the line's top
        m_plot->removeItem(items.line);
    }
    m_markItems.clear();
    for (const PlotMark& mark : m_model->marks()) {
        MarkItems items;
        // x in time, y as a fraction of the axis rect: the line spans the plot at any zoom.
        items.line = new QCPItemLine(m_plot);
        for (QCPItemPosition* end : {items.line->start, items.line->end}) {
            end->setAxes(m_plot->xAxis, m_plot->yAxis);
            end->setAxisRect(m_plot->axisRect());
            end->setTypeX(QCPItemPosition::ptPlotCoords);
            end->setTypeY(QCPItemPosition::ptAxisRectRatio);
        }
        items.line->start->setCoords(mark.t, 0); // the top of the axis rect
        items.line->end->setCoords(mark.t, 1);

        // The label sits in a strip above the axis rect, where it hides no curve, its row
        // (fitMarks) a pixel offset up from the line's top; outside the axis rect it is not
        // clipped, so fitMarks() hides it when its line is out of view.
        items.label = new QCPItemText(m_plot);
        items.label->setClipToAxisRect(false);
        items.label->position->setAxes(m_plot->xAxis, m_plot->yAxis);
        items.label->position->setAxisRect(m_plot->axisRect());
        items.label->position->setTypeX(QCPItemPosition::ptPlotCoords);
        items.label->position->setParentAnchorY(items.line->start);
        items.label->position->setTypeY(QCPItemPosition::ptAbsolute);
        items.label->position->setCoords(mark.t, 0);
        items.label->setPadding(kLabelPadding);
        items.label->setFont(markFont(font()));
        items.label->setText(mark.text);

        // A mark in the run's abandoned future is faded and dotted, as its curves are.
        QColor line = kLine, ink = kInk;
        if (mark.ghost) {
            line.setAlpha(kGhostAlpha);
            ink.setAlpha(kGhostAlpha);
        }
        items.line->setPen(QPen(line, 1.5, mark.ghost ? Qt::DotLine : Qt::DashLine));
        items.label->setColor(ink);
        m_markItems.push_back(items);
    }
    fitMarks();
}

QCPItemText* PlotWidget::markLabel(int index) const
{
    return m_markItems.at(static_cast<std::size_t>(index)).label;
}

void PlotWidget::fitMarks(int widthPx)
{
    // The width of the axis rect in pixels: on screen its own; for an export of another
    // width, that width less the same margins.
    const int screenAxisPx = m_plot->axisRect()->width();
    const int marginsPx = m_plot->width() - screenAxisPx;
    double axisPx = screenAxisPx;
    if (widthPx > 0)
        axisPx = m_plot->width() > 0 && marginsPx > 0 ? widthPx - marginsPx : widthPx;
    if (axisPx <= 0)
        axisPx = 800; // never laid out: as prepareGraphs assumes

    const QFontMetricsF metrics(markFont(font()));
    // A row is a label's height: its text, its padding (as addMark sets it) and a pixel.
    const double rowPx =
        std::ceil(metrics.height()) + kLabelPadding.top() + kLabelPadding.bottom() + 1;
    const QCPRange range = m_plot->xAxis->range();
    const auto pixel = [&](double t) { return (t - range.lower) / range.size() * axisPx; };

    const std::deque<PlotMark>& marks = m_model->marks();
    Q_ASSERT(marks.size() == m_markItems.size());
    for (const MarkItems& items : m_markItems)
        items.label->setVisible(false); // until placed
    std::vector<MarkGroup> groups = groupMarks(marks, range, pixel);
    const std::vector<PlacedLabel> placed =
        placeLabels(groups, metrics, axisPx, kMarkRows, kRightMarginPx);
    int rows = marks.empty() ? 0 : 1;
    for (std::size_t k = 0; k < groups.size(); ++k) {
        const PlotMark& mark = marks[groups[k].first];
        QCPItemText* label = m_markItems[groups[k].first].label;
        const QString text = groupText(groups[k]);
        label->setText(text);
        label->setVisible(!text.isEmpty());
        label->setPositionAlignment((placed[k].leftwards ? Qt::AlignRight : Qt::AlignLeft) |
                                    Qt::AlignBottom);
        label->position->setCoords(mark.t, -static_cast<double>(placed[k].row) * rowPx);
        rows = std::max(rows, static_cast<int>(placed[k].row) + 1);
    }

    // Room above the axis rect for the labels' rows, only while there are marks, and at
    // least for the upper half of the top tick label (else it hides under the legend above);
    // and room on the right for the last tick label of the time axis.
    const int strip = rows == 0 ? 0 : static_cast<int>(rows * rowPx) + 4;
    const int top = std::max(strip, QFontMetrics(m_plot->yAxis->tickLabelFont()).height() / 2 + 2);
    if (strip != m_markStrip ||
        m_plot->axisRect()->minimumMargins() != QMargins(0, top, kRightMarginPx, 0)) {
        m_markStrip = strip;
        m_plot->axisRect()->setMinimumMargins(QMargins(0, top, kRightMarginPx, 0));
    }
}

} // namespace rigidlab::ui
