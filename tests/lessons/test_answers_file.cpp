// SPDX-License-Identifier: GPL-3.0-or-later
// The answers file saved beside a handed-in worksheet (lessons/ANSWERS_FORMAT.md): what is
// written reads back the same, and a damaged file is refused with where and what is wrong,
// never half read.

#include "format/answers_file.h"

#include "test_main.h"

#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>

using namespace rigidlab;

class TestAnswersFile : public QObject {
    Q_OBJECT
private slots:
    void roundTrips();
    void readsFromDisk();
    void refusesDamaged_data();
    void refusesDamaged();
    void mismatchWithTheLesson();
};

namespace {

const QString kSource = QStringLiteral("work.answers.json");

lessons::Answers sample()
{
    lessons::Answers a;
    a.lessonFile = QStringLiteral("restitution.json");
    a.lessonTitle = QStringLiteral("Odrazy a srážky");
    a.language = QStringLiteral("cs");
    a.student = QStringLiteral("Jana Nováková");
    a.className = QStringLiteral("2.B");
    a.date = QStringLiteral("2026-12-03");
    lessons::StepAnswers first;
    first.integrator = physics::IntegratorKind::Verlet;
    first.dt = 0.001;
    first.solver = physics::SolverKind::PaperImpulse;
    // A wrong prediction judged ahead, a right answer, "Show me" before anything was measured,
    // and a value that does not round-trip through a short decimal.
    const auto number = [](std::optional<double> answer, std::optional<double> measured,
                           bool ahead) {
        lessons::AnswerTry t;
        t.answer = answer;
        t.measured = measured;
        t.ahead = ahead;
        return t;
    };
    first.questions = {
        {number(0.5, 0.4096, true), number(0.41, 0.4096, false)},
        {number(std::nullopt, std::nullopt, false), number(0.1 + 0.2, -1e-300, false)}};
    a.steps = {first, lessons::StepAnswers{}};
    return a;
}

/// `{"rigidlab-answers": 1, "lesson": "l.json", ...rest}`.
QByteArray withRest(const char* rest)
{
    return QByteArray(R"({"rigidlab-answers": 1, "lesson": "l.json")") + rest + '}';
}

} // namespace

void TestAnswersFile::roundTrips()
{
    const lessons::Answers a = sample();
    const lessons::AnswersLoadResult r = lessons::loadAnswersJson(lessons::answersJson(a), kSource);
    QVERIFY2(r.ok, qPrintable(r.error));
    QVERIFY(r.answers == a);
    QCOMPARE(r.answers.steps[0].questions[1][1].answer, 0.1 + 0.2); // every digit kept
}

void TestAnswersFile::readsFromDisk()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(kSource);
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(lessons::answersJson(sample()));
    file.close();
    const lessons::AnswersLoadResult r = lessons::loadAnswersFile(path);
    QVERIFY2(r.ok, qPrintable(r.error));
    QVERIFY(r.answers == sample());
    const lessons::AnswersLoadResult missing =
        lessons::loadAnswersFile(dir.filePath(QStringLiteral("none.json")));
    QVERIFY(!missing.ok);
    QVERIFY2(missing.error.startsWith(dir.filePath(QStringLiteral("none.json"))),
             qPrintable(missing.error));
}

void TestAnswersFile::refusesDamaged_data()
{
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<QString>("message");
    QTest::newRow("empty") << QByteArray() << QStringLiteral("line 1");
    QTest::newRow("cut-short") << lessons::answersJson(sample()).left(120)
                               << QStringLiteral("line ");
    QTest::newRow("not-an-object") << QByteArray("[1, 2]") << QStringLiteral("JSON object");
    QTest::newRow("version-missing")
        << QByteArray(R"({"lesson": "l.json"})")
        << QStringLiteral("rigidlab-answers: missing: an answers file starts with");
    QTest::newRow("version-2") << QByteArray(R"({"rigidlab-answers": 2, "lesson": "l"})")
                               << QStringLiteral("rigidlab-answers: unsupported format version 2");
    QTest::newRow("lesson-missing") << QByteArray(R"({"rigidlab-answers": 1})")
                                    << QStringLiteral("lesson: required, but missing");
    QTest::newRow("unknown-key") << withRest(R"(, "name": "Jana")")
                                 << QStringLiteral("name: unknown key");
    QTest::newRow("student-number")
        << withRest(R"(, "student": 7)") << QStringLiteral("student: must be a string");
    QTest::newRow("student-two-lines")
        << withRest(R"(, "student": "a\nb")") << QStringLiteral("student: must be one line");
    QTest::newRow("student-long")
        << withRest((R"(, "student": ")" + QByteArray(201, 'x') + '"').constData())
        << QStringLiteral("student: longer than 200 characters");
    QTest::newRow("language-unknown")
        << withRest(R"(, "language": "de")") << QStringLiteral("language: unknown language \"de\"");
    QTest::newRow("date-bad") << withRest(R"(, "date": "3.12.2026")")
                              << QStringLiteral("date: must be a date YYYY-MM-DD");
    QTest::newRow("steps-object") << withRest(R"(, "steps": {})")
                                  << QStringLiteral("steps: must be an array");
    QTest::newRow("step-not-object")
        << withRest(R"(, "steps": [3])") << QStringLiteral("steps[0]: must be an object");
    QTest::newRow("integrator-unknown")
        << withRest(R"(, "steps": [{"integrator": "leapfrog"}])")
        << QStringLiteral("steps[0].integrator: unknown integrator \"leapfrog\"");
    QTest::newRow("solver-unknown") << withRest(R"(, "steps": [{"solver": "magic"}])")
                                    << QStringLiteral("steps[0].solver: unknown solver");
    QTest::newRow("dt-negative") << withRest(R"(, "steps": [{"dt": -0.01}])")
                                 << QStringLiteral("steps[0].dt: must be");
    QTest::newRow("dt-huge") << withRest(R"(, "steps": [{"dt": 1e9}])")
                             << QStringLiteral("steps[0].dt: must be from");
    QTest::newRow("tries-missing-array")
        << withRest(R"(, "steps": [{"questions": [{"tries": 1}]}])")
        << QStringLiteral("steps[0].questions[0].tries: must be an array");
    QTest::newRow("answer-text")
        << withRest(R"(, "steps": [{"questions": [{"tries": [{"answer": "0,5"}]}]}])")
        << QStringLiteral("steps[0].questions[0].tries[0].answer: must be a number");
    QTest::newRow("answer-huge")
        << withRest(R"(, "steps": [{"questions": [{"tries": [{"answer": 1e300}]}]}])")
        << QStringLiteral("steps[0].questions[0].tries[0].answer: must be from -1e+15 to 1e+15");
    QTest::newRow("measured-huge")
        << withRest(R"(, "steps": [{"questions": [{"tries": [{"measured": -2e15}]}]}])")
        << QStringLiteral("steps[0].questions[0].tries[0].measured: must be from");
    QTest::newRow("ahead-string")
        << withRest(R"(, "steps": [{"questions": [{"tries": [{"ahead": "yes"}]}]}])")
        << QStringLiteral("steps[0].questions[0].tries[0].ahead: must be");
    QTest::newRow("try-unknown-key")
        << withRest(R"(, "steps": [{"questions": [{"tries": [{"verdict": "right"}]}]}])")
        << QStringLiteral("steps[0].questions[0].tries[0].verdict: unknown key");
    QByteArray many = R"(, "steps": [{"questions": [{"tries": [)";
    for (int i = 0; i <= lessons::kMaxAnswerTries; ++i)
        many += i ? ", {}" : "{}";
    many += "]}]}]";
    QTest::newRow("too-many-tries") << withRest(many.constData())
                                    << QStringLiteral("steps[0].questions[0].tries: more than 100");
}

void TestAnswersFile::refusesDamaged()
{
    QFETCH(QByteArray, json);
    QFETCH(QString, message);
    const lessons::AnswersLoadResult r = lessons::loadAnswersJson(json, kSource);
    QVERIFY(!r.ok);
    QVERIFY2(r.error.startsWith(kSource + QStringLiteral(": ")), qPrintable(r.error));
    QVERIFY2(r.error.contains(message), qPrintable(r.error));
    QVERIFY(!r.error.contains(u'\n'));
    QVERIFY(r.answers == lessons::Answers{}); // nothing half read
}

void TestAnswersFile::mismatchWithTheLesson()
{
    const lessons::Answers a = sample(); // 2 steps, the first with 2 questions
    const QString file = a.lessonFile;
    QCOMPARE(lessons::answersMismatch(a, file, {2, 0}), QString());
    QCOMPARE(lessons::answersMismatch(a, file, {2, 0, 5}), QString()); // later steps unvisited
    QVERIFY(lessons::answersMismatch(a, file, {2})
                .contains(QStringLiteral("2 steps, the lesson has 1")));
    QVERIFY(lessons::answersMismatch(a, file, {1, 0})
                .contains(QStringLiteral("steps[0].questions: 2 questions, the lesson's step 1 "
                                         "has 1")));
    // Answers to another lesson, even one with as many questions.
    QCOMPARE(lessons::answersMismatch(a, QStringLiteral("stacks.json"), {2, 0}),
             QStringLiteral("lesson: answers to \"restitution.json\", not to \"stacks.json\""));
    // A name of more than one line or longer than the file allows, as --student gives it.
    QCOMPARE(lessons::answerTextProblem(QStringLiteral("Jana Nováková")), QString());
    QCOMPARE(lessons::answerTextProblem(QStringLiteral("Jana\nNováková")),
             QStringLiteral("must be one line"));
    QVERIFY(lessons::answerTextProblem(QString(lessons::kMaxAnswerText + 1, u'a'))
                .startsWith(QStringLiteral("longer than")));
}

RIGIDLAB_TEST_GUILESS_MAIN(TestAnswersFile)
#include "test_answers_file.moc"
