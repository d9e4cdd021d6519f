// SPDX-License-Identifier: GPL-3.0-or-later
#include "plots/column_graph.h"

#include <algorithm>
#include <cmath>
#include <limits>

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

namespace {

/// Up to this many points a curve is drawn point by point.
constexpr std::size_t kFewPoints = 64;

bool earlier(const PlotPoint& p, double t)
{
    return p.t < t;
}

bool later(double t, const PlotPoint& p)
{
    return t < p.t;
}

using PointIt = std::vector<PlotPoint>::const_iterator;

/// Points drawn one by one, with their markers if any.
void drawAsTheyAre(PointIt begin, PointIt end, ColumnGraph* graph)
{
    QVector<QCPGraphData> drawn;
    drawn.reserve(static_cast<qsizetype>(end - begin));
    for (auto it = begin; it != end; ++it)
        drawn.append(QCPGraphData(it->t, it->v));
    graph->data()->set(drawn, true);
    graph->setColumns({});
}

} // namespace

void ColumnGraph::setPoints(const std::vector<PlotPoint>& points, double from, double to,
                            int columns, bool logKeys)
{
    // The points in range, and one on either side so that the line reaches the edges.
    auto begin = std::lower_bound(points.begin(), points.end(), from, earlier);
    auto end = std::upper_bound(begin, points.end(), to, later);
    if (begin != points.begin())
        --begin;
    if (end != points.end())
        ++end;
    const auto count = static_cast<std::size_t>(end - begin);
    columns = std::max(columns, 1);

    const bool log = logKeys && from > 0 && to > from;
    // A few points are drawn as they are (with their markers, if any). More go by pixel
    // column: spread over the few columns of a run's first second, 200 points of a zigzag
    // cost as much as 2000. Markers without a line (measured points) are each a point.
    if (count <= kFewPoints || !(to > from) || lineStyle() == QCPGraph::lsNone) {
        drawAsTheyAre(begin, end, this);
        return;
    }

    // Which pixel column a time falls in; the neighbours outside the range get their own.
    const double span = log ? std::log(to / from) : to - from;
    const auto columnOf = [&](double t) {
        const double x = (log ? std::log(t / from) : t - from) / span * columns;
        return static_cast<long long>(std::floor(std::clamp(x, -1.0, double(columns))));
    };

    constexpr double kGap = std::numeric_limits<double>::quiet_NaN();
    QVector<QCPGraphData> drawn;
    std::vector<ColumnGraph::Column> dense;
    dense.reserve(static_cast<std::size_t>(2 * columns + 4));
    drawn.reserve(3 * columns + 6);
    long long column = std::numeric_limits<long long>::min();
    auto first = end, last = end, lowest = end, highest = end; // end while the column is empty
    double gapT = kGap; // the column's last gap [s], NaN if none
    const auto flush = [&] {
        if (first != end) {
            // In the order they came, so the line runs through the column as the data did.
            const auto a = std::min(lowest, highest), b = std::max(lowest, highest);
            drawn.append(QCPGraphData(a->t, a->v));
            if (b != a)
                drawn.append(QCPGraphData(b->t, b->v));
            dense.push_back({first->t, lowest->v, highest->v, first->v, last->v});
        }
        // One gap per column that has one, after its extremes (their order within a column
        // is below a pixel); the keys stay sorted.
        const bool lastIsGap = !drawn.isEmpty() && std::isnan(drawn.back().value);
        if (!std::isnan(gapT) && !lastIsGap) {
            const double t = drawn.isEmpty() ? gapT : std::max(gapT, drawn.back().key);
            drawn.append(QCPGraphData(t, kGap));
            dense.push_back({t, kGap, kGap, kGap, kGap});
        }
        first = last = lowest = highest = end;
        gapT = kGap;
    };
    for (auto it = begin; it != end; ++it) {
        const long long c = columnOf(it->t);
        if (c != column) {
            flush();
            column = c;
        }
        if (std::isnan(it->v)) {
            gapT = it->t;
            continue;
        }
        if (first == end)
            first = it;
        last = it;
        if (lowest == end || it->v < lowest->v)
            lowest = it;
        if (highest == end || it->v > highest->v)
            highest = it;
    }
    flush();
    data()->set(drawn, true);
    setColumns(std::move(dense));
}

} // namespace rigidlab::ui
