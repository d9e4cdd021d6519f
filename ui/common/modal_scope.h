// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A stretch of code that runs a modal dialog and then acts on its answer (export into the chosen
// folder, open the chosen file).
//
// Why: a window may be asked to close while such a dialog is up (by the window manager, a
// session ending, a script). If it closed then, its deferred deletion can run inside the
// dialog's own event loop (Qt deletes a deferred object when control returns to the loop that
// was running when deleteLater() was called), which deletes the dialog with its parent: the
// static QFileDialog helpers then return "" and the user's export is silently dropped, and a
// dialog on the stack is deleted twice. So a window asked to close meanwhile waits until the
// outermost scope has ended, then closes: what the user chose is carried out first.

#include <QObject>
#include <QPointer>

#include <functional>
#include <vector>

namespace rigidlab::ui {

class ModalScope {
public:
    ModalScope();
    ~ModalScope();
    ModalScope(const ModalScope&) = delete;
    ModalScope& operator=(const ModalScope&) = delete;

    /// Whether some modal stretch is running now.
    static bool active();
    /// Runs `then` when the outermost scope ends, unless `context` is gone by then; at once
    /// when no scope is open.
    static void whenDone(QObject* context, std::function<void()> then);

private:
    struct Pending {
        QPointer<QObject> context;
        std::function<void()> then;
    };
    static int s_depth;
    static std::vector<Pending> s_pending;
};

} // namespace rigidlab::ui
