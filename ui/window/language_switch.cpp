// SPDX-License-Identifier: GPL-3.0-or-later
#include "window/language_switch.h"

#include "common/language.h"
#include "editor/scene_document.h"
#include "lesson_player/lesson_player.h"
#include "simulation/simulation_controller.h"
#include "window/main_window.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QMenu>
#include <QPointer>
#include <QUndoStack>

namespace rigidlab::ui {

WindowState captureState(MainWindow& window)
{
    WindowState state;
    SimulationController& controller = window.controller();
    if (const lessons::Lesson* lesson = window.lessonPlayer().lesson()) {
        state.lessonPath = lesson->path;
        state.lessonStep = window.lessonPlayer().stepIndex();
        state.answers = window.lessonPlayer().work();
    } else {
        state.scenePath = window.document()->path();
        if (window.document()->isModified() || !window.documentIsFile()) {
            state.editedScene = window.document()->scene();
            state.editedIsFile = window.documentIsFile();
            state.editedModified = window.document()->isModified();
        }
    }
    state.steps = controller.world().stepCount();
    state.running = controller.isRunning();
    state.timeScale = controller.timeScale();
    state.edits = controller.editLog().edits();
    state.presentation = window.presentation();
    state.geometry = window.saveGeometry();
    return state;
}

QString restoreState(MainWindow& window, const WindowState& state)
{
    QString error;
    if (!state.lessonPath.isEmpty()) {
        error = window.openLesson(state.lessonPath, true);
        if (error.isEmpty() && state.lessonStep > 0)
            window.lessonPlayer().goToStep(state.lessonStep);
    } else if (state.editedScene) {
        window.adoptDocument(*state.editedScene, state.scenePath, state.editedIsFile,
                             state.editedModified);
    } else if (!state.scenePath.isEmpty()) {
        error = window.openScene(state.scenePath, true);
    }
    if (!error.isEmpty())
        return error;
    // The same steps from the same start give the same world (the engine is deterministic).
    // The settings changed by hand are changed again at their steps (edits after the step
    // shown belong to a future the new window does not have).
    SimulationController& controller = window.controller();
    std::size_t edit = 0;
    const auto makeDueEdits = [&] {
        for (;
             edit < state.edits.size() && state.edits[edit].step <= controller.world().stepCount();
             ++edit)
            controller.applyEdit(state.edits[edit]);
    };
    makeDueEdits();
    while (controller.world().stepCount() < state.steps) {
        const long long before = controller.world().stepCount();
        controller.stepForward();
        if (controller.world().stepCount() == before)
            break; // a world that cannot step (diverged) stays where it stopped
        makeDueEdits();
    }
    controller.setTimeScale(state.timeScale);
    // The answers once the run has measured what they were judged against.
    if (!state.lessonPath.isEmpty())
        window.lessonPlayer().restoreWork(state.answers);
    if (state.running)
        controller.setRunning(true);
    return QString();
}

QMenu* addLanguageMenu(QMenu* viewMenu, MainWindow& window)
{
    QMenu* menu =
        viewMenu->addMenu(QCoreApplication::translate("rigidlab::ui::MainWindow", "&Language"));
    menu->setObjectName(QStringLiteral("languageMenu"));
    auto* group = new QActionGroup(menu);
    group->setExclusive(true);
    for (const lessons::Language& language : lessons::kLanguages) {
        const QString code = language.code.toString();
        // Each language in its own name, so that whoever cannot read the current one finds
        // theirs.
        QAction* action = menu->addAction(language.name.toString());
        action->setObjectName(QStringLiteral("language-") + code);
        action->setCheckable(true);
        action->setChecked(code == currentLanguage());
        action->setActionGroup(group);
        QObject::connect(action, &QAction::triggered, &window, [&window, code] {
            if (code == currentLanguage())
                return;
            saveLanguage(code);
            emit window.languageChosen(code);
        });
    }
    return menu;
}

MainWindow* switchLanguage(MainWindow* old, const QString& code)
{
    if (!findLanguage(code))
        return old;
    const WindowState state = captureState(*old);
    // The old window saves its layout as it closes; the new one reads it back. Closing the
    // only window must not end the application meanwhile.
    const bool quitOnClose = QGuiApplication::quitOnLastWindowClosed();
    QGuiApplication::setQuitOnLastWindowClosed(false);
    const bool wasVisible = old->isVisible();
    // Its edits go to the new window (captureState): nothing to ask about as it closes.
    old->document()->undoStack()->setClean();
    old->close();
    old->deleteLater();
    applyLanguage(code);

    auto* window = new MainWindow;
    window->setAttribute(Qt::WA_DeleteOnClose);
    restoreState(*window, state);
    window->restoreGeometry(state.geometry);
    if (wasVisible)
        window->show();
    if (state.presentation)
        window->setPresentation(true);
    QGuiApplication::setQuitOnLastWindowClosed(quitOnClose);
    return window;
}

void followLanguageChoice(MainWindow* window)
{
    QObject::connect(window, &MainWindow::languageChosen, window, [window](const QString& code) {
        // After the menu's own handling has returned: the old window and its menu go. A window
        // closed meanwhile is switched no more.
        QMetaObject::invokeMethod(
            qApp,
            [old = QPointer<MainWindow>(window), code] {
                if (old)
                    followLanguageChoice(switchLanguage(old, code));
            },
            Qt::QueuedConnection);
    });
}

} // namespace rigidlab::ui
