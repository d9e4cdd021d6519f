// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The lesson's page in the dock's column, above its questions: the lesson's title and its
// introduction, which folds away, the step's count beside a progress bar, its title and its
// text; with no lesson open, the start page. Its widgets go into the lesson player's column in
// two parts (the student's fields and the start button sit between them), as a form that uic
// makes sets itself up in a widget.

#include "format/lesson.h"

#include <QObject>

class QLabel;
class QProgressBar;
class QToolButton;
class QVBoxLayout;

namespace rigidlab::ui {

class StepText;

class StepPage : public QObject {
    Q_OBJECT
public:
    /// Makes the widgets, children of `column`.
    explicit StepPage(QWidget* column);

    /// The lesson's title and its introduction, added to `layout`.
    void addHead(QVBoxLayout* layout);
    /// The step's count and progress, its title and its text, added to `layout`.
    void addStep(QVBoxLayout* layout);

    /// Shows step `step` of `lesson` (its introduction on the first step only).
    void showStep(const lessons::Lesson& lesson, int step);
    /// The start page: what RigidLab is, and the first lesson's line of the list
    /// (`firstLesson`; empty: none).
    void showStart(const QString& firstLesson);
    /// Tells a screen reader the step shown (its number, title and first sentence) and puts
    /// the focus on its text.
    void announceStep(const lessons::Lesson& lesson, int step);
    /// A lesson opened: the introduction folds by itself again until the reader folds it.
    void forgetReadersChoice() { m_aboutChosen = false; }
    /// Folds the introduction away when it would leave the step's text less than `textShare`
    /// of the column's `height` [px] at `width` [px], `above` being taken above the lesson's
    /// title [px] and `spacing` between the column's widgets [px] (unless the reader folded or
    /// opened it by hand).
    void fitIntroduction(int height, int width, int above, int spacing, double textShare);

    StepText* text() const { return m_text; }
    /// The step's count, where a step is read from.
    QWidget* stepCount() const;
    bool introductionShown() const;

private:
    QWidget* m_column;
    QLabel* m_title;
    QToolButton* m_aboutToggle; ///< folds the introduction (m_about) away
    QLabel* m_about;
    bool m_aboutChosen = false; ///< the reader folded or opened the introduction by hand
    bool m_firstStep = true;    ///< the step shown is the lesson's first (or none is open)
    QProgressBar* m_progress;
    QLabel* m_stepCount; ///< "Step 2 of 4", beside the progress bar
    QLabel* m_stepTitle;
    StepText* m_text;
};

} // namespace rigidlab::ui
