// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What a choice question (lessons/format/question_kinds/choice.h) shows in the window
// (question_kinds/kind_ui.h): its options to tick on the worksheet (the key marks the right
// one), its options and the right one in the lesson editor (choice_editor.h).

#include "question_kinds/choice_editor.h"
#include "question_kinds/kind_ui.h"

#include "common/language.h"

#include "format/lesson_rows.h"
#include "format/question_kinds/choice.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QVBoxLayout>

#include <type_traits>
#include <vector>

namespace rigidlab::ui {

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
