// SPDX-License-Identifier: GPL-3.0-or-later
// How the shipped lessons word their figures: a number and its unit stay on one line, in the
// texts as written and in the verdicts and hints the lab makes from them.

#include "test_lesson.h"
#include "test_lesson_physics.h"

#include "format/languages.h"
#include "run/measurements.h"

#include <QDirIterator>
#include <QRegularExpression>
#include <QTextBoundaryFinder>

using namespace rigidlab;
using namespace rigidlab::test;

namespace {

/// The units the lessons write after a number.
const QString kUnits = QStringLiteral("(?:m/s²|m/s|rad/s|kg·m²|kg·m/s|kg m/s|N·s|N/m|mm|cm/s|cm|"
                                      "kg|g|ms|Hz|J|N|m|s|%|°|rad)");

/// Every text of `lesson` a student reads, named by where it is.
std::vector<std::pair<QString, QString>> textsOf(const lessons::Lesson& lesson)
{
    std::vector<std::pair<QString, QString>> out{
        {QStringLiteral("title"), lesson.title},
        {QStringLiteral("summary"), lesson.summary},
        {QStringLiteral("level"), lesson.level},
        {QStringLiteral("description"), lesson.description}};
    for (qsizetype g = 0; g < lesson.goals.size(); ++g)
        out.emplace_back(QStringLiteral("goals[%1]").arg(g), lesson.goals[g]);
    for (std::size_t s = 0; s < lesson.steps.size(); ++s) {
        const lessons::LessonStep& step = lesson.steps[s];
        const QString at = QStringLiteral("steps[%1].").arg(s);
        out.emplace_back(at + QStringLiteral("title"), step.title);
        out.emplace_back(at + QStringLiteral("text"), step.text);
        out.emplace_back(at + QStringLiteral("scene.title"), step.scene.title);
        out.emplace_back(at + QStringLiteral("scene.description"), step.scene.description);
        for (std::size_t q = 0; q < step.questions.size(); ++q) {
            const QString qat = at + QStringLiteral("questions[%1].").arg(q);
            out.emplace_back(qat + QStringLiteral("prompt"), step.questions[q].prompt);
            out.emplace_back(qat + QStringLiteral("hint"), step.questions[q].hint);
        }
    }
    return out;
}

/// Where `text` separates a number from its unit by a breakable space ("3 m/s").
QStringList spacesBeforeUnits(const QString& text)
{
    static const QRegularExpression figure(QStringLiteral("\\d[ \\t\\n]+") + kUnits +
                                           QStringLiteral("(?![\\p{L}\\d/²·])"));
    QStringList out;
    for (auto it = figure.globalMatch(text); it.hasNext();) {
        const QRegularExpressionMatch m = it.next();
        out << text.mid(std::max<qsizetype>(0, m.capturedStart() - 20), 40);
    }
    return out;
}

/// Where a line may break inside a number and its unit in `text` ("3 m/s" broken after the
/// slash), each as the figure and its neighbourhood; empty when none may.
QStringList breaksInsideUnits(const QString& text)
{
    // A unit as shown: a word joiner may follow its slash, a no-break space join its words.
    static const QRegularExpression figure(QStringLiteral("\\d[ \\x{00A0}]") +
                                           QString(kUnits)
                                               .replace(u'/', QStringLiteral("/\\x{2060}?"))
                                               .replace(u' ', QStringLiteral("[ \\x{00A0}]")) +
                                           QStringLiteral("(?![\\p{L}\\d/²·])"));
    QStringList out;
    QTextBoundaryFinder lines(QTextBoundaryFinder::Line, text);
    for (auto it = figure.globalMatch(text); it.hasNext();) {
        const QRegularExpressionMatch m = it.next();
        for (qsizetype at = m.capturedStart() + 1; at < m.capturedEnd(); ++at) {
            lines.setPosition(at);
            if (lines.isAtBoundary()) {
                out << text.mid(std::max<qsizetype>(0, m.capturedStart() - 20), 40);
                break;
            }
        }
    }
    return out;
}

/// The verdicts made from a measured question's hint, value and answer: its first and second
/// wrong try and its value shown (a choice question's verdicts quote its options, which are
/// texts of the lesson checked above).
QStringList verdictsOf(const lessons::Question& q)
{
    if (!q.as<lessons::MeasuredQuestion>())
        return {};
    return {lessons::judgeAttempt(q, 3.25, 1.75, 1).message,
            lessons::judgeAttempt(q, 3.25, 1.75, 2).message,
            lessons::showAnswer(q, 1.75, true).message};
}

} // namespace

void TestLesson::unitsStayWithTheirNumbers()
{
    QStringList broken;
    int texts = 0, verdicts = 0;
    QDirIterator files(kLessonsDir, {QStringLiteral("*.json")}, QDir::Files);
    while (files.hasNext()) {
        const QString path = files.next();
        for (const lessons::Language& language : lessons::kLanguages) {
            const QString code = language.code.toString();
            const lessons::LessonLoadResult r =
                lessons::loadLessonFile(path, lessons::LessonLoadOptions{code});
            QVERIFY2(r.ok, qPrintable(r.error));
            const QString where = QFileInfo(path).fileName() + u' ' + code + QStringLiteral(": ");
            for (const auto& [place, text] : textsOf(r.lesson)) {
                ++texts;
                // As written: a breakable space between a number and its unit.
                for (const QString& at : spacesBeforeUnits(text))
                    broken << where + place + QStringLiteral(": \"") + at + u'"';
                // As the player shows a prompt or a step's text.
                for (const QString& at : breaksInsideUnits(lessons::keepUnitsTogether(text)))
                    broken << where + place + QStringLiteral(" as shown: \"") + at + u'"';
            }
            // The verdicts made from a question: its hint, its value and the answer.
            for (const lessons::LessonStep& step : r.lesson.steps)
                for (const lessons::Question& q : step.questions) {
                    const QStringList messages = verdictsOf(q);
                    if (!messages.isEmpty())
                        verdicts += 2; // a first and a second try
                    for (const QString& v : messages)
                        for (const QString& at : breaksInsideUnits(v))
                            broken << where + QStringLiteral("verdict \"") + at + u'"';
                }
        }
    }
    QVERIFY(texts > 200);
    QVERIFY(verdicts > 20);
    QVERIFY2(broken.isEmpty(), qPrintable(broken.join(u'\n')));
    // The finder itself: a breakable space does break, and "m/s" breaks after its slash
    // unless kept together; so the checks above could fail.
    QVERIFY(!spacesBeforeUnits(QStringLiteral("falls 3 m/s faster")).isEmpty());
    QVERIFY(spacesBeforeUnits(QStringLiteral("falls 3\u00a0m/s faster")).isEmpty());
    QVERIFY(!breaksInsideUnits(QStringLiteral("falls 3 m/s faster")).isEmpty());
    QVERIFY(!breaksInsideUnits(QStringLiteral("falls 3\u00a0m/s faster")).isEmpty());
    QVERIFY(breaksInsideUnits(lessons::keepUnitsTogether(QStringLiteral("falls 3\u00a0m/s faster")))
                .isEmpty());
    // A unit of two words as a teacher may type it: whole in a verdict's figure.
    const QString figure = lessons::formatAnswer(4, 0.05, QStringLiteral("kg m/s"));
    QVERIFY2(!breaksInsideUnits(QStringLiteral("gets 4 kg m/s back")).isEmpty(),
             "the finder sees a break inside \"kg m/s\"");
    QVERIFY2(
        breaksInsideUnits(lessons::keepUnitsTogether(QStringLiteral("gets %1 back").arg(figure)))
            .isEmpty(),
        qPrintable(figure));
}
