// SPDX-License-Identifier: GPL-3.0-or-later
#include "lesson_player/step_page.h"

#include "lesson_player/step_text.h"

#include "common/announcer.h"
#include "common/drawable_text.h"

#include "format/verdict.h"

#include <QCoreApplication>
#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QRegularExpression>
#include <QSignalBlocker>
#include <QTimer>
#include <QToolButton>
#include <QVBoxLayout>

namespace rigidlab::ui {

// Its words are the lesson player's (its translation context), as the rest of the lesson dock.

StepPage::StepPage(QWidget* column)
    : QObject(column), m_column(column), m_title(new QLabel(column)),
      m_aboutToggle(new QToolButton(column)), m_about(new QLabel(column)),
      m_progress(new QProgressBar(column)), m_stepCount(new QLabel(column)),
      m_stepTitle(new QLabel(column)), m_text(new StepText(column))
{
    m_text->setNameWhenEmpty(
        QCoreApplication::translate("rigidlab::ui::LessonPlayer", "Step text"));
}

void StepPage::addHead(QVBoxLayout* layout)
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
    m_aboutToggle->setText(
        QCoreApplication::translate("rigidlab::ui::LessonPlayer", "Introduction"));
    m_aboutToggle->setToolTip(QCoreApplication::translate(
        "rigidlab::ui::LessonPlayer", "Show or hide the lesson's introduction"));
    m_aboutToggle->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    m_aboutToggle->setAutoRaise(true);
    m_aboutToggle->setCheckable(true);
    m_aboutToggle->setChecked(true);
    m_aboutToggle->setArrowType(Qt::DownArrow);
    connect(m_aboutToggle, &QToolButton::toggled, this, [this](bool on) {
        m_aboutToggle->setArrowType(on ? Qt::DownArrow : Qt::RightArrow);
        m_about->setVisible(on && m_firstStep);
    });
    connect(m_aboutToggle, &QToolButton::clicked, this, [this] { m_aboutChosen = true; });
    layout->addWidget(m_aboutToggle);
    layout->addWidget(m_about);
}

void StepPage::addStep(QVBoxLayout* layout)
{
    // "Step 2 of 4" beside the bar rather than on it: text across the bar's filled edge is
    // half white on blue, half black on blue, and the black part unreadable.
    m_progress->setTextVisible(false);
    m_progress->setMaximumHeight(QFontMetrics(m_column->font()).height() / 2 + 4);
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
    // it.
    layout->addWidget(m_text);
}

void StepPage::showStep(const lessons::Lesson& l, int step)
{
    for (QWidget* w : {static_cast<QWidget*>(m_progress), static_cast<QWidget*>(m_stepCount),
                       static_cast<QWidget*>(m_stepTitle), static_cast<QWidget*>(m_text)})
        w->setVisible(true);
    m_firstStep = step == 0;
    const lessons::LessonStep& s = l.steps[static_cast<std::size_t>(step)];
    const int steps = static_cast<int>(l.steps.size());
    // A character no font has (an emoji) shows as its placeholder, not as an empty box.
    m_title->setText(drawableText(l.title, m_title->font()));
    QString about = l.summary;
    if (!l.level.isEmpty() || l.minutes > 0)
        about += QStringLiteral("\n") +
                 QCoreApplication::translate("rigidlab::ui::LessonPlayer", "%1 · about %2 min")
                     .arg(l.level)
                     .arg(l.minutes);
    m_about->setText(about);
    // The summary introduces the lesson; on the later steps their text has its room.
    m_aboutToggle->setVisible(m_firstStep && !about.isEmpty());
    m_about->setVisible(m_firstStep && m_aboutToggle->isChecked());
    m_progress->setRange(0, steps);
    m_progress->setValue(step + 1);
    m_stepCount->setText(QCoreApplication::translate("rigidlab::ui::LessonPlayer", "Step %1 of %2")
                             .arg(step + 1)
                             .arg(steps));
    m_stepTitle->setText(drawableText(s.title, m_stepTitle->font()));
    m_text->showMarkdown(drawableText(lessons::keepUnitsTogether(s.text), m_text->font()));
}

void StepPage::showStart(const QString& firstLesson)
{
    for (QWidget* w : {static_cast<QWidget*>(m_progress), static_cast<QWidget*>(m_stepCount),
                       static_cast<QWidget*>(m_stepTitle), static_cast<QWidget*>(m_text)})
        w->setVisible(false);
    m_firstStep = true;
    m_aboutToggle->setVisible(false);
    m_about->setVisible(true);
    m_title->setText(QCoreApplication::translate("rigidlab::ui::LessonPlayer", "Start here"));
    QString about = QCoreApplication::translate(
        "rigidlab::ui::LessonPlayer",
        "RigidLab is a laboratory of moving bodies: run a prepared scene, "
        "change its settings and measure what happens. Each lesson walks "
        "you through one idea of mechanics step by step, with questions "
        "to answer on the way.");
    if (!firstLesson.isEmpty())
        about += QStringLiteral("\n\n") +
                 QCoreApplication::translate(
                     "rigidlab::ui::LessonPlayer",
                     "The first lesson is “%1”; the list above holds the others.")
                     .arg(firstLesson);
    m_about->setText(about);
    m_text->showMarkdown(QString());
}

void StepPage::announceStep(const lessons::Lesson& lesson, int step)
{
    // The step's first sentence, which says what it is about.
    const QString text = m_text->toPlainText().simplified();
    static const QRegularExpression sentence(QStringLiteral("^.*?[.!?:](?=\\s|$)"));
    const QRegularExpressionMatch first = sentence.match(text);
    announce(*m_column,
             QCoreApplication::translate("rigidlab::ui::LessonPlayer", "Step %1 of %2: %3. %4")
                 .arg(step + 1)
                 .arg(lesson.steps.size())
                 .arg(lesson.steps[static_cast<std::size_t>(step)].title,
                      first.hasMatch() ? first.captured() : text.left(200)));
    // Then the focus on the step's text, so that a reader goes on reading it; once the window
    // has set up the step (docks shown and hidden move the focus).
    QTimer::singleShot(0, this, [this] {
        if (m_text->isVisible())
            m_text->setFocus(Qt::OtherFocusReason);
    });
}

void StepPage::fitIntroduction(int height, int width, int above, int spacing, double textShare)
{
    if (m_aboutChosen || m_about->text().isEmpty())
        return;
    // What is above the text when the step opens: the titles, the bar, the introduction.
    for (QWidget* w : {static_cast<QWidget*>(m_title), static_cast<QWidget*>(m_aboutToggle),
                       static_cast<QWidget*>(m_stepCount), static_cast<QWidget*>(m_stepTitle)}) {
        const int h = w->hasHeightForWidth() ? w->heightForWidth(width) : w->sizeHint().height();
        above += h + spacing;
    }
    const int about = m_about->heightForWidth(width) + spacing;
    const bool fits = height - above - about >= textShare * height;
    const QSignalBlocker quiet(m_aboutToggle); // not the reader's choice
    m_aboutToggle->setChecked(fits);
    m_aboutToggle->setArrowType(fits ? Qt::DownArrow : Qt::RightArrow);
    m_about->setVisible(fits);
}

QWidget* StepPage::stepCount() const
{
    return m_stepCount;
}

bool StepPage::introductionShown() const
{
    return !m_about->isHidden();
}

} // namespace rigidlab::ui
