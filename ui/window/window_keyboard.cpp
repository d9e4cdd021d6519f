// SPDX-License-Identifier: GPL-3.0-or-later
#include "window/window_keyboard.h"

#include "common/announcer.h"
#include "common/focus_first.h"
#include "common/focus_ring.h"
#include "common/shortcuts.h"
#include "common/shortcuts_guard.h"
#include "common/theme.h"
#include "lesson_player/lesson_player.h"
#include "panels/inspector_panel.h"
#include "panels/number_field.h"
#include "view/scene_words.h"
#include "view/world_view.h"
#include "window/menu_bar_focus.h"
#include "window/window_keyboard_sight.h"
#include "window/window_keyboard_toolbar.h"
#include "window/window_layout.h"

#include <QAction>
#include <QApplication>
#include <QDockWidget>
#include <QKeyEvent>
#include <QMainWindow>
#include <QMenu>
#include <QPalette>
#include <QSettings>

#include <array>

namespace rigidlab::ui {

namespace {
const QString kSingleKeysSetting = QStringLiteral("keyboard/singleKeyShortcuts");
const QString kReducedMotionSetting = QStringLiteral("accessibility/reducedMotion");
/// Qt's animated effects, which reduced motion turns off.
constexpr std::array kEffects{Qt::UI_AnimateMenu,    Qt::UI_FadeMenu,    Qt::UI_AnimateCombo,
                              Qt::UI_AnimateTooltip, Qt::UI_FadeTooltip, Qt::UI_AnimateToolBox};
} // namespace

WindowKeyboard::WindowKeyboard(const Parts& parts) : QObject(&parts.window), m_parts(parts)
{
    ShortcutsGuard::install();
    FocusRing::install();
    tellFieldFocusFirst();
    skipControlsOutOfSight(parts.window);
    keepMenuBarFocusVisible(parts.window);
    QPalette palette = QApplication::palette();
    palette.setColor(QPalette::PlaceholderText, theme::placeholderText());
    QApplication::setPalette(palette);
    m_next = make(tr("Next lesson step"), "nextStep");
    connect(m_next, &QAction::triggered, &parts.player, &LessonPlayer::next);
    m_previous = make(tr("Previous lesson step"), "previousStep");
    connect(m_previous, &QAction::triggered, &parts.player, &LessonPlayer::back);
    m_focusScene = make(tr("Focus the scene"), "focusScene");
    connect(m_focusScene, &QAction::triggered, &parts.view, [&view = parts.view] {
        // A reader speaks a focus that moves; on the scene already, F6 says where it is.
        if (view.hasFocus())
            announce(view, scene_words::sceneName(view.run()) + QStringLiteral(". ") +
                               scene_words::summary(view.run(), view.selectedBody()));
        else
            view.setFocus(Qt::ShortcutFocusReason);
    });
    m_focusToolbar = make(tr("Focus the toolbar"), "focusToolbar");
    connect(m_focusToolbar, &QAction::triggered, new ToolbarKeys(parts.window, parts.view),
            &ToolbarKeys::enter);
    m_nextBody = make(tr("Select next body"), "selectNextBody");
    connect(m_nextBody, &QAction::triggered, &parts.view, &WorldView::selectNextBody);
    m_previousBody = make(tr("Select previous body"), "selectPreviousBody");
    connect(m_previousBody, &QAction::triggered, &parts.view, &WorldView::selectPreviousBody);
    m_singleKeys = make(tr("Single-&key shortcuts"), "singleKeys");
    m_singleKeys->setCheckable(true);
    m_singleKeys->setChecked(true);
    m_singleKeys->setToolTip(tr("Letters, Space and arrows alone act as shortcuts; off, only "
                                "keys with Ctrl, Alt or F-keys do"));
    connect(m_singleKeys, &QAction::toggled, this, [this](bool on) {
        setSingleKeyShortcuts(m_parts.window, on);
        QSettings().setValue(kSingleKeysSetting, on);
    });
    connect(&parts.view, &WorldView::numbersRequested, this, &WindowKeyboard::showNumbers);
    parts.view.installEventFilter(this);
    lessonFollowsScene();
    connect(&parts.player, &LessonPlayer::stepActivated, this, &WindowKeyboard::lessonFollowsScene);
    connect(&parts.player, &LessonPlayer::lessonClosed, this, &WindowKeyboard::lessonFollowsScene);
    for (std::size_t i = 0; i < kEffects.size(); ++i)
        m_effectsBefore[i] = QApplication::isEffectEnabled(kEffects[i]);
    m_reducedMotion = make(tr("&Reduced motion"), "reducedMotion");
    m_reducedMotion->setCheckable(true);
    m_reducedMotion->setToolTip(
        tr("Panels, menus, lists and tooltips appear at once, without animation"));
    connect(m_reducedMotion, &QAction::toggled, this, [this](bool on) {
        setReducedMotion(on);
        QSettings().setValue(kReducedMotionSetting, on);
    });
}

bool WindowKeyboard::eventFilter(QObject* watched, QEvent* event)
{
    // A student working in the scene who is asked something answers next: Tab goes to the
    // step's answer, not through the lesson panel's list of lessons and the step's text first.
    // From there Tab and Shift+Tab go on in the panel's own order. On a step that asks nothing
    // (or nothing more), or with the lesson out of sight, Tab goes where it always goes.
    if (watched == &m_parts.view && event->type() == QEvent::KeyPress) {
        const auto* key = static_cast<const QKeyEvent*>(event);
        QWidget* answer = key->key() == Qt::Key_Tab && key->modifiers() == Qt::NoModifier
                              ? m_parts.player.firstAnswer()
                              : nullptr;
        if (answer && inSightInWindow(*answer)) {
            answer->setFocus(Qt::TabFocusReason);
            return true;
        }
    }
    return QObject::eventFilter(watched, event);
}

void WindowKeyboard::lessonFollowsScene()
{
    QDockWidget* lesson = m_parts.layout.dock(QStringLiteral("lesson"));
    if (!lesson)
        return;
    // The panel's stops in the order the player gave them (its text, the answers, then the
    // buttons), wherever the chain has them now.
    QList<QWidget*> stops;
    QWidget* start = &m_parts.window;
    for (QWidget* w = start->nextInFocusChain(); w && w != start; w = w->nextInFocusChain())
        if (lesson->isAncestorOf(w) && (w->focusPolicy() & Qt::TabFocus))
            stops << w;
    QWidget* previous = &m_parts.view;
    for (QWidget* w : std::as_const(stops)) {
        QWidget::setTabOrder(previous, w);
        previous = w;
    }
}

QList<ControlHelpRow> WindowKeyboard::helpRows()
{
    return {{{QKeySequence(Qt::Key_Tab)},
             tr("On the scene, in a lesson step that asks something: go to its answer")}};
}

void WindowKeyboard::setReducedMotion(bool on)
{
    QMainWindow::DockOptions options = m_parts.window.dockOptions();
    options.setFlag(QMainWindow::AnimatedDocks, !on);
    m_parts.window.setDockOptions(options);
    // Off again, each effect is as the platform had it.
    for (std::size_t i = 0; i < kEffects.size(); ++i)
        QApplication::setEffectEnabled(kEffects[i], !on && m_effectsBefore[i]);
}

QAction* WindowKeyboard::make(const QString& text, const char* name)
{
    auto* a = new QAction(text, this);
    a->setObjectName(QLatin1String(name));
    a->setShortcuts(controlKeys(name));
    m_parts.window.addAction(a);
    return a;
}

void WindowKeyboard::addToSimulationMenu(QMenu& menu) const
{
    menu.addSeparator();
    for (QAction* a :
         {m_focusScene, m_focusToolbar, m_nextBody, m_previousBody, m_next, m_previous})
        menu.addAction(a);
}

void WindowKeyboard::addToViewMenu(QMenu& menu) const
{
    menu.addAction(m_singleKeys);
    menu.addAction(m_reducedMotion);
}

void WindowKeyboard::applySavedChoice()
{
    const bool on = QSettings().value(kSingleKeysSetting, true).toBool();
    if (on != m_singleKeys->isChecked())
        m_singleKeys->setChecked(on);
    const bool reduced = QSettings().value(kReducedMotionSetting, false).toBool();
    if (reduced != m_reducedMotion->isChecked())
        m_reducedMotion->setChecked(reduced);
}

void WindowKeyboard::showNumbers(int body)
{
    if (body < 0)
        return;
    if (QDockWidget* dock = m_parts.layout.dock(QStringLiteral("inspector"))) {
        dock->show();
        dock->raise();
        // Asked for, the numbers get room: at 1024x768 a lesson's table below left the
        // inspector a sliver of its column (a few rows in sight, the table's head still).
        const int least = m_parts.window.height() * 3 / 10;
        if (dock->height() < least && m_parts.window.dockWidgetArea(dock) != Qt::NoDockWidgetArea &&
            !dock->isFloating())
            m_parts.window.resizeDocks({dock}, {least}, Qt::Vertical);
    }
    // Laid out before the focus goes in: an inspector out of sight until now fills its rows
    // in as it is shown (InspectorPanel::refresh), and the field must be where it is seen.
    QCoreApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
    // The mass is the number a student changes; the others follow it in the tab order.
    if (NumberField* mass = m_parts.inspector.massField(); mass && mass->isVisible())
        mass->setFocus(Qt::OtherFocusReason);
    else
        m_parts.inspector.setFocus(Qt::OtherFocusReason);
}

} // namespace rigidlab::ui
