// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A QCPGraph that draws a dense curve column by column, at a cost that does not depend on
// its values.
//
// Qt's raster engine fills an antialiased path by sorting, on every scanline, the edges that
// cross it. A line that zigzags the full height of the plot in every pixel column (Verlet's
// energy, rounding noise on a tight axis) crosses each scanline hundreds of times, and one
// replot took 40-70 ms for a curve of 450 columns. What such a line covers in a column is
// the run of pixels from its lowest to its highest value there: drawn as that run, a filled
// rectangle, it costs a few spans.
//
//   per column:   its pixels run from its lowest to its highest value, and to where the
//                 column next to it ends (the line between them is in its pixels too);
//                 thin (that run within kThinPx): a vertex of an antialiased polyline;
//                 thick: a rectangle over that run, pen-wide, and a line from its last
//                 value on to the next thin column.
//
//        |  |||                               thin    thick     thin
//   ___/ |  ||| \___                          .__.  |||||||  .__.
//
// Without columns (setColumns with none) it is a plain QCPGraph of its data.

#include "plots/plot_series.h"

#include <qcustomplot.h>

#include <vector>

namespace rigidlab::ui {

/// The marker of a plot's index-th series (circle, square, triangle, ...; it cycles after 8):
/// with the line style, what tells the series apart in greyscale and for colour-blind eyes.
QCPScatterStyle::ScatterShape plotMarker(int index);

class ColumnGraph : public QCPGraph {
public:
    /// One pixel column of a dense curve [s, unit of the value]. A NaN `low` is a gap.
    struct Column {
        double t = 0;     ///< a time within the column [s]
        double low = 0;   ///< the lowest value in the column
        double high = 0;  ///< the highest
        double first = 0; ///< the value the column starts with
        double last = 0;  ///< the value it ends with
    };
    /// Columns thinner than this [px] are drawn as a line through their middle.
    static constexpr double kThinPx = 2.0;

    ColumnGraph(QCPAxis* keyAxis, QCPAxis* valueAxis) : QCPGraph(keyAxis, valueAxis) {}

    /// Markers on a dense curve are this far apart [px]; each series starts them at its own
    /// offset (setMarkerPhase), so that curves lying on one another show every marker.
    static constexpr double kMarkerSpacingPx = 56.0;
    /// The index of the series among its plot's, for the offset of its markers.
    void setMarkerPhase(int index) { m_markerPhase = index; }

    /// Takes the points to draw for the time range [from, to] [s] spread over `columns` pixel
    /// columns (on a log time axis if `logKeys`): the points in range and the one on either
    /// side, as they are if there are few, else each column's lowest and highest, in the
    /// order they came, and the columns. A gap (NaN) stays a gap. At most 3 * columns + 6
    /// points, whatever the data.
    void setPoints(const std::vector<PlotPoint>& points, double from, double to, int columns,
                   bool logKeys);
    /// Draws these columns instead of the data; empty: the data, as a QCPGraph does.
    void setColumns(std::vector<Column> columns) { m_columns = std::move(columns); }
    const std::vector<Column>& columns() const { return m_columns; }

protected:
    void draw(QCPPainter* painter) override;

private:
    /// The markers along the columns (the scatter style's shape), one every kMarkerSpacingPx.
    void drawMarkers(QCPPainter* painter) const;

    std::vector<Column> m_columns;
    int m_markerPhase = 0;
};

} // namespace rigidlab::ui
