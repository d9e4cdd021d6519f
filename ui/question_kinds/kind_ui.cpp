// SPDX-License-Identifier: GPL-3.0-or-later
#include "question_kinds/kind_ui.h"

#include <QCoreApplication>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QVBoxLayout>

namespace rigidlab::ui {

AnswerRow typedNumberRow(QLabel* prompt, QVBoxLayout* layout, const QString& unit,
                         const QString& showTip)
{
    // In the player's words (its translation context): the measured kind's row is this one.
    QWidget* box = prompt->parentWidget();
    auto* row = new QHBoxLayout;
    auto* buttons = new QHBoxLayout;
    auto* edit = new QLineEdit(box);
    // No validator: it would drop the separator the locale does not use ("0.0156" typed
    // in Czech became 00156). What was typed is read when it is checked, point or comma.
    edit->setPlaceholderText(
        QCoreApplication::translate("rigidlab::ui::LessonPlayer", "your answer"));
    // A screen reader names the field by its question and says the unit it is in.
    prompt->setBuddy(edit);
    if (!unit.isEmpty())
        edit->setAccessibleDescription(
            QCoreApplication::translate("rigidlab::ui::LessonPlayer", "your answer, in %1")
                .arg(unit));
    row->addWidget(edit, 1);
    row->addWidget(new QLabel(unit, box));
    auto* check =
        new QPushButton(QCoreApplication::translate("rigidlab::ui::LessonPlayer", "Check"), box);
    buttons->addWidget(check);
    auto* show =
        new QPushButton(QCoreApplication::translate("rigidlab::ui::LessonPlayer", "Show me"), box);
    show->setToolTip(showTip);
    buttons->addWidget(show);
    layout->addLayout(row);
    layout->addLayout(buttons);
    auto* result = new QLabel(box);
    result->setWordWrap(true);
    result->setVisible(false); // no empty line under the buttons before the first try
    layout->addWidget(result);
    AnswerRow parts;
    parts.edit = edit;
    parts.check = check;
    parts.show = show;
    parts.result = result;
    return parts;
}

} // namespace rigidlab::ui
