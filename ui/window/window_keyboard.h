// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The window's keyboard beyond the run actions: the lesson's next and previous step, the
// focus to the scene or to the toolbar (window_keyboard_toolbar.h), choosing a body without a
// mouse, single-key shortcuts on or off, and Enter on a body showing its numbers in the
// inspector; Tab from the scene to the step's answer. It installs the shortcuts guard (keys go
// to the focused control first), the focus ring (common/) and the guard that keeps Tab to
// controls in sight (window_keyboard_sight.h).

#include "common/shortcuts.h"

#include <QList>
#include <QObject>

#include <array>

class QAction;
class QMainWindow;
class QMenu;

namespace rigidlab::ui {

class InspectorPanel;
class LessonPlayer;
class WindowLayout;
class WorldView;

class WindowKeyboard : public QObject {
    Q_OBJECT
public:
    struct Parts {
        QMainWindow& window;
        WorldView& view;
        LessonPlayer& player;
        InspectorPanel& inspector;
        WindowLayout& layout;
    };
    explicit WindowKeyboard(const Parts& parts);

    /// Help › Controls' rows for the keys handled here that are no action's: Tab on the scene.
    static QList<ControlHelpRow> helpRows();
    /// Adds the lesson-step and body actions to the Simulation menu.
    void addToSimulationMenu(QMenu& menu) const;
    /// Adds "Single-key shortcuts" to a menu (View).
    void addToViewMenu(QMenu& menu) const;
    QAction* singleKeys() const { return m_singleKeys; }
    /// View › Reduced motion: no animated docks, menus, lists or tooltips (kept).
    QAction* reducedMotion() const { return m_reducedMotion; }
    /// Applies the saved choices of single-key shortcuts and reduced motion (after every
    /// action exists).
    void applySavedChoice();

protected:
    /// Tab on the scene, on a lesson step that asks something: to its answer.
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    QAction* make(const QString& text, const char* name);
    /// The lesson panel's controls right after the scene in the focus chain, in their own
    /// order, so that Tab from the scene to the step's answer passes only the panel's own
    /// controls above it by.
    void lessonFollowsScene();
    void showNumbers(int body);
    void setReducedMotion(bool on);

    Parts m_parts;
    QAction* m_next = nullptr;
    QAction* m_previous = nullptr;
    QAction* m_focusScene = nullptr;
    QAction* m_focusToolbar = nullptr;
    QAction* m_nextBody = nullptr;
    QAction* m_previousBody = nullptr;
    QAction* m_singleKeys = nullptr;
    QAction* m_reducedMotion = nullptr;
    std::array<bool, 6> m_effectsBefore{}; ///< Qt's effects as the platform had them
};

} // namespace rigidlab::ui
