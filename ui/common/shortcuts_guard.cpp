// SPDX-License-Identifier: GPL-3.0-or-later
#include "common/shortcuts_guard.h"

#include <QAbstractButton>
#include <QAbstractItemView>
#include <QAbstractSlider>
#include <QAbstractSpinBox>
#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QKeyEvent>
#include <QKeySequence>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QScrollArea>
#include <QTabBar>
#include <QTextEdit>

namespace rigidlab::ui {

namespace {

/// The property an action keeps all its keys in while single keys are off.
constexpr char kAllKeys[] = "rigidlabAllKeys";

bool isArrowOrPaging(int key)
{
    switch (key) {
    case Qt::Key_Left:
    case Qt::Key_Right:
    case Qt::Key_Up:
    case Qt::Key_Down:
    case Qt::Key_Home:
    case Qt::Key_End:
    case Qt::Key_PageUp:
    case Qt::Key_PageDown:
        return true;
    default:
        return false;
    }
}

bool typesText(const QWidget& w)
{
    if (const auto* line = qobject_cast<const QLineEdit*>(&w))
        return !line->isReadOnly();
    if (const auto* text = qobject_cast<const QTextEdit*>(&w))
        return !text->isReadOnly();
    if (const auto* plain = qobject_cast<const QPlainTextEdit*>(&w))
        return !plain->isReadOnly();
    if (const auto* combo = qobject_cast<const QComboBox*>(&w))
        return combo->isEditable();
    return qobject_cast<const QAbstractSpinBox*>(&w) != nullptr;
}

bool movesWithArrows(const QWidget& w)
{
    return typesText(w) || qobject_cast<const QAbstractItemView*>(&w) ||
           qobject_cast<const QTabBar*>(&w) || qobject_cast<const QAbstractSlider*>(&w) ||
           qobject_cast<const QComboBox*>(&w) || qobject_cast<const QLineEdit*>(&w) ||
           qobject_cast<const QTextEdit*>(&w) || qobject_cast<const QPlainTextEdit*>(&w);
}

/// Shows `w` within every scroll area it is in, innermost first.
void scrollIntoView(QWidget* w)
{
    for (QWidget* p = w->parentWidget(); p; p = p->parentWidget())
        if (auto* area = qobject_cast<QScrollArea*>(p);
            area && area->widget() && area->widget()->isAncestorOf(w))
            area->ensureWidgetVisible(w, 16, 16);
}

} // namespace

ShortcutsGuard& ShortcutsGuard::install()
{
    static ShortcutsGuard* guard = nullptr;
    if (!guard) {
        guard = new ShortcutsGuard(qApp);
        qApp->installEventFilter(guard);
    }
    return *guard;
}

bool ShortcutsGuard::widgetTakesKey(const QWidget& widget, const QKeyEvent& key)
{
    const Qt::KeyboardModifiers mods = key.modifiers() & ~(Qt::ShiftModifier | Qt::KeypadModifier);
    if (mods != Qt::NoModifier)
        return false;
    const int k = key.key();
    if (k == Qt::Key_Space || k == Qt::Key_Return || k == Qt::Key_Enter)
        return qobject_cast<const QAbstractButton*>(&widget) || movesWithArrows(widget);
    if (isArrowOrPaging(k))
        return movesWithArrows(widget);
    if (k == Qt::Key_Backspace || k == Qt::Key_Delete)
        return typesText(widget);
    return typesText(widget) && !key.text().isEmpty() && key.text().at(0).isPrint();
}

bool ShortcutsGuard::eventFilter(QObject* watched, QEvent* event)
{
    if (!watched->isWidgetType())
        return false;
    auto* widget = static_cast<QWidget*>(watched);
    switch (event->type()) {
    case QEvent::ShortcutOverride:
        if (widgetTakesKey(*widget, *static_cast<QKeyEvent*>(event))) {
            event->accept();
            return true;
        }
        break;
    case QEvent::KeyPress: {
        // Return presses a focused button, as Space does (Qt's buttons take Space only).
        const auto* key = static_cast<QKeyEvent*>(event);
        auto* button = qobject_cast<QAbstractButton*>(widget);
        if (button && button->isEnabled() && key->modifiers() == Qt::NoModifier &&
            (key->key() == Qt::Key_Return || key->key() == Qt::Key_Enter)) {
            button->click();
            return true;
        }
        break;
    }
    case QEvent::FocusIn:
        scrollIntoView(widget);
        // Tab leaves a table rather than walking its cells forever.
        if (auto* view = qobject_cast<QAbstractItemView*>(widget))
            view->setTabKeyNavigation(false);
        break;
    default:
        break;
    }
    return false;
}

bool isSingleKey(const QKeySequence& keys)
{
    if (keys.count() != 1)
        return false;
    const Qt::KeyboardModifiers mods = keys[0].keyboardModifiers();
    const int key = keys[0].key();
    if (key >= Qt::Key_F1 && key <= Qt::Key_F35)
        return false; // function keys type nothing and are not pressed by accident
    if (key == Qt::Key_Delete || key == Qt::Key_Escape)
        return false;
    return (mods & ~Qt::ShiftModifier) == Qt::NoModifier;
}

void setSingleKeyShortcuts(QWidget& window, bool on)
{
    for (QAction* a : window.findChildren<QAction*>()) {
        const QVariant saved = a->property(kAllKeys);
        if (on) {
            if (saved.isValid())
                a->setShortcuts(saved.value<QList<QKeySequence>>());
            continue;
        }
        const QList<QKeySequence> all =
            saved.isValid() ? saved.value<QList<QKeySequence>>() : a->shortcuts();
        QList<QKeySequence> kept;
        for (const QKeySequence& k : all)
            if (!isSingleKey(k))
                kept << k;
        if (kept.size() == all.size())
            continue;
        a->setProperty(kAllKeys, QVariant::fromValue(all));
        a->setShortcuts(kept);
    }
}

} // namespace rigidlab::ui
