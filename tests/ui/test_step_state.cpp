// SPDX-License-Identifier: GPL-3.0-or-later
// Where the student is in a lesson, with no window: going to a step and what stops it, the
// step's questions started afresh, the tries kept and counted, what the unanswered questions
// hold back; and the session's answers record the worksheet is written from.

#include "lesson_player/answers_record.h"
#include "lesson_player/step_state.h"

#include <QTest>

using namespace rigidlab;
using namespace rigidlab::ui;

namespace {

lessons::Question measured(const QString& prompt, const QStringList& holdBack)
{
    lessons::Question q;
    q.prompt = prompt;
    q.holdBack = holdBack;
    q.kind = lessons::MeasuredQuestion{};
    return q;
}

/// Three steps: two questions on the first (the run and a panel held back), none on the
/// second, a choice on the third.
lessons::Lesson threeSteps(const QString& path)
{
    lessons::Lesson lesson;
    lesson.path = path;
    lesson.title = QStringLiteral("Three steps");
    lesson.steps.resize(3);
    lesson.steps[0].title = QStringLiteral("First");
    lesson.steps[0].questions = {measured(QStringLiteral("How high?"),
                                          {QStringLiteral("run"), QStringLiteral("panel:bounces")}),
                                 measured(QStringLiteral("How fast?"), {QStringLiteral("run")})};
    lesson.steps[1].title = QStringLiteral("Second");
    lessons::Question choice;
    choice.prompt = QStringLiteral("Which?");
    choice.kind = lessons::ChoiceQuestion{{QStringLiteral("a"), QStringLiteral("b")}, 1};
    lesson.steps[2].title = QStringLiteral("Third");
    lesson.steps[2].questions = {choice};
    return lesson;
}

lessons::AnswerTry typed(double answer, double measuredValue)
{
    lessons::AnswerTry t;
    t.answer = answer;
    t.measured = measuredValue;
    return t;
}

} // namespace

class TestStepState : public QObject {
    Q_OBJECT
private slots:
    void noLessonHasNoStep()
    {
        StepState state;
        QCOMPARE(state.lesson(), nullptr);
        QCOMPARE(state.step(), nullptr);
        QCOMPARE(state.stepCount(), 0);
        QCOMPARE(state.questionCount(), std::size_t{0});
        QVERIFY(state.heldBack().isEmpty());
        QVERIFY(!state.holdsRun());
        QVERIFY(!state.hasBack());
        QVERIFY(!state.hasNext());
        QVERIFY(!state.isLast());
        QVERIFY(!state.goTo(0));
    }

    void opensOnTheFirstStep()
    {
        StepState state;
        state.open(threeSteps(QStringLiteral("/lessons/three.json")));
        QVERIFY(state.lesson());
        QCOMPARE(state.index(), 0);
        QCOMPARE(state.stepCount(), 3);
        QCOMPARE(state.step()->title, QStringLiteral("First"));
        QCOMPARE(state.questionCount(), std::size_t{2});
        QCOMPARE(state.question(1).prompt, QStringLiteral("How fast?"));
        QVERIFY(!state.hasBack());
        QVERIFY(state.hasNext());
        QVERIFY(!state.isLast());
    }

    void goesOnlyToStepsTheLessonHas()
    {
        StepState state;
        state.open(threeSteps(QStringLiteral("/lessons/three.json")));
        QVERIFY(!state.goTo(-1));
        QVERIFY(!state.goTo(3));
        QCOMPARE(state.index(), 0);
        QVERIFY(state.goTo(2));
        QCOMPARE(state.index(), 2);
        QCOMPARE(state.step()->title, QStringLiteral("Third"));
        QCOMPARE(state.questionCount(), std::size_t{1});
        QVERIFY(state.hasBack());
        QVERIFY(!state.hasNext());
        QVERIFY(state.isLast());
        QVERIFY(state.goTo(1));
        QCOMPARE(state.questionCount(), std::size_t{0});
        QVERIFY(state.heldBack().isEmpty());
        state.close();
        QCOMPARE(state.lesson(), nullptr);
        QCOMPARE(state.index(), 0);
        QCOMPARE(state.questionCount(), std::size_t{0});
    }

    void answeredQuestionsReleaseWhatTheyHeld()
    {
        StepState state;
        state.open(threeSteps(QStringLiteral("/lessons/three.json")));
        // Each name once, in the questions' order.
        QCOMPARE(state.heldBack(),
                 (QStringList{QStringLiteral("run"), QStringLiteral("panel:bounces")}));
        QVERIFY(state.holdsRun());
        state.setAnswered(0);
        // The run stays held while the second question, which holds it too, is not answered.
        QCOMPARE(state.heldBack(), QStringList{QStringLiteral("run")});
        QVERIFY(state.holdsRun());
        state.setAnswered(1);
        QVERIFY(state.heldBack().isEmpty());
        QVERIFY(!state.holdsRun());
    }

    void keepsTriesInOrderUntilTheStepIsGoneToAgain()
    {
        StepState state;
        state.open(threeSteps(QStringLiteral("/lessons/three.json")));
        state.keepTry(1, typed(2.0, 3.0), 1);
        state.keepTry(1, typed(3.0, 3.0), 2);
        QCOMPARE(state.questionState(1).tries.size(), std::size_t{2});
        QCOMPARE(state.questionState(1).tries[1].answer, std::optional<double>(3.0));
        QCOMPARE(state.questionState(1).count.attempts, 2);
        // A kept try says nothing of whether the question is answered: setAnswered() does.
        QVERIFY(!state.questionState(1).count.answered);
        QVERIFY(state.questionState(0).tries.empty());
        const auto tries = state.tries();
        QCOMPARE(tries.size(), std::size_t{2});
        QVERIFY(tries[0].empty());
        QCOMPARE(tries[1], state.questionState(1).tries);
        // Restart step: the same step, its questions afresh.
        state.setAnswered(0);
        QVERIFY(state.goTo(0));
        QVERIFY(state.questionState(1).tries.empty());
        QCOMPARE(state.questionState(1).count.attempts, 0);
        QCOMPARE(state.heldBack().size(), 2);
    }

    void recordKeepsEveryQuestionOfAStep()
    {
        AnswersRecord record;
        const lessons::Lesson lesson = threeSteps(QStringLiteral("/lessons/three.json"));
        record.start(lesson);
        QVERIFY(record.isOf(lesson));
        record.student = QStringLiteral("Ada");
        record.keepTries(0, 2, 1, {typed(2.0, 3.0)});
        physics::WorldDef def;
        def.dt = 0.004;
        record.keepSettings(0, def);
        // The step's every question has its place, the ones not tried empty.
        QCOMPARE(record.tries(0).size(), std::size_t{2});
        QVERIFY(record.tries(0)[0].empty());
        QCOMPARE(record.tries(0)[1].size(), std::size_t{1});
        const lessons::Answers answers = record.answers(lesson, QString());
        QCOMPARE(answers.student, QStringLiteral("Ada"));
        QCOMPARE(answers.lessonFile, QStringLiteral("three.json"));
        // The steps not visited after the last one visited add nothing.
        QCOMPARE(answers.steps.size(), std::size_t{1});
        QCOMPARE(answers.steps[0].dt, std::optional<double>(0.004));
        // The same lesson again goes on with its record; another starts a new one.
        record.start(lesson);
        QCOMPARE(record.tries(0).size(), std::size_t{2});
        const lessons::Lesson other = threeSteps(QStringLiteral("/lessons/other.json"));
        QVERIFY(!record.isOf(other));
        QVERIFY(record.answers(other, QString()).steps.empty());
        record.start(other);
        QVERIFY(record.tries(0).empty());
    }
};

QTEST_GUILESS_MAIN(TestStepState)
#include "test_step_state.moc"
