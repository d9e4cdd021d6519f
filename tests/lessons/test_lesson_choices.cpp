// SPDX-License-Identifier: GPL-3.0-or-later
// Choice questions: read from a lesson file (or refused, with their place), judged try by try
// as the player and the worksheet judge them, and kept in an answers file.

#include "test_lesson.h"
#include "test_lesson_json.h"

#include "format/answers_file.h"
#include "question_kinds.h"

using namespace rigidlab;
using namespace rigidlab::test;
using namespace rigidlab::test::lesson_json;

namespace {

/// A step with one choice question: `choices`, and `more` fields after them.
QByteArray choiceStep(const char* choices, const char* more = R"("answer": 1)")
{
    const QByteArray question = QByteArray(R"("questions": [{"prompt": "Which?", "choices": )") +
                                choices + (more[0] ? QByteArray(", ") + more : QByteArray()) + "}]";
    return oneStep(question.constData());
}

} // namespace

void TestLesson::choiceQuestionRead()
{
    const QByteArray json = oneStep(
        R"("questions": [{"prompt": {"en": "Which ball bounces higher?", "cs": "Který výš?"},)"
        R"( "choices": [{"en": "the first", "cs": "první"}, {"en": "the second", "cs": "druhý"},)"
        R"( {"en": "both", "cs": "oba"}], "answer": 2, "hint": {"en": "e", "cs": "e"},)"
        R"( "holdBack": ["run"]}])");
    for (const auto& [language, options] :
         {std::pair{QStringLiteral("en"), QStringList{"the first", "the second", "both"}},
          std::pair{QStringLiteral("cs"), QStringList{"první", "druhý", "oba"}}}) {
        lessons::LessonLoadOptions o;
        o.language = language;
        const lessons::LessonLoadResult r = lessons::loadLessonJson(json, "l.json", o);
        QVERIFY2(r.ok, qPrintable(r.error));
        const lessons::Question& q = r.lesson.steps.at(0).questions.at(0);
        QVERIFY(isChoice(q));
        QCOMPARE(choiceOf(q).choices, options);
        QCOMPARE(choiceOf(q).answer, 2);
        QCOMPARE(q.holdBack, QStringList{"run"});
        QVERIFY(!q.hint.isEmpty());
        // A predict-first choice holds the run back until it is answered, as a number does.
        QCOMPARE(r.lesson.steps[0].heldBack({false}), QStringList{"run"});
        QVERIFY(r.lesson.steps[0].heldBack({true}).isEmpty());
        // The question is whole in both languages (the lesson's plain titles are not).
        QVERIFY2(r.warnings.filter(QStringLiteral("questions")).isEmpty(),
                 qPrintable(r.warnings.join(u'\n')));
    }
    // A measured question is not a choice.
    const lessons::LessonLoadResult measured = lessons::loadLessonJson(
        oneStep(R"("questions": [{"prompt": "p", "measure": {"kind": "apex", "body": "ball"}}])"),
        "l.json");
    QVERIFY2(measured.ok, qPrintable(measured.error));
    QVERIFY(!isChoice(measured.lesson.steps[0].questions[0]));
}

void TestLesson::choiceMissingLanguageWarns()
{
    // An option without Czech in a translated lesson only warns, naming the option; English
    // is read in its place.
    const QByteArray json =
        oneStep(R"("questions": [{"prompt": {"en": "Which?", "cs": "Který?"},)"
                R"( "choices": [{"en": "one", "cs": "jeden"}, {"en": "two"}], "answer": 0}])");
    lessons::LessonLoadOptions o;
    o.language = QStringLiteral("cs");
    const lessons::LessonLoadResult r = lessons::loadLessonJson(json, "l.json", o);
    QVERIFY2(r.ok, qPrintable(r.error));
    QCOMPARE(choiceOf(r.lesson.steps[0].questions[0]).choices, (QStringList{"jeden", "two"}));
    QCOMPARE(r.warnings.filter(QStringLiteral("questions")),
             QStringList{QStringLiteral("l.json: steps[0].questions[0].choices[1]: no "
                                        "Czech text (\"cs\"): it will show in English")});
}

void TestLesson::rejectsBadChoice_data()
{
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<QString>("message");
    const QString at = QStringLiteral("steps[0].questions[0].");
    QTest::newRow("answer-missing") << choiceStep(R"(["a", "b"])", "")
                                    << at + "answer: required, but missing (the index of the "
                                            "right option, 0 for the first)";
    QTest::newRow("answer-out-of-range")
        << choiceStep(R"(["a", "b"])", R"("answer": 2)")
        << at + "answer: must be a whole number from 0 to 1, got 2";
    QTest::newRow("answer-negative") << choiceStep(R"(["a", "b", "c"])", R"("answer": -1)")
                                     << at + "answer: must be a whole number from 0 to 2, got -1";
    QTest::newRow("answer-text") << choiceStep(R"(["a", "b"])", R"("answer": "a")")
                                 << at + "answer: must be a whole number from 0 to 1, got \"a\"";
    QTest::newRow("one-choice") << choiceStep(R"(["a"])", R"("answer": 0)")
                                << at + "choices: 1 options, fewer than the 2 a choice needs";
    QTest::newRow("no-choice") << choiceStep("[]", R"("answer": 0)")
                               << at + "choices: 0 options, fewer than the 2 a choice needs";
    QTest::newRow("seven-choices") << choiceStep(R"(["a", "b", "c", "d", "e", "f", "g"])")
                                   << at + "choices: 7 options, more than the limit of 6";
    QTest::newRow("empty-choice") << choiceStep(R"(["a", " "])")
                                  << at + "choices[1]: must be a non-empty string \"...\", got "
                                          "\" \"";
    QTest::newRow("empty-choice-language")
        << choiceStep(R"(["a", {"en": "b", "cs": ""}])") << at + "choices[1].cs: must not be empty";
    QTest::newRow("choice-number") << choiceStep(R"(["a", 5])")
                                   << at + "choices[1]: must be a non-empty string \"...\", got 5";
    QTest::newRow("choices-object")
        << choiceStep(R"({"en": ["a", "b"]})")
        << at + "choices: must be an array of 2 to 6 options, each a text \"...\" or {\"en\": "
                "\"...\", \"cs\": \"...\"}, got an object";
    QTest::newRow("measure-and-choices")
        << choiceStep(R"(["a", "b"])",
                      R"("answer": 0, "measure": {"kind": "apex", "body": "ball"})")
        << at + "measure: not for a question with \"choices\": it is answered by choosing, "
                "nothing is measured";
    for (const char* key : {"unit", "tolerance", "absoluteTolerance"}) {
        const QByteArray more = QByteArray(R"("answer": 0, ")") + key +
                                (QByteArray(key) == "unit" ? R"(": "m")" : R"(": 0.1)");
        QTest::newRow(key) << choiceStep(R"(["a", "b"])", more.constData())
                           << at + key +
                                  ": not for a question with \"choices\": it is answered by "
                                  "choosing, nothing is measured";
    }
    QTest::newRow("answer-without-choices")
        << oneStep(R"("questions": [{"prompt": "p", "answer": 0}])")
        << at + "choices: required with \"answer\", but missing (the options to choose from)";
    QTest::newRow("hold-back-unknown")
        << choiceStep(R"(["a", "b"])", R"("answer": 0, "holdBack": ["walk"])")
        << at + "holdBack[0]: unknown name \"walk\" (expected run, panel:NAME, plot:NAME, "
                "column:collision.after, column:bounces.heights)";
}

void TestLesson::rejectsBadChoice()
{
    QFETCH(QByteArray, json);
    QFETCH(QString, message);
    const lessons::LessonLoadResult r = lessons::loadLessonJson(json, QStringLiteral("l.json"));
    QVERIFY(!r.ok);
    QCOMPARE(r.error, QStringLiteral("l.json: ") + message);
    QVERIFY(!r.error.contains(u'\n'));
}

void TestLesson::judgeChoiceTries()
{
    lessons::Question q;
    q.prompt = QStringLiteral("Which?");
    q.kind = lessons::ChoiceQuestion{
        {QStringLiteral("up"), QStringLiteral("down"), QStringLiteral("still")}, 1};
    q.hint = QStringLiteral("gravity");
    const auto pick = [&q](int c) {
        lessons::AnswerTry t;
        t.choice = c;
        t.choiceText = choiceOf(q).choices[c];
        t.right = c == choiceOf(q).answer;
        return t;
    };
    // A wrong first try reads the hint and leaves the question open; the second gives the
    // right option and answers it.
    lessons::TryCount count;
    lessons::Verdict v = lessons::judgeTry(q, pick(0), count);
    QVERIFY(v.measured && !v.right && !v.shown && !count.answered);
    QVERIFY2(v.message.contains(QStringLiteral("gravity")) && !v.message.contains(u"down"),
             qPrintable(v.message));
    v = lessons::judgeTry(q, pick(2), count);
    QVERIFY(!v.right && v.shown && count.answered);
    QVERIFY2(v.message.contains(QStringLiteral("“down”")) &&
                 v.message.contains(QStringLiteral("“still”")),
             qPrintable(v.message));
    // Right at once answers it.
    lessons::TryCount once;
    v = lessons::judgeTry(q, pick(1), once);
    QVERIFY(v.right && v.shown && once.answered);
    // Show me names the right option.
    lessons::TryCount shown;
    v = lessons::judgeTry(q, lessons::AnswerTry{}, shown);
    QVERIFY(v.shown && !v.right && shown.answered);
    QVERIFY2(v.message.contains(QStringLiteral("“down”")), qPrintable(v.message));
}

void TestLesson::choiceTriesInAnswersFile()
{
    // A choice try keeps the option's text and whether it was right; a number's try beside it
    // reads as before.
    lessons::Answers a;
    a.lessonFile = QStringLiteral("x.json");
    lessons::StepAnswers step;
    lessons::AnswerTry chosen;
    chosen.choice = 2;
    chosen.choiceText = QStringLiteral("oba stejně");
    chosen.right = false;
    lessons::AnswerTry number;
    number.answer = 0.5;
    number.measured = 0.41;
    step.questions = {{chosen, lessons::AnswerTry{}}, {number}};
    a.steps = {step};
    const QByteArray bytes = lessons::answersJson(a);
    QVERIFY(bytes.contains("\"choice\": 2"));
    const lessons::AnswersLoadResult r = lessons::loadAnswersJson(bytes, "a.json");
    QVERIFY2(r.ok, qPrintable(r.error));
    QCOMPARE(r.answers, a);
    // Damaged choice tries are refused with their place.
    const auto refused = [](const char* tryJson) {
        const QByteArray file =
            QByteArray(R"({"rigidlab-answers": 1, "lesson": "x.json", "steps": [{"questions": )"
                       R"([{"tries": [)") +
            tryJson + "]}]}]}";
        return lessons::loadAnswersJson(file, "a.json").error;
    };
    QCOMPARE(refused(R"({"choice": 1, "text": "a"})"),
             QStringLiteral("a.json: steps[0].questions[0].tries[0].right: required, but missing"));
    QCOMPARE(refused(R"({"choice": 9, "text": "a", "right": true})"),
             QStringLiteral("a.json: steps[0].questions[0].tries[0].choice: must be a whole "
                            "number from 0 to 5, got 9"));
    QCOMPARE(refused(R"({"choice": 0, "text": "", "right": true})"),
             QStringLiteral("a.json: steps[0].questions[0].tries[0].text: must be the option's "
                            "text, 1 to 1000 characters"));
    QCOMPARE(refused(R"({"choice": 0, "text": "a", "right": true, "answer": 1})"),
             QStringLiteral("a.json: steps[0].questions[0].tries[0].answer: not with \"choice\": "
                            "a try either chooses an option or gives a number"));
    QCOMPARE(refused(R"({"answer": 1, "right": true})"),
             QStringLiteral("a.json: steps[0].questions[0].tries[0].right: only with \"choice\" "
                            "(the option chosen)"));
}
