// SPDX-License-Identifier: GPL-3.0-or-later
// A choice question, as a teacher writes it in the lesson editor (its options in Czech and
// English, added, reordered, the right one chosen, each edit undoable), saved, reopened and
// played as a student plays it: radio buttons in a group named by the question, a wrong first
// choice that reads the hint, a right one that releases the run it held back, and the tries
// kept for the worksheet.

#include "build_paths.h"
#include "lesson_editor/lesson_draft.h"
#include "lesson_editor/lesson_editor.h"
#include "lesson_player/lesson_player.h"
#include "simulation/simulation_controller.h"
#include "window/main_window.h"

#include "format/lesson_pack.h"
#include "format/scene_loader.h"

#include "editor_on_step.h"
#include "test_main.h"

#include "question_kinds.h"
#include <QAction>
#include <QButtonGroup>
#include <QComboBox>
#include <QGroupBox>
#include <QJsonArray>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QRadioButton>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QtTest>

using rigidlab::test::choiceOf;
using rigidlab::test::isChoice;

using namespace rigidlab;
using rigidlab::test::child;

namespace {

void typeInto(QLineEdit* field, const QString& text)
{
    field->setFocus();
    QTest::keyClick(field, Qt::Key_A, Qt::ControlModifier);
    for (const QChar c : text) {
        QTest::sendKeyEvent(QTest::Press, field, Qt::Key_unknown, QString(c), {});
        QTest::sendKeyEvent(QTest::Release, field, Qt::Key_unknown, QString(c), {});
    }
}

/// The options of the selected question's table, as {cs, en} per row.
/// The table's column of a language, by its heading (the window's language comes first).
int columnOf(QTableWidget* table, const QString& heading)
{
    for (int c = 0; c < table->columnCount(); ++c)
        if (table->horizontalHeaderItem(c)->text() == heading)
            return c;
    return -1;
}

/// The Czech column of the options' table, and the English one.
int czech(QTableWidget* table)
{
    return columnOf(table, QStringLiteral("Czech"));
}
int english(QTableWidget* table)
{
    return columnOf(table, QStringLiteral("English"));
}

/// Each option's texts, Czech then English.
QList<QStringList> tableTexts(QTableWidget* table)
{
    QList<QStringList> out;
    for (int r = 0; r < table->rowCount(); ++r)
        out.append({table->item(r, czech(table))->text(), table->item(r, english(table))->text()});
    return out;
}

/// The window's Play action.
QAction* playAction(QWidget& w)
{
    for (QAction* a : w.findChildren<QAction*>())
        if (a->text().remove(u'&') == QObject::tr("Play"))
            return a;
    return nullptr;
}

/// The label under the choice question's buttons that says the verdict.
QString verdictOf(ui::LessonPlayer& player)
{
    return player.result(0);
}

} // namespace

class TestLessonEditorChoice : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void writtenInTheEditor();
    void savedReopenedAndPlayed();
    void playedWrongTwiceOrShown();
    void backToAStepAnsweredByShowMe();

private:
    void undoRedoOptions(ui::LessonDraft& d, QTableWidget* table, QComboBox* right);
    void removedAndSaved(ui::LessonEditor& ed);

    QTemporaryDir m_dir;
    QString m_saved;
};

void TestLessonEditorChoice::initTestCase()
{
    QVERIFY(m_dir.isValid());
    m_saved = m_dir.filePath(QStringLiteral("choice.rlesson"));
}

void TestLessonEditorChoice::writtenInTheEditor()
{
    test::EditorOnStep rig;
    QCOMPARE(rig.open(), QString());
    ui::LessonEditor& ed = rig.ed;
    ui::LessonDraft& d = ed.draft();
    const auto question = [&rig] { return rig.question(); };

    // A predict-first question, made a choice with the kind chooser (by key): the run stays
    // held back, nothing is measured any more.
    QTest::mouseClick(child<QPushButton>(ed, QStringLiteral("addPredictQuestion")), Qt::LeftButton);
    auto* kind = child<QComboBox>(ed, QStringLiteral("questionType"));
    QVERIFY(kind && kind->isVisible());
    kind->setFocus();
    QTest::keyClick(kind, Qt::Key_Down);
    QCOMPARE(question().value(u"choices").toArray().size(), 2);
    QCOMPARE(question().value(u"answer").toInt(-1), 0);
    QVERIFY(!question().contains(u"measure") && !question().contains(u"unit"));
    QVERIFY(question().value(u"holdBack").toArray().contains(QStringLiteral("run")));
    auto* table = child<QTableWidget>(ed, QStringLiteral("choiceOptions"));
    QVERIFY(table && table->isVisible());
    QVERIFY(!child<QComboBox>(ed, QStringLiteral("questionBody"))->isVisible());
    QVERIFY(!table->accessibleName().isEmpty());

    typeInto(child<QLineEdit>(ed, QStringLiteral("questionPrompt_cs")),
             QStringLiteral("Který míček vyskočí výš?"));
    typeInto(child<QLineEdit>(ed, QStringLiteral("questionPrompt_en")),
             QStringLiteral("Which ball bounces higher?"));
    // The options side by side, Czech and English; a third one added, then moved up.
    const QList<QStringList> texts{{"oba stejně", "both the same"},
                                   {"ten s e = 0,5", "the one with e = 0.5"},
                                   {"ten s e = 0,8", "the one with e = 0.8"}};
    child<QPushButton>(ed, QStringLiteral("addChoiceOption"))->click();
    QCOMPARE(table->rowCount(), 3);
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 2; ++c)
            table->item(r, c == 0 ? czech(table) : english(table))->setText(texts[r][c]);
    QCOMPARE(tableTexts(table), texts);
    table->setCurrentCell(2, 0);
    child<QPushButton>(ed, QStringLiteral("choiceOptionUp"))->click();
    const QJsonArray choices = question().value(u"choices").toArray();
    QCOMPARE(choices.size(), 3);
    QCOMPARE(choices.at(1).toObject().value(u"en").toString(),
             QStringLiteral("the one with e = 0.8"));
    QCOMPARE(choices.at(1).toObject().value(u"cs").toString(), QStringLiteral("ten s e = 0,8"));
    // The right one chosen from a list, by key; the list lines up with the question's other
    // fields (its row is in a form of the choice's own, under the table of options).
    auto* right = child<QComboBox>(ed, QStringLiteral("choiceRight"));
    QCoreApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
    const auto leftOf = [&ed](const QWidget* w) { return w->mapTo(&ed, QPoint()).x(); };
    auto* prompt = child<QLineEdit>(ed, QStringLiteral("questionPrompt_en"));
    QCOMPARE(leftOf(right), leftOf(prompt));
    QCOMPARE(leftOf(kind), leftOf(prompt));
    right->setFocus();
    QTest::keyClick(right, Qt::Key_Down);
    QCOMPARE(question().value(u"answer").toInt(), 1);
    QVERIFY2(child<QLabel>(ed, QStringLiteral("questionAnswer"))->text().contains(u"0.8"),
             qPrintable(child<QLabel>(ed, QStringLiteral("questionAnswer"))->text()));

    undoRedoOptions(d, table, right);
    removedAndSaved(ed);
}

void TestLessonEditorChoice::undoRedoOptions(ui::LessonDraft& d, QTableWidget* table,
                                             QComboBox* right)
{
    const auto question = [&d] {
        return d.value(0, QStringLiteral("questions")).toArray().at(0).toObject();
    };
    // Each edit is one undo step: undone, the right one is the first again; redone, the second.
    d.undoStack()->undo();
    QCOMPARE(question().value(u"answer").toInt(), 0);
    QCOMPARE(right->currentIndex(), 0);
    d.undoStack()->redo();
    QCOMPARE(question().value(u"answer").toInt(), 1);
    // Undoing the move puts the options back in their order, in the table too.
    d.undoStack()->undo();
    d.undoStack()->undo();
    QCOMPARE(table->item(2, english(table))->text(), QStringLiteral("the one with e = 0.8"));
    d.undoStack()->redo();
    d.undoStack()->redo();
    QCOMPARE(table->item(1, english(table))->text(), QStringLiteral("the one with e = 0.8"));
}

void TestLessonEditorChoice::removedAndSaved(ui::LessonEditor& ed)
{
    ui::LessonDraft& d = ed.draft();
    const auto question = [&d] {
        return d.value(0, QStringLiteral("questions")).toArray().at(0).toObject();
    };
    auto* table = child<QTableWidget>(ed, QStringLiteral("choiceOptions"));
    // Removing an option is refused below two; the lesson loads without a problem.
    table->setCurrentCell(0, 0);
    child<QPushButton>(ed, QStringLiteral("removeChoiceOption"))->click();
    QCOMPARE(question().value(u"choices").toArray().size(), 2);
    QCOMPARE(question().value(u"answer").toInt(), 0); // still the e = 0.8 ball
    QVERIFY(!child<QPushButton>(ed, QStringLiteral("removeChoiceOption"))->isEnabled());
    d.undoStack()->undo();
    QCOMPARE(question().value(u"choices").toArray().size(), 3);
    QCOMPARE(d.check(QStringLiteral("en")).error, QString());
    QCOMPARE(ed.saveAs(m_saved), QString());
}

void TestLessonEditorChoice::savedReopenedAndPlayed()
{
    // Reopened, the same question.
    ui::LessonDraft reopened;
    QCOMPARE(reopened.open(m_saved), QString());
    const QJsonObject q = reopened.value(0, QStringLiteral("questions")).toArray().at(0).toObject();
    QCOMPARE(q.value(u"answer").toInt(), 1);
    QCOMPARE(q.value(u"choices").toArray().size(), 3);

    // Played as a student: radio buttons in a group named by the question.
    ui::MainWindow w;
    w.show();
    QCOMPARE(w.openLesson(m_saved, true), QString());
    ui::LessonPlayer& player = w.lessonPlayer();
    const lessons::Question& question = player.lesson()->steps.at(0).questions.at(0);
    QVERIFY(isChoice(question));
    QGroupBox* group = nullptr;
    for (QGroupBox* g : w.findChildren<QGroupBox*>())
        if (g->accessibleName() == question.prompt)
            group = g;
    QVERIFY2(group, qPrintable(question.prompt));
    const QList<QRadioButton*> options = group->findChildren<QRadioButton*>();
    QCOMPARE(options.size(), 3);
    for (int i = 0; i < 3; ++i)
        QCOMPARE(options[i]->accessibleName(), choiceOf(question).choices[i]);
    QVERIFY(player.heldBack().contains(QStringLiteral("run")));

    // Check with nothing chosen asks for a choice, and counts nothing.
    player.choose(0, -1);
    QVERIFY2(verdictOf(player).contains(QStringLiteral("Choose")), qPrintable(verdictOf(player)));
    QVERIFY(player.heldBack().contains(QStringLiteral("run")));
    // By key: the arrow keys move between the options.
    QApplication::setActiveWindow(&w);
    QVERIFY(QTest::qWaitForWindowActive(&w));
    options[0]->click();
    options[0]->setFocus();
    QTest::keyClick(options[0], Qt::Key_Down);
    QVERIFY(options[1]->isChecked());
    // A wrong first choice: marked and worded as wrong, the right one not given away, the run
    // still held back.
    player.choose(0, 2);
    QVERIFY2(verdictOf(player).startsWith(QStringLiteral("✗")), qPrintable(verdictOf(player)));
    QVERIFY2(!verdictOf(player).contains(choiceOf(question).choices[1]),
             qPrintable(verdictOf(player)));
    QVERIFY(player.heldBack().contains(QStringLiteral("run")));
    // The right one: marked right, the run released.
    player.choose(0, 1);
    QVERIFY2(verdictOf(player).startsWith(QStringLiteral("✓")), qPrintable(verdictOf(player)));
    QVERIFY(player.heldBack().isEmpty());
    // The answers keep the options chosen, by their text, and whether each was right.
    const lessons::Answers answers = player.answers();
    const std::vector<lessons::AnswerTry>& tries = answers.steps.at(0).questions.at(0);
    QCOMPARE(tries.size(), std::size_t{2});
    QCOMPARE(tries[0].choiceText, choiceOf(question).choices[2]);
    QVERIFY(!tries[0].right);
    QCOMPARE(tries[1].choiceText, choiceOf(question).choices[1]);
    QVERIFY(tries[1].right);
    const lessons::AnswersLoadResult read =
        lessons::loadAnswersJson(lessons::answersJson(answers), QStringLiteral("a.json"));
    QVERIFY2(read.ok, qPrintable(read.error));
    QCOMPARE(read.answers.steps.at(0).questions.at(0), tries);
}

void TestLessonEditorChoice::playedWrongTwiceOrShown()
{
    // Each played as a lesson of its own: the session keeps the tries of a lesson played.
    for (const bool shown : {false, true}) {
        const QString path = m_dir.filePath(shown ? QStringLiteral("shown.rlesson")
                                                  : QStringLiteral("twice.rlesson"));
        QVERIFY(QFile::copy(m_saved, path));
        ui::MainWindow w;
        w.show();
        QCOMPARE(w.openLesson(path, true), QString());
        ui::LessonPlayer& player = w.lessonPlayer();
        const lessons::Question& question = player.lesson()->steps.at(0).questions.at(0);
        QVERIFY(player.heldBack().contains(QStringLiteral("run")));
        if (shown) {
            // Shown: the right option named, marked as shown, the run released.
            player.showMe(0);
            QVERIFY2(verdictOf(player).startsWith(QStringLiteral("◆")),
                     qPrintable(verdictOf(player)));
        } else {
            // Twice wrong: the second names the right option and releases the run.
            player.choose(0, 0);
            QVERIFY(player.heldBack().contains(QStringLiteral("run")));
            player.choose(0, 2);
            QVERIFY2(verdictOf(player).startsWith(QStringLiteral("✗")),
                     qPrintable(verdictOf(player)));
        }
        QVERIFY2(verdictOf(player).contains(choiceOf(question).choices[1]),
                 qPrintable(verdictOf(player)));
        QVERIFY(player.heldBack().isEmpty());
        QVERIFY(w.controller().isRunning()); // predicted, now see: the run starts
    }
}

void TestLessonEditorChoice::backToAStepAnsweredByShowMe()
{
    // The tunnelling lesson's first step holds the run back for a choice and two numbers; all
    // shown, the student goes on and comes back: the step is as she left it, nothing held.
    ui::MainWindow w;
    w.show();
    QCOMPARE(w.openLesson(rigidlab::test::sourcePath(u"/lessons/lessons/tunnelling.json"), true),
             QString());
    ui::LessonPlayer& player = w.lessonPlayer();
    const int questions = static_cast<int>(player.lesson()->steps.at(0).questions.size());
    QCOMPARE(questions, 3);
    QVERIFY(player.heldBack().contains(QStringLiteral("run")));
    QStringList verdicts;
    for (int q = 0; q < questions; ++q) {
        player.showMe(q);
        verdicts << player.result(q);
    }
    QVERIFY(player.heldBack().isEmpty());
    player.next();
    QCOMPARE(player.stepIndex(), 1);
    player.back();
    QCOMPARE(player.stepIndex(), 0);
    QVERIFY2(player.heldBack().isEmpty(), qPrintable(player.heldBack().join(u", ")));
    for (int q = 0; q < questions; ++q)
        QCOMPARE(player.result(q), verdicts[q]);
    // The window lets the step run again without waiting for an answer: Play is on.
    QVERIFY(playAction(w) && playAction(w)->isEnabled());
    // The tries were not counted twice: the record holds one Show me per question.
    const lessons::Answers answers = player.answers();
    for (int q = 0; q < questions; ++q)
        QCOMPARE(answers.steps.at(0).questions.at(static_cast<std::size_t>(q)).size(),
                 std::size_t{1});
    // Restart step starts it afresh (test_lesson_predict), held back again; gone back to
    // from the next step, the answers are there again.
    player.restartStep();
    QVERIFY(player.heldBack().contains(QStringLiteral("run")));
    player.next();
    player.back();
    QVERIFY(player.heldBack().isEmpty());
    QCOMPARE(player.answers().steps.at(0).questions.at(0).size(), std::size_t{1});
}

RIGIDLAB_TEST_MAIN(TestLessonEditorChoice)
#include "test_lesson_editor_choice.moc"
