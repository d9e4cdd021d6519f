// SPDX-License-Identifier: GPL-3.0-or-later
#include "window/window_actions.h"

#include "common/shortcuts.h"
#include "simulation/simulation_controller.h"
#include "view/world_view.h"
#include "window/window_names.h"

#include <QAction>
#include <QMainWindow>
#include <QStyle>
#include <QToolBar>

#include <cmath>
#include <utility>

namespace rigidlab::ui {

WindowActions::WindowActions(QMainWindow& window, SimulationController& controller, WorldView& view)
    : QObject(&window), m_window(window), m_controller(controller), m_view(view)
{
    m_toolbar = window.addToolBar(tr("Simulation"));
    m_toolbar->setObjectName(QStringLiteral("simulationToolbar"));
    m_toolbar->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);

    m_play = makeRunAction(QStyle::SP_MediaPlay, tr("Play"), "play",
                           tr("Play or pause (%1)").arg(controlKeysText("play")));
    connect(m_play, &QAction::triggered, &controller, &SimulationController::toggleRunning);
    m_step = makeRunAction(QStyle::SP_MediaSeekForward, tr("Step"), "step",
                           tr("One step forward (%1)").arg(controlKeysText("step")));
    connect(m_step, &QAction::triggered, &controller, &SimulationController::stepForward);
    m_back = makeRunAction(QStyle::SP_MediaSeekBackward, tr("Back"), "back",
                           tr("One step back in time (%1)").arg(controlKeysText("back")));
    connect(m_back, &QAction::triggered, &controller, &SimulationController::stepBack);
    m_reset =
        makeRunAction(QStyle::SP_BrowserReload, tr("Reset"), "reset",
                      tr("Back to the start of the scene (%1)").arg(controlKeysText("reset")));
    connect(m_reset, &QAction::triggered, &controller, &SimulationController::reset);
    m_fit = makeRunAction(-1, tr("&Fit scene"), "fit",
                          tr("Zoom to show every body (%1)").arg(controlKeysText("fit")));
    connect(m_fit, &QAction::triggered, &view, &WorldView::fitScene);
    connect(&controller, &SimulationController::runningChanged, this, [this](bool running) {
        m_play->setText(running ? tr("Pause") : tr("Play"));
        m_play->setIcon(
            m_window.style()->standardIcon(running ? QStyle::SP_MediaPause : QStyle::SP_MediaPlay));
    });

    // Q and E turn the selected body (the SAT lesson turns its polygons this way).
    for (const auto& [name, degrees] : {std::pair{"turnLeft", 5.0}, std::pair{"turnRight", -5.0}}) {
        auto* turn = new QAction(
            degrees > 0 ? tr("Turn selected body left") : tr("Turn selected body right"), this);
        turn->setObjectName(QLatin1String(name));
        turn->setShortcuts(controlKeys(name));
        connect(turn, &QAction::triggered, this, [this, degrees] {
            if (m_view.selectedBody() >= 0)
                m_controller.rotateBody(m_view.selectedBody(), degrees * M_PI / 180.0);
        });
        window.addAction(turn);
        m_rotate << turn;
    }
    for (QAction* a : {m_back, m_play, m_step, m_reset, m_fit})
        m_toolbar->addAction(a);
    m_toolbar->addSeparator();
    makeOverlayActions();
    for (QAction* a : {m_step, m_back})
        a->setProperty("runToolTip", a->toolTip());
}

QAction* WindowActions::makeRunAction(int icon, const QString& text, const char* name,
                                      const QString& tip)
{
    auto* a = new QAction(text, this);
    if (icon >= 0)
        a->setIcon(m_window.style()->standardIcon(static_cast<QStyle::StandardPixmap>(icon)));
    a->setObjectName(QLatin1String(name));
    a->setShortcuts(controlKeys(name));
    a->setToolTip(tip);
    return a;
}

void WindowActions::makeOverlayActions()
{
    for (std::size_t i = 0; i < kOverlayNames.size(); ++i) {
        const OverlayNames& info = kOverlayNames[i];
        auto* a = new QAction(windowNameText(info.text), this);
        a->setCheckable(true);
        a->setChecked(m_view.overlays().isEnabled(info.overlay));
        a->setShortcut(QKeySequence(QString::fromLatin1(info.shortcut)));
        connect(a, &QAction::toggled, this,
                [this, o = info.overlay](bool on) { m_view.overlays().setEnabled(o, on); });
        m_overlays[i] = a;
        // Short toolbar labels: the first word.
        auto* shortcutless = m_toolbar->addAction(windowNameText(info.shortText));
        shortcutless->setCheckable(true);
        shortcutless->setChecked(a->isChecked());
        shortcutless->setToolTip(tr("%1 (%2)").arg(
            windowNameText(info.text).remove(QLatin1Char('&')), QLatin1String(info.shortcut)));
        connect(shortcutless, &QAction::toggled, a, &QAction::setChecked);
        connect(a, &QAction::toggled, shortcutless, &QAction::setChecked);
    }
}

void WindowActions::setRunState(bool editing, bool runHeld)
{
    m_play->setEnabled(!runHeld);
    m_step->setEnabled(!editing && !runHeld);
    m_back->setEnabled(!editing);
    const QString editingTip = tr("The world does not step in Edit mode: leave it (%1) or press "
                                  "Play to run the scene as edited")
                                   .arg(controlKeysText("editMode"));
    for (QAction* a : {m_step, m_back})
        a->setToolTip(editing ? editingTip : a->property("runToolTip").toString());
}

} // namespace rigidlab::ui
