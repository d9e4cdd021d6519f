// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The window's run actions (Play, Step, Back, Reset, Fit, turning the selected body), the
// overlay switches, and the simulation toolbar that shows them. Each action takes its keys
// from the key table (common/shortcuts.h) and works on the controller or the view alone.

#include "view/overlays.h"

#include <QList>
#include <QObject>

#include <array>
#include <cstddef>

class QAction;
class QMainWindow;
class QToolBar;

namespace rigidlab::ui {

class SimulationController;
class WorldView;

class WindowActions : public QObject {
    Q_OBJECT
public:
    /// Makes the actions and the simulation toolbar on `window`.
    WindowActions(QMainWindow& window, SimulationController& controller, WorldView& view);

    QAction* play() const { return m_play; }
    QAction* step() const { return m_step; }
    QAction* back() const { return m_back; }
    QAction* reset() const { return m_reset; }
    QAction* fit() const { return m_fit; }
    const QList<QAction*>& rotate() const { return m_rotate; }
    QAction* overlay(Overlay overlay) const
    {
        return m_overlays[static_cast<std::size_t>(overlay)];
    }
    const std::array<QAction*, kOverlayCount>& overlays() const { return m_overlays; }
    QToolBar* toolbar() const { return m_toolbar; }

    /// Step and Back are off while editing (the world does not step) and Step and Play while a
    /// question holds the run back; a tooltip says why.
    void setRunState(bool editing, bool runHeld);

private:
    QAction* makeRunAction(int icon, const QString& text, const char* name, const QString& tip);
    void makeOverlayActions();

    QMainWindow& m_window;
    SimulationController& m_controller;
    WorldView& m_view;
    QToolBar* m_toolbar = nullptr;
    QAction* m_play = nullptr;
    QAction* m_step = nullptr;
    QAction* m_back = nullptr;
    QAction* m_reset = nullptr;
    QAction* m_fit = nullptr;
    QList<QAction*> m_rotate;
    std::array<QAction*, kOverlayCount> m_overlays{};
};

} // namespace rigidlab::ui
