// SPDX-License-Identifier: GPL-3.0-or-later
#include "lesson_player/lesson_player.h"
#include "lesson_player/lesson_list.h"
#include "lesson_player/question_area.h"
#include "lesson_player/question_rows.h"
#include "lesson_player/step_text.h"

#include "common/announcer.h"
#include "common/drawable_text.h"
#include "common/modal_scope.h"
#include "simulation/run_view.h"

#include <QEvent>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QRegularExpression>
#include <QScrollArea>
#include <QScrollBar>
#include <QSignalBlocker>
#include <QTimer>
#include <QToolButton>
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
    : QWidget(parent), m_run(run), m_lessonBox(new LessonList(this)), m_title(new QLabel(this)),
      m_aboutToggle(new QToolButton(this)), m_about(new QLabel(this)),
      m_progress(new QProgressBar(this)), m_stepCount(new QLabel(this)),
      m_stepTitle(new QLabel(this)), m_text(new StepText(this)),
      m_questions(new QuestionRows(this)), m_back(new QPushButton(tr("◀ Back"), this)),
      m_restart(new QPushButton(tr("Restart step"), this)),
      m_next(new QPushButton(tr("Next ▶"), this)),
      m_export(new QPushButton(tr("Export plots…"), this)),
      m_handIn(new QPushButton(tr("Hand in…"), this)), m_studentBox(new QWidget(this)),
      m_studentName(new QLineEdit(m_studentBox)), m_studentClass(new QLineEdit(m_studentBox)),
      m_start(new QPushButton(tr("Start the first lesson"), this))
{
    m_text->setNameWhenEmpty(tr("Step text"));
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_lessonBox);
    buildIntroduction(layout);
    buildStudentFields(layout);
    // On a first start, with no lesson open, the way in: one button to the first lesson.
    m_start->setObjectName(QStringLiteral("startFirstLesson"));
    connect(m_start, &QPushButton::clicked, this, [this] { openChosen(firstLessonPath()); });
    layout->addWidget(m_start);
    // "Step 2 of 4" beside the bar rather than on it: text across the bar's filled edge is
    // half white on blue, half black on blue, and the black part unreadable.
    m_progress->setTextVisible(false);
    m_progress->setMaximumHeight(QFontMetrics(font()).height() / 2 + 4);
    auto* progressRow = new QHBoxLayout;
    progressRow->addWidget(m_stepCount);
    progressRow->addWidget(m_progress, 1);
    layout->addLayout(progressRow);
    QFont bold = m_stepTitle->font();
    bold.setBold(true);
    bold.setPointSizeF(bold.pointSizeF() * 1.15);
    m_stepTitle->setFont(bold);
    m_stepTitle->setWordWrap(true);
    layout->addWidget(m_stepTitle);
    QFont textFont = m_text->font();
    textFont.setPointSizeF(textFont.pointSizeF() * 1.1); // readable on a projector
    m_text->setFont(textFont);
    // The text is as tall as its words; the lesson's column scrolls it, with the titles above
    // it. The questions and the buttons stay in sight below it (takeNavigation()): the class
    // sees what it is asked, where it answers and the verdict while the text is read.
    layout->addWidget(m_text);
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

void LessonPlayer::buildIntroduction(QVBoxLayout* layout)
{
    QFont big = m_title->font();
    big.setPointSizeF(big.pointSizeF() * 1.35);
    big.setBold(true);
    m_title->setFont(big);
    m_title->setWordWrap(true);
    m_about->setWordWrap(true);
    // Grey through the palette, not a style sheet: a style sheet would keep the text at its
    // first font when presentation mode enlarges the window's.
    QPalette grey = m_about->palette();
    grey.setColor(QPalette::WindowText, QColor(0x55, 0x55, 0x55)); // 7.5:1 on white
    m_about->setPalette(grey);
    layout->addWidget(m_title);
    // The introduction folds away, leaving its room to the step's text and questions.
    m_aboutToggle->setObjectName(QStringLiteral("lessonIntroToggle"));
    m_aboutToggle->setText(tr("Introduction"));
    m_aboutToggle->setToolTip(tr("Show or hide the lesson's introduction"));
    m_aboutToggle->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    m_aboutToggle->setAutoRaise(true);
    m_aboutToggle->setCheckable(true);
    m_aboutToggle->setChecked(true);
    m_aboutToggle->setArrowType(Qt::DownArrow);
    connect(m_aboutToggle, &QToolButton::toggled, this, [this](bool on) {
        m_aboutToggle->setArrowType(on ? Qt::DownArrow : Qt::RightArrow);
        m_about->setVisible(on && m_state.index() == 0);
    });
    connect(m_aboutToggle, &QToolButton::clicked, this, [this] { m_aboutChosen = true; });
    layout->addWidget(m_aboutToggle);
    layout->addWidget(m_about);
}

void LessonPlayer::buildNavigation(QVBoxLayout* layout)
{
    // The questions and the buttons are a widget of their own, so that the window can keep
    // them in sight below the lesson that scrolls (takeNavigation()). Two buttons a row, so
    // that the panel fits the narrow column of a 1024-pixel projector.
    m_navigation = new QWidget(this);
    m_navigation->setObjectName(QStringLiteral("lessonInSight"));
    auto* column = new QVBoxLayout(m_navigation);
    column->setContentsMargins(0, 0, 0, 0);
    m_questionArea = new QuestionArea(m_questions, m_navigation);
    column->addWidget(m_questionArea);
    m_buttons = new QWidget(m_navigation);
    m_buttons->setObjectName(QStringLiteral("lessonNavigation"));
    column->addWidget(m_buttons);
    auto* buttons = new QGridLayout(m_buttons);
    // In line with the text above, wherever the window puts them.
    const QMargins margins = layout->contentsMargins();
    buttons->setContentsMargins(margins.left(), 0, margins.right(), 0);
    m_questions->setContentsMargins(margins.left(), 0, margins.right(), 0);
    buttons->addWidget(m_back, 0, 0);
    buttons->addWidget(m_next, 0, 1);
    buttons->addWidget(m_restart, 1, 0);
    buttons->addWidget(m_export, 1, 1);
    buttons->addWidget(m_handIn, 2, 0, 1, 2);
    layout->addWidget(m_navigation);

    connect(m_back, &QPushButton::clicked, this, &LessonPlayer::back);
    connect(m_next, &QPushButton::clicked, this, &LessonPlayer::next);
    connect(m_restart, &QPushButton::clicked, this, &LessonPlayer::restartStep);
    connect(m_export, &QPushButton::clicked, this, &LessonPlayer::exportRequested);
    connect(m_handIn, &QPushButton::clicked, this, &LessonPlayer::handInInteractively);
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
    m_aboutChosen = false;
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
    const lessons::LessonStep* step = m_state.step();
    if (!step)
        return;
    // The step's first sentence, which says what it is about.
    const QString text = m_text->toPlainText().simplified();
    static const QRegularExpression sentence(QStringLiteral("^.*?[.!?:](?=\\s|$)"));
    const QRegularExpressionMatch first = sentence.match(text);
    announce(*this, tr("Step %1 of %2: %3. %4")
                        .arg(m_state.index() + 1)
                        .arg(m_state.stepCount())
                        .arg(step->title, first.hasMatch() ? first.captured() : text.left(200)));
    // Then the focus on the step's text, so that a reader goes on reading it; once the window
    // has set up the step (docks shown and hidden move the focus).
    QTimer::singleShot(0, this, [this] {
        if (m_text->isVisible())
            m_text->setFocus(Qt::OtherFocusReason);
    });
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
    const lessons::Lesson* l = m_state.lesson();
    for (QWidget* w :
         {static_cast<QWidget*>(m_progress), static_cast<QWidget*>(m_stepCount),
          static_cast<QWidget*>(m_stepTitle), static_cast<QWidget*>(m_restart),
          static_cast<QWidget*>(m_back), static_cast<QWidget*>(m_next),
          static_cast<QWidget*>(m_export), static_cast<QWidget*>(m_handIn), m_studentBox})
        w->setVisible(l != nullptr);
    m_text->setVisible(l != nullptr);
    fitTextMinimum();
    m_start->setVisible(!l && !firstLessonPath().isEmpty());
    if (!l)
        return showStartPage();
    const lessons::LessonStep& s = *m_state.step();
    const int step = m_state.index();
    // A character no font has (an emoji) shows as its placeholder, not as an empty box.
    m_title->setText(drawableText(l->title, m_title->font()));
    QString about = l->summary;
    if (!l->level.isEmpty() || l->minutes > 0)
        about += QStringLiteral("\n") + tr("%1 · about %2 min").arg(l->level).arg(l->minutes);
    m_about->setText(about);
    // The summary introduces the lesson; on the later steps their text has its room.
    m_aboutToggle->setVisible(step == 0 && !about.isEmpty());
    m_about->setVisible(step == 0 && m_aboutToggle->isChecked());
    m_progress->setRange(0, m_state.stepCount());
    m_progress->setValue(step + 1);
    m_stepCount->setText(tr("Step %1 of %2").arg(step + 1).arg(m_state.stepCount()));
    m_stepTitle->setText(drawableText(s.title, m_stepTitle->font()));
    m_text->showMarkdown(drawableText(lessons::keepUnitsTogether(s.text), m_text->font()));
    m_back->setEnabled(m_state.hasBack());
    m_next->setEnabled(m_state.hasNext());
    m_export->setEnabled(!s.plots.isEmpty());
    showHandIn();
    buildQuestions();
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

void LessonPlayer::showStartPage()
{
    m_aboutToggle->setVisible(false);
    m_about->setVisible(true);
    m_title->setText(tr("Start here"));
    QString about = tr("RigidLab is a laboratory of moving bodies: run a prepared scene, "
                       "change its settings and measure what happens. Each lesson walks "
                       "you through one idea of mechanics step by step, with questions "
                       "to answer on the way.");
    if (const QString first = m_lessonBox->shortText(firstLessonPath()); !first.isEmpty())
        about += QStringLiteral("\n\n") +
                 tr("The first lesson is “%1”; the list above holds the others.").arg(first);
    m_about->setText(about);
    m_text->showMarkdown(QString());
    buildQuestions();
}

QScrollArea* LessonPlayer::scrollArea() const
{
    QWidget* viewport = parentWidget();
    return qobject_cast<QScrollArea*>(viewport ? viewport->parentWidget() : nullptr);
}

void LessonPlayer::fitIntroduction()
{
    QScrollArea* scroll = scrollArea();
    if (!m_state.lesson() || m_state.index() != 0 || m_aboutChosen || !scroll ||
        m_about->text().isEmpty())
        return;
    const int height = scroll->viewport()->height();
    const QMargins margins = layout()->contentsMargins();
    const int width = scroll->viewport()->width() - margins.left() - margins.right();
    if (height <= 0 || width <= 0)
        return;
    // What is above the text when the step opens: the list, the titles, the bar, the intro.
    const int spacing = layout()->spacing();
    int above = margins.top();
    for (QWidget* w : {static_cast<QWidget*>(m_lessonBox), static_cast<QWidget*>(m_title),
                       static_cast<QWidget*>(m_aboutToggle), static_cast<QWidget*>(m_stepCount),
                       static_cast<QWidget*>(m_stepTitle)}) {
        const int h = w->hasHeightForWidth() ? w->heightForWidth(width) : w->sizeHint().height();
        above += h + spacing;
    }
    const int about = m_about->heightForWidth(width) + spacing;
    const bool fits = height - above - about >= kTextShare * height;
    const QSignalBlocker quiet(m_aboutToggle); // not the reader's choice
    m_aboutToggle->setChecked(fits);
    m_aboutToggle->setArrowType(fits ? Qt::DownArrow : Qt::RightArrow);
    m_about->setVisible(fits);
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
    const bool fromStep = m_state.lesson() && (m_state.index() > 0 || m_about->isHidden());
    return fromStep ? std::max(0, m_stepCount->y() - layout()->spacing()) : 0;
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
    order << m_back << m_next << m_restart << m_export << m_handIn;
    for (qsizetype k = 1; k < order.size(); ++k)
        setTabOrder(order[k - 1], order[k]);
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

} // namespace rigidlab::ui
