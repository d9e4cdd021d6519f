// SPDX-License-Identifier: GPL-3.0-or-later
// WindowLayout's presentation mode: full screen, larger text, thicker lines and a
// high-contrast palette for a projector at the back of a bright room; leaving it puts the
// window back as it was.
#include "window/window_layout.h"

#include "common/theme.h"
#include "lesson_player/question_area.h"
#include "plots/plot_widget.h"

#include <QDockWidget>
#include <QMainWindow>
#include <QToolBar>

namespace rigidlab::ui {

namespace {

/// Black on white, strong selection: survives a washed-out projector.
QPalette highContrastPalette()
{
    QPalette p;
    for (const auto role : {QPalette::Window, QPalette::Base, QPalette::Button,
                            QPalette::AlternateBase, QPalette::ToolTipBase})
        p.setColor(role, Qt::white);
    for (const auto role : {QPalette::WindowText, QPalette::Text, QPalette::ButtonText,
                            QPalette::ToolTipText, QPalette::BrightText})
        p.setColor(role, Qt::black);
    p.setColor(QPalette::Highlight, QColor(0, 60, 170));
    p.setColor(QPalette::HighlightedText, Qt::white);
    p.setColor(QPalette::PlaceholderText, QColor(70, 70, 70));
    p.setColor(QPalette::Disabled, QPalette::WindowText, QColor(90, 90, 90));
    p.setColor(QPalette::Disabled, QPalette::Text, QColor(90, 90, 90));
    p.setColor(QPalette::Disabled, QPalette::ButtonText, QColor(90, 90, 90));
    return p;
}

} // namespace

void WindowLayout::setPresentation(bool on)
{
    if (on == m_presentation)
        return;
    if (on) {
        m_normalGeometry = m_window.saveGeometry();
        m_normalState = m_window.saveState();
        m_normalFont = m_window.font();
        m_normalPalette = m_window.palette();
        m_normalWasMaximized = m_window.isMaximized();
    }
    m_presentation = on;
    theme::setPresentation(on);
    scaleExplicitFonts(on);
    if (on) {
        QFont f = m_normalFont;
        f.setPointSizeF(f.pointSizeF() * theme::kPresentationFontScale);
        m_window.setFont(f);
        m_window.setPalette(highContrastPalette());
    } else {
        m_window.setFont(m_normalFont);
        m_window.setPalette(m_normalPalette);
    }
    for (PlotWidget* plot : m_window.findChildren<PlotWidget*>())
        plot->setPresentation(on);
    for (QToolBar* bar : m_window.findChildren<QToolBar*>())
        bar->setIconSize(on ? QSize(32, 32) : QSize());
    // Icons alone where there are icons (their tooltips name them), so that every action fits
    // a 1024-pixel projector's width at the larger text instead of hiding behind "»".
    if (auto* bar = m_window.findChild<QToolBar*>(QStringLiteral("simulationToolbar")))
        bar->setToolButtonStyle(on ? Qt::ToolButtonIconOnly : Qt::ToolButtonTextBesideIcon);
    emit presentationChanged(on);
    if (on) {
        m_window.showFullScreen();
        // The larger text widens the panels: the columns go back to their shares, so that the
        // world keeps half of the screen (again once full screen has its size: windowResized).
        fitSideColumns();
    } else {
        if (m_normalWasMaximized)
            m_window.showMaximized();
        else
            m_window.showNormal();
        // showNormal() gives back the geometry from before full screen (Qt keeps it); the
        // docks take their old places and sizes.
        restoreNormalState();
        // And again once the window has its old size back (windowResized): a state restored
        // while it was still full screen keeps the docks in proportion instead.
        m_restoreStatePending = true;
    }
}

void WindowLayout::restoreNormalState()
{
    // The saved state shows the docks and toolbars that were shown when presentation mode
    // began; one opened since (the inspector, to show a value to the class) would close with
    // it, and so would the editor's tools of a new scene made before the window had its size
    // back (the second pass, windowResized). Each keeps what it is now. The plots' least
    // heights for the large type would hold the docks taller than they were: they are made
    // again for the restored sizes.
    std::vector<std::pair<QPointer<QWidget>, bool>> shownNow;
    for (QDockWidget* dock : m_window.findChildren<QDockWidget*>())
        shownNow.emplace_back(dock, !dock->isHidden());
    for (QToolBar* bar : m_window.findChildren<QToolBar*>())
        shownNow.emplace_back(bar, !bar->isHidden());
    relaxPlotHeights();
    m_window.restoreState(m_normalState);
    for (const auto& [widget, shown] : shownNow)
        if (widget && widget->isHidden() == shown)
            widget->setVisible(shown);
}

void WindowLayout::scaleExplicitFonts(bool on)
{
    // Widgets that set a font of their own (the lesson's text, titles, hints) do not follow
    // the window's: they grow by the same factor, and get their own fonts back afterwards.
    if (!on) {
        for (const auto& [widget, font] : m_explicitFonts)
            if (widget)
                widget->setFont(font);
        m_explicitFonts.clear();
        return;
    }
    for (QWidget* w : m_window.findChildren<QWidget*>()) {
        if (!w->testAttribute(Qt::WA_SetFont) || w->property(kFontFollowsProperty).toBool() ||
            qobject_cast<PlotWidget*>(w) ||
            (w->parentWidget() && qobject_cast<PlotWidget*>(w->parentWidget())))
            continue;
        m_explicitFonts.push_back({QPointer<QWidget>(w), w->font()});
        QFont f = w->font();
        const bool reading = w->property(kReadingSizeProperty).toBool();
        f.setPointSizeF(f.pointSizeF() * theme::kPresentationFontScale /
                        (reading ? theme::kReadingFontScale : 1.0));
        w->setFont(f);
    }
}

} // namespace rigidlab::ui
