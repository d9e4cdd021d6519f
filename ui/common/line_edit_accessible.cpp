// SPDX-License-Identifier: GPL-3.0-or-later
#include "common/line_edit_accessible.h"

#include <QAccessibleWidget>
#include <QFontMetrics>
#include <QLineEdit>
#include <QValidator>

namespace rigidlab::ui {

namespace {

class LineEditAccessible : public QAccessibleWidget,
                           public QAccessibleTextInterface,
                           public QAccessibleEditableTextInterface {
public:
    explicit LineEditAccessible(QLineEdit* field)
        : QAccessibleWidget(field, QAccessible::EditableText)
    {
        addControllingSignal(QStringLiteral("textChanged(const QString&)"));
        addControllingSignal(QStringLiteral("returnPressed()"));
    }

    void* interface_cast(QAccessible::InterfaceType t) override
    {
        if (t == QAccessible::TextInterface)
            return static_cast<QAccessibleTextInterface*>(this);
        if (t == QAccessible::EditableTextInterface)
            return static_cast<QAccessibleEditableTextInterface*>(this);
        return QAccessibleWidget::interface_cast(t);
    }

    QString text(QAccessible::Text t) const override
    {
        if (t == QAccessible::Value && !field()->displayText().isEmpty())
            return field()->displayText();
        const QString own = QAccessibleWidget::text(t);
        // An empty field says what it waits for ("your answer").
        return own.isEmpty() && t == QAccessible::Description ? field()->placeholderText() : own;
    }
    void setText(QAccessible::Text t, const QString& text) override
    {
        if (t != QAccessible::Value) {
            QAccessibleWidget::setText(t, text);
            return;
        }
        if (const QValidator* v = field()->validator()) {
            QString candidate = text;
            int pos = 0;
            if (v->validate(candidate, pos) != QValidator::Acceptable)
                return;
        }
        field()->setText(text);
    }

    QAccessible::State state() const override
    {
        QAccessible::State s = QAccessibleWidget::state();
        s.editable = true;
        s.readOnly = field()->isReadOnly();
        s.passwordEdit = field()->echoMode() != QLineEdit::Normal;
        s.selectableText = true;
        return s;
    }

    // QAccessibleTextInterface: the text as shown (bullets for a password), offsets in it.
    QString text(int start, int end) const override
    {
        return start > end ? QString() : field()->displayText().mid(start, end - start);
    }
    int characterCount() const override { return static_cast<int>(field()->displayText().size()); }
    /// One run, the whole text, with no attributes: a run that covers nothing (Qt's answer)
    /// left Orca nothing of the text to say.
    QString attributes(int, int* start, int* end) const override
    {
        *start = 0;
        *end = characterCount();
        return QString();
    }
    int cursorPosition() const override { return field()->cursorPosition(); }
    void setCursorPosition(int position) override { field()->setCursorPosition(position); }
    QString textAtOffset(int offset, QAccessible::TextBoundaryType boundary, int* start,
                         int* end) const override
    {
        return QAccessibleTextInterface::textAtOffset(at(offset), boundary, start, end);
    }
    QString textBeforeOffset(int offset, QAccessible::TextBoundaryType boundary, int* start,
                             int* end) const override
    {
        return QAccessibleTextInterface::textBeforeOffset(at(offset), boundary, start, end);
    }
    QString textAfterOffset(int offset, QAccessible::TextBoundaryType boundary, int* start,
                            int* end) const override
    {
        return QAccessibleTextInterface::textAfterOffset(at(offset), boundary, start, end);
    }

    int selectionCount() const override { return field()->hasSelectedText() ? 1 : 0; }
    void selection(int index, int* start, int* end) const override
    {
        *start = *end = 0;
        if (index != 0 || !field()->hasSelectedText())
            return;
        *start = field()->selectionStart();
        *end = field()->selectionEnd();
    }
    void addSelection(int start, int end) override { setSelection(0, start, end); }
    void removeSelection(int index) override
    {
        if (index == 0)
            field()->deselect();
    }
    void setSelection(int index, int start, int end) override
    {
        if (index == 0)
            field()->setSelection(start, end - start);
    }
    void scrollToSubstring(int start, int end) override
    {
        field()->setCursorPosition(end);
        field()->setCursorPosition(start);
    }

    /// The character's box on the screen: from the caret's box, which Qt places after any
    /// scrolling and alignment, moved by the width of the text between the two.
    QRect characterRect(int offset) const override
    {
        const QString shown = field()->displayText();
        if (offset < 0 || offset >= shown.size())
            return QRect();
        const QFontMetrics metrics(field()->font());
        const QRect caret = field()->inputMethodQuery(Qt::ImCursorRectangle).toRect();
        const int caretAt = field()->cursorPosition();
        const int x = caret.x() + metrics.horizontalAdvance(shown.left(offset)) -
                      metrics.horizontalAdvance(shown.left(caretAt));
        const QRect box(x, caret.y(), metrics.horizontalAdvance(shown.mid(offset, 1)),
                        metrics.height());
        return QRect(field()->mapToGlobal(box.topLeft()), box.size());
    }
    int offsetAtPoint(const QPoint& point) const override
    {
        return field()->cursorPositionAt(field()->mapFromGlobal(point));
    }

    // QAccessibleEditableTextInterface.
    void deleteText(int start, int end) override
    {
        field()->setText(field()->text().remove(start, end - start));
    }
    void insertText(int offset, const QString& text) override
    {
        field()->setText(field()->text().insert(offset, text));
    }
    void replaceText(int start, int end, const QString& text) override
    {
        field()->setText(field()->text().replace(start, end - start, text));
    }

private:
    QLineEdit* field() const { return static_cast<QLineEdit*>(widget()); }
    /// -2 is the caret's offset.
    int at(int offset) const { return offset == -2 ? cursorPosition() : offset; }
};

} // namespace

QAccessibleInterface* lineEditInterface(const QString& className, QObject* object)
{
    if (className == QLatin1String("QLineEdit"))
        if (auto* field = qobject_cast<QLineEdit*>(object))
            return new LineEditAccessible(field);
    return nullptr;
}

} // namespace rigidlab::ui
