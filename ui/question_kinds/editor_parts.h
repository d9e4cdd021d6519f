// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Small parts the lesson editor's panes share: a push button named for tests and read by a
// screen reader without its mnemonic's '&'; a list whose rows end in "…" rather than
// scroll sideways; a field shown the draft's text without moving the cursor of its writer; the
// languages its texts are written in, side by side, and a text of the file in one of them.

#include "common/language.h"

#include "format/languages.h"

#include <QBoxLayout>
#include <QJsonObject>
#include <QJsonValue>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QStyledItemDelegate>

#include <array>

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

/// How many languages the editor writes each text in: those the lab ships.
inline constexpr std::size_t kEditorLanguages = lessons::kLanguages.size();

/// The languages of the editor's columns, by code: the window's first (the teacher writes in it
/// first), then the rest of lessons::kLanguages in its order.
inline std::array<QString, kEditorLanguages> editorLanguages()
{
    std::array<QString, kEditorLanguages> out;
    std::size_t i = 0;
    out[i++] = currentLanguage();
    for (const lessons::Language& l : lessons::kLanguages)
        if (l.code != out[0] && i < out.size())
            out[i++] = l.code.toString();
    return out;
}

/// A text of the file as written in `language`: a plain string is English (the fallback
/// language); empty when the text has no such language.
inline QString writtenText(const QJsonValue& v, const QString& language)
{
    if (v.isObject())
        return v.toObject().value(language).toString();
    return language == lessons::kFallbackLanguage ? v.toString() : QString();
}

/// A text of the file as the window shows it: in the window's language, or where it lacks it in
/// the one the player falls back to (lessons::textLanguage).
inline QString shownText(const QJsonValue& v)
{
    if (!v.isObject())
        return v.toString();
    const QJsonObject texts = v.toObject();
    return texts.value(lessons::textLanguage(currentLanguage(), texts.keys())).toString();
}

/// The text `v` with `language` set to `text` (removed when empty); a plain string was English.
/// Null when no language is left.
inline QJsonValue withWrittenText(const QJsonValue& v, const QString& language, const QString& text)
{
    QJsonObject texts = v.isObject() ? v.toObject() : QJsonObject();
    if (v.isString())
        texts.insert(lessons::kFallbackLanguage.toString(), v);
    if (text.trimmed().isEmpty())
        texts.remove(language);
    else
        texts.insert(language, text);
    return texts.isEmpty() ? QJsonValue() : QJsonValue(texts);
}

} // namespace rigidlab::ui
