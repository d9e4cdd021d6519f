// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// rigidlab --screenshots DIR: the plain window at a given size on the welcome scene, on
// every step of the shipped lessons and in the views a teacher checks before a class, one PNG per
// view and an index of what each shows. For checking the layout at classroom sizes (a projector's
// 1024×768) without clicking through.

#include <QSize>
#include <QString>
#include <QStringList>

#include <functional>
#include <optional>

namespace rigidlab::ui {

class MainWindow;

struct ScreenshotOptions {
    QString folder;                     ///< created if missing
    QSize size{1280, 720};              ///< of the window and of every PNG [px]
    double welcomeSeconds = 2.0;        ///< simulated time the welcome scene runs [s]
    bool welcome = true;                ///< shoot the welcome scene (00-welcome.png)
    std::optional<QStringList> lessons; ///< lesson files; nullopt: all shipped lessons
    int maxStepsPerLesson = 0;          ///< 0: every step
    /// Shoot the classroom views too: a lesson step with the controls, inspector and
    /// collision panels (90-panels.png), Help › Controls (91-help-controls.png), presentation
    /// mode (92-presentation.png), the editor on a new scene (93-editor.png) and a measurement
    /// with its residuals and fit (94-measurement.png), the lesson editor (lesson-editor.png)
    /// and File › Class results… on a made-up class (97-class-results.png).
    bool classroom = true;
    /// Called on the new window before anything is shot (presentation mode, ...).
    std::function<void(MainWindow&)> setUp;
};

struct ScreenshotResult {
    bool ok = false;
    QString error;     ///< one line, when !ok
    QStringList files; ///< file names written into the folder, index.txt last
    QStringList notes; ///< what the caller should know (a window that could not be that small)
};

/// Opens a window of its own with settings of its own (a temporary folder, for as long as it
/// runs: neither the user's saved layout nor their recent files are read or written), runs each
/// view for a fixed number of steps (the step's exportTime, or welcomeSeconds) and writes
/// DIR/00-welcome.png, DIR/LESSON-NN.png, ... and DIR/index.txt ("FILE<TAB>what it shows" per
/// line), each atomically. Needs a QApplication.
ScreenshotResult writeScreenshots(const ScreenshotOptions& options);

} // namespace rigidlab::ui
