// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The lesson player: pick a lesson, read a step, answer its questions, go back and forth.
// It only shows; the window applies each step (scene, settings, panels) when told to. It wires
// the parts that do the work: where the student is (step_state), the judging of the tries
// (question_judge, with the session's answers_record), and the widgets: the list of lessons
// (lesson_list), the lesson's and the step's titles and text (step_page), the questions
// (question_rows, in a question_area), the buttons (step_buttons) and the student's name with
// Hand in (hand_in); and it shares the column's height between them when a step opens.

#include "lesson_player/question_judge.h"
#include "lesson_player/step_state.h"
#include "question_kinds/kind_ui.h"

#include "format/answers_file.h"
#include "format/lesson.h"
#include "format/lesson_catalog.h"

#include <QWidget>

#include <functional>
#include <vector>

class QMenu;
class QScrollArea;
class QPushButton;
class QVBoxLayout;

namespace rigidlab::ui {

class HandIn;
class LessonList;
class QuestionArea;
class QuestionRows;
class RunView;
class StepButtons;
class StepPage;
class StepText;

/// One try at a question: Check with a typed answer, or "Show me" (no answer), with the
/// measured value it was judged against. The same record the answers file keeps.
using QuestionTry = lessons::AnswerTry;

/// What the student did on the current step's questions: enough to show the same verdicts
/// again, in another language (the language switch).
struct StepWork {
    std::vector<std::vector<QuestionTry>> tries; ///< per question, in order
    QStringList typed;                           ///< per question, what its box holds
};

class LessonPlayer : public QWidget {
    Q_OBJECT
public:
    explicit LessonPlayer(const RunView& run, QWidget* parent = nullptr);

    /// Hands the step's questions (answer boxes, Check, Show me, verdicts) and the Back / Next /
    /// Restart step / Export plots buttons to the caller, to lay out where they stay in sight
    /// (below the scrolling lesson, in the same column); the caller owns them then.
    QWidget* takeNavigation();

    /// Lists these lessons, numbered in the order given (the window: the shipped ones, then the
    /// user's own, lessons::allLessonsInOrder).
    void listLessons(const std::vector<lessons::LessonEntry>& entries);
    /// Opens a lesson; its first step is activated. Returns the error, empty on success.
    /// The leave guard is asked first (unsaved edits of the scene); when it says no, nothing
    /// changes, the text says so and openCancelled() is true until the next call.
    QString openLesson(const QString& path);
    /// Asked before a lesson replaces the scene: true to go on (the window asks about unsaved
    /// changes). Unset: always on.
    void setLeaveGuard(std::function<bool()> guard) { m_leaveGuard = std::move(guard); }
    bool openCancelled() const { return m_openCancelled; }
    const lessons::Lesson* lesson() const { return m_state.lesson(); }
    int stepIndex() const { return m_state.index(); }
    QStringList lessonPaths() const;
    /// Per lessonPaths() entry, its menu line: "1. Title — description (≈N min)".
    QStringList lessonMenuTexts() const;
    /// The lesson to begin with, in teaching order; empty when there is none. The one place
    /// that decides it.
    QString firstLessonPath() const;

    /// The step's first answer that can be given now (a box, or a question's options), where
    /// Tab from the scene goes; null on a step that asks nothing, or nothing more.
    QWidget* firstAnswer() const;
    /// The answer box and result line of question i of the current step (for tests).
    void answer(int question, const QString& text);
    QString result(int question) const;
    /// Chooses option `option` of choice question i and presses its Check (for tests).
    void choose(int question, int option);
    /// Presses question i's "Show me" (for tests).
    void showMe(int question);
    /// What the current step's questions still hold back ("run", "panel:collision", ...):
    /// those of the questions not yet answered right, twice or by "Show me".
    QStringList heldBack() const;
    /// The tries and typed answers of the current step's questions.
    StepWork work() const;
    /// Judges `work`'s tries again, in order, with the values they were judged against, and
    /// fills the boxes: the same verdicts in the current language, and what they released.
    void restoreWork(const StepWork& work);

    /// The student's name and class, typed once above the lesson and kept for the session
    /// (another lesson, a language switch).
    void setStudent(const QString& name, const QString& className);
    QString student() const;
    /// The work on the open lesson so far, every step visited, with who and when: what Hand in
    /// writes (the worksheet and the answers file beside it).
    lessons::Answers answers() const;
    /// Writes the worksheet to `pdfPath` and the answers beside it (answersPathFor). Returns
    /// the error, empty on success.
    QString handIn(const QString& pdfPath);
    /// For the teacher: "Worksheet to print…" (the empty sheet) and "Teacher's key…" added to
    /// `menu`, on while a lesson is open.
    void addWorksheetActions(QMenu& menu);

public slots:
    void next();
    void back();
    void restartStep();
    void goToStep(int index);
    void closeLesson();
    /// Asks for the name if none is typed, then for the file, and hands in.
    void handInInteractively();

signals:
    /// The window should set up this step.
    void stepActivated(const rigidlab::lessons::Lesson& lesson, int step);
    void exportRequested();
    void lessonClosed();
    /// A worksheet was handed in: the PDF and the answers file beside it.
    void handedIn(const QString& pdfPath, const QString& answersPath);
    /// An answer released some of what the step held back; `held` is what it still holds.
    void heldBackChanged(const QStringList& held);

protected:
    void changeEvent(QEvent* event) override;
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    /// Back, Next, Restart step and Export plots, and what the buttons and the list do.
    void buildNavigation(QVBoxLayout* layout);
    /// Opens the lesson the list or the start button chose (none: closes), and says why not.
    void openChosen(const QString& path);
    void showStep();
    /// Tells a screen reader the step just shown (its number, title and first sentence) and
    /// puts the focus on its text.
    void announceStep();
    /// Tab in the order the lesson is shown: text, questions, then the step's buttons.
    void orderTabs();
    /// The text's least height: a few of its lines, whatever its font.
    void fitTextMinimum();
    /// The questions' height in the column: what the step's text leaves them when it has
    /// kTextLines lines in sight below its title (the first question whole in any case).
    void fitQuestionRoom();
    /// Where the lesson's column is scrolled to when a step opens [px]: its top on the first
    /// step while its introduction is open, else the step's count and title.
    int stepTop() const;
    /// The scroll area the window put the player in, if any.
    QScrollArea* scrollArea() const;
    /// Folds the introduction away on the first step when it would leave the step's text less
    /// than kTextShare of the column's height (unless the reader opened it by hand).
    void fitIntroduction();
    /// The step's questions, each row handing in to rowHooks().
    void buildQuestions();
    /// What question i's answer row, as its kind builds it, asks of the player.
    RowHooks rowHooks(std::size_t i);
    /// A try at question i handed in by its row, judged and shown; false when it is not judged
    /// yet (QuestionJudge::Judged::kept).
    bool judge(std::size_t i, const QuestionTry& attempt);
    /// Shows what became of a try at question i: its verdict, Show me off once the value is
    /// given, and what it released (told to the window unless replaying).
    void showJudged(std::size_t i, const QuestionTry& attempt, const QuestionJudge::Judged& judged);
    /// Judges again the tries the session's record holds for the current step (the student
    /// went on and came back): the same verdicts, and what they released stays released.
    void replayRecordedTries();

    const RunView& m_run;
    StepState m_state;
    QuestionJudge m_judge{m_state, m_run};
    LessonList* m_lessonBox;
    StepPage* m_page; ///< the lesson's title and introduction, the step's title and text
    StepText* m_text; ///< the step's text, on m_page
    QuestionRows* m_questions;
    StepButtons* m_buttons;                 ///< Back, Next, Restart step, Export plots, Hand in
    QWidget* m_navigation = nullptr;        ///< the questions and m_buttons
    QuestionArea* m_questionArea = nullptr; ///< the questions, in sight below the text
    HandIn* m_handIn;     ///< the name and class, shown while a lesson is open; Hand in
    QPushButton* m_start; ///< opens the first lesson; shown while none is open
    std::function<bool()> m_leaveGuard;
    bool m_openCancelled = false; ///< the last openLesson() was declined by the leave guard
    /// Tries of the record being judged again while a step is built: the window sets the step
    /// up with what they released, so no change is announced.
    bool m_replaying = false;
};

} // namespace rigidlab::ui
