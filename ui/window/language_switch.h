// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Switching the window's language: View › Language, and a new window in the new
// language that carries on where the old one was. The window is rebuilt rather than
// retranslated in place: every text is then made by the code that makes it in the first
// place, so no widget can be left half in the old language.

#include "format/scene.h"
#include "lesson_player/lesson_player.h"
#include "simulation/setting_edit.h"

#include <QByteArray>
#include <QString>

#include <optional>

class QMenu;

namespace rigidlab::ui {

class MainWindow;

/// What a window shows that a new window should show too.
struct WindowState {
    QString lessonPath; ///< the open lesson, empty when none is
    int lessonStep = 0; ///< its step, 0 = the first
    QString scenePath;  ///< the open scene when no lesson is
    /// The scene as edited, when no lesson is open and it is not the file as saved (a new
    /// scene, or unsaved edits): carried over so that switching loses no edit.
    std::optional<lessons::Scene> editedScene;
    bool editedIsFile = false;   ///< scenePath is the edited scene's own file (Save writes there)
    bool editedModified = false; ///< with edits not saved
    long long steps = 0; ///< the world's steps since its start (replayed: the run is deterministic)
    bool running = false; ///< the clock was running
    double timeScale = 1.0;
    /// The settings changed by hand (Controls, Inspector), each made again at its step: the
    /// same world, the same marks on the plots, the same values in the panels.
    SettingEdits edits;
    StepWork answers; ///< the step's questions: tries, verdicts and what is typed
    bool presentation = false;
    QByteArray geometry; ///< QWidget::saveGeometry
};

/// What `window` shows now.
WindowState captureState(MainWindow& window);
/// Opens in `window` what `state` says, at the same step of the same scene; returns the
/// error, empty on success.
QString restoreState(MainWindow& window, const WindowState& state);

/// Adds the Language submenu to `viewMenu`: one checkable entry per language in kLanguages,
/// in its own name, the current one checked. Choosing another saves it and emits
/// window.languageChosen(code).
QMenu* addLanguageMenu(QMenu* viewMenu, MainWindow& window);

/// Puts `code` in effect and replaces `old` with a new window in that language showing the
/// same scene or lesson step at the same step; `old` is closed and deleted later. Returns the
/// new window (deleted when closed), or `old` itself when `code` is no language.
MainWindow* switchLanguage(MainWindow* old, const QString& code);

/// Makes `window` (and every window that replaces it) switch when its Language menu is used.
void followLanguageChoice(MainWindow* window);

} // namespace rigidlab::ui
