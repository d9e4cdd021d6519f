// SPDX-License-Identifier: GPL-3.0-or-later
#include "window/menu_bar_focus.h"

#include <QApplication>
#include <QKeyEvent>
#include <QMainWindow>
#include <QMenuBar>
#include <QPointer>
#include <QTimer>

namespace rigidlab::ui {

namespace {

bool isModifierKey(int key)
{
    return key == Qt::Key_Alt || key == Qt::Key_AltGr || key == Qt::Key_Shift ||
           key == Qt::Key_Control || key == Qt::Key_Meta;
}

class MenuBarWatch : public QObject {
public:
    explicit MenuBarWatch(QMainWindow& window) : QObject(&window), m_window(window)
    {
        qApp->installEventFilter(this);
        connect(qApp, &QApplication::focusChanged, this, [this](QWidget* old, QWidget* now) {
            if (!now || now != m_window.menuWidget())
                return;
            // Decided now, while the chord's Alt is the key being handled; acted on once Qt
            // has finished with it.
            const bool chord = m_chord;
            QPointer<QWidget> before(old);
            QTimer::singleShot(0, this, [this, chord, before] { leaveIfUnasked(chord, before); });
        });
    }

protected:
    bool eventFilter(QObject*, QEvent* event) override
    {
        const QEvent::Type type = event->type();
        if (type != QEvent::KeyPress && type != QEvent::ShortcutOverride &&
            type != QEvent::KeyRelease)
            return false;
        const auto* key = static_cast<const QKeyEvent*>(event);
        if (key->key() == Qt::Key_Alt) {
            // Alt going down starts afresh (Qt sends its press twice: as a possible override
            // and as a key); coming up, it ends the chord once it is handled.
            if (type == QEvent::KeyRelease) {
                m_held = false;
                QTimer::singleShot(0, this, [this] { m_chord = false; });
            } else if (!m_held) {
                m_held = true;
                m_chord = false;
            }
        } else if (type != QEvent::KeyRelease && !isModifierKey(key->key()) &&
                   (key->modifiers() & Qt::AltModifier)) {
            m_chord = true;
        }
        return false;
    }

private:
    void leaveIfUnasked(bool chord, const QPointer<QWidget>& before)
    {
        auto* bar = qobject_cast<QMenuBar*>(m_window.menuWidget());
        // Alt and a menu's letter open that menu, and the menu bar with it: asked for.
        if (!bar || !bar->hasFocus() || QApplication::activePopupWidget() ||
            (!chord && bar->activeAction()))
            return;
        // Esc, as the student would press it: Qt closes the menu bar's keyboard mode and
        // gives the focus back to the control it came from.
        QKeyEvent esc(QEvent::KeyPress, Qt::Key_Escape, Qt::NoModifier);
        QCoreApplication::sendEvent(bar, &esc);
        if (bar->hasFocus() && before)
            before->setFocus(Qt::OtherFocusReason);
        else if (bar->hasFocus())
            bar->clearFocus();
    }

    QMainWindow& m_window;
    bool m_chord = false; ///< a key other than a modifier went down with Alt since Alt did
    bool m_held = false;  ///< Alt is down
};

} // namespace

void keepMenuBarFocusVisible(QMainWindow& window)
{
    new MenuBarWatch(window);
}

} // namespace rigidlab::ui
