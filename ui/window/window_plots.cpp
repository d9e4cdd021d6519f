// SPDX-License-Identifier: GPL-3.0-or-later
#include "window/window_plots.h"

#include "plots/plot_export.h"
#include "plots/plot_exporter.h"
#include "plots/plot_turns.h"
#include "plots/plot_widget.h"
#include "simulation/history.h"
#include "simulation/run_view.h"
#include "simulation/sample_recorder.h"
#include "window/window_documents.h"

#include <QCoreApplication>
#include <QMainWindow>
#include <QMenu>
#include <QPointer>
#include <QStatusBar>

namespace rigidlab::ui {

namespace {

/// The translation context of the export texts.
struct PlotExportMenu {
    Q_DECLARE_TR_FUNCTIONS(PlotExportMenu)
};

void exportPlotDialog(QWidget& window, PlotWidget& plot, const QString& format)
{
    // The plot's own dialog (folder, proposed name, CSV dialect), then a word in the status bar.
    const QString path = plot.exporter().exportInteractively(*formatFromSuffix(format.toLower()));
    if (auto* main = qobject_cast<QMainWindow*>(&window); main && !path.isEmpty())
        main->statusBar()->showMessage(PlotExportMenu::tr("Exported %1").arg(path), 5000);
}

} // namespace

void followController(PlotWidget& plot, const RunView& run, PlotTurns& turns)
{
    // The live samples, cleared with a new scene, cut back on a rewind, marked where a setting
    // changed, drained after the frames when its turn comes.
    plot.model().setSource(&run.recorder().samples());
    QObject::connect(&run, &RunView::samplesCleared, &plot, &PlotWidget::clear);
    QObject::connect(&run, &RunView::rewound, &plot, &PlotWidget::rewind);
    QObject::connect(&run, &RunView::marked, &plot.model(), &PlotModel::addMark);
    turns.add(&plot);
    // The plot keeps its points as far back as the timeline goes (going back shows them).
    QObject::connect(&run, &RunView::worldChanged, &plot, [p = &plot, r = &run] {
        p->model().setTimelineStart(r->history().earliestTime());
        p->exporter().setContext(r->scene().title); // names its exports
    });
}

void fillExportMenu(QMenu& menu, QWidget& window, std::function<QList<PlotWidget*>()> onScreen)
{
    // Made when it opens: a lesson step shows other plots than the plain lab.
    QObject::connect(&menu, &QMenu::aboutToShow, &menu, [&menu, &window, onScreen] {
        menu.clear();
        qDeleteAll(menu.findChildren<QMenu*>(QString(), Qt::FindDirectChildrenOnly));
        const QList<PlotWidget*> plots = onScreen();
        for (PlotWidget* plot : plots) {
            QMenu* sub = menu.addMenu(plot->title());
            for (const char* fmt : {"PNG", "PDF", "SVG", "CSV"})
                sub->addAction(PlotExportMenu::tr("As %1…").arg(QLatin1String(fmt)), &window,
                               [&window, p = QPointer<PlotWidget>(plot), fmt] {
                                   if (p)
                                       exportPlotDialog(window, *p, QString::fromLatin1(fmt));
                               });
        }
        if (plots.isEmpty())
            menu.addAction(PlotExportMenu::tr("No plot is shown"))->setEnabled(false);
    });
}

} // namespace rigidlab::ui
