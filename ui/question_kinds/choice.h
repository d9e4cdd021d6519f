// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What a choice question (lessons/format/question_kinds/choice.h) shows in the window
// (question_kinds/kind_ui.h): its options as radio buttons in the lesson player, to tick on the
// worksheet (the key marks the right one), and with the right one in the lesson editor
// (choice_editor.h).

#include "question_kinds/choice_editor.h"
#include "question_kinds/kind_ui.h"

#include "common/language.h"

#include "format/lesson_rows.h"
#include "format/question_kinds/choice.h"
#include "format/verdict.h"

#include <QButtonGroup>
#include <QCoreApplication>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QJsonArray>
#include <QLabel>
#include <QPushButton>
#include <QRadioButton>
#include <QVBoxLayout>

#include <type_traits>
#include <vector>

namespace rigidlab::ui {

// The lesson player's answer row.

namespace choice {

/// An option's text beside its radio button: wrapped in the lesson's narrow column (a radio
/// button's own text never wraps, and widened the column past the dock), and a click on it
/// chooses the option as a click on the button does.
class OptionText : public QLabel {
public:
    OptionText(const QString& text, QAbstractButton* button, QWidget* parent)
        : QLabel(text, parent), m_button(button)
    {
        setWordWrap(true);
        setBuddy(button);
    }

protected:
    void mouseReleaseEvent(QMouseEvent* event) override
    {
        QLabel::mouseReleaseEvent(event);
        m_button->click();
        m_button->setFocus();
    }

private:
    QAbstractButton* m_button;
};

/// The options as radio buttons in a group a screen reader names by the question (`name`);
/// the arrow keys move between them, Tab leaves the group for Check. Their ids are their
/// indices in `choices`.
inline QButtonGroup* addOptions(const QStringList& choices, const QString& name, QLabel* prompt,
                                QVBoxLayout* layout)
{
    auto* group = new QGroupBox(prompt->parentWidget());
    group->setFlat(true);
    group->setAccessibleName(name);
    auto* options = new QVBoxLayout(group);
    options->setContentsMargins(0, 0, 0, 0);
    auto* buttonGroup = new QButtonGroup(group);
    for (qsizetype c = 0; c < choices.size(); ++c) {
        auto* option = new QRadioButton(group);
        option->setAccessibleName(choices[c]);
        buttonGroup->addButton(option, static_cast<int>(c));
        auto* line = new QHBoxLayout;
        line->addWidget(option, 0, Qt::AlignTop);
        line->addWidget(new OptionText(lessons::keepUnitsTogether(choices[c]), option, group), 1);
        options->addLayout(line);
    }
    if (QAbstractButton* first = buttonGroup->button(0))
        prompt->setBuddy(first);
    layout->addWidget(group);
    return buttonGroup;
}

} // namespace choice

/// The options, Check and Show me, and the verdict's line: the option chosen is judged at once.
inline AnswerRow answerRow(const lessons::ChoiceQuestion& q, QLabel* prompt, QVBoxLayout* layout,
                           const RowHooks& hooks)
{
    // In the player's words (its translation context), as typedNumberRow's.
    QWidget* box = prompt->parentWidget();
    AnswerRow row;
    row.choices = choice::addOptions(q.choices, hooks.prompt, prompt, layout);
    auto* buttons = new QHBoxLayout;
    row.check =
        new QPushButton(QCoreApplication::translate("rigidlab::ui::LessonPlayer", "Check"), box);
    row.check->setAccessibleDescription(
        QCoreApplication::translate("rigidlab::ui::LessonPlayer", "Check the option chosen"));
    row.show =
        new QPushButton(QCoreApplication::translate("rigidlab::ui::LessonPlayer", "Show me"), box);
    row.show->setToolTip(QCoreApplication::translate("rigidlab::ui::LessonPlayer",
                                                     "Give up and show the right answer"));
    buttons->addWidget(row.check);
    buttons->addWidget(row.show);
    layout->addLayout(buttons);
    row.result = new QLabel(box);
    row.result->setWordWrap(true);
    row.result->setVisible(false);
    layout->addWidget(row.result);
    QButtonGroup* group = row.choices;
    const QStringList choices = q.choices;
    const int right = q.answer;
    QObject::connect(row.check, &QPushButton::clicked, row.check, [hooks, group, choices, right] {
        const int chosen = group->checkedId();
        if (chosen < 0)
            return hooks.askFirst(QCoreApplication::translate("rigidlab::ui::LessonPlayer",
                                                              "Choose an answer first."));
        lessons::AnswerTry attempt;
        attempt.choice = chosen;
        attempt.choiceText = choices.value(chosen);
        attempt.right = chosen == right;
        hooks.judge(attempt);
    });
    QObject::connect(row.show, &QPushButton::clicked, row.show,
                     [hooks] { hooks.judge(lessons::AnswerTry{}); });
    return row;
}

// The worksheet and the lesson editor.

/// The options to tick by hand; the key marks the right one in bold as well as by its box and
/// names it below, the handed-in sheet gives the tries.
inline std::vector<SheetLine> worksheetLines(const lessons::ChoiceQuestion& q,
                                             const SheetQuestion& at)
{
    using Is = SheetLine::Is;
    const bool key = at.sheet == WorksheetKind::Key;
    std::vector<SheetLine> lines;
    for (qsizetype c = 0; c < q.choices.size(); ++c) {
        const bool right = key && c == q.answer;
        lines.push_back(
            {right ? Is::Bold : Is::Text,
             QStringLiteral("%1 %2").arg(right ? QStringLiteral("[x]") : QStringLiteral("[  ]"),
                                         q.choices[c])});
    }
    if (key)
        lines.push_back(
            {Is::Bold, QCoreApplication::translate("ChoiceQuestion", "Right answer: “%1”")
                           .arg(q.choices.value(q.answer))});
    else if (at.sheet == WorksheetKind::Answers)
        lines.push_back({Is::Tries, QString()});
    return lines;
}

inline QString kindTitle(std::type_identity<lessons::ChoiceQuestion>)
{
    return QCoreApplication::translate("ChoiceQuestion", "a choice of answers");
}

/// A question becoming one: two options in the window's language, the first right.
inline QJsonObject newKindKeys(std::type_identity<lessons::ChoiceQuestion>,
                               const QJsonObject& /*scene*/)
{
    namespace keys = lessons::schema::question_keys;
    using lessons::schema::jsonKey;
    return QJsonObject{{jsonKey(keys::kChoices),
                        QJsonArray{QJsonObject{{currentLanguage(), ChoiceEditor::optionName(1)}},
                                   QJsonObject{{currentLanguage(), ChoiceEditor::optionName(2)}}}},
                       {jsonKey(keys::kAnswer), 0}};
}

namespace choice {

/// Its fields in the lesson editor: the options' table and the right one (ChoiceEditor).
class Page : public KindPage {
public:
    explicit Page(QWidget* parent) : KindPage(parent)
    {
        auto* layout = new QVBoxLayout(this);
        layout->setContentsMargins(0, 0, 0, 0);
        m_options = new ChoiceEditor(this);
        layout->addWidget(m_options);
        QObject::connect(m_options, &ChoiceEditor::edited, this, [this] {
            if (edited)
                edited();
        });
    }
    void showQuestion(const QJsonObject& q, const QJsonObject& /*scene*/) override
    {
        m_options->setQuestion(q);
    }
    void applyTo(QJsonObject& q) const override { q = m_options->applyTo(q); }

private:
    ChoiceEditor* m_options;
};

} // namespace choice

inline KindPage* editorPage(std::type_identity<lessons::ChoiceQuestion>, QWidget* parent)
{
    return new choice::Page(parent);
}

/// Nothing is measured for a choice: its line says which option is right.
inline AnswerLine answerLine(const lessons::ChoiceQuestion& q, const lessons::LessonStep&,
                             const lessons::Question&)
{
    return {QCoreApplication::translate("ChoiceQuestion", "The right option"),
            QCoreApplication::translate("ChoiceQuestion",
                                        "The student chooses one of %1 options; the right one is "
                                        "“%2”.")
                .arg(q.choices.size())
                .arg(q.choices.value(q.answer))};
}

} // namespace rigidlab::ui
