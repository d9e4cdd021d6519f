// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What a measured question (lessons/format/question_kinds/measured.h) shows in the window
// (question_kinds/kind_ui.h): an answer box with its unit in the lesson player, judged against
// the value the run measures; lines for the prediction and the measured value on the worksheet
// (the key gives the value the step's run measures and the range accepted), what is measured
// and how closely in the lesson editor (measured_page.h), and under it the value the lab
// measures, from the same run without a window that the player judges against.

#include "common/number_format.h"
#include "question_kinds/kind_ui.h"
#include "question_kinds/measure_names.h"
#include "question_kinds/measured_page.h"

#include "format/lesson_rows.h"
#include "format/question_kinds/measured.h"
#include "format/verdict.h"
#include "run/measurements.h"

#include <QCoreApplication>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QPushButton>

#include <cmath>
#include <optional>
#include <type_traits>
#include <vector>

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

// The worksheet and the lesson editor.

namespace measured {

/// The value the key gives: the one the student's tries were judged against, else the step's
/// run without a window.
inline std::optional<double> keyValue(const lessons::MeasuredQuestion& q, const SheetQuestion& at)
{
    for (const lessons::AnswerTry& t : at.tries)
        if (t.measured && !t.ahead)
            return t.measured;
    return lessons::measureAhead(lessons::askedStep(*at.step, *at.question), q.measure);
}

} // namespace measured

/// Lines to write the prediction and the measured value on; the key's value with the range it
/// accepts; handed in, the tries and the value they were last judged against.
inline std::vector<SheetLine> worksheetLines(const lessons::MeasuredQuestion& q,
                                             const SheetQuestion& at)
{
    using Is = SheetLine::Is;
    switch (at.sheet) {
    case WorksheetKind::Empty:
        return {
            {Is::Text,
             QCoreApplication::translate("MeasuredQuestion", "Your prediction (%1):").arg(q.unit)},
            {Is::WritingLine, {}},
            {Is::Text,
             QCoreApplication::translate("MeasuredQuestion", "Measured (%1):").arg(q.unit)},
            {Is::WritingLine, {}}};
    case WorksheetKind::Key: {
        const std::optional<double> value = measured::keyValue(q, at);
        if (!value)
            return {{Is::Text, QCoreApplication::translate("MeasuredQuestion",
                                                           "Not measured within the step's run.")}};
        const double slack = q.tolerance * std::abs(*value) + q.absoluteTolerance;
        return {{Is::Text,
                 QCoreApplication::translate("MeasuredQuestion",
                                             "Measured: %1 (accepted from %2 to %3)")
                     .arg(sheetQuantity(*value, q.unit), sheetQuantity(*value - slack, q.unit),
                          sheetQuantity(*value + slack, q.unit))}};
    }
    case WorksheetKind::Answers: {
        std::vector<SheetLine> lines{{Is::Tries, q.unit}};
        std::optional<double> measured;
        for (const lessons::Verdict& v : at.verdicts)
            if (v.measured)
                measured = v.value;
        if (measured)
            lines.push_back(
                {Is::Bold, QCoreApplication::translate("MeasuredQuestion", "Measured value: %1")
                               .arg(sheetQuantity(*measured, q.unit))});
        return lines;
    }
    }
    return {};
}

inline QString kindTitle(std::type_identity<lessons::MeasuredQuestion>)
{
    return QCoreApplication::translate("MeasuredQuestion", "a number measured from the run");
}

/// A question becoming one: the speed at 1 s of the first body of `scene` that moves, right
/// within 5 %.
inline QJsonObject newKindKeys(std::type_identity<lessons::MeasuredQuestion>,
                               const QJsonObject& scene)
{
    namespace keys = lessons::schema::question_keys;
    using lessons::schema::jsonKey;
    const MeasureName& k = kMeasureNames[1]; // speed at a time: any body, any scene
    QJsonObject measure{{QStringLiteral("kind"), QLatin1String(k.id)}, {QStringLiteral("time"), 1}};
    const QList<std::pair<QString, QString>> bodies = movingBodies(scene);
    if (!bodies.isEmpty())
        measure.insert(QStringLiteral("body"), bodies.front().first);
    return QJsonObject{{jsonKey(keys::kMeasure), measure},
                       {jsonKey(keys::kUnit), QLatin1String(k.unit)},
                       {jsonKey(keys::kTolerance), 0.05}};
}

inline KindPage* editorPage(std::type_identity<lessons::MeasuredQuestion>, QWidget* parent)
{
    return new MeasuredPage(parent);
}

/// What the lab measures for it, from the run the player judges against (the question's
/// settings asked for), and the answers it accepts. Whether the integrators a student may
/// choose measure wider apart than this is said in the step's problems
/// (lesson_editor/step_checks.h): those runs take a worker thread.
inline AnswerLine answerLine(const lessons::MeasuredQuestion& q, const lessons::LessonStep& step,
                             const lessons::Question& question)
{
    const QString name =
        QCoreApplication::translate("MeasuredQuestion", "The answer the lab measures");
    const std::optional<double> value =
        lessons::measureAhead(lessons::askedStep(step, question), q.measure);
    if (!value)
        return {name, QCoreApplication::translate(
                          "MeasuredQuestion",
                          "⚠ The run does not get there (or diverges first): raise the step's "
                          "export time or choose an earlier time.")};
    const QLocale locale;
    const double band = std::abs(*value) * q.tolerance + q.absoluteTolerance;
    return {name, lessons::keepUnitsTogether(
                      QCoreApplication::translate(
                          "MeasuredQuestion",
                          "The lab measures %1 %3; answers from %2 to %4 %3 are right.")
                          .arg(formatReadable(*value, 4, 0, locale),
                               formatReadable(*value - band, 4, 0, locale), q.unit,
                               formatReadable(*value + band, 4, 0, locale)))};
}

} // namespace rigidlab::ui
