#pragma once
// The work-precision diagram: a PlotWidget on log-log axes, error at the end of the run
// against CPU seconds, one line per integrator (the engine's solid, Boost.Odeint's dashed),
// its observed order written at its most accurate point. Rows come one by one (the window's
// background sweep) or all at once (rigidlab-cli error-vs-time --plot); it exports like every
// other plot.

#include "plot_widget.h"

#include "rigidlab/lessons/error_vs_time.h"

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

private:
    void redraw(const QString& integrator);
    int seriesFor(const QString& integrator);

    QString m_problem;
    std::vector<lessons::SweepRow> m_rows;
    std::map<QString, int> m_series;          ///< integrator -> series index
    std::map<QString, QCPItemText*> m_labels; ///< integrator -> its order, owned by plot()
};

} // namespace rigidlab::ui
