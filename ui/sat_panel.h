#pragma once
// The separating axis theorem, step by step, for two polygons of the scene: a table of the
// axes tested so far, and an overlay in the view that draws the current axis with both
// projections on it, the gap or overlap, and at the end the normal, depth and contact points.
// Everything shown is the data physics::satPolygons returns; nothing is computed twice.
// The overlay also shows, for a body whose non-convex outline was replaced by its hull, the
// area where the detection is now wrong.

#include "rigidlab/physics/sat.h"

#include <QGraphicsItem>
#include <QWidget>

class QLabel;
class QPushButton;
class QTableWidget;

namespace rigidlab::ui {

class SimulationController;

class SatPanel;

class SatOverlayItem : public QGraphicsItem {
public:
    explicit SatOverlayItem(const SatPanel& panel);
    QRectF boundingRect() const override;
    void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override;

private:
    void paintHulls(QPainter* painter, double px) const;
    const SatPanel& m_panel;
};

class SatPanel : public QWidget {
    Q_OBJECT
public:
    SatPanel(SimulationController& controller, QWidget* parent = nullptr);

    /// The two bodies to test (ids), or -1 for none.
    void setBodies(int a, int b);
    QGraphicsItem* overlay() { return m_overlay; }
    const physics::SatResult& result() const { return m_result; }
    /// How many of the tested axes are shown (the step the student is at).
    int shown() const { return m_shown; }
    bool active() const { return m_a >= 0 && m_b >= 0; }
    int bodyA() const { return m_a; }
    int bodyB() const { return m_b; }
    const SimulationController& controller() const { return m_controller; }
    QString summary() const; ///< the text under the table

public slots:
    void nextAxis();
    void previousAxis();
    void showAll();
    void refresh();

private:
    void updateTable();

    SimulationController& m_controller;
    SatOverlayItem* m_overlay;
    int m_a = -1, m_b = -1;
    int m_shown = 1;
    bool m_all = false;
    physics::SatResult m_result;
    QLabel* m_verdict;
    QTableWidget* m_table;
    QLabel* m_summary;
    QPushButton* m_prev;
    QPushButton* m_next;
    QPushButton* m_all_button;
};

} // namespace rigidlab::ui
