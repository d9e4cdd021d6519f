// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Keys pressed as a person presses them, one at a time on the focused control, and a watch on
// where the focus goes: the keyboard tests' helpers (test_keyboard.cpp,
// test_keyboard_lesson.cpp).

#include <QApplication>
#include <QFileDialog>
#include <QStringList>
#include <QWidget>
#include <QtTest>

namespace rigidlab::test {

/// Whether some of `w` shows: its part inside its parents is not empty, and at one point of a
/// 3×3 grid over that part the window's topmost widget is `w`, its child or its parent, not
/// another dock or panel lying over it.
inline bool seen(const QWidget& w)
{
    const QWidget* window = w.window();
    QRect r(w.mapTo(window, QPoint()), w.size());
    for (const QWidget* p = w.parentWidget(); p && p != window; p = p->parentWidget())
        r &= QRect(p->mapTo(window, QPoint()), p->size());
    r &= window->rect();
    if (!w.isVisible() || r.isEmpty())
        return false;
    for (int i = 1; i <= 3; ++i)
        for (int j = 1; j <= 3; ++j) {
            const QPoint at(r.left() + i * r.width() / 4, r.top() + j * r.height() / 4);
            const QWidget* top = window->childAt(at);
            if (!top || top == &w || w.isAncestorOf(top) || top->isAncestorOf(&w))
                return true;
        }
    return false;
}

/// Every widget that took the focus while it could not be seen: hidden, out of its window's
/// sight (Qt moves docks behind a tab away rather than hiding them), or covered by another
/// dock lying over it.
class FocusWatch : public QObject {
public:
    FocusWatch()
    {
        connect(qApp, &QApplication::focusChanged, this, [this](QWidget*, QWidget* now) {
            // The lab's window; Qt's own file dialog hides and shows parts of itself.
            if (!now || qobject_cast<QFileDialog*>(now->window()))
                return;
            ++m_stops;
            if (!seen(*now))
                m_hidden << QStringLiteral("%1 '%2' visible %3, %4x%5 at (%6, %7)")
                                .arg(QLatin1String(now->metaObject()->className()),
                                     now->objectName())
                                .arg(now->isVisible())
                                .arg(now->width())
                                .arg(now->height())
                                .arg(now->mapTo(now->window(), QPoint()).x())
                                .arg(now->mapTo(now->window(), QPoint()).y());
        });
    }
    const QStringList& hidden() const { return m_hidden; }
    int stops() const { return m_stops; }

private:
    QStringList m_hidden;
    int m_stops = 0;
};

inline QWidget* focused(QWidget& window)
{
    QWidget* f = QApplication::focusWidget();
    return f ? f : &window;
}

/// One key pressed and released on the focused control, then the events it caused handled,
/// as between a person's key presses.
inline void key(QWidget& window, Qt::Key k, Qt::KeyboardModifiers mods = Qt::NoModifier)
{
    QTest::keyClick(focused(window), k, mods);
    QCoreApplication::processEvents();
}

} // namespace rigidlab::test
