// SPDX-License-Identifier: GPL-3.0-or-later
#include "plots/plot_accessible.h"

#include "common/spoken_numbers.h"
#include "plots/plot_widget.h"

#include <qcustomplot.h>

#include <QAccessibleWidget>
#include <QCoreApplication>
#include <QStringList>

#include <algorithm>
#include <cmath>

namespace rigidlab::ui {

namespace {

/// The translation context of a plot in words.
struct PlotWords {
    Q_DECLARE_TR_FUNCTIONS(PlotWords)
};

QString axisText(const QCPAxis& axis)
{
    const QCPRange r = axis.range();
    return PlotWords::tr("%1, from %2 to %3")
        .arg(axis.label(), spokenReadable(r.lower, 3, r.size()),
             spokenReadable(r.upper, 3, r.size()));
}

QString seriesText(const PlotModel& plot, int series)
{
    const std::vector<QPointF> points = plot.points(series);
    const QString unit = plot.seriesUnit(series);
    const double scale = plot.seriesScale(series);
    QString lowest, highest, now;
    bool found = false;
    double lo = 0, hi = 0;
    for (const QPointF& p : points) {
        if (!std::isfinite(p.y()))
            continue;
        lo = found ? std::min(lo, p.y()) : p.y();
        hi = found ? std::max(hi, p.y()) : p.y();
        found = true;
    }
    if (!found)
        return PlotWords::tr("%1: no values yet").arg(plot.seriesLegend(series));
    const auto quantity = [&](double v) { return spokenQuantity(v, unit, 4, scale); };
    return PlotWords::tr("%1: now %2, least %3, greatest %4")
        .arg(plot.seriesLegend(series), quantity(points.back().y()), quantity(lo), quantity(hi));
}

/// The interface of a PlotWidget and of the QCustomPlot it draws with.
class PlotAccessible : public QAccessibleWidget {
public:
    PlotAccessible(QWidget* widget, const PlotWidget* plot)
        : QAccessibleWidget(widget, QAccessible::Chart), m_plot(plot)
    {
    }
    QString text(QAccessible::Text t) const override
    {
        if (t == QAccessible::Name)
            return m_plot->title();
        if (t == QAccessible::Description)
            return describePlot(*m_plot);
        return QAccessibleWidget::text(t);
    }

private:
    const PlotWidget* m_plot;
};

} // namespace

QAccessibleInterface* plotInterface(const QString& className, QObject* object)
{
    if (!object || !object->isWidgetType())
        return nullptr;
    auto* widget = static_cast<QWidget*>(object);
    if (className == QLatin1String(PlotWidget::staticMetaObject.className()))
        return new PlotAccessible(widget, static_cast<const PlotWidget*>(widget));
    if (className == QLatin1String("QCustomPlot"))
        if (const auto* plot = qobject_cast<const PlotWidget*>(widget->parentWidget()))
            return new PlotAccessible(widget, plot);
    return nullptr;
}

QString describePlot(const PlotWidget& plot)
{
    QStringList parts;
    parts << PlotWords::tr("Plot %1.").arg(plot.title());
    const QCustomPlot& p = *plot.plot();
    parts << PlotWords::tr("Horizontal axis: %1.").arg(axisText(*p.xAxis));
    parts << PlotWords::tr("Vertical axis: %1.").arg(axisText(*p.yAxis));
    if (p.yAxis2->visible())
        parts << PlotWords::tr("Right axis: %1.").arg(axisText(*p.yAxis2));
    for (int i = 0; i < plot.model().seriesCount(); ++i)
        parts << seriesText(plot.model(), i) + QLatin1Char('.');
    return parts.join(QLatin1Char(' '));
}

} // namespace rigidlab::ui
