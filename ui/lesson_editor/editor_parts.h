// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Small parts the lesson editor's panes share: a push button named for tests and read by a
// screen reader without its mnemonic's '&'; a list whose rows end in "…" rather than
// scroll sideways; a field shown the draft's text without moving the cursor of its writer.

#include <QBoxLayout>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QStyledItemDelegate>

namespace rigidlab::ui {

inline QPushButton* addEditorButton(QWidget* parent, QBoxLayout* row, const QString& text,
                                    const char* objectName)
{
    auto* b = new QPushButton(text, parent);
    b->setObjectName(QLatin1String(objectName));
    QString plain = text;
    b->setAccessibleName(plain.remove(u'&'));
    row->addWidget(b);
    return b;
}

/// Rows as wide as the list, however long their text: QListView widens a narrower row to
/// the list's width, and the style then elides what does not fit.
class RowsFitWidth : public QStyledItemDelegate {
public:
    using QStyledItemDelegate::QStyledItemDelegate;
    QSize sizeHint(const QStyleOptionViewItem& option, const QModelIndex& index) const override
    {
        return {1, QStyledItemDelegate::sizeHint(option, index).height()};
    }
};

/// A long (Czech) title ends in "…" instead of scrolling the list sideways; give each row a
/// tooltip with all of it.
inline void fitRowsToWidth(QListWidget* list)
{
    list->setItemDelegate(new RowsFitWidth(list));
    list->setTextElideMode(Qt::ElideRight);
    list->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
}

/// The draft's text in a field: left alone when it already says it (so that the cursor of the
/// teacher typing there stays where it is), else shown from its start, not its end.
inline void showText(QLineEdit* field, const QString& text)
{
    if (field->text() == text)
        return;
    field->setText(text);
    if (!field->hasFocus())
        field->setCursorPosition(0);
}

} // namespace rigidlab::ui
