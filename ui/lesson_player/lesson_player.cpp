// SPDX-License-Identifier: GPL-3.0-or-later
#include "lesson_player/lesson_player.h"
#include "lesson_player/step_text.h"

#include "common/modal_scope.h"
#include "panels/number_field.h"
#include "simulation/simulation_controller.h"

#include "format/lesson_catalog.h"

#include "run/measurements.h"

#include <QAbstractItemView>
#include <QComboBox>
#include <QDir>
#include <QEvent>
#include <QFileInfo>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QScrollArea>
#include <QToolButton>
#include <QVBoxLayout>

#include <cmath>

namespace rigidlab::ui {

namespace {

/// The largest answer taken, in the question's unit: far beyond any measured value, and small
/// enough that |answer - measured| stays finite.
constexpr double kMaxAnswer = 1e15;

} // namespace

LessonPlayer::LessonPlayer(SimulationController& controller, QWidget* parent)
    : QWidget(parent), m_controller(controller), m_lessonBox(new QComboBox(this)),
      m_title(new QLabel(this)), m_aboutToggle(new QToolButton(this)), m_about(new QLabel(this)),
      m_progress(new QProgressBar(this)), m_stepCount(new QLabel(this)),
      m_stepTitle(new QLabel(this)), m_text(new StepText(this)), m_questionBox(new QWidget(this)),
      m_questionLayout(new QVBoxLayout(m_questionBox)), m_back(new QPushButton(tr("◀ Back"), this)),
      m_restart(new QPushButton(tr("Restart step"), this)),
      m_next(new QPushButton(tr("Next ▶"), this)),
      m_export(new QPushButton(tr("Export plots…"), this)),
      m_start(new QPushButton(tr("Start the first lesson"), this))
{
    auto* layout = new QVBoxLayout(this);
    m_lessonBox->setToolTip(
        tr("The lessons that come with RigidLab (File › Open lesson for others)"));
    layout->addWidget(m_lessonBox);
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
        m_about->setVisible(on && (!m_lesson || m_step == 0));
    });
    layout->addWidget(m_aboutToggle);
    layout->addWidget(m_about);
    // On a first start, with no lesson open, the way in: one button to the first lesson.
    m_start->setObjectName(QStringLiteral("startFirstLesson"));
    connect(m_start, &QPushButton::clicked, this, [this] {
        const QString error = openLesson(firstLessonPath());
        const ModalScope modal;
        if (!error.isEmpty() && !m_openCancelled)
            QMessageBox::warning(this, tr("Cannot open lesson"), error);
    });
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
    // The text is as tall as its words; the lesson's column scrolls it (with the title above
    // it) while the questions and buttons below stay (takeNavigation()).
    layout->addWidget(m_text);
    // The start page (no lesson, so no text) keeps to the top instead of spreading out.
    layout->addStretch(0);
    // The questions and the buttons are a widget of their own, so that the window can keep
    // them in sight below a lesson text that scrolls (takeNavigation()). Two buttons a row,
    // so that the panel fits the narrow column of a 1024-pixel projector.
    m_navigation = new QWidget(this);
    m_navigation->setObjectName(QStringLiteral("lessonNavigation"));
    auto* bottom = new QVBoxLayout(m_navigation);
    // In line with the text above, wherever the window puts them.
    const QMargins margins = layout->contentsMargins();
    bottom->setContentsMargins(margins.left(), 0, margins.right(), 0);
    m_questionBox->setParent(m_navigation);
    m_questionBox->setObjectName(QStringLiteral("lessonQuestions"));
    m_questionLayout->setContentsMargins(0, 0, 0, 0);
    bottom->addWidget(m_questionBox);
    auto* buttons = new QGridLayout;
    bottom->addLayout(buttons);
    buttons->setContentsMargins(0, 0, 0, 0);
    buttons->addWidget(m_back, 0, 0);
    buttons->addWidget(m_next, 0, 1);
    buttons->addWidget(m_restart, 1, 0);
    buttons->addWidget(m_export, 1, 1);
    layout->addWidget(m_navigation);

    connect(m_back, &QPushButton::clicked, this, &LessonPlayer::back);
    connect(m_next, &QPushButton::clicked, this, &LessonPlayer::next);
    connect(m_restart, &QPushButton::clicked, this, &LessonPlayer::restartStep);
    connect(m_export, &QPushButton::clicked, this, &LessonPlayer::exportRequested);
    connect(m_lessonBox, &QComboBox::activated, this, [this](int index) {
        const QString path = m_lessonBox->itemData(index).toString();
        if (path.isEmpty())
            return closeLesson();
        const QString error = openLesson(path);
        const ModalScope modal;
        if (!error.isEmpty() && !m_openCancelled)
            QMessageBox::warning(this, tr("Cannot open lesson"), error);
    });
    showStep();
}

void LessonPlayer::scanFolder(const QString& folder)
{
    // A broken shipped lesson is a test failure, not a menu entry: lessonsInOrder skips it.
    listLessons(lessons::lessonsInOrder(folder));
}

void LessonPlayer::listLessons(const std::vector<lessons::LessonEntry>& entries)
{
    m_lessonBox->clear();
    m_paths.clear();
    m_menuTexts.clear();
    m_lessonBox->addItem(tr("Choose a lesson…"), QString());
    for (std::size_t i = 0; i < entries.size(); ++i) {
        const lessons::LessonEntry& entry = entries[i];
        const QString text = lessons::lessonMenuText(entry, static_cast<int>(i) + 1);
        m_lessonBox->addItem(text, entry.path);
        m_lessonBox->setItemData(m_lessonBox->count() - 1, text, Qt::ToolTipRole);
        m_paths << entry.path;
        m_menuTexts << text;
    }
    // The box stays as narrow as its column; its list opens as wide as its longest line.
    m_lessonBox->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_lessonBox->setMinimumContentsLength(12);
    m_lessonBox->view()->setTextElideMode(Qt::ElideNone);
    m_lessonBox->view()->setMinimumWidth(m_lessonBox->view()->sizeHintForColumn(0) + 24);
    if (!m_lesson)
        showStep(); // the start page names the first lesson
}

QString LessonPlayer::firstLessonPath() const
{
    // listLessons() lists the lessons in teaching order (lessons::lessonsInOrder), the shipped
    // ones before the user's own.
    return m_paths.value(0);
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
    m_lesson = std::make_unique<lessons::Lesson>(std::move(r.lesson));
    const int index = m_lessonBox->findData(QFileInfo(path).absoluteFilePath());
    if (index >= 0)
        m_lessonBox->setCurrentIndex(index);
    m_step = 0;
    showStep();
    emit stepActivated(*m_lesson, m_step);
    return QString();
}

void LessonPlayer::closeLesson()
{
    if (!m_lesson)
        return;
    m_lesson.reset();
    m_lessonBox->setCurrentIndex(0);
    showStep();
    emit lessonClosed();
}

void LessonPlayer::goToStep(int index)
{
    if (!m_lesson || index < 0 || index >= static_cast<int>(m_lesson->steps.size()))
        return;
    m_step = index;
    showStep();
    emit stepActivated(*m_lesson, m_step);
}

void LessonPlayer::next()
{
    goToStep(m_step + 1);
}
void LessonPlayer::back()
{
    goToStep(m_step - 1);
}
void LessonPlayer::restartStep()
{
    goToStep(m_step);
}

void LessonPlayer::showStep()
{
    const bool has = m_lesson != nullptr;
    for (QWidget* w : {static_cast<QWidget*>(m_progress), static_cast<QWidget*>(m_stepCount),
                       static_cast<QWidget*>(m_stepTitle), static_cast<QWidget*>(m_restart),
                       static_cast<QWidget*>(m_back), static_cast<QWidget*>(m_next),
                       static_cast<QWidget*>(m_export)})
        w->setVisible(has);
    // No lesson: a "start here" page instead of an empty text box.
    m_text->setVisible(has);
    fitTextMinimum();
    const QString first = firstLessonPath();
    m_start->setVisible(!has && !first.isEmpty());
    if (!has) {
        m_aboutToggle->setVisible(false);
        m_about->setVisible(true);
        m_title->setText(tr("Start here"));
        QString about = tr("RigidLab is a laboratory of moving bodies: run a prepared scene, "
                           "change its settings and measure what happens. Each lesson walks "
                           "you through one idea of mechanics step by step, with questions "
                           "to answer on the way.");
        const int index = m_lessonBox->findData(first);
        if (index >= 0)
            about += QStringLiteral("\n\n") +
                     tr("The first lesson is “%1”; the list above holds the others.")
                         .arg(m_lessonBox->itemText(index));
        m_about->setText(about);
        m_text->showMarkdown(QString());
        m_rows.clear();
        buildQuestions();
        return;
    }
    const lessons::Lesson& l = *m_lesson;
    const lessons::LessonStep& s = l.steps[static_cast<size_t>(m_step)];
    m_title->setText(l.title);
    QString about = l.summary;
    if (!l.level.isEmpty() || l.minutes > 0)
        about += QStringLiteral("\n") + tr("%1 · about %2 min").arg(l.level).arg(l.minutes);
    m_about->setText(about);
    // The summary introduces the lesson; on the later steps their text has its room.
    m_aboutToggle->setVisible(m_step == 0 && !about.isEmpty());
    m_about->setVisible(m_step == 0 && m_aboutToggle->isChecked());
    m_progress->setRange(0, static_cast<int>(l.steps.size()));
    m_progress->setValue(m_step + 1);
    m_stepCount->setText(tr("Step %1 of %2").arg(m_step + 1).arg(l.steps.size()));
    m_stepTitle->setText(s.title);
    m_text->showMarkdown(s.text);
    m_back->setEnabled(m_step > 0);
    m_next->setEnabled(m_step + 1 < static_cast<int>(l.steps.size()));
    m_export->setEnabled(!s.plots.isEmpty());
    buildQuestions();
}

void LessonPlayer::buildQuestions()
{
    while (QLayoutItem* item = m_questionLayout->takeAt(0)) {
        delete item->widget();
        delete item;
    }
    m_rows.clear();
    if (!m_lesson)
        return;
    const lessons::LessonStep& step = m_lesson->steps[static_cast<size_t>(m_step)];
    for (std::size_t i = 0; i < step.questions.size(); ++i) {
        const lessons::Question& q = step.questions[i];
        auto* box = new QWidget(m_questionBox);
        auto* v = new QVBoxLayout(box);
        v->setContentsMargins(0, 4, 0, 4);
        auto* prompt = new QLabel(q.prompt, box);
        prompt->setWordWrap(true);
        v->addWidget(prompt);
        // The answer and its unit on a line of their own, the buttons below: side by side
        // they left the answer a few letters wide in a narrow column.
        auto* row = new QHBoxLayout;
        auto* buttons = new QHBoxLayout;
        auto* edit = new QLineEdit(box);
        // No validator: it would drop the separator the locale does not use ("0.0156" typed
        // in Czech became 00156). What was typed is read when it is checked, point or comma.
        edit->setPlaceholderText(tr("your answer"));
        row->addWidget(edit, 1);
        row->addWidget(new QLabel(q.unit, box));
        auto* check = new QPushButton(tr("Check"), box);
        buttons->addWidget(check);
        auto* show = new QPushButton(tr("Show me"), box);
        show->setToolTip(tr("Give up and show the measured value"));
        buttons->addWidget(show);
        v->addLayout(row);
        v->addLayout(buttons);
        auto* result = new QLabel(box);
        result->setWordWrap(true);
        result->setVisible(false); // no empty line under the buttons before the first try
        v->addWidget(result);
        m_questionLayout->addWidget(box);
        QuestionRow questionRow;
        questionRow.edit = edit;
        questionRow.result = result;
        questionRow.show = show;
        m_rows.push_back(questionRow);
        auto judge = [this, i, edit, result] {
            if (!m_lesson)
                return;
            const std::optional<double> parsed = parseNumber(edit->text());
            if (!parsed) {
                result->setStyleSheet(QStringLiteral("color: #a05a00;"));
                result->setText(tr("Type a number first."));
                result->setVisible(true);
                return;
            }
            const double answer = *parsed;
            if (std::abs(answer) > kMaxAnswer) {
                result->setStyleSheet(QStringLiteral("color: #a05a00;"));
                result->setText(tr("Type a number from %1 to %2.")
                                    .arg(formatNumber(-kMaxAnswer), formatNumber(kMaxAnswer)));
                result->setVisible(true);
                return;
            }
            settle(i, judgeTry(i, answer));
        };
        connect(check, &QPushButton::clicked, this, judge);
        connect(edit, &QLineEdit::returnPressed, this, judge);
        connect(show, &QPushButton::clicked, this, [this, i] {
            if (m_lesson && i < m_rows.size())
                settle(i, lessons::showAnswer(
                              m_lesson->steps[static_cast<size_t>(m_step)].questions[i],
                              measuredValue(i)));
        });
    }
}

std::optional<double> LessonPlayer::measuredValue(std::size_t i)
{
    const lessons::LessonStep& step = m_lesson->steps[static_cast<size_t>(m_step)];
    const lessons::Question& q = step.questions[i];
    if (const auto live = m_controller.measurements().value(q.measure, step.scene))
        return live;
    // While the scene may not run, the student could never get a verdict: the same run is
    // done without a window instead (it is deterministic, so it measures what the window
    // will show once it runs).
    if (!heldBack().contains(QStringView(lessons::kHoldBackRun)))
        return std::nullopt;
    QuestionRow& row = m_rows[i];
    if (!row.aheadDone) {
        row.ahead = lessons::measureAhead(step, q.measure);
        row.aheadDone = true;
    }
    return row.ahead;
}

lessons::Verdict LessonPlayer::judgeTry(std::size_t i, double answer)
{
    const lessons::Question& q = m_lesson->steps[static_cast<size_t>(m_step)].questions[i];
    QuestionRow& row = m_rows[i];
    const std::optional<double> value = measuredValue(i);
    if (value && !row.answered)
        ++row.attempts;
    // Once answered, every later try is judged with the value given.
    return lessons::judgeAttempt(q, answer, value, row.answered ? 2 : row.attempts);
}

void LessonPlayer::settle(std::size_t i, const lessons::Verdict& v)
{
    QuestionRow& row = m_rows[i];
    row.result->setStyleSheet(!v.measured ? QStringLiteral("color: #a05a00;")
                              : v.right   ? QStringLiteral("color: #1e7b34; font-weight: bold;")
                              : v.shown   ? QStringLiteral("color: #b3261e; font-weight: bold;")
                                          : QStringLiteral("color: #a05a00; font-weight: bold;"));
    row.result->setText(v.message);
    row.result->setVisible(true);
    if (!v.measured && heldBack().contains(QStringView(lessons::kHoldBackRun))) {
        // Not measurable without a window within the limit: let the scene run rather than
        // leave the student with no way on.
        row.answered = true;
        emit heldBackChanged(heldBack());
        return;
    }
    if (!v.shown || row.answered)
        return;
    row.answered = true;
    row.show->setEnabled(false);
    emit heldBackChanged(heldBack());
}

QStringList LessonPlayer::heldBack() const
{
    if (!m_lesson)
        return {};
    std::vector<bool> answered;
    for (const QuestionRow& row : m_rows)
        answered.push_back(row.answered);
    return m_lesson->steps[static_cast<size_t>(m_step)].heldBack(answered);
}

void LessonPlayer::showMe(int question)
{
    if (question < 0 || question >= static_cast<int>(m_rows.size()))
        return;
    m_rows[static_cast<size_t>(question)].show->click();
}

void LessonPlayer::answer(int question, const QString& text)
{
    if (question < 0 || question >= static_cast<int>(m_rows.size()))
        return;
    m_rows[static_cast<size_t>(question)].edit->setText(text);
    emit m_rows[static_cast<size_t>(question)].edit->returnPressed();
}

QString LessonPlayer::result(int question) const
{
    if (question < 0 || question >= static_cast<int>(m_rows.size()))
        return QString();
    return m_rows[static_cast<size_t>(question)].result->text();
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

void LessonPlayer::changeEvent(QEvent* event)
{
    QWidget::changeEvent(event);
    if (event->type() == QEvent::FontChange || event->type() == QEvent::ParentChange)
        fitTextMinimum();
}

QWidget* LessonPlayer::takeNavigation()
{
    layout()->removeWidget(m_navigation);
    m_navigation->setParent(nullptr);
    return m_navigation;
}

} // namespace rigidlab::ui
