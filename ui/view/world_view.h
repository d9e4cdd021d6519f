// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The central view: the world drawn with y up, metres mapped to pixels. Pan by dragging
// empty space or with the middle button, zoom with the wheel around the cursor, fit the
// scene on demand. A left press on a dynamic body grabs it (a spring to the cursor); a click
// selects a body for the inspector.

#include "view/overlays.h"

#include <QGraphicsView>

#include <functional>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

namespace rigidlab::ui {

class BodiesItem;
class BodyItem;
class SceneNarrator;
class RunView;
class SimulationController;
struct Pose;

class WorldView : public QGraphicsView {
    Q_OBJECT
public:
    explicit WorldView(SimulationController& controller, QWidget* parent = nullptr);
    ~WorldView() override;

    OverlayItem& overlays() { return *m_overlays; }
    /// The run the view shows.
    const RunView& run() const { return m_run; }
    /// What the view tells a screen reader as the world runs (scene_narrator.h).
    SceneNarrator& narrator() const { return *m_narrator; }
    /// The item drawing body `id` (for tests).
    const BodyItem* itemFor(int id) const;
    /// The items drawing compared world `variant` (index into the controller's variants),
    /// in body order (for tests).
    std::vector<const BodyItem*> ghostItems(int variant) const;
    int selectedBody() const { return m_selected; }
    /// The main world's body drawn at view position `viewPos` (the topmost where bodies
    /// overlap), or -1: what a click there grabs and selects.
    int bodyAt(const QPoint& viewPos) const;
    /// The one item that paints every body (for tests).
    const BodiesItem& bodiesItem() const { return *m_bodiesItem; }
    /// Pixels per metre now.
    double zoom() const { return transform().m11(); }

    /// The worlds the legend names (0 when nothing is compared): 0 the main one, then the
    /// compared ones in order.
    int worldCount() const;
    /// The legend's line for a world: its name and how it is drawn, or, once it stopped, one
    /// short line: when, and why in a few words (the ghost also gets a label of its own).
    QString legendLine(int world) const;
    /// The legend line's full text, its tooltip: for a stopped world, the whole diagnosis
    /// (when, how far the energy grew, which body); else the line itself.
    QString legendDetail(int world) const;
    /// Whether that world stopped with a diagnosis.
    bool stoppedWorld(int world) const;
    /// Where the legend's lines are drawn, one for each world, in viewport pixels.
    std::vector<QRect> legendLayout() const;
    /// Where the "… stopped" labels beside the stopped ghosts are drawn, in the order of the
    /// compared worlds, in viewport pixels; they never overlap.
    std::vector<QRect> stoppedLabelRects() const;
    /// Where the bodies' labels are drawn (world_view_labels.cpp): the body's id and its
    /// label's box in viewport pixels, inside the view and not over each other or the legend.
    std::vector<std::pair<int, QRect>> bodyLabelRects() const;

    /// Shows `worldRect` [m] in the whole viewport with `marginPx` pixels to spare on each
    /// side, and keeps it shown on resize (as Fit scene does) until the user pans or zooms.
    void fitRect(QRectF worldRect, double marginPx);
    /// More for Fit scene to show besides the bodies: a panel's drawing over the world, in
    /// world coordinates [m] (an empty rect when it draws nothing).
    void setFitExtra(std::function<QRectF()> extra) { m_fitExtra = std::move(extra); }
    /// The region [m] the run's event will sweep (a lesson step's bodies from its start to its
    /// export time): fits the view to it with the bodies, at once and whenever the view fits
    /// again, so that the class sees the whole event. An empty rect turns it off.
    void setActionBounds(const QRectF& worldRect);
    /// Whether loading a scene fits the view to it (the default). The scene editor turns it off
    /// while it reloads the world after each edit, so that the view holds still under the pen
    /// (nor does it widen to follow a body drawn outside what it shows).
    void setFitOnRebuild(bool on) { m_fitOnRebuild = on; }
    /// A view position in the world [m].
    physics::Vec2 worldAt(const QPoint& viewPos) const { return toWorld(viewPos); }

    /// Zooms by `factor` about the middle of the view, as the wheel does about the pointer
    /// (the keyboard's + and −); the view no longer fits itself to the scene.
    void zoomBy(double factor);
    /// Moves what the view shows by `pixels` (x right, y down), as dragging empty space does
    /// (the keyboard's Ctrl+arrows); the view no longer fits itself to the scene.
    void panBy(const QPoint& pixels);

public slots:
    void fitScene();
    void rebuild();
    void syncPoses();
    void selectBody(int id);
    /// Selects the next (or previous) body that moves, after the selected one, wrapping
    /// around: choosing a body without a mouse (world_view_keys.cpp).
    void selectNextBody();
    void selectPreviousBody();

signals:
    void bodySelected(int id);
    /// Enter on the selected body: show its numbers (the window raises the inspector).
    void numbersRequested(int id);

protected:
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void drawBackground(QPainter* painter, const QRectF& rect) override;
    void drawForeground(QPainter* painter, const QRectF& rect) override;
    void resizeEvent(QResizeEvent* event) override;
    bool viewportEvent(QEvent* event) override;
    /// The scene's keys, with a body selected: arrows move it, Shift+arrows change its
    /// velocity, Enter asks for its numbers (world_view_keys.cpp).
    void keyPressEvent(QKeyEvent* event) override;
    bool event(QEvent* event) override;

private:
    /// syncPoses() for the main world's bodies, then the compared worlds' ghosts, for a view
    /// showing `shown` of the scene [m].
    void syncMainPoses(const QRectF& shown);
    void syncGhostPoses(const QRectF& shown);
    /// Hands the bodies' items to m_bodiesItem in the order they are painted.
    void paintBodiesInOrder();
    /// Auto-fit after the bodies moved: follows bodies leaving the fitted area, gives back
    /// what it widened for a world that stopped.
    void followContent();
    physics::Vec2 toWorld(const QPoint& viewPos) const;
    /// Everything the scene shows: bodies, spring and joint anchors [m].
    QRectF contentRect() const;
    /// The part of `item` (body `body` of `world`) that contentRect takes: its box, the
    /// scenery's cut to the run's event [m].
    QRectF shownRect(const BodyItem& item, const physics::World& world, physics::BodyId body) const;
    /// What contentRect adds to the bodies: spring and joint anchors, the fit's extra and the
    /// run's event [m].
    QRectF anchorsAndExtras() const;
    /// Whether contentRect() lies within `area`, as its walk would say, asked body by body:
    /// the square of its reach about its origin first, its exact box only where that square
    /// crosses the edge.
    bool contentWithin(const QRectF& area) const;
    /// Selects the body `step` places from the selected one among those that move.
    void selectBodyAfter(int step);
    /// Shows `box` (grown by a margin) in the whole viewport.
    void showRect(QRectF box);
    void setZoom(double pixelsPerMetre);
    /// The least half-size [m] a moving body is drawn with at this zoom (see BodyItem).
    double minimumBodyRadius() const;
    void applyMinimumBodySize();
    QFont legendFont() const;
    /// The scene's names of its few moving bodies, above them (world_view_labels.cpp).
    void drawBodyLabels(QPainter* painter) const;
    /// The legend's height from the top of the view [px], 0 without one.
    int legendHeight() const;
    /// How many worlds (the main one and the compared ones) stopped.
    int stoppedCount() const;
    /// The item drawing compared world `variant`'s first body, or nullptr.
    const BodyItem* ghostOf(int variant) const;
    QString stoppedLabel(int variant) const;

    SimulationController& m_controller; ///< changes the run: grabbing, moving a body
    const RunView& m_run;               ///< the same run, read
    QGraphicsScene* m_scene;
    OverlayItem* m_overlays;
    SceneNarrator* m_narrator;
    BodiesItem* m_bodiesItem; ///< paints m_items and the ghosts; owned by the scene
    std::vector<std::unique_ptr<BodyItem>> m_items; ///< indexed by body id; not in the scene
    /// As last drawn while the main world ran, with its sine and cosine: the pose a world that
    /// stopped keeps (frozenPose), and the next frame's poses of the bodies that did not move
    /// (SimulationController::drawPose).
    std::vector<Pose> m_itemPoses;
    /// Per world (0 the main one): whether it was drawn running since the last rebuild, so
    /// that once stopped it is drawn frozen there rather than where it flew off to.
    std::vector<bool> m_drawnRunning;
    struct Ghost {
        int variant = 0; ///< index into the controller's variants
        int body = 0;
        std::unique_ptr<BodyItem> item; ///< not in the scene: m_bodiesItem paints it
        physics::Transform pose;        ///< as last drawn while its world ran [m]
    };
    /// The pose body `body` of world `world` (0 the main one, v + 1 compared world v) is
    /// frozen at, once that world stopped: as last drawn before it did.
    std::optional<physics::Transform> frozenPose(int world, physics::BodyId body) const;
    std::vector<Ghost> m_ghosts;
    int m_selected = -1;
    bool m_panning = false;
    bool m_autoFit = true;    ///< fit the scene on resize until the user pans or zooms
    QRectF m_fitted;          ///< what auto-fit shows; it widens to follow bodies, up to a limit
    QRectF m_fitLimit;        ///< auto-fit never widens beyond this
    QRectF m_startFit;        ///< what the last fit showed before any widening
    int m_stoppedCount = 0;   ///< worlds stopped when auto-fit last looked
    int m_legendReserved = 0; ///< the legend's height the last fit kept free [px]
    QPoint m_lastMouse;
    std::function<QRectF()> m_fitExtra; ///< see setFitExtra
    QRectF m_action;                    ///< see setActionBounds
    bool m_fitOnRebuild = true;         ///< see setFitOnRebuild
    /// Hundreds of bodies: drawn without antialiasing, and not grown to the readable size
    /// (see applyMinimumBodySize).
    bool m_crowded = false;
};

} // namespace rigidlab::ui
