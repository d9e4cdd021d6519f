// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What a measured question (lessons/format/question_kinds/measured.h) shows in the window
// (question_kinds/kind_ui.h).

#include "question_kinds/kind_ui.h"

#include "format/question_kinds/measured.h"

#include <QCoreApplication>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>

#include <optional>

namespace rigidlab::ui {

// The lesson player's answer row.

/// The answer box with its unit: a number typed is judged against the value the run measures,
/// on the run the question asks for (RowHooks::askedRun); Show me gives that value.
inline AnswerRow answerRow(const lessons::MeasuredQuestion& q, QLabel* prompt, QVBoxLayout* layout,
                           const RowHooks& hooks)
{
    // In the player's words (its translation context), as typedNumberRow's.
    const AnswerRow row =
        typedNumberRow(prompt, layout, q.unit,
                       QCoreApplication::translate("rigidlab::ui::LessonPlayer",
                                                   "Give up and show the measured value"));
    QLabel* result = row.result;
    const auto check = [hooks, result] {
        const std::optional<double> typed = hooks.typedNumber();
        if (!typed)
            return;
        // A question that asks for settings first is judged on the run it asks for.
        const RunAdvice run = hooks.askedRun();
        if (run.setFirst)
            return hooks.askFirst(run.advice);
        lessons::AnswerTry attempt = hooks.measured();
        attempt.answer = typed;
        if (hooks.judge(attempt) && !run.advice.isEmpty())
            result->setText(run.advice + u' ' + result->text());
    };
    QObject::connect(row.check, &QPushButton::clicked, row.check, check);
    QObject::connect(row.edit, &QLineEdit::returnPressed, row.edit, check);
    QObject::connect(row.show, &QPushButton::clicked, row.show,
                     [hooks] { hooks.judge(hooks.measured()); });
    return row;
}

} // namespace rigidlab::ui
