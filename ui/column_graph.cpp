#include "column_graph.h"

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
    std::vector<QRectF> spans; // the thick columns, filled after the lines
    bool previousThick = false;
    double previousLast = 0; // [px] where the previous thick column ends
    for (const Column& c : m_columns) {
        if (std::isnan(c.low)) {
            drawRun();
            previousThick = false;
            continue;
        }
        const double x = keys->coordToPixel(c.t);
        double top = values->coordToPixel(c.high), bottom = values->coordToPixel(c.low);
        if (top > bottom)
            std::swap(top, bottom); // a reversed axis
        if (bottom - top <= kThinPx) {
            run.append(QPointF(x, 0.5 * (top + bottom)));
            previousThick = false;
            continue;
        }
        if (previousThick) {
            // Joined to the thick column before by its own span, not by a line.
            top = std::min(top, previousLast);
            bottom = std::max(bottom, previousLast);
        } else {
            run.append(QPointF(x, values->coordToPixel(c.first)));
        }
        drawRun();
        spans.emplace_back(x - 0.5 * width, top - 0.5 * width, width, bottom - top + width);
        previousThick = true;
        previousLast = values->coordToPixel(c.last);
        run.append(QPointF(x, previousLast));
    }
    drawRun();

    // Rectangles need no antialiasing: their edges are whole pixels wide and vertical.
    painter->save();
    painter->setAntialiasing(false);
    for (const QRectF& r : spans)
        painter->fillRect(r, pen.color());
    painter->restore();
}

} // namespace rigidlab::ui
