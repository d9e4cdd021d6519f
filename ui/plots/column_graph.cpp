// SPDX-License-Identifier: GPL-3.0-or-later
#include "plots/column_graph.h"

#include <algorithm>
#include <cmath>

namespace rigidlab::ui {

void ColumnGraph::draw(QCPPainter* painter)
{
    if (m_columns.empty() || !keyAxis() || !valueAxis()) {
        QCPGraph::draw(painter);
        return;
    }
    const QCPAxis* keys = keyAxis();
    const QCPAxis* values = valueAxis();
    const QPen pen = this->pen();
    const double width = std::max(1.0, pen.widthF());
    painter->setPen(pen);
    painter->setBrush(Qt::NoBrush);

    QPolygonF run; // the thin columns since the last thick one or gap, as a polyline
    const auto drawRun = [&] {
        if (run.size() >= 2)
            painter->drawPolyline(run);
        run.clear();
    };
    std::vector<QRectF> spans;              // the thick columns, filled after the lines
    bool previous = false;                  // there is a column before this one, since the last gap
    double previousX = 0, previousLast = 0; // [px] where it is and where it ends
    for (const Column& c : m_columns) {
        if (std::isnan(c.low)) {
            drawRun();
            previous = false;
            continue;
        }
        const double x = keys->coordToPixel(c.t);
        double top = values->coordToPixel(c.high), bottom = values->coordToPixel(c.low);
        if (top > bottom)
            std::swap(top, bottom); // a reversed axis
        // The line from the column next to it belongs to this column's pixels too.
        const bool adjacent = previous && std::abs(x - previousX) <= 1.5;
        if (adjacent) {
            top = std::min(top, previousLast);
            bottom = std::max(bottom, previousLast);
        }
        const double last = values->coordToPixel(c.last);
        if (bottom - top <= kThinPx) {
            run.append(QPointF(x, 0.5 * (top + bottom)));
        } else {
            if (!adjacent)
                run.append(QPointF(x, values->coordToPixel(c.first)));
            drawRun();
            spans.emplace_back(x - 0.5 * width, top - 0.5 * width, width, bottom - top + width);
            run.append(QPointF(x, last));
        }
        previous = true;
        previousX = x;
        previousLast = last;
    }
    drawRun();

    // Rectangles need no antialiasing: their edges are whole pixels wide and vertical.
    painter->save();
    painter->setAntialiasing(false);
    for (const QRectF& r : spans)
        painter->fillRect(r, pen.color());
    painter->restore();
    drawMarkers(painter);
}

void ColumnGraph::drawMarkers(QCPPainter* painter) const
{
    if (scatterStyle().isNone() || m_columns.empty())
        return;
    const QCPAxis* keys = keyAxis();
    const QCPAxis* values = valueAxis();
    // Seven phases a spacing apart: the offsets of series 0..6 do not coincide.
    double next = keys->coordToPixel(m_columns.front().t) +
                  std::fmod(m_markerPhase * kMarkerSpacingPx / 7.0, kMarkerSpacingPx);
    QPen markerPen = pen();
    markerPen.setStyle(Qt::SolidLine);
    scatterStyle().applyTo(painter, markerPen);
    for (const Column& c : m_columns) {
        if (std::isnan(c.low))
            continue;
        const double x = keys->coordToPixel(c.t);
        if (x < next)
            continue;
        scatterStyle().drawShape(painter, x, values->coordToPixel(c.last));
        next = x + kMarkerSpacingPx;
    }
}

QCPScatterStyle::ScatterShape plotMarker(int index)
{
    // Shapes that stay apart in greyscale and at 7 px; open ones, so the curve shows through.
    static const QCPScatterStyle::ScatterShape shapes[] = {QCPScatterStyle::ssCircle,
                                                           QCPScatterStyle::ssSquare,
                                                           QCPScatterStyle::ssTriangle,
                                                           QCPScatterStyle::ssDiamond,
                                                           QCPScatterStyle::ssTriangleInverted,
                                                           QCPScatterStyle::ssCross,
                                                           QCPScatterStyle::ssPlus,
                                                           QCPScatterStyle::ssStar};
    const int n = static_cast<int>(std::size(shapes));
    return shapes[((index % n) + n) % n];
}

} // namespace rigidlab::ui
