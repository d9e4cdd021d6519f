// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The lesson editor's questions of one step: a list of them, buttons to add a measured
// question or a predict-before-reveal one (which holds the run back until answered) and to
// remove one, and the selected one's prompt and hint in each language (one is enough), its
// kind, the page of its kind (ui/question_kinds/: what is measured, the options of a choice…),
// what the student sets first where its kind has that, and under them the kind's line of the
// right answer (for a measured one, what the same headless run the player judges against
// measures).

#include "question_kinds/editor_parts.h"

#include "format/lesson.h"

#include <QJsonObject>
#include <QWidget>

#include <array>
#include <cstddef>
#include <vector>

class QCheckBox;
class QComboBox;
class QFormLayout;
class QLabel;
class QLineEdit;
class QListWidget;

namespace rigidlab::ui {

class KindPage;
class LessonDraft;
class QuestionSetEditor;

class QuestionEditor : public QWidget {
    Q_OBJECT
public:
    QuestionEditor(LessonDraft& draft, QWidget* parent = nullptr);

    /// Shows the questions of `step` (-1: none).
    void setStep(int step);
    /// Reads the step's questions back from the draft (after any edit, undo or redo).
    void refresh();
    int currentQuestion() const;
    void addQuestion(bool predict);
    void removeQuestion();
    /// Makes the selected question one of the kind at `kind` in lessons::Question::kind (a
    /// measured number, a choice…), one edit.
    void setKind(std::size_t kind);

private:
    QFormLayout* buildForm();
    /// The question's kind in `form`: its chooser and the page of each kind of
    /// ui/question_kinds/, each shown for a question of its kind.
    void addKindRows(QFormLayout* form);
    /// A field per language in `form`, named `name`_CODE, labelled `label` with the language.
    void addLanguageFields(QFormLayout* form, const QString& name, const QString& label,
                           std::array<QLineEdit*, kEditorLanguages>& fields);
    QJsonObject question() const;
    /// Replaces the selected question by `q`, one undoable edit.
    void store(const QJsonObject& q);
    void edited();
    /// Under the question, its kind's line of the right answer.
    void showAnswer();

    LessonDraft& m_draft;
    int m_step = -1;
    bool m_refreshing = false;
    QListWidget* m_list = nullptr;
    std::array<QLineEdit*, kEditorLanguages> m_prompt{};
    std::array<QLineEdit*, kEditorLanguages> m_hint{};
    QComboBox* m_questionKind = nullptr; ///< a number measured from the run, a choice…
    /// The page of each kind of ui/question_kinds/, by its index in lessons::QuestionKind.
    std::vector<KindPage*> m_pages;
    QFormLayout* m_fields = nullptr; ///< the selected question's form
    QCheckBox* m_holdRun = nullptr;
    QuestionSetEditor* m_set = nullptr; ///< what the student sets first

    QLabel* m_answer = nullptr;
    QWidget* m_form = nullptr; ///< the selected question's fields
    QJsonObject m_measuredFor; ///< what the answer shown was measured for
};

} // namespace rigidlab::ui
