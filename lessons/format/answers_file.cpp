// SPDX-License-Identifier: GPL-3.0-or-later
#include "format/answers_file.h"

#include "format/json_reader.h"
#include "format/languages.h"
#include "format/lesson.h"

#include <QDate>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <cmath>

namespace rigidlab::lessons {

namespace {

using detail::FileMessages;
using detail::JsonReader;

const QString kVersionKey = QStringLiteral("rigidlab-answers");

QString fromView(std::string_view name)
{
    return QString::fromUtf8(name.data(), static_cast<qsizetype>(name.size()));
}

/// A text of at most kMaxAnswerText characters, without line breaks (it is one line of the
/// sheet's header).
bool readText(JsonReader& r, const QJsonObject& o, QStringView key, QString& out, bool required)
{
    if (!r.string(o, key, QString(), out, required))
        return false;
    if (const QString problem = answerTextProblem(out); !problem.isEmpty())
        return r.fail(key.toString(), problem);
    return true;
}

/// An array at `o[key]` of at most `most` elements (absent: empty).
bool readArray(JsonReader& r, const QJsonObject& o, QStringView key, const QString& place, int most,
               QJsonArray& out)
{
    const auto it = o.constFind(key);
    if (it == o.constEnd())
        return true;
    const QString at = detail::joinPlace(place, key);
    if (!r.asArray(it.value(), at, out))
        return false;
    if (out.size() > most)
        return r.fail(at, FileMessages::tr("more than %1 entries").arg(most));
    return true;
}

/// A number or null (nullopt) at `o[key]`; absent is null.
bool readOptionalNumber(JsonReader& r, const QJsonObject& o, QStringView key, const QString& place,
                        std::optional<double>& out)
{
    const auto it = o.constFind(key);
    if (it == o.constEnd() || it.value().isNull())
        return true;
    double value = 0;
    const QString at = detail::joinPlace(place, key);
    if (!r.numberValue(it.value(), at, value))
        return false;
    if (std::abs(value) > kMaxAnswerMagnitude)
        return r.fail(
            at, FileMessages::tr("must be from -%1 to %1, got %2")
                    .arg(detail::formatNumber(kMaxAnswerMagnitude), detail::formatNumber(value)));
    out = value;
    return true;
}

/// A choice question's try: {"choice": 1, "text": "...", "right": false}.
bool readChoiceTry(JsonReader& r, const QJsonObject& o, const QString& place, AnswerTry& out)
{
    for (const QStringView key : {QStringView(u"answer"), QStringView(u"measured")})
        if (o.contains(key) && !o.value(key).isNull())
            return r.fail(detail::joinPlace(place, key),
                          FileMessages::tr("not with \"choice\": a try either chooses an option "
                                           "or gives a number"));
    int choice = 0;
    if (!r.integer(o, u"choice", place, choice, 0, kMaxChoices - 1, true) ||
        !r.string(o, u"text", place, out.choiceText, true) ||
        !r.boolean(o, u"right", place, out.right, true))
        return false;
    if (out.choiceText.trimmed().isEmpty() || out.choiceText.size() > kMaxAnswerChoiceText)
        return r.fail(detail::joinPlace(place, u"text"),
                      FileMessages::tr("must be the option's text, 1 to %1 characters")
                          .arg(kMaxAnswerChoiceText));
    out.choice = choice;
    return true;
}

bool readTry(JsonReader& r, const QJsonValue& v, const QString& place, AnswerTry& out)
{
    QJsonObject o;
    if (!r.asObject(v, place, o) ||
        !r.checkKeys(o, place, {u"answer", u"measured", u"ahead", u"choice", u"text", u"right"}))
        return false;
    if (o.contains(u"choice"))
        return readChoiceTry(r, o, place, out);
    for (const QStringView key : {QStringView(u"text"), QStringView(u"right")})
        if (o.contains(key))
            return r.fail(detail::joinPlace(place, key),
                          FileMessages::tr("only with \"choice\" (the option chosen)"));
    return readOptionalNumber(r, o, u"answer", place, out.answer) &&
           readOptionalNumber(r, o, u"measured", place, out.measured) &&
           r.boolean(o, u"ahead", place, out.ahead);
}

bool readSettings(JsonReader& r, const QJsonObject& o, const QString& place, StepAnswers& out)
{
    QString integrator, solver;
    double dt = 0;
    if (!r.string(o, u"integrator", place, integrator) || !r.string(o, u"solver", place, solver) ||
        !r.number(o, u"dt", place, dt, detail::NumberRule::Positive, limits::kDt))
        return false;
    if (o.contains(u"integrator")) {
        out.integrator = physics::integratorFromName(integrator.toStdString());
        if (!out.integrator)
            return r.fail(detail::joinPlace(place, u"integrator"),
                          detail::unknownIntegrator(integrator));
    }
    if (o.contains(u"solver")) {
        out.solver = physics::solverFromName(solver.toStdString());
        if (!out.solver)
            return r.fail(detail::joinPlace(place, u"solver"), detail::unknownSolver(solver));
    }
    if (o.contains(u"dt"))
        out.dt = dt;
    return true;
}

bool readStep(JsonReader& r, const QJsonValue& v, const QString& place, StepAnswers& out)
{
    QJsonObject o;
    QJsonArray questions;
    if (!r.asObject(v, place, o) ||
        !r.checkKeys(o, place, {u"questions", u"integrator", u"dt", u"solver"}) ||
        !readSettings(r, o, place, out) ||
        !readArray(r, o, u"questions", place, kMaxAnswerQuestions, questions))
        return false;
    const QString questionsPlace = detail::joinPlace(place, u"questions");
    for (qsizetype q = 0; q < questions.size(); ++q) {
        const QString at = detail::indexPlace(questionsPlace, q);
        QJsonObject question;
        QJsonArray tries;
        if (!r.asObject(questions[q], at, question) || !r.checkKeys(question, at, {u"tries"}) ||
            !readArray(r, question, u"tries", at, kMaxAnswerTries, tries))
            return false;
        std::vector<AnswerTry>& list = out.questions.emplace_back();
        const QString triesPlace = detail::joinPlace(at, u"tries");
        for (qsizetype t = 0; t < tries.size(); ++t)
            if (!readTry(r, tries[t], detail::indexPlace(triesPlace, t), list.emplace_back()))
                return false;
    }
    return true;
}

bool readAnswers(JsonReader& r, const QJsonObject& root, Answers& out)
{
    if (!r.formatVersion(root, kVersionKey, FileMessages::tr("an answers file"),
                         kAnswersFormatVersion) ||
        !r.checkKeys(root, QString(),
                     {kVersionKey, u"lesson", u"title", u"language", u"student", u"class", u"date",
                      u"steps"}) ||
        !readText(r, root, u"lesson", out.lessonFile, true) ||
        !readText(r, root, u"title", out.lessonTitle, false) ||
        !readText(r, root, u"language", out.language, false) ||
        !readText(r, root, u"student", out.student, false) ||
        !readText(r, root, u"class", out.className, false) ||
        !readText(r, root, u"date", out.date, false))
        return false;
    if (!out.language.isEmpty() && !isShippedLanguage(out.language))
        return r.fail(QStringLiteral("language"),
                      FileMessages::tr("unknown language \"%1\" (expected %2)")
                          .arg(out.language, shippedLanguageCodes()));
    if (!out.date.isEmpty() && !QDate::fromString(out.date, Qt::ISODate).isValid())
        return r.fail(QStringLiteral("date"),
                      FileMessages::tr("must be a date YYYY-MM-DD, got \"%1\"").arg(out.date));
    QJsonArray steps;
    if (!readArray(r, root, u"steps", QString(), kMaxAnswerSteps, steps))
        return false;
    for (qsizetype i = 0; i < steps.size(); ++i)
        if (!readStep(r, steps[i], detail::indexPlace(QStringLiteral("steps"), i),
                      out.steps.emplace_back()))
            return false;
    return true;
}

QJsonValue optionalNumber(const std::optional<double>& value)
{
    return value ? QJsonValue(*value) : QJsonValue(QJsonValue::Null);
}

} // namespace

AnswersLoadResult loadAnswersJson(const QByteArray& bytes, const QString& path)
{
    AnswersLoadResult result;
    const detail::ParsedJson parsed = detail::parseJson(bytes, path, kMaxAnswersFileBytes);
    if (!parsed.ok) {
        result.error = parsed.error;
        return result;
    }
    JsonReader r(path);
    if (!parsed.document.isObject()) {
        r.fail(QString(), FileMessages::tr("must be a JSON object {...}"));
        result.error = r.error();
        return result;
    }
    result.ok = readAnswers(r, parsed.document.object(), result.answers);
    result.error = r.error();
    if (!result.ok)
        result.answers = Answers{};
    return result;
}

AnswersLoadResult loadAnswersFile(const QString& path)
{
    const detail::FileBytes file = detail::readFileBytes(path, kMaxAnswersFileBytes);
    if (!file.ok) {
        AnswersLoadResult result;
        result.error = file.error;
        return result;
    }
    return loadAnswersJson(file.bytes, path);
}

QByteArray answersJson(const Answers& answers)
{
    QJsonObject root;
    root.insert(kVersionKey, kAnswersFormatVersion);
    root.insert(QStringLiteral("lesson"), answers.lessonFile);
    root.insert(QStringLiteral("title"), answers.lessonTitle);
    root.insert(QStringLiteral("language"), answers.language);
    root.insert(QStringLiteral("student"), answers.student);
    root.insert(QStringLiteral("class"), answers.className);
    root.insert(QStringLiteral("date"), answers.date);
    QJsonArray steps;
    for (const StepAnswers& step : answers.steps) {
        QJsonObject s;
        if (step.integrator)
            s.insert(QStringLiteral("integrator"),
                     fromView(physics::integratorName(*step.integrator)));
        if (step.dt)
            s.insert(QStringLiteral("dt"), *step.dt);
        if (step.solver)
            s.insert(QStringLiteral("solver"), fromView(physics::solverName(*step.solver)));
        QJsonArray questions;
        for (const std::vector<AnswerTry>& tries : step.questions) {
            QJsonArray list;
            for (const AnswerTry& t : tries)
                list.append(
                    t.choice ? QJsonObject{{QStringLiteral("choice"), *t.choice},
                                           {QStringLiteral("text"), t.choiceText},
                                           {QStringLiteral("right"), t.right}}
                             : QJsonObject{{QStringLiteral("answer"), optionalNumber(t.answer)},
                                           {QStringLiteral("measured"), optionalNumber(t.measured)},
                                           {QStringLiteral("ahead"), t.ahead}});
            questions.append(QJsonObject{{QStringLiteral("tries"), list}});
        }
        s.insert(QStringLiteral("questions"), questions);
        steps.append(s);
    }
    root.insert(QStringLiteral("steps"), steps);
    return QJsonDocument(root).toJson(QJsonDocument::Indented);
}

QString answerTextProblem(const QString& text)
{
    if (text.size() > kMaxAnswerText)
        return FileMessages::tr("longer than %1 characters").arg(kMaxAnswerText);
    if (text.contains(u'\n') || text.contains(u'\r'))
        return FileMessages::tr("must be one line");
    return {};
}

QString answersMismatch(const Answers& answers, const QString& lessonFile,
                        const std::vector<int>& questionsPerStep)
{
    if (!answers.lessonFile.isEmpty() && answers.lessonFile != lessonFile)
        return FileMessages::tr("lesson: answers to \"%1\", not to \"%2\"")
            .arg(answers.lessonFile, lessonFile);
    if (answers.steps.size() > questionsPerStep.size())
        return FileMessages::tr("steps: %1 steps, the lesson has %2")
            .arg(answers.steps.size())
            .arg(questionsPerStep.size());
    for (std::size_t i = 0; i < answers.steps.size(); ++i) {
        const auto held = answers.steps[i].questions.size();
        if (held > static_cast<std::size_t>(questionsPerStep[i]))
            return FileMessages::tr(
                       "steps[%1].questions: %2 questions, the lesson's step %3 has %4")
                .arg(i)
                .arg(held)
                .arg(i + 1)
                .arg(questionsPerStep[i]);
    }
    return QString();
}

} // namespace rigidlab::lessons
