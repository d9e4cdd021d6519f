// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The instruments in a window: their panel in a dock (View › Instruments), their drawing on
// the scene, dragging on it, the centre-of-mass frame of the view, and graphs of chosen bodies
// in docks of their own. The window makes one and gives it its dock place; a lesson may hide
// them all (setAvailable).

#include "instruments/body_graph_dialog.h"

#include <QList>
#include <QObject>
#include <QPointer>

#include <functional>
#include <string>
#include <vector>

class QAction;
class QDockWidget;
class QMainWindow;

namespace rigidlab::ui {

class InstrumentsItem;
class InstrumentsPanel;
class PlotTurns;
class PlotWidget;
class RunView;
class WorldView;

class Instruments : public QObject {
    Q_OBJECT
public:
    /// Its graphs drain after the run's frames when their turn in `turns` comes.
    Instruments(QMainWindow& window, const RunView& run, WorldView& view, PlotTurns& turns);

    InstrumentsPanel* panel() const { return m_panel; }
    QDockWidget* dock() const { return m_dock; }
    /// Graph of bodies… (the probe's Plot, the inspector's and a plot's menu open it too).
    QAction* graphAction() const { return m_graphAction; }
    /// Whether a lesson lets the student use the instruments (true unless it hides them).
    void setAvailable(bool available);
    bool available() const { return m_available; }

    /// Where a graph's dock goes (the window tabs it with its plots); unset, below the scene.
    void setGraphPlacer(std::function<void(QDockWidget*)> placer)
    {
        m_placeGraph = std::move(placer);
    }
    /// A graph of bodies in a dock of its own, recorded from now on; returns its plot.
    PlotWidget* showGraph(const BodyGraphSpec& spec);
    /// Asks which graph, starting from `bodies` ticked, then shows it.
    void askGraph(const std::vector<physics::BodyId>& bodies);
    /// The graphs of bodies whose docks are shown (File › Export plot offers them).
    QList<PlotWidget*> graphsShown() const;

private:
    /// A graph's dock and what it plots, its bodies also by their scene ids: a new scene
    /// (another file, or the same one edited) keeps the graphs whose bodies it still has.
    struct GraphDock {
        QPointer<QDockWidget> dock;
        BodyGraphSpec spec;
        std::vector<std::string> bodyIds;  ///< of spec.bodies
        std::vector<std::string> frameIds; ///< of spec.frame.bodies
    };
    void followFrame();
    /// The plot of a graph, fed from the world from now on.
    PlotWidget* makeGraphPlot(const BodyGraphSpec& spec);
    /// Gives the graphs whose bodies the new scene has a plot of them there; closes the others.
    void keepGraphsOfThisScene();

    QMainWindow& m_window;
    const RunView& m_run;
    PlotTurns& m_turns;
    WorldView& m_view;
    InstrumentsPanel* m_panel;
    InstrumentsItem* m_item;
    QDockWidget* m_dock;
    QAction* m_graphAction;
    std::vector<GraphDock> m_graphs;
    int m_graphsMade = 0; ///< names each graph's dock apart from the ones closed before
    std::vector<physics::BodyId> m_frame; ///< the view's frame: empty, the lab's
    bool m_available = true;
    std::function<void(QDockWidget*)> m_placeGraph; ///< see setGraphPlacer
};

} // namespace rigidlab::ui
