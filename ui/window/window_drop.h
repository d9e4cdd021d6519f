// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Files dropped on the window: a scene or a lesson (.json, .rlesson) dragged from a file
// manager opens as File › Open would open it. Drops land on the main window wherever they are
// let go, since the widgets inside it accept none of their own.

#include <QObject>
#include <QString>

#include <functional>

class QMimeData;
class QWidget;

namespace rigidlab::ui {

class WindowDrop : public QObject {
    Q_OBJECT
public:
    /// Watches `window` (and lets it accept drops); `open` gets the path of a dropped file.
    WindowDrop(QWidget& window, std::function<void(const QString& path)> open);

    /// The one local file of a drop that may be opened, or empty: a single .json or .rlesson.
    static QString droppedFile(const QMimeData* data);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    std::function<void(const QString&)> m_open;
};

} // namespace rigidlab::ui
