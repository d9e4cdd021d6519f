// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The work-precision diagram: a PlotWidget on log-log axes, error at the end of the run
// against CPU seconds, one line per integrator (the engine's solid, Boost.Odeint's dashed),
// its observed order written at its most accurate point. Rows come one by one (the window's
// background sweep) or all at once (rigidlab-cli error-vs-time --plot); it exports like every
// other plot.

#include "plots/plot_widget.h"

#include "numerics/error_vs_time.h"

#include <QPointF>
#include <QRectF>
#include <QString>

#include <map>
#include <vector>

class QCPItemText;

namespace rigidlab::ui {

class WorkPrecisionPlot : public PlotWidget {
    Q_OBJECT
public:
    explicit WorkPrecisionPlot(QWidget* parent = nullptr);

    /// Shows only this problem's rows (the title says which).
    void setProblem(const QString& problem);
    QString problem() const { return m_problem; }
    /// Adds a row of the sweep (rows of other problems are kept, for setProblem).
    void addRow(const lessons::SweepRow& row);
    void setRows(const std::vector<lessons::SweepRow>& rows);
    const std::vector<lessons::SweepRow>& rows() const { return m_rows; }
    /// Forgets every row.
    void clearRows();
    /// The order written next to an integrator's line, or an empty string.
    QString orderLabel(const QString& integrator) const;
    /// Where each integrator's order label was drawn, in the plot's pixels (for tests).
    const std::map<QString, QRectF>& labelBoxes() const { return m_labelBoxes; }
    /// The diagram is at least this tall, so that its decades can be read [px].
    static constexpr int kMinPlotHeight = 300;

private slots:
    void arrangeLabels();

private:
    /// "p = 2.0", or in words why the order cannot be measured.
    QString orderText(const QString& integrator) const;
    void redraw(const QString& integrator);
    int seriesFor(const QString& integrator);

    QString m_problem;
    std::vector<lessons::SweepRow> m_rows;
    std::map<QString, int> m_series;          ///< integrator -> series index
    std::map<QString, QCPItemText*> m_labels; ///< integrator -> its order, owned by plot()
    std::map<QString, QPointF> m_anchors;     ///< integrator -> its most accurate point [s, m]
    std::map<QString, QRectF> m_labelBoxes;   ///< integrator -> where its label was drawn [px]
};

} // namespace rigidlab::ui
