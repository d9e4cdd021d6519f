// SPDX-License-Identifier: GPL-3.0-or-later
#include "results/class_table.h"

#include "run/measurements.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QLocale>

#include <algorithm>
#include <cmath>

namespace rigidlab::lessons {

namespace {

struct ClassResults {
    Q_DECLARE_TR_FUNCTIONS(ClassResults)
};

// What the table reads of a question, in one place: how its kind is answered.
AnswerForm formOf(const Question& q)
{
    return std::visit([](const auto& kind) { return answerForm(kind); }, q.kind);
}
bool hasHint(const Question& q)
{
    return !q.hint.isEmpty();
}

/// The tries of question `q` of step `s`, none when the student did not get there.
const std::vector<AnswerTry>& triesAt(const Answers& answers, std::size_t s, std::size_t q)
{
    static const std::vector<AnswerTry> none;
    if (s >= answers.steps.size() || q >= answers.steps[s].questions.size())
        return none;
    return answers.steps[s].questions[q];
}

QuestionOutcome outcomeOf(const Question& question, const std::vector<AnswerTry>& tries)
{
    QuestionOutcome out;
    TryCount count;
    bool firstJudged = false;
    for (const AnswerTry& t : tries) {
        const Verdict v = judgeTry(question, t, count);
        const bool given = t.answer.has_value() || t.choice.has_value();
        if (!given) {
            out.showMe = out.showMe || v.shown;
            continue;
        }
        // The first answer judged is the one the table names; an answer checked before the
        // run measured anything stands in only until one is judged.
        if (!firstJudged && (v.measured || out.first == FirstVerdict::None)) {
            out.firstNumber = t.answer;
            out.firstChoice = t.choice ? t.choiceText : QString();
            out.first = !v.measured ? FirstVerdict::NotMeasured
                        : v.right   ? FirstVerdict::Right
                                    : FirstVerdict::NotRight;
            firstJudged = v.measured;
        }
        if (!v.measured)
            continue;
        ++out.tries;
        // A wrong answer that did not give the value away read the hint (or "try again").
        if (!v.right && !v.shown && hasHint(question))
            out.hint = true;
    }
    return out;
}

QString number(double value)
{
    QLocale locale;
    locale.setNumberOptions(QLocale::OmitGroupSeparator);
    return locale.toString(value, 'g', 6);
}

QString verdictText(FirstVerdict v)
{
    // A sign with each word, so that nothing is told by colour alone.
    switch (v) {
    case FirstVerdict::Right:
        return ClassResults::tr("✓ right");
    case FirstVerdict::NotRight:
        return ClassResults::tr("✗ not right");
    case FirstVerdict::NotMeasured:
        return ClassResults::tr("… not measured yet");
    case FirstVerdict::None:
        break;
    }
    return ClassResults::tr("— not answered");
}

QString helpText(const QuestionOutcome& o)
{
    if (o.hint && o.showMe)
        return ClassResults::tr("hint, Show me");
    if (o.hint)
        return ClassResults::tr("hint");
    if (o.showMe)
        return ClassResults::tr("Show me");
    return QString();
}

ClassCell questionCell(const QuestionHead& head, const QuestionOutcome& o, ClassColumnKind kind)
{
    switch (kind) {
    case ClassColumnKind::FirstAnswer:
        if (head.choice)
            return {o.firstChoice, std::nullopt};
        if (o.firstNumber)
            return {number(*o.firstNumber), o.firstNumber};
        return {};
    case ClassColumnKind::Verdict:
        return {verdictText(o.first), std::nullopt};
    case ClassColumnKind::Tries:
        return {QString::number(o.tries), static_cast<double>(o.tries)};
    case ClassColumnKind::Help:
        return {helpText(o), std::nullopt};
    default:
        return {};
    }
}

} // namespace

int ClassTable::rightFirst(std::size_t q) const
{
    return static_cast<int>(std::count_if(rows.begin(), rows.end(), [q](const StudentRow& r) {
        return r.questions.at(q).first == FirstVerdict::Right;
    }));
}

std::optional<double> ClassTable::rightFirstPercent(std::size_t q) const
{
    if (rows.empty())
        return std::nullopt;
    // To a tenth of a per cent: what a table of a class tells apart, without round-off digits.
    return std::round(1000.0 * rightFirst(q) / static_cast<double>(rows.size())) / 10.0;
}

ClassTable emptyClassTable(const Lesson& lesson)
{
    ClassTable table;
    table.lessonFile = QFileInfo(lesson.path).fileName();
    table.lessonTitle = lesson.title;
    for (std::size_t s = 0; s < lesson.steps.size(); ++s) {
        const auto& questions = lesson.steps[s].questions;
        for (std::size_t q = 0; q < questions.size(); ++q)
            table.questions.push_back({static_cast<int>(s), static_cast<int>(q),
                                       formOf(questions[q]).unit, formOf(questions[q]).chosen});
    }
    return table;
}

StudentRow studentRow(const Lesson& lesson, const Answers& answers, const QString& file)
{
    StudentRow row{file, answers.student, answers.className, answers.date, {}};
    for (std::size_t s = 0; s < lesson.steps.size(); ++s) {
        const auto& questions = lesson.steps[s].questions;
        for (std::size_t q = 0; q < questions.size(); ++q)
            row.questions.push_back(outcomeOf(questions[q], triesAt(answers, s, q)));
    }
    return row;
}

std::vector<ClassColumn> classColumns(const ClassTable& table)
{
    // The student's own columns, then the same group for every question.
    static constexpr ClassColumnKind kStudent[] = {ClassColumnKind::Student, ClassColumnKind::Class,
                                                   ClassColumnKind::Date};
    static constexpr ClassColumnKind kQuestion[] = {ClassColumnKind::FirstAnswer,
                                                    ClassColumnKind::Verdict,
                                                    ClassColumnKind::Tries, ClassColumnKind::Help};
    std::vector<ClassColumn> columns;
    for (ClassColumnKind kind : kStudent)
        columns.push_back({kind, -1});
    for (int q = 0; q < static_cast<int>(table.questions.size()); ++q)
        for (ClassColumnKind kind : kQuestion)
            columns.push_back({kind, q});
    return columns;
}

QString classColumnHead(const ClassTable& table, const ClassColumn& column)
{
    if (column.question < 0) {
        switch (column.kind) {
        case ClassColumnKind::Student:
            return ClassResults::tr("Name");
        case ClassColumnKind::Class:
            return ClassResults::tr("Class");
        default:
            return ClassResults::tr("Date");
        }
    }
    const QuestionHead& head = table.questions.at(static_cast<std::size_t>(column.question));
    // "1.2": step 1, its question 2, as the worksheet numbers them.
    const QString which = QStringLiteral("%1.%2").arg(head.step + 1).arg(head.question + 1);
    switch (column.kind) {
    case ClassColumnKind::FirstAnswer:
        return head.unit.isEmpty() ? ClassResults::tr("%1 first answer").arg(which)
                                   : ClassResults::tr("%1 first answer [%2]").arg(which, head.unit);
    case ClassColumnKind::Verdict:
        return ClassResults::tr("%1 verdict").arg(which);
    case ClassColumnKind::Tries:
        return ClassResults::tr("%1 tries").arg(which);
    default:
        return ClassResults::tr("%1 hint or Show me").arg(which);
    }
}

ClassCell classCell(const ClassTable& table, std::size_t row, const ClassColumn& column)
{
    const StudentRow& r = table.rows.at(row);
    if (column.question < 0) {
        switch (column.kind) {
        case ClassColumnKind::Student:
            return {r.student, std::nullopt};
        case ClassColumnKind::Class:
            return {r.className, std::nullopt};
        default:
            return {r.date, std::nullopt};
        }
    }
    const auto q = static_cast<std::size_t>(column.question);
    return questionCell(table.questions.at(q), r.questions.at(q), column.kind);
}

ClassCell classSummaryCell(const ClassTable& table, const ClassColumn& column)
{
    if (column.kind == ClassColumnKind::Student)
        return {ClassResults::tr("Right at the first answer [%]"), std::nullopt};
    if (column.kind != ClassColumnKind::Verdict)
        return {};
    const auto q = static_cast<std::size_t>(column.question);
    const std::optional<double> percent = table.rightFirstPercent(q);
    if (!percent)
        return {};
    // "60 % (3 of 5)": the count with the share, so that a small class is not overread.
    return {ClassResults::tr("%1 % (%2 of %3)")
                .arg(number(*percent))
                .arg(table.rightFirst(q))
                .arg(table.rows.size()),
            percent};
}

} // namespace rigidlab::lessons
