// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The lesson editor test's class, in two files: test_lesson_editor.cpp (the lesson as data,
// shipped lessons) and test_lesson_editor_widgets.cpp (the editor's window, keys and mouse).

#include "build_paths.h"
#include "common/language.h"
#include "editor/edit_tools.h"
#include "editor/scene_document.h"
#include "lesson_editor/lesson_draft.h"
#include "lesson_editor/lesson_editor.h"
#include "lesson_editor/question_editor.h"
#include "lesson_editor/step_checks.h"
#include "lesson_editor/step_settings_editor.h"
#include "lesson_player/lesson_player.h"
#include "mnemonics.h"
#include "near.h"
#include "plots/lesson_export.h"
#include "shipped_lessons.h"
#include "test_files.h"
#include "window/main_window.h"
#include "window/screenshots.h"

#include "format/lesson_pack.h"
#include "format/scene_compare.h"
#include "format/scene_loader.h"

#include <QAbstractButton>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QPointer>
#include <QPushButton>
#include <QSpinBox>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTimer>
#include <QToolBar>
#include <QToolButton>
#include <QUndoStack>
#include <QtTest>

#include <memory>

using namespace rigidlab;
using rigidlab::test::filesUnder;
using rigidlab::test::readAll;
using rigidlab::test::writeFile;
using rigidlab::ui::LessonDraft;

/// The source tree (its lessons and scenes).
inline const QString kSource = rigidlab::test::sourcePath();

class TestLessonEditor : public QObject {
    Q_OBJECT
private slots:
    // In order, on one lesson, as a teacher writes it.
    void initTestCase();
    void newLessonWithSteps();
    void missingTranslationMarked();
    void questionsLocksAndChecks();
    void undoAndRedo();
    void savedAndReopened();
    void playsAsAStudent();
    void samePlotsAsByHand();
    // The editor's window, driven with keys and mouse.
    void widgetsTextsAndSteps();
    void widgetsUndoSaveAndTry();
    void widgetsShownAndLocked();
    void widgetsStepSceneFromTheWindow();
    void widgetsQuestions();
    void screenshotOfTheEditor();
    void editorMnemonicsAreUnique_data();
    void editorMnemonicsAreUnique();
    void lettersStayInListsAndFields_data();
    void lettersStayInListsAndFields();
    void spinBoxesAndScrollAreasNamed();
    void keptLessonAfterACrash();
    void windowClosingAsksTheEditor();
    // The checks that run the steps, in a worker (they wait on its signal, which lets the
    // window activate another window: after the tests that type into the editor).
    void toleranceTighterThanIntegrators();
    void stepThatDivergesIsMarked();
    void staleStepChecksDropped();
    void cancelledStepChecksLeaveNoWarning();
    void tryAndBackToTheEditor();
    void questionAsksTheStudentToSet();
    void teachersOwnStep();
    void teachersOwnQuestion();
    // Shipped lessons.
    void shippedLessonsOpenAndSaveUnchanged_data();
    void shippedLessonsOpenAndSaveUnchanged();

private:
    QTemporaryDir m_dir;
    QString m_saved; ///< where the lesson is saved
    LessonDraft m_draft;
    std::unique_ptr<ui::MainWindow> m_window; ///< the window the editor's widgets are in
    ui::LessonEditor* m_editor = nullptr;
};
