// SPDX-License-Identifier: GPL-3.0-or-later
#include "common/focus_first.h"

#include <QAbstractSpinBox>
#include <QApplication>
#include <QEvent>
#include <QFocusEvent>
#include <QLineEdit>
#include <QPointer>
#include <QTimer>

namespace rigidlab::ui {

namespace {

/// Whether `widget`, taking the focus for `reason`, selects its text as it does
/// (QLineEdit::focusInEvent and QAbstractSpinBox::focusInEvent).
bool selectsOnFocus(const QObject& widget, Qt::FocusReason reason)
{
    const bool byTab = reason == Qt::TabFocusReason || reason == Qt::BacktabFocusReason;
    if (const auto* field = qobject_cast<const QLineEdit*>(&widget))
        return (byTab || reason == Qt::ShortcutFocusReason) && field->inputMask().isEmpty() &&
               !field->hasSelectedText() && !field->text().isEmpty();
    if (const auto* box = qobject_cast<const QAbstractSpinBox*>(&widget))
        return byTab && !box->text().isEmpty();
    return false;
}

class FocusFirst : public QObject {
public:
    using QObject::QObject;

protected:
    bool eventFilter(QObject* watched, QEvent* event) override
    {
        switch (event->type()) {
        case QEvent::Polish:
            // Polish comes once, before a widget is first shown; the caret stays where it is,
            // but Qt now knows it as placed.
            if (auto* field = qobject_cast<QLineEdit*>(watched))
                field->setCursorPosition(field->cursorPosition());
            break;
        case QEvent::FocusIn:
            if (watched->isWidgetType() &&
                selectsOnFocus(*watched, static_cast<QFocusEvent*>(event)->reason())) {
                // The field takes the focus without selecting (a reason it does not select
                // for), Qt tells the focus, and the text is selected after that.
                QFocusEvent plain(QEvent::FocusIn, Qt::OtherFocusReason);
                QCoreApplication::sendEvent(watched, &plain);
                m_toSelect = static_cast<QWidget*>(watched);
                QTimer::singleShot(0, this, [this] { selectNow(); });
                return true;
            }
            break;
        case QEvent::KeyPress:
        case QEvent::ShortcutOverride:
            // A key typed at once replaces the text, as it would have.
            if (watched == m_toSelect)
                selectNow();
            break;
        case QEvent::MouseButtonPress:
        case QEvent::FocusOut:
            // A click places the caret; a field left keeps its text as it is.
            if (m_toSelect && (watched == m_toSelect ||
                               m_toSelect->isAncestorOf(qobject_cast<QWidget*>(watched))))
                m_toSelect = nullptr;
            break;
        default:
            break;
        }
        return false;
    }

private:
    void selectNow()
    {
        QWidget* widget = m_toSelect;
        m_toSelect = nullptr;
        if (!widget || !widget->hasFocus())
            return;
        if (auto* field = qobject_cast<QLineEdit*>(widget))
            field->selectAll();
        else if (auto* box = qobject_cast<QAbstractSpinBox*>(widget))
            box->selectAll();
    }

    /// The field whose text is still to be selected, after its focus was told.
    QPointer<QWidget> m_toSelect;
};

} // namespace

void tellFieldFocusFirst()
{
    static const bool installed = [] {
        qApp->installEventFilter(new FocusFirst(qApp));
        return true;
    }();
    Q_UNUSED(installed);
}

} // namespace rigidlab::ui
