// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The lesson editor's questions of one step: a list of them, buttons to add a measured
// question or a predict-before-reveal one (which holds the run back until answered) and to
// remove one, and the selected one's prompt and hint in each language (one is enough), its
// kind (a number measured from the run, or a choice), and for a number what is measured (the
// quantity, the body by its label, the time; the prompt the editor wrote follows them), its
// unit and tolerance, and beside them the answer the lab measures for it (the same headless
// run the player judges against); for a choice, its options (choice_editor.h).

#include "lesson_editor/editor_parts.h"

#include "format/lesson.h"

#include <QJsonObject>
#include <QList>
#include <QWidget>

#include <array>
#include <cstddef>
#include <utility>
#include <vector>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
class QLabel;
class QLineEdit;
class QListWidget;

namespace rigidlab::ui {

class ChoiceEditor;
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
    /// measured number, a choice), one edit.
    void setKind(std::size_t kind);

private:
    QFormLayout* buildForm();
    /// The question's kind in `form`: its chooser, the options of a choice and the page of each
    /// kind of ui/question_kinds/ (the measured kind's fields are the form's own rows), each
    /// shown for a question of its kind.
    void addKindRows(QFormLayout* form);
    /// A field per language in `form`, named `name`_CODE, labelled `label` with the language.
    void addLanguageFields(QFormLayout* form, const QString& name, const QString& label,
                           std::array<QLineEdit*, kEditorLanguages>& fields);
    QJsonObject question() const;
    /// Replaces the selected question by `q`, one undoable edit.
    void store(const QJsonObject& q);
    void edited();
    /// The measured question's fields into `q`: what is measured, its unit and tolerance.
    void applyMeasured(QJsonObject& q);
    /// A measured question, of speed at 1 s of the scene's first body that moves.
    QJsonObject defaultMeasured() const;
    /// A choice question's keys, of two options, the first right.
    QJsonObject defaultChoice() const;
    /// The prompt of `q` rewritten for its measure when it is still the one the editor wrote
    /// for `before`'s.
    void followMeasure(const QJsonObject& before, QJsonObject& q) const;
    /// The step's bodies that move: (id, label or id), in the scene's order.
    QList<std::pair<QString, QString>> movingBodies() const;
    /// A body's label (its id where it has none).
    QString bodyName(const QString& id) const;
    /// Under the question, what the lab measures for it or which option is right.
    void showAnswer();
    void showMeasured(const lessons::LessonStep& step, const lessons::Question& question,
                      const lessons::MeasuredQuestion& q);

    LessonDraft& m_draft;
    int m_step = -1;
    bool m_refreshing = false;
    QListWidget* m_list = nullptr;
    std::array<QLineEdit*, kEditorLanguages> m_prompt{};
    std::array<QLineEdit*, kEditorLanguages> m_hint{};
    QComboBox* m_questionKind = nullptr; ///< a number measured from the run, or a choice
    ChoiceEditor* m_choices = nullptr;
    /// The page of each kind of ui/question_kinds/, by its index in lessons::QuestionKind; null
    /// for the measured and the choice kind, whose fields are the form's own rows.
    std::vector<KindPage*> m_pages;
    QFormLayout* m_fields = nullptr; ///< the selected question's form
    QComboBox* m_kind = nullptr;
    QComboBox* m_body = nullptr;
    QDoubleSpinBox* m_time = nullptr;
    QLineEdit* m_unit = nullptr;
    QDoubleSpinBox* m_tolerance = nullptr;
    QCheckBox* m_holdRun = nullptr;
    QuestionSetEditor* m_set = nullptr; ///< what the student sets first

    QLabel* m_answer = nullptr;
    QWidget* m_form = nullptr; ///< the selected question's fields
    QJsonObject m_measuredFor; ///< what the answer shown was measured for
};

} // namespace rigidlab::ui
