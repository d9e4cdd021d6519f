// SPDX-License-Identifier: GPL-3.0-or-later
// Number-given questions: read from a lesson file (or refused, with their place), judged try by
// try as the player and the worksheet judge them.

#include "test_lesson.h"
#include "test_lesson_json.h"

#include "question_kinds.h"

#include "run/measurements.h"

#include <QLocale>

using namespace rigidlab;
using namespace rigidlab::test;
using namespace rigidlab::test::lesson_json;

namespace {

/// A step with one question: a prompt and `fields`.
QByteArray givenStep(const char* fields)
{
    const QByteArray question =
        QByteArray(R"("questions": [{"prompt": "How much momentum?", )") + fields + "}]";
    return oneStep(question.constData());
}

lessons::Question givenQuestion(double number, double within, const QString& hint = {})
{
    lessons::Question q;
    q.prompt = QStringLiteral("p");
    q.hint = hint;
    q.kind = lessons::NumberGivenQuestion{number, within, QStringLiteral("kg m/s")};
    return q;
}

lessons::AnswerTry typed(double answer)
{
    lessons::AnswerTry t;
    t.answer = answer;
    return t;
}

} // namespace

void TestLesson::numberGivenRead()
{
    const lessons::LessonLoadResult r = lessons::loadLessonJson(
        givenStep(R"("number": 0.8, "within": 0.05, "unit": "kg m/s", "hint": "p = m v")"),
        "l.json");
    QVERIFY2(r.ok, qPrintable(r.error));
    const lessons::Question& q = r.lesson.steps.at(0).questions.at(0);
    const auto* given = std::get_if<lessons::NumberGivenQuestion>(&q.kind);
    QVERIFY(given);
    QCOMPARE(given->number, 0.8);
    QCOMPARE(given->within, 0.05);
    QCOMPARE(given->unit, QStringLiteral("kg m/s"));
    QCOMPARE(q.hint, QStringLiteral("p = m v"));
    // A unit is a key several kinds have: a question with a measure and a unit stays measured.
    const lessons::LessonLoadResult measured = lessons::loadLessonJson(
        givenStep(R"("measure": {"kind": "apex", "body": "ball"}, "unit": "m")"), "l.json");
    QVERIFY2(measured.ok, qPrintable(measured.error));
    QCOMPARE(measuredOf(measured.lesson.steps[0].questions[0]).unit, QStringLiteral("m"));
}

void TestLesson::rejectsBadNumberGiven_data()
{
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<QString>("message");
    const QString at = QStringLiteral("steps[0].questions[0].");
    QTest::newRow("number-text") << givenStep(R"("number": "0.8", "within": 0.05)")
                                 << at + "number: must be a number, got \"0.8\"";
    QTest::newRow("within-missing")
        << givenStep(R"("number": 0.8)") << at + "within: required, but missing";
    QTest::newRow("within-zero") << givenStep(R"("number": 0.8, "within": 0)")
                                 << at + "within: must be a positive number, got 0";
    QTest::newRow("within-negative") << givenStep(R"("number": 0.8, "within": -0.1)")
                                     << at + "within: must be a positive number, got -0.1";
    QTest::newRow("within-without-number")
        << givenStep(R"("within": 0.05)") << at + "number: required, but missing";
    QTest::newRow("number-and-measure")
        << givenStep(
               R"("number": 0.8, "within": 0.05, "measure": {"kind": "apex", "body": "ball"})")
        << at + "measure: not for a question with \"number\": its answer is the number the "
                "lesson gives, nothing is measured or chosen";
    QTest::newRow("number-and-tolerance")
        << givenStep(R"("number": 0.8, "within": 0.05, "tolerance": 0.1)")
        << at + "tolerance: not for a question with \"number\": its answer is the number the "
                "lesson gives, nothing is measured or chosen";
    // With options as well it is a choice (the kind listed first), and the number is refused.
    QTest::newRow("number-and-choices")
        << givenStep(R"("choices": ["a", "b"], "answer": 0, "number": 0.8)")
        << at + "number: not for a question with \"choices\": it is answered by choosing, "
                "nothing is measured";
}

void TestLesson::rejectsBadNumberGiven()
{
    QFETCH(QByteArray, json);
    QFETCH(QString, message);
    const lessons::LessonLoadResult r = lessons::loadLessonJson(json, QStringLiteral("l.json"));
    QVERIFY(!r.ok);
    QCOMPARE(r.error, QStringLiteral("l.json: ") + message);
}

void TestLesson::judgeNumberGivenTries()
{
    QLocale::setDefault(QLocale::c());
    const lessons::Question q = givenQuestion(0.8, 0.05, QStringLiteral("p = m v"));
    // At the edge of the band it is right; just past it, wrong.
    for (const auto& [answer, right] :
         {std::pair{0.8, true}, std::pair{0.85, true}, std::pair{0.75, true},
          std::pair{0.8501, false}, std::pair{0.7, false}, std::pair{-0.8, false}}) {
        lessons::TryCount count;
        const lessons::Verdict v = lessons::judgeTry(q, typed(answer), count);
        QVERIFY2(v.measured && v.right == right,
                 qPrintable(QStringLiteral("%1: %2").arg(answer).arg(v.message)));
    }
    // A wrong first try reads the hint and keeps the number back; the second gives it.
    lessons::TryCount count;
    lessons::Verdict v = lessons::judgeTry(q, typed(0.5), count);
    QVERIFY(!v.right && !v.shown && !count.answered);
    QVERIFY2(v.message.contains(QStringLiteral("p = m v")) && !v.message.contains(u"0.8"),
             qPrintable(v.message));
    v = lessons::judgeTry(q, typed(0.6), count);
    QVERIFY(!v.right && v.shown && count.answered);
    QCOMPARE(v.message,
             QStringLiteral("Not quite: the right answer is 0.8\u00a0kg\u00a0m/\u2060s (you "
                            "said 0.6\u00a0kg\u00a0m/\u2060s)."));
    // Right at once.
    lessons::TryCount once;
    v = lessons::judgeTry(q, typed(0.82), once);
    QVERIFY(v.right && v.shown && once.answered);
    QCOMPARE(v.message, QStringLiteral("Right: the answer is 0.8\u00a0kg\u00a0m/\u2060s (you said "
                                       "0.82\u00a0kg\u00a0m/\u2060s)."));
    // Show me gives the number.
    lessons::TryCount shown;
    v = lessons::judgeTry(q, lessons::AnswerTry{}, shown);
    QVERIFY(v.shown && !v.right && shown.answered);
    QCOMPARE(v.value, 0.8);
    QCOMPARE(v.message, QStringLiteral("The right answer is 0.8\u00a0kg\u00a0m/\u2060s."));
    // A unit with a slash stays on its number's line, here and in a choice's verdict alike.
    lessons::Question speed = givenQuestion(2, 0.1);
    std::get<lessons::NumberGivenQuestion>(speed.kind).unit = QStringLiteral("m/s");
    lessons::TryCount speedCount;
    QCOMPARE(lessons::judgeTry(speed, lessons::AnswerTry{}, speedCount).message,
             QStringLiteral("The right answer is 2\u00a0m/\u2060s."));
    lessons::Question choice;
    choice.kind = lessons::ChoiceQuestion{{QStringLiteral("3\u00a0m/s"), QStringLiteral("0")}, 0};
    lessons::TryCount choiceCount;
    QCOMPARE(lessons::judgeTry(choice, lessons::AnswerTry{}, choiceCount).message,
             QStringLiteral("The right answer: “3\u00a0m/\u2060s”."));
}
