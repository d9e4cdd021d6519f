// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The window's docks and where they go: each panel and plot in a dock under its lesson name,
// the docks arranged for the screen the window is on (window_layout.cpp), remembered per
// screen size, and presentation mode (presentation_mode.cpp). It knows the panels only as
// widgets: what they show is theirs.

#include <QByteArray>
#include <QFont>
#include <QList>
#include <QMap>
#include <QObject>
#include <QPalette>
#include <QPointer>
#include <QRect>
#include <QString>

#include <array>
#include <functional>
#include <utility>
#include <vector>

class QDockWidget;
class QMainWindow;
class QSettings;
class QWidget;

namespace rigidlab::ui {

class PlotWidget;

/// The property a widget enlarged by theme::kReadingFontScale carries: presentation mode makes
/// it theme::kPresentationFontScale times the system's size, not both factors at once.
inline constexpr const char* kReadingSizeProperty = "rigidlabReadingSize";

class WindowLayout : public QObject {
    Q_OBJECT
public:
    /// The widgets that get a dock each (window_docks.cpp).
    struct Panels {
        QWidget* lesson = nullptr;
        QWidget* lessonNavigation = nullptr; ///< below the lesson, outside its scrolling
        QWidget* controls = nullptr;
        QWidget* inspector = nullptr;
        QList<PlotWidget*> plots; ///< each under its object name, its row's (plot_table.h)
        QWidget* sat = nullptr;
        QWidget* bounces = nullptr;
        QWidget* collision = nullptr;
        QWidget* error = nullptr;
        QWidget* measurement = nullptr; ///< an imported measurement and its fit; scrolls itself
    };
    /// Makes the docks on `window`.
    WindowLayout(QMainWindow& window, const Panels& panels);

    /// The dock holding a panel or plot, by its lesson name ("energy", "sat", "compare-drift").
    QDockWidget* dock(const QString& name) const;
    /// Every named dock (the compared worlds' dock is compareDock()).
    const QMap<QString, QDockWidget*>& docks() const { return m_docks; }
    /// The dock of the plots comparing worlds side by side.
    QDockWidget* compareDock() const { return m_compareDock; }
    /// The docks of a lesson step's panels and plots that share tabs with another: those
    /// that are not hidden, the one the step cares most about raised (its table, then the
    /// first plot it names).
    void raiseFirst(QList<QDockWidget*> docks) const;

    /// Tabs the docks of each kind together again (a dock shown again may come back beside its
    /// tab group rather than in it).
    void regroup();
    /// Runs `change` (docks shown and hidden one by one, then grouped) and gives the window its
    /// size back: while they were shown one by one, their least heights added up may have grown
    /// it past the screen; grouped, they fit again.
    void keepingSize(const std::function<void()>& change);
    /// The screen's available area the window is on.
    QRect availableScreenArea() const;
    /// Sizes the window for a screen's available area (never larger) and arranges the docks:
    /// on a small screen the plots share a tabbed dock (window_layout.cpp).
    void fitToScreen(const QRect& available);
    bool compact() const { return m_compact; }
    /// Side columns no wider than their share of the window's width: the world keeps half.
    void fitSideColumns();
    /// The plots' least heights again once the layout has settled (several asks, one run):
    /// a plot's legend took another row, say.
    void fitPlotHeightSoon();
    void save(QSettings& settings) const;
    void restore(const QSettings& settings);

    /// Presentation mode: full screen, larger text, thicker lines, a high-contrast palette.
    /// Leaving it restores the layout (presentation_mode.cpp).
    void setPresentation(bool on);
    bool presentation() const { return m_presentation; }

    /// The window's show and resize events, which the layout follows.
    void windowShown();
    void windowResized();
    void windowMoved();

signals:
    void presentationChanged(bool on);

private:
    /// Who scrolls a panel taller or wider than its dock: a scroll area the dock puts it in,
    /// or the panel itself (one that keeps its plots in sight and scrolls only the rest).
    enum class Scrolling { InDock, Own };
    /// A dock for `w` in `area`, found by `name` (dock()), its object name `name` + "Dock" and
    /// its title from that (common/dock_names.h); `full`: the tooltip's longer title.
    QDockWidget* addDock(const QString& name, QWidget* w, int area, const QString& full = QString(),
                         Scrolling scrolling = Scrolling::InDock);
    void buildLessonDock(const Panels& panels);
    /// Stacked plots on a roomy `screen`, tabbed on a small one.
    void arrangeDocks(const QSize& screen);
    /// The window and its frame inside the screen's available area, once the window manager
    /// has told the frame (after the window is shown, often later than its first move).
    void keepFrameOnScreen();
    /// The right column's height shared by its kinds' weights (a small screen).
    void shareColumnHeight();
    /// The plots under the world tall enough for a readable data area (a small screen).
    void fitPlotHeight();
    /// Each table panel shown scrolled to its table, not to the description above it.
    void scrollTablesToData();
    /// The plots' least heights back to the plain one (until fitPlotHeight() runs again).
    void relaxPlotHeights();
    /// A plot resized: fitPlotHeight() again, once the layout has settled.
    bool eventFilter(QObject* watched, QEvent* event) override;
    /// Fonts set on widgets of their own grow with presentation mode, and come back after.
    void scaleExplicitFonts(bool on);
    /// A dock shown from the View menu comes to the front of its tabs.
    void showWhenAsked(QDockWidget& dock);
    /// The docks' places and sizes from before presentation mode, each dock shown or hidden
    /// as it was when presentation mode ended (presentation_mode.cpp).
    void restoreNormalState();

    QMainWindow& m_window;
    QMap<QString, QDockWidget*> m_docks;
    QDockWidget* m_compareDock = nullptr;
    /// On a small screen, the right column's kinds top to bottom (settings, tables, plots).
    QList<QList<QDockWidget*>> m_rightGroups;
    QRect m_screenArea;     ///< the available area the layout was made for
    bool m_compact = false; ///< plots tabbed for a small screen
    bool m_presentation = false;
    bool m_restoreStatePending = false; ///< docks to put back once full screen has ended
    bool m_plotFitPending = false;      ///< a fitPlotHeight() is queued
    QSize m_frameFitted; ///< the window manager's frame the window was last fitted with [px]
    bool m_normalWasMaximized = false;
    QByteArray m_normalGeometry; ///< before presentation mode
    QByteArray m_normalState;
    QFont m_normalFont;
    std::vector<std::pair<QPointer<QWidget>, QFont>> m_explicitFonts; ///< before presentation
    QPalette m_normalPalette;
};

} // namespace rigidlab::ui
