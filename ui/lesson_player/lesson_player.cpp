// SPDX-License-Identifier: GPL-3.0-or-later
#include "lesson_player/lesson_player.h"
#include "lesson_player/hand_in.h"
#include "lesson_player/lesson_list.h"
#include "lesson_player/question_area.h"
#include "lesson_player/question_rows.h"
#include "lesson_player/step_buttons.h"
#include "lesson_player/step_page.h"
#include "lesson_player/step_text.h"

#include "common/modal_scope.h"
#include "simulation/run_view.h"

#include <QEvent>
#include <QMenu>
#include <QMessageBox>
#include <QPushButton>
#include <QScrollArea>
#include <QScrollBar>
#include <QTimer>
#include <QVBoxLayout>

#include <algorithm>

namespace rigidlab::ui {

namespace {

/// The least share of the lesson column's height that the step's text has in sight when a
/// step opens: the introduction folds away rather than take it.
constexpr double kTextShare = 0.4;
/// The lines of the step's text kept in sight below its title before the questions below it
/// take the column's height (the first question is in sight whatever the text leaves it).
constexpr int kTextLines = 6;

} // namespace

LessonPlayer::LessonPlayer(const RunView& run, QWidget* parent)
    : QWidget(parent), m_run(run), m_lessonBox(new LessonList(this)), m_page(new StepPage(this)),
      m_text(m_page->text()), m_questions(new QuestionRows(this)), m_buttons(new StepButtons(this)),
      m_handIn(new HandIn(m_state, m_judge, this)),
      m_start(new QPushButton(tr("Start the first lesson"), this))
{
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_lessonBox);
    m_page->addHead(layout);
    layout->addWidget(m_handIn);
    // On a first start, with no lesson open, the way in: one button to the first lesson.
    m_start->setObjectName(QStringLiteral("startFirstLesson"));
    connect(m_start, &QPushButton::clicked, this, [this] { openChosen(firstLessonPath()); });
    layout->addWidget(m_start);
    m_page->addStep(layout);
    // The questions and the buttons stay in sight below the text (takeNavigation()): the
    // class sees what it is asked, where it answers and the verdict while the text is read.
    // The questions and their verdicts as large as the step's text (the text's font is
    // followed, in eventFilter; presentation mode scales the text, not them twice).
    m_questions->setProperty(kFontFollowsProperty, true);
    m_questions->setFont(m_text->font());
    m_text->installEventFilter(this);
    // The start page (no lesson, so no text) keeps to the top instead of spreading out.
    layout->addStretch(0);
    buildNavigation(layout);
    showStep();
}

void LessonPlayer::buildNavigation(QVBoxLayout* layout)
{
    // The questions and the buttons are a widget of their own, so that the window can keep
    // them in sight below the lesson that scrolls (takeNavigation()).
    m_navigation = new QWidget(this);
    m_navigation->setObjectName(QStringLiteral("lessonInSight"));
    auto* column = new QVBoxLayout(m_navigation);
    column->setContentsMargins(0, 0, 0, 0);
    m_questionArea = new QuestionArea(m_questions, m_navigation);
    column->addWidget(m_questionArea);
    column->addWidget(m_buttons);
    // In line with the text above, wherever the window puts them.
    const QMargins margins = layout->contentsMargins();
    m_buttons->layout()->setContentsMargins(margins.left(), 0, margins.right(), 0);
    m_questions->setContentsMargins(margins.left(), 0, margins.right(), 0);
    layout->addWidget(m_navigation);

    connect(m_buttons, &StepButtons::backClicked, this, &LessonPlayer::back);
    connect(m_buttons, &StepButtons::nextClicked, this, &LessonPlayer::next);
    connect(m_buttons, &StepButtons::restartClicked, this, &LessonPlayer::restartStep);
    connect(m_buttons, &StepButtons::exportClicked, this, &LessonPlayer::exportRequested);
    connect(m_buttons, &StepButtons::handInClicked, this, &LessonPlayer::handInInteractively);
    connect(m_handIn, &HandIn::handedIn, this, &LessonPlayer::handedIn);
    // The scene changed (a fitted e applied, an edit): what a run without a window measured
    // on the old one is measured again when next asked.
    connect(&m_run, &RunView::sceneLoaded, this, [this] { m_judge.forgetMeasuredAhead(); });
    connect(m_lessonBox, &LessonList::lessonChosen, this, &LessonPlayer::openChosen);
}

void LessonPlayer::openChosen(const QString& path)
{
    if (path.isEmpty())
        return closeLesson();
    const QString error = openLesson(path);
    const ModalScope modal;
    if (!error.isEmpty() && !m_openCancelled)
        QMessageBox::warning(this, tr("Cannot open lesson"), error);
}

void LessonPlayer::listLessons(const std::vector<lessons::LessonEntry>& entries)
{
    m_lessonBox->setLessons(entries);
    if (!m_state.lesson())
        showStep(); // the start page names the first lesson
}

QStringList LessonPlayer::lessonPaths() const
{
    return m_lessonBox->paths();
}

QStringList LessonPlayer::lessonMenuTexts() const
{
    return m_lessonBox->menuTexts();
}

QString LessonPlayer::firstLessonPath() const
{
    // listLessons() lists the lessons in teaching order (lessons::lessonsInOrder), the shipped
    // ones before the user's own.
    return m_lessonBox->paths().value(0);
}

QString LessonPlayer::openLesson(const QString& path)
{
    m_openCancelled = m_leaveGuard && !m_leaveGuard();
    if (m_openCancelled)
        return tr("The lesson was not opened: the edited scene stays.");
    // In the language the app chose (lessons::setLessonLanguage; English until it does).
    lessons::LessonLoadResult r =
        lessons::loadLessonFile(path, lessons::LessonLoadOptions{lessons::lessonLanguage()});
    if (!r.ok)
        return r.error;
    if (r.lesson.steps.empty())
        return tr("%1: the lesson has no steps").arg(path);
    m_state.open(std::move(r.lesson));
    m_page->forgetReadersChoice();
    m_lessonBox->showChosen(path);
    m_judge.startRecord();
    showStep();
    emit stepActivated(*m_state.lesson(), m_state.index());
    announceStep();
    return QString();
}

void LessonPlayer::closeLesson()
{
    if (!m_state.lesson())
        return;
    m_state.close();
    m_lessonBox->showNone();
    showStep();
    emit lessonClosed();
}

void LessonPlayer::goToStep(int index)
{
    const int from = m_state.index();
    if (!m_state.lesson() || index < 0 || index >= m_state.stepCount())
        return;
    m_judge.recordSettings(); // the world still runs the step being left
    m_state.goTo(index);
    showStep();
    // A step come back to is as the student left it, before the window sets it up with what
    // its answers released. Restart step starts it afresh, held back again; a lesson opened
    // anew starts with none shown.
    if (index != from)
        replayRecordedTries();
    emit stepActivated(*m_state.lesson(), m_state.index());
    announceStep();
}

void LessonPlayer::announceStep()
{
    if (const lessons::Lesson* lesson = m_state.lesson())
        m_page->announceStep(*lesson, m_state.index());
}

void LessonPlayer::next()
{
    goToStep(m_state.index() + 1);
}
void LessonPlayer::back()
{
    goToStep(m_state.index() - 1);
}
void LessonPlayer::restartStep()
{
    goToStep(m_state.index());
}

void LessonPlayer::showStep()
{
    const lessons::Lesson* lesson = m_state.lesson();
    const lessons::LessonStep* step = m_state.step();
    m_buttons->showStep(m_state.index(), m_state.stepCount(), step && !step->plots.isEmpty());
    m_handIn->setVisible(lesson != nullptr);
    m_start->setVisible(!lesson && !firstLessonPath().isEmpty());
    if (lesson)
        m_page->showStep(*lesson, m_state.index());
    else
        m_page->showStart(m_lessonBox->shortText(firstLessonPath()));
    fitTextMinimum();
    buildQuestions();
    if (!lesson)
        return;
    fitIntroduction();
    fitQuestionRoom();
    // A new step is read from its top: the lesson's title and introduction on the first
    // step while it is open, else the step's own title (the lesson's is a scroll up).
    const auto toTop = [this] {
        if (QScrollArea* scroll = scrollArea())
            scroll->verticalScrollBar()->setValue(stepTop());
    };
    toTop();
    QTimer::singleShot(0, this, toTop); // once the text's new height is laid out
}

QScrollArea* LessonPlayer::scrollArea() const
{
    QWidget* viewport = parentWidget();
    return qobject_cast<QScrollArea*>(viewport ? viewport->parentWidget() : nullptr);
}

void LessonPlayer::fitIntroduction()
{
    QScrollArea* scroll = scrollArea();
    if (!m_state.lesson() || m_state.index() != 0 || !scroll)
        return;
    const int height = scroll->viewport()->height();
    const QMargins margins = layout()->contentsMargins();
    const int width = scroll->viewport()->width() - margins.left() - margins.right();
    if (height <= 0 || width <= 0)
        return;
    // Above the lesson's title: the list of lessons.
    const int spacing = layout()->spacing();
    const int above = margins.top() + m_lessonBox->sizeHint().height() + spacing;
    m_page->fitIntroduction(height, width, above, spacing, kTextShare);
}

bool LessonPlayer::eventFilter(QObject* watched, QEvent* event)
{
    if (event->type() == QEvent::Resize) {
        const QScrollArea* scroll = scrollArea();
        if (scroll && watched == scroll->viewport()) {
            fitIntroduction();
            fitQuestionRoom();
        }
    }
    if (watched == m_text && event->type() == QEvent::FontChange) {
        m_questions->setFont(m_text->font());
        fitQuestionRoom();
    }
    return QWidget::eventFilter(watched, event);
}

void LessonPlayer::fitTextMinimum()
{
    // The scrolling part of the column keeps at least four lines of the text, in its current
    // (maybe presentation) font, however many questions are below it.
    QWidget* viewport = parentWidget();
    if (auto* scroll = qobject_cast<QScrollArea*>(viewport ? viewport->parentWidget() : nullptr))
        scroll->setMinimumHeight(4 * QFontMetrics(m_text->font()).lineSpacing() +
                                 2 * m_text->frameWidth() + 8);
}

int LessonPlayer::stepTop() const
{
    // The lesson's title and the name fields are a scroll up, once the introduction has
    // folded away (it does when the column is short) or on a later step.
    const bool fromStep = m_state.lesson() && (m_state.index() > 0 || !m_page->introductionShown());
    return fromStep ? std::max(0, m_page->stepCount()->y() - layout()->spacing()) : 0;
}

void LessonPlayer::fitQuestionRoom()
{
    QScrollArea* scroll = scrollArea();
    QWidget* column = scroll ? scroll->parentWidget() : nullptr;
    if (!column || column != m_navigation->parentWidget())
        return m_questionArea->fit();
    // What the column shows of a step when it opens (showStep() scrolls there): what is above
    // the text from stepTop(), then kTextLines of the text.
    layout()->activate();
    const int text = m_text->y() - stepTop() +
                     kTextLines * QFontMetrics(m_text->font()).lineSpacing() +
                     2 * m_text->frameWidth() + 2 * scroll->frameWidth();
    const int columnSpacing = column->layout() ? std::max(0, column->layout()->spacing()) : 0;
    const QMargins columnMargins =
        column->layout() ? column->layout()->contentsMargins() : QMargins();
    const int room = column->height() - columnMargins.top() - columnMargins.bottom() - text -
                     m_buttons->sizeHint().height() - 2 * columnSpacing -
                     std::max(0, m_navigation->layout()->spacing());
    m_questionArea->setRoom(std::max(0, room));
}

void LessonPlayer::changeEvent(QEvent* event)
{
    QWidget::changeEvent(event);
    if (event->type() == QEvent::FontChange || event->type() == QEvent::ParentChange)
        fitTextMinimum();
    if (event->type() == QEvent::ParentChange)
        if (QScrollArea* scroll = scrollArea())
            scroll->viewport()->installEventFilter(this);
    if (event->type() == QEvent::FontChange)
        fitIntroduction();
}

QWidget* LessonPlayer::takeNavigation()
{
    layout()->removeWidget(m_navigation);
    m_navigation->setParent(nullptr);
    return m_navigation;
}

void LessonPlayer::buildQuestions()
{
    m_judge.forgetMeasuredAhead();
    static const std::vector<lessons::Question> none;
    const lessons::LessonStep* step = m_state.step();
    // Each kind builds its row (ui/question_kinds/); the player judges what it hands in.
    m_questions->build(step ? step->questions : none,
                       [this](std::size_t i) { return rowHooks(i); });
    orderTabs();
}

RowHooks LessonPlayer::rowHooks(std::size_t i)
{
    // Each hook does nothing once the row is gone (another step, no lesson).
    const auto live = [this, i] { return i < m_state.questionCount() && i < m_questions->count(); };
    RowHooks hooks;
    hooks.prompt = m_state.question(i).prompt;
    hooks.judge = [this, i, live](const QuestionTry& attempt) {
        return live() && judge(i, attempt);
    };
    hooks.typedNumber = [this, i, live]() -> std::optional<double> {
        return live() ? m_questions->typedNumber(i) : std::nullopt;
    };
    hooks.askFirst = [this, i, live](const QString& text) {
        if (live())
            m_questions->askFirst(i, text);
    };
    hooks.measured = [this, i, live] { return live() ? m_judge.measuredTry(i) : QuestionTry{}; };
    hooks.askedRun = [this, i, live] {
        RunAdvice out;
        if (!live())
            return out;
        const AskedRun asked = m_judge.askedRun(i);
        if (!asked.matches())
            out.advice = askedRunAdvice(asked);
        out.setFirst = !asked.matches() && asked.studentCanSet;
        return out;
    };
    return hooks;
}

bool LessonPlayer::judge(std::size_t i, const QuestionTry& attempt)
{
    const QuestionJudge::Judged judged = m_judge.judge(i, attempt);
    if (!judged.kept) {
        m_questions->askFirst(i, judged.verdict.message);
        return false;
    }
    showJudged(i, attempt, judged);
    return true;
}

void LessonPlayer::showJudged(std::size_t i, const QuestionTry& attempt,
                              const QuestionJudge::Judged& judged)
{
    m_questions->showVerdict(i, judged.verdict, attempt, !m_replaying);
    if (judged.given)
        m_questions->setGiven(i);
    if (judged.released && !m_replaying)
        emit heldBackChanged(heldBack());
}

void LessonPlayer::orderTabs()
{
    // Made after the buttons below them, the questions would come last to Tab: the step's
    // text, its questions with their answers, then Back, Next and the others, as they are
    // shown.
    QList<QWidget*> order{m_text};
    order << m_questions->tabStops();
    order << m_buttons->tabStops();
    for (qsizetype k = 1; k < order.size(); ++k)
        setTabOrder(order[k - 1], order[k]);
}

QWidget* LessonPlayer::firstAnswer() const
{
    return m_questions->firstAnswer();
}

void LessonPlayer::replayRecordedTries()
{
    // Copied: judging a try writes the record again (the same tries, in the same order).
    const std::vector<std::vector<QuestionTry>> questions = m_judge.recordedTries();
    m_replaying = true;
    for (std::size_t i = 0; i < std::min(questions.size(), m_questions->count()); ++i)
        for (const QuestionTry& attempt : questions[i])
            showJudged(i, attempt, m_judge.judgeAgain(i, attempt));
    m_replaying = false;
}

QStringList LessonPlayer::heldBack() const
{
    return m_state.heldBack();
}

StepWork LessonPlayer::work() const
{
    return StepWork{m_state.tries(), m_questions->typed()};
}

void LessonPlayer::restoreWork(const StepWork& work)
{
    if (!m_state.lesson())
        return;
    // Afresh: the step may already hold the record's tries, the same as `work`'s.
    m_state.goTo(m_state.index());
    buildQuestions();
    for (std::size_t i = 0; i < m_questions->count(); ++i) {
        if (i < work.tries.size())
            for (const QuestionTry& attempt : work.tries[i])
                showJudged(i, attempt, m_judge.judgeAgain(i, attempt));
        if (i < static_cast<std::size_t>(work.typed.size()))
            m_questions->setTyped(i, work.typed[static_cast<qsizetype>(i)]);
    }
}

void LessonPlayer::answer(int question, const QString& text)
{
    m_questions->answer(question, text);
}

QString LessonPlayer::result(int question) const
{
    return m_questions->result(question);
}

void LessonPlayer::choose(int question, int option)
{
    m_questions->choose(question, option);
}

void LessonPlayer::showMe(int question)
{
    m_questions->showMe(question);
}

void LessonPlayer::setStudent(const QString& name, const QString& className)
{
    m_handIn->setStudent(name, className);
}

QString LessonPlayer::student() const
{
    return m_handIn->student();
}

lessons::Answers LessonPlayer::answers() const
{
    return m_handIn->answers();
}

QString LessonPlayer::handIn(const QString& pdfPath)
{
    return m_handIn->handIn(pdfPath);
}

void LessonPlayer::handInInteractively()
{
    m_handIn->handInInteractively();
}

void LessonPlayer::addWorksheetActions(QMenu& menu)
{
    QAction* empty = menu.addAction(tr("Works&heet to print…"), this,
                                    [this] { m_handIn->writeSheetInteractively(false); });
    empty->setObjectName(QStringLiteral("emptyWorksheet"));
    empty->setToolTip(tr("The open lesson's questions with lines to write on, and its figures"));
    QAction* key = menu.addAction(tr("Teacher's &key…"), this,
                                  [this] { m_handIn->writeSheetInteractively(true); });
    key->setObjectName(QStringLiteral("worksheetKey"));
    key->setToolTip(tr("The open lesson's questions with the values the simulation measures"));
    for (QAction* action : {empty, key}) {
        action->setEnabled(lesson() != nullptr);
        connect(this, &LessonPlayer::stepActivated, action, [action] { action->setEnabled(true); });
        connect(this, &LessonPlayer::lessonClosed, action, [action] { action->setEnabled(false); });
    }
}

} // namespace rigidlab::ui
