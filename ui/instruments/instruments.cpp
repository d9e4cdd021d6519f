// SPDX-License-Identifier: GPL-3.0-or-later
#include "instruments/instruments.h"

#include "common/accessible_names.h"
#include "common/dock_names.h"
#include "common/shortcuts.h"

#include "instruments/instruments_item.h"
#include "instruments/instruments_panel.h"
#include "plots/body_series.h"
#include "plots/plot_exporter.h"
#include "plots/plot_turns.h"
#include "plots/plot_widget.h"
#include "simulation/history.h"
#include "simulation/run_view.h"
#include "view/world_view.h"

#include <QAction>
#include <QDockWidget>
#include <QGraphicsScene>
#include <QMainWindow>
#include <QScrollArea>
#include <QTabWidget>

#include <algorithm>
#include <memory>
#include <optional>

namespace rigidlab::ui {

namespace {

/// A graph of bodies and the plot it feeds, recorded while the world moves.
class GraphFeed : public QObject {
public:
    GraphFeed(PlotWidget& plot, BodyQuantity q, ReferenceFrame frame)
        : QObject(&plot), graph(plot, q, std::move(frame))
    {
    }
    BodyGraph graph;
};

/// The scene ids of `bodies`.
std::vector<std::string> sceneIds(const lessons::Scene& scene,
                                  const std::vector<physics::BodyId>& bodies)
{
    std::vector<std::string> ids;
    for (physics::BodyId b : bodies)
        ids.push_back(scene.bodies[static_cast<std::size_t>(b)].name);
    return ids;
}

/// The bodies of `scene` with these ids, or nullopt when one is not there.
std::optional<std::vector<physics::BodyId>> bodiesWithIds(const lessons::Scene& scene,
                                                          const std::vector<std::string>& ids)
{
    std::vector<physics::BodyId> bodies;
    for (const std::string& id : ids) {
        const auto found = std::find_if(scene.bodies.begin(), scene.bodies.end(),
                                        [&](const physics::BodyDef& b) { return b.name == id; });
        if (found == scene.bodies.end())
            return std::nullopt;
        bodies.push_back(static_cast<physics::BodyId>(found - scene.bodies.begin()));
    }
    return bodies;
}

QString graphTitle(const BodyGraphSpec& spec)
{
    return spec.frame.isLab() ? Instruments::tr("Graph: %1").arg(quantityName(spec.quantity))
                              : Instruments::tr("Graph: %1 (centre-of-mass frame)")
                                    .arg(quantityName(spec.quantity));
}

} // namespace

Instruments::Instruments(QMainWindow& window, const RunView& run, WorldView& view, PlotTurns& turns)
    : QObject(&window), m_window(window), m_run(run), m_turns(turns), m_view(view),
      m_panel(new InstrumentsPanel(run, &window)), m_item(new InstrumentsItem(*m_panel, run)),
      m_dock(new QDockWidget(&window)), m_graphAction(new QAction(tr("&Graph of bodies…"), this))
{
    nameDock(*m_dock, QStringLiteral("instrumentsDock"));
    // A panel that scrolls, as the window's others do: its tabs' least height added to a
    // lesson step's panels and plots held the window taller than a 1024×768 projector.
    auto* scroll = new QScrollArea(m_dock);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setWidget(m_panel);
    nameScrollArea(*scroll, m_dock->windowTitle());
    m_dock->setWidget(scroll);
    window.addDockWidget(Qt::RightDockWidgetArea, m_dock);
    m_dock->hide(); // until asked for: View › Instruments
    m_dock->toggleViewAction()->setObjectName(QStringLiteral("instruments"));
    m_dock->toggleViewAction()->setShortcuts(controlKeys("instruments"));
    m_graphAction->setObjectName(QStringLiteral("graphOfBodies"));
    m_graphAction->setShortcuts(controlKeys("graphOfBodies"));
    m_graphAction->setToolTip(tr("Plot a quantity of chosen bodies against time"));
    connect(m_graphAction, &QAction::triggered, this, [this] {
        const int selected = m_view.selectedBody();
        askGraph(selected >= 0 ? std::vector<physics::BodyId>{selected}
                               : std::vector<physics::BodyId>{});
    });
    m_view.scene()->addItem(m_item);
    m_item->setVisible(false);
    new InstrumentsMouse(*m_panel, m_view);
    connect(m_dock, &QDockWidget::visibilityChanged, this,
            [this](bool shown) { m_item->setVisible(shown && m_available); });
    connect(m_panel, &InstrumentsPanel::changed, this, [this] { m_item->update(); });
    connect(m_panel->tabs(), &QTabWidget::currentChanged, this, [this] { m_item->update(); });
    // A body clicked on the scene is the one the open tab measures.
    connect(&m_view, &WorldView::bodySelected, this, [this](int id) {
        if (id < 0)
            return;
        if (m_panel->tabs()->currentIndex() == InstrumentsPanel::ProbeTab)
            m_panel->setProbeBody(id);
        else if (m_panel->tabs()->currentIndex() == InstrumentsPanel::ProtractorTab &&
                 m_panel->protractorMode() == InstrumentsPanel::ProtractorMode::Body)
            m_panel->setProtractorBody(id);
    });
    connect(m_panel, &InstrumentsPanel::plotRequested, this,
            [this](int body) { askGraph({body}); });
    connect(m_panel, &InstrumentsPanel::frameChanged, this,
            [this](const std::vector<physics::BodyId>& ids) {
                m_frame = ids;
                followFrame();
            });
    connect(m_panel, &InstrumentsPanel::frameMomentumRequested, this,
            [this](const std::vector<physics::BodyId>& ids) {
                BodyGraphSpec spec;
                spec.quantity = BodyQuantity::Px;
                spec.bodies = ids;
                spec.sum = true;
                spec.frame.bodies = m_frame;
                showGraph(spec);
            });
    connect(&m_run, &RunView::worldChanged, this, &Instruments::followFrame);
    connect(&m_run, &RunView::sceneLoaded, this, [this] {
        keepGraphsOfThisScene();
        m_frame.clear();
    });
}

void Instruments::setAvailable(bool available)
{
    m_available = available;
    if (!available)
        m_dock->hide();
    m_dock->toggleViewAction()->setEnabled(available);
    m_graphAction->setEnabled(available);
    m_item->setVisible(available && m_dock->isVisible());
}

void Instruments::followFrame()
{
    // In the centre-of-mass frame the view moves with the centre of mass: the bodies are drawn
    // as an observer riding along sees them.
    if (m_frame.empty())
        return;
    const FrameMotion motion = frameMotion(m_run.world(), ReferenceFrame{m_frame});
    m_view.centerOn(QPointF(motion.origin.x(), motion.origin.y()));
}

PlotWidget* Instruments::makeGraphPlot(const BodyGraphSpec& spec)
{
    auto* plot = new PlotWidget(graphTitle(spec), &m_window);
    plot->setObjectName(QStringLiteral("bodyGraph"));
    plot->setTitleShown(false); // its dock says it; exports do
    plot->exporter().setContext(m_run.scene().title);
    plot->addMenuAction(m_graphAction); // another graph, from this one's menu
    auto* feed = new GraphFeed(*plot, spec.quantity, spec.frame);
    const lessons::Scene& scene = m_run.scene();
    if (spec.eachBody)
        for (physics::BodyId id : spec.bodies)
            feed->graph.addBody(id, scene.bodyLabel(id));
    if (spec.sum && !spec.bodies.empty()) {
        QStringList names;
        for (physics::BodyId id : spec.bodies)
            names << scene.bodyLabel(id);
        feed->graph.addSum(spec.bodies, names.join(QStringLiteral(" + ")));
    }
    // From now on, and with the timeline: going back keeps the future as the plots' ghost.
    plot->model().setTimelineStart(m_run.history().earliestTime());
    feed->graph.record(m_run.world(), m_run.time());
    connect(&m_run, &RunView::worldChanged, feed, [this, feed, plot] {
        feed->graph.record(m_run.world(), m_run.time());
        plot->model().setTimelineStart(m_run.history().earliestTime());
    });
    connect(&m_run, &RunView::rewound, plot, &PlotWidget::rewind);
    connect(&m_run, &RunView::samplesCleared, plot, &PlotWidget::clear);
    m_turns.add(plot);
    return plot;
}

PlotWidget* Instruments::showGraph(const BodyGraphSpec& spec)
{
    PlotWidget* plot = makeGraphPlot(spec);
    auto* dock = new QDockWidget(plot->title(), &m_window);
    dock->setObjectName(QStringLiteral("bodyGraphDock%1").arg(++m_graphsMade));
    dock->setAttribute(Qt::WA_DeleteOnClose);
    dock->setWidget(plot);
    if (m_placeGraph)
        m_placeGraph(dock);
    else
        m_window.addDockWidget(Qt::BottomDockWidgetArea, dock);
    const lessons::Scene& scene = m_run.scene();
    m_graphs.push_back(
        {dock, spec, sceneIds(scene, spec.bodies), sceneIds(scene, spec.frame.bodies)});
    dock->show();
    dock->raise(); // in front of the plots it may share tabs with
    return plot;
}

void Instruments::keepGraphsOfThisScene()
{
    const lessons::Scene& scene = m_run.scene();
    std::vector<GraphDock> kept;
    for (GraphDock& g : m_graphs) {
        if (!g.dock) // closed by the user
            continue;
        const auto bodies = bodiesWithIds(scene, g.bodyIds);
        const auto frame = bodiesWithIds(scene, g.frameIds);
        if (!bodies || !frame) {
            // A body of the old scene that the new one lacks: the graph would mean nothing.
            g.dock->deleteLater();
            continue;
        }
        g.spec.bodies = *bodies;
        g.spec.frame.bodies = *frame;
        // A new plot: the bodies' indices, names and the world it reads are the new scene's.
        QWidget* old = g.dock->widget();
        g.dock->setWidget(makeGraphPlot(g.spec));
        if (old) {
            old->hide();
            old->deleteLater(); // not now: a signal of the old scene may still be on its way
        }
        kept.push_back(std::move(g));
    }
    m_graphs = std::move(kept);
}

void Instruments::askGraph(const std::vector<physics::BodyId>& bodies)
{
    QStringList labels;
    for (int i = 0; i < static_cast<int>(m_run.world().bodies().size()); ++i)
        labels << m_run.scene().bodyLabel(i);
    BodyGraphSpec initial;
    initial.bodies = bodies;
    BodyGraphDialog dialog(labels, initial, &m_window);
    if (dialog.exec() == QDialog::Accepted && !dialog.spec().bodies.empty())
        showGraph(dialog.spec());
}

QList<PlotWidget*> Instruments::graphsShown() const
{
    QList<PlotWidget*> plots;
    for (const GraphDock& g : m_graphs)
        if (g.dock && !g.dock->isHidden())
            if (auto* plot = qobject_cast<PlotWidget*>(g.dock->widget()))
                plots << plot;
    return plots;
}

} // namespace rigidlab::ui
