// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The lesson editor's window: the lesson's title, summary, level and minutes; its steps in a
// list (each marked with what is wrong in it) with buttons to add, remove, move and duplicate
// them; the selected step's title and text in each language side by side (the window's first),
// each with the text as the player shows it and a quiet mark where a language is missing (the
// student then reads the text in the language it has). Everything it shows is
// read back from its LessonDraft and every change is one of the draft's undoable edits, so
// the window's Undo and Redo are the draft's own. It saves .rlesson files and, while the
// lesson has unsaved edits, writes a copy of it now and then (the autosave a crash leaves):
// a file of its own, held by a lock file while the editor is open, so that two editors never
// write over each other and a crash's autosave is told from a live one.

#include "question_kinds/editor_parts.h"
#include "lesson_editor/lesson_draft.h"

#include <QWidget>

#include <array>
#include <memory>

class QAction;
class QGridLayout;
class QLabel;
class QLineEdit;
class QListWidget;
class QLockFile;
class QPlainTextEdit;
class QPushButton;
class QSpinBox;
class QTimer;

namespace rigidlab::ui {

class QuestionEditor;
class StepChecks;
class StepSettingsEditor;
class StepText;

class LessonEditor : public QWidget {
    Q_OBJECT
public:
    explicit LessonEditor(QWidget* parent = nullptr);
    ~LessonEditor() override;

    LessonDraft& draft() { return m_draft; }
    /// Opens a lesson file; returns the loader's error (empty when it opened).
    QString open(const QString& path);
    /// A new lesson with one step on `scene`.
    void newLesson(const lessons::Scene& scene);
    /// The autosave at `path` that a crash left, opened as unsaved work (LessonDraft::openKept);
    /// this editor's autosave from now on, removed once the lesson is saved or discarded.
    QString openKept(const QString& path);

    int currentStep() const;
    QuestionEditor& questions() { return *m_questions; }
    StepSettingsEditor& stepSettings() { return *m_settings; }
    /// The checks that run the steps' scenes (divergence, integrators' spread), in a worker.
    StepChecks& stepChecks() { return *m_checks; }
    void selectStep(int index);

    /// Save: to the lesson's file, or asks where when it has none. Returns the error.
    QString save();
    /// Save As to `path` (.rlesson). Returns the error.
    QString saveAs(const QString& path);
    /// Where Save As first offers to save a new lesson: a file named after its title in the
    /// teacher's own lessons folder (so that the window lists it), not over another one.
    QString defaultSavePath() const;
    /// A new editor's autosave: a file of its own in the lab's data folder.
    static QString newAutosavePath();
    /// The autosaves that no open editor (of any running lab) holds, newest first: what
    /// crashes left.
    static QStringList keptLessons();
    /// Where the autosave goes (the lab's data folder unless a test says otherwise).
    void setAutosavePath(const QString& path) { m_autosavePath = path; }
    const QString& autosavePath() const { return m_autosavePath; }
    /// Writes the autosave now when there are unsaved edits; returns whether it wrote one.
    /// It stays after a crash, and is removed when the lesson is saved or its edits discarded.
    bool autosave();

signals:
    /// Try as a student: play the lesson saved at `path` from `step`.
    void tryAsStudent(const QString& path, int step);
    /// Edit the step's scene in the window's scene editor.
    void editStepScene(const lessons::Scene& scene);
    /// The scene open in the window, please, for `step` (LessonDraft::setStepScene).
    void stepSceneWanted(int step);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;
    void closeEvent(QCloseEvent* event) override;

private:
    void buildLessonFields(QGridLayout& grid);
    QWidget* buildStepList();
    QWidget* buildStepTexts();
    void buildActions();
    QPushButton* makeButton(const QString& text, const QString& name, const QKeySequence& keys,
                            void (LessonEditor::*slot)());
    void addStep();
    void removeStep();
    void moveUp();
    void moveDown();
    void duplicateStep();
    void saveAsDialog();
    void trySelected();
    void sendStepScene();
    void refresh();
    void refreshLesson();
    void refreshSteps();
    void refreshStepTexts();
    void updateTitle();
    /// What the step list says after a step's title: its missing languages and problems.
    QString stepMarks(int index, const LessonDraft::Check& check,
                      const QStringList& runLines) const;
    /// The steps' runs checked again (in the worker) when what they depend on changed.
    void checkRuns();
    void textEdited(int step, const QString& key, int language, const QString& text);

    LessonDraft m_draft;
    bool m_refreshing = false;
    std::array<QLineEdit*, kEditorLanguages> m_title{};
    std::array<QLineEdit*, kEditorLanguages> m_summary{};
    std::array<QLineEdit*, kEditorLanguages> m_level{};
    QSpinBox* m_minutes = nullptr;
    QListWidget* m_steps = nullptr;
    std::array<QLineEdit*, kEditorLanguages> m_stepTitle{};
    std::array<QPlainTextEdit*, kEditorLanguages> m_stepText{};
    std::array<QLabel*, kEditorLanguages> m_missing{};
    std::array<StepText*, kEditorLanguages> m_preview{};
    QLabel* m_problems = nullptr;
    QuestionEditor* m_questions = nullptr;
    StepSettingsEditor* m_settings = nullptr;
    StepChecks* m_checks = nullptr;
    QAction* m_undo = nullptr;
    QAction* m_redo = nullptr;
    QTimer* m_autosaveTimer = nullptr;
    QString m_autosavePath;
    /// Held while the file at m_autosavePath is this editor's (to write, and to remove).
    std::unique_ptr<QLockFile> m_autosaveLock;
    /// Takes the lock on m_autosavePath: the file is this editor's from now on.
    void lockAutosave();
    /// Removes this editor's autosave, if it has one, and lets go of its lock.
    void discardAutosave();
};

} // namespace rigidlab::ui
