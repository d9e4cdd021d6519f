// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The separating axis theorem, step by step, for two polygons of the scene: a table of the
// axes tested so far, and an overlay in the view that draws the current axis with both
// projections on it, the gap or overlap, and at the end the normal, depth and contact points.
// Everything shown is the data physics::satPolygons returns; nothing is computed twice.
// The overlay also shows, for a body whose non-convex outline was replaced by its hull, the
// area where the detection is now wrong.

#include "panels/fitting_table.h"
#include "view/sat_overlay.h"
#include "view/sat_view_model.h"

#include "rigidlab/physics/sat.h"

#include <QPointer>

#include <QWidget>

class QBoxLayout;
class QLabel;
class QPushButton;
class QTableWidget;

namespace rigidlab::ui {

class RunView;
class WorldView;

class SatPanel : public QWidget {
    Q_OBJECT
public:
    SatPanel(const RunView& run, QWidget* parent = nullptr);
    ~SatPanel() override;

    /// The two bodies to test (ids), or -1 for none.
    void setBodies(int a, int b);
    /// What the panel draws in the world view; the window adds it to the view's scene. While
    /// the panel is active, the view follows it: it fits both shapes, the axis line, both
    /// projections and the label of the axis shown.
    SatOverlayItem* overlay() { return m_overlay; }
    const SatOverlayItem& overlayItem() const { return *m_overlay; }
    /// What the table and the overlay both show.
    const SatViewModel& model() const { return m_model; }
    const physics::SatResult& result() const { return m_model.result(); }
    /// How many of the tested axes are shown (the step the student is at).
    int shown() const { return m_model.shown(); }
    bool active() const { return m_model.active(); }
    int bodyA() const { return m_model.bodyA(); }
    int bodyB() const { return m_model.bodyB(); }
    QString summary() const; ///< the text under the table
    const QTableWidget& table() const { return *m_table; }
    /// The axes shown, as "Export as CSV…" in the table's context menu writes them.
    CsvTable csv() const;
    /// How many times the table was filled in (for tests: not for a frame in which the pair
    /// stood still, nor while the panel is out of sight).
    int tableFillCount() const { return m_tableFills; }

public slots:
    void nextAxis();
    void previousAxis();
    void showAll();
    /// Tests the pair again where it moved or changed shape; the table, out of sight (behind
    /// another dock's tab, its dock closed, in a window on screen), when it is shown again.
    void refresh();

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
    void changeEvent(QEvent* event) override;
    void showEvent(QShowEvent* event) override;

private:
    void updateTable();
    /// In a window on screen, but not shown (a widget of its own, or in a window not shown, as
    /// tests make them, is never out of sight).
    bool outOfSight() const;
    /// Row `i` of the table: its three cells and the tooltip that explains them.
    struct RowText {
        QStringList cells;
        QString tip;
    };
    RowText rowText(int i) const;
    void buildTable();
    void buildButtons(QBoxLayout* layout);
    /// The table and its header at the window's (maybe presentation) scale; the buttons as
    /// wide as their text.
    void fitFonts();
    /// The axis and overlap columns narrow enough to leave the intervals room (no sideways
    /// scrolling).
    void fitColumns();
    /// The buttons side by side where the panel is wide enough for them, else stacked.
    void fitButtons();
    /// The view showing the overlay, or null (registers the overlay with its Fit scene).
    WorldView* worldView();
    /// Pans and zooms the view to what the overlay draws: always after a step through the
    /// axes, otherwise (a body dragged or turned) only when part of it left the view.
    void followAxis(bool always);

    const RunView& m_run;
    SatViewModel m_model; ///< before the overlay, which reads it
    SatOverlayItem* m_overlay;
    QLabel* m_verdict;
    QTableWidget* m_table;
    QLabel* m_summary;
    QPushButton* m_prev;
    QPushButton* m_next;
    QPushButton* m_all_button;
    QBoxLayout* m_buttons;      ///< Previous, Next, All
    QPointer<WorldView> m_view; ///< the view whose Fit scene includes the overlay
    bool m_tableBehind = false; ///< the model changed while the table was out of sight
    int m_tableFills = 0;       ///< see tableFillCount()
};

} // namespace rigidlab::ui
