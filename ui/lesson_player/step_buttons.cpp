// SPDX-License-Identifier: GPL-3.0-or-later
#include "lesson_player/step_buttons.h"

#include "common/shortcuts.h"

#include <QCoreApplication>
#include <QGridLayout>
#include <QPushButton>

namespace rigidlab::ui {

StepButtons::StepButtons(QWidget* parent)
    : QWidget(parent), m_back(new QPushButton(this)), m_restart(new QPushButton(this)),
      m_next(new QPushButton(this)), m_export(new QPushButton(this)),
      m_handIn(new QPushButton(this))
{
    setObjectName(QStringLiteral("lessonNavigation"));
    // In the lesson player's words (its translation context), as the rest of the lesson dock.
    m_back->setText(QCoreApplication::translate("rigidlab::ui::LessonPlayer", "◀ Back"));
    m_restart->setText(QCoreApplication::translate("rigidlab::ui::LessonPlayer", "Restart step"));
    m_next->setText(QCoreApplication::translate("rigidlab::ui::LessonPlayer", "Next ▶"));
    m_export->setText(QCoreApplication::translate("rigidlab::ui::LessonPlayer", "Export plots…"));
    m_handIn->setText(QCoreApplication::translate("rigidlab::ui::LessonPlayer", "Hand in…"));
    m_handIn->setObjectName(QStringLiteral("handIn"));
    // A key as well as the button (Help › Controls lists it).
    const QList<QKeySequence> keys = controlKeys("handIn");
    if (!keys.isEmpty())
        m_handIn->setShortcut(keys.front());
    m_handIn->setToolTip(
        QCoreApplication::translate("rigidlab::ui::LessonPlayer",
                                    "Write your worksheet as a PDF: the questions, your answers "
                                    "and their verdicts, the plots and the settings (%1)")
            .arg(controlKeysText("handIn")));
    auto* grid = new QGridLayout(this);
    grid->addWidget(m_back, 0, 0);
    grid->addWidget(m_next, 0, 1);
    grid->addWidget(m_restart, 1, 0);
    grid->addWidget(m_export, 1, 1);
    grid->addWidget(m_handIn, 2, 0, 1, 2);
    connect(m_back, &QPushButton::clicked, this, &StepButtons::backClicked);
    connect(m_next, &QPushButton::clicked, this, &StepButtons::nextClicked);
    connect(m_restart, &QPushButton::clicked, this, &StepButtons::restartClicked);
    connect(m_export, &QPushButton::clicked, this, &StepButtons::exportClicked);
    connect(m_handIn, &QPushButton::clicked, this, &StepButtons::handInClicked);
}

void StepButtons::showStep(int step, int steps, bool plots)
{
    for (QPushButton* b : {m_back, m_next, m_restart, m_export, m_handIn})
        b->setVisible(steps > 0);
    m_back->setEnabled(step > 0);
    m_next->setEnabled(step + 1 < steps);
    m_export->setEnabled(plots);
    // The lesson's last step: Hand in is how it ends.
    const bool last = steps > 0 && step + 1 == steps;
    m_handIn->setText(last ? QCoreApplication::translate("rigidlab::ui::LessonPlayer",
                                                         "Finish: hand in the worksheet…")
                           : QCoreApplication::translate("rigidlab::ui::LessonPlayer", "Hand in…"));
}

QList<QWidget*> StepButtons::tabStops() const
{
    return {m_back, m_next, m_restart, m_export, m_handIn};
}

} // namespace rigidlab::ui
