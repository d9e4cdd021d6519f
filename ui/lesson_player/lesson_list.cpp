// SPDX-License-Identifier: GPL-3.0-or-later
#include "lesson_player/lesson_list.h"

#include <QAbstractItemView>
#include <QCoreApplication>
#include <QFileInfo>
#include <QKeyEvent>
#include <QScreen>
#include <QScrollBar>
#include <QStyledItemDelegate>

#include <algorithm>

namespace rigidlab::ui {

namespace {

/// The longest short title a lesson has in the list box [characters].
constexpr int kShortTitleLength = 24;
/// The least room between the lesson list's popup and the screen's edges [px].
constexpr int kPopupMarginPx = 8;
/// The list's role holding an entry's full menu line (the box itself shows the short one).
constexpr int kFullTextRole = Qt::UserRole + 1;

/// A lesson's title as the list box shows it: up to its first ": " or dash ("Energy drift:
/// four ways…" → "Energy drift"), and at most kShortTitleLength characters, cut between words.
QString shortTitle(const QString& title)
{
    QString out = title;
    for (const QString& cut : {QStringLiteral(": "), QStringLiteral(" – "), QStringLiteral(" — ")})
        if (const qsizetype at = out.indexOf(cut); at > 0)
            out.truncate(at);
    if (out.size() > kShortTitleLength) {
        const qsizetype space = out.lastIndexOf(u' ', kShortTitleLength);
        out.truncate(space > 0 ? space : kShortTitleLength);
        out += QChar(0x2026); // …
    }
    return out;
}

/// The open list shows each lesson's full line (title, description, time).
class FullTextDelegate : public QStyledItemDelegate {
public:
    using QStyledItemDelegate::QStyledItemDelegate;

protected:
    void initStyleOption(QStyleOptionViewItem* option, const QModelIndex& index) const override
    {
        QStyledItemDelegate::initStyleOption(option, index);
        const QString full = index.data(kFullTextRole).toString();
        if (!full.isEmpty())
            option->text = full;
    }
};

} // namespace

LessonList::LessonList(QWidget* parent) : QComboBox(parent)
{
    setObjectName(QStringLiteral("lessonChoice"));
    view()->setItemDelegate(new FullTextDelegate(view()));
    connect(this, &QComboBox::currentIndexChanged, this, &LessonList::showCurrentTip);
    connect(this, &QComboBox::activated, this,
            [this](int index) { emit lessonChosen(itemData(index).toString()); });
}

void LessonList::showCurrentTip()
{
    // In the lesson player's words (its translation context), as the rest of the lesson dock.
    const QString what = QCoreApplication::translate(
        "rigidlab::ui::LessonPlayer", "The lessons that come with RigidLab (File › Open lesson "
                                      "for others)");
    const QString full = currentData(kFullTextRole).toString();
    setToolTip(full.isEmpty() ? what : full + QStringLiteral("\n\n") + what);
}

void LessonList::setLessons(const std::vector<lessons::LessonEntry>& entries)
{
    clear();
    m_paths.clear();
    m_menuTexts.clear();
    addItem(QCoreApplication::translate("rigidlab::ui::LessonPlayer", "Choose a lesson…"),
            QString());
    for (std::size_t i = 0; i < entries.size(); ++i) {
        const lessons::LessonEntry& entry = entries[i];
        const QString text = lessons::lessonMenuText(entry, static_cast<int>(i) + 1);
        // The box shows the short title, its list and tooltip the whole line.
        addItem(QCoreApplication::translate("rigidlab::lessons", "%1. %2")
                    .arg(static_cast<int>(i) + 1)
                    .arg(shortTitle(entry.title)),
                entry.path);
        setItemData(count() - 1, text, Qt::ToolTipRole);
        setItemData(count() - 1, text, kFullTextRole);
        m_paths << entry.path;
        m_menuTexts << text;
    }
    // The box stays as narrow as its column; its list opens as wide as its longest line.
    setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    setMinimumContentsLength(12);
    // Never wider than the screen, though: a line too long for it loses words in its middle,
    // not its end (the lesson's time).
    QAbstractItemView* list = view();
    const int wanted =
        list->sizeHintForColumn(0) + 24 + list->verticalScrollBar()->sizeHint().width();
    const QScreen* shownOn = screen();
    const int most = shownOn ? shownOn->availableGeometry().width() - 2 * kPopupMarginPx : wanted;
    list->setTextElideMode(wanted > most ? Qt::ElideMiddle : Qt::ElideNone);
    list->setMinimumWidth(std::min(wanted, most));
    showCurrentTip();
}

QString LessonList::shortText(const QString& path) const
{
    const int index = findData(path);
    return index >= 0 ? itemText(index) : QString();
}

void LessonList::showChosen(const QString& path)
{
    const int index = findData(QFileInfo(path).absoluteFilePath());
    if (index >= 0)
        setCurrentIndex(index);
}

void LessonList::keyPressEvent(QKeyEvent* event)
{
    // On the closed list of lessons an arrow would open each lesson it passes: it opens the
    // list instead, where the arrows walk and Return opens the one chosen.
    const int key = event->key();
    if (key == Qt::Key_Up || key == Qt::Key_Down || key == Qt::Key_PageUp ||
        key == Qt::Key_PageDown || key == Qt::Key_Home || key == Qt::Key_End) {
        showPopup();
        return;
    }
    QComboBox::keyPressEvent(event);
}

} // namespace rigidlab::ui
