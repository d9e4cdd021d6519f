#include "plot_series.h"

#include <qcustomplot.h>

#include <cmath>
#include <limits>
#include <utility>

namespace rigidlab::ui {

PlotSeries::PlotSeries(QCPGraph* graph, QString name, YAxis axis, SampleValue value)
    : m_graph(graph), m_name(std::move(name)), m_axis(axis), m_value(std::move(value))
{
    Q_ASSERT(m_graph);
}

int PlotSeries::size() const
{
    return m_graph->data()->size();
}

double PlotSeries::firstKey() const
{
    Q_ASSERT(!isEmpty());
    return m_graph->data()->constBegin()->key;
}

double PlotSeries::lastKey() const
{
    Q_ASSERT(!isEmpty());
    return (m_graph->data()->constEnd() - 1)->key;
}

void PlotSeries::append(double t, double value, int budget)
{
    Q_ASSERT(isEmpty() || t > lastKey());
    QCPGraphDataContainer& data = *m_graph->data();
    const bool keep = data.isEmpty() || m_sinceKept + 1 >= m_stride;

    if (m_lastIsProvisional) {
        // The provisional point moves on with the run; the keys stay sorted since t is later.
        auto last = data.end() - 1;
        last->key = t;
        last->value = value;
    } else {
        data.add(QCPGraphData(t, value));
    }

    if (keep) {
        m_sinceKept = 0;
        m_lastIsProvisional = false;
    } else {
        ++m_sinceKept;
        m_lastIsProvisional = true;
    }
    if (data.size() > budget)
        decimate();
}

void PlotSeries::decimate()
{
    QCPGraphDataContainer& data = *m_graph->data();
    const int kept = data.size() - (m_lastIsProvisional ? 1 : 0);

    QVector<QCPGraphData> thinned;
    thinned.reserve(kept / 2 + 2);
    auto it = data.constBegin();
    for (int i = 0; i < kept; i += 2)
        thinned.append(*(it + i));

    // With an even count the newest kept point is among the dropped ones: it stays as the
    // provisional end of the curve, and the next kept point comes a whole new stride after
    // the last surviving one.
    const bool lastKeptDropped = kept % 2 == 0;
    if (m_lastIsProvisional || lastKeptDropped)
        thinned.append(*(data.constEnd() - 1));
    if (lastKeptDropped) {
        m_sinceKept += m_stride;
        m_lastIsProvisional = true;
    }
    m_stride *= 2;
    data.set(thinned, true);
}

void PlotSeries::removeBefore(double t, int budget)
{
    m_graph->data()->removeBefore(t);
    if (isEmpty()) {
        m_lastIsProvisional = false;
        m_sinceKept = 0;
    }
    afterRemoval(budget);
}

void PlotSeries::removeAfter(double t, int budget)
{
    m_graph->data()->removeAfter(t);
    // What is left ends on a point that now counts as kept.
    m_lastIsProvisional = false;
    m_sinceKept = 0;
    afterRemoval(budget);
}

void PlotSeries::removeFrom(double t, int budget)
{
    removeAfter(std::nextafter(t, -std::numeric_limits<double>::infinity()), budget);
}

void PlotSeries::clear()
{
    m_graph->data()->clear();
    m_stride = 1;
    m_sinceKept = 0;
    m_lastIsProvisional = false;
}

void PlotSeries::afterRemoval(int budget)
{
    // Once few points are left (after a rewind, or scrolling past a burst), new points may
    // come denser again; the old sparse ones scroll out or stay as they are.
    if (m_stride > 1 && size() * 4 < budget)
        m_stride /= 2;
}

} // namespace rigidlab::ui
