// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What a kind of question shows in the window, each kind in its own file here (listed in
// question_kinds/question_kinds.h, as lessons/format/question_kinds.h lists the kinds). Beside
// a kind K's struct, its file has these, found by its type:
//
//   answerRow(const K&, prompt, layout, hooks)   the lesson player's answer row under the
//                                                question's prompt (an AnswerRow)
//   worksheetLines(const K&, const SheetQuestion&)   its lines on the worksheet under the prompt
//   kindTitle(std::type_identity<K>)             its name in the lesson editor's list of kinds
//   newKindKeys(std::type_identity<K>, scene)    the keys a question gets on becoming one
//   editorPage(std::type_identity<K>, parent)    its fields in the lesson editor (a KindPage)
//   answerLine(const K&, step, question)         the editor's line under it: its right answer
//
// The worksheet and the lesson editor visit a question's kind once and call these, drawing no
// kind themselves: a kind missing one of them does not compile there.

#include "common/number_format.h"

#include "format/answers_file.h"
#include "format/lesson.h"
#include "format/verdict.h"

#include <QJsonObject>
#include <QString>
#include <QWidget>

#include <functional>
#include <optional>
#include <span>

class QButtonGroup;
class QLabel;
class QLineEdit;
class QPushButton;
class QVBoxLayout;

namespace rigidlab::ui {

/// Which worksheet is written: a student's, handed in; one to fill in by hand; the key.
enum class WorksheetKind { Answers, Empty, Key };

/// A question's answer row in the lesson player, as its kind builds it: the parts the player
/// reads (the typed text or the option chosen, kept with the student's work) and marks (the
/// verdict; Show me, off once the answer is given).
struct AnswerRow {
    QLineEdit* edit = nullptr;       ///< the box a number is typed in
    QButtonGroup* choices = nullptr; ///< the options, by their index
    QPushButton* check = nullptr;
    QPushButton* show = nullptr; ///< Show me
    QLabel* result = nullptr;    ///< the verdict, hidden until the first try
};

/// What a kind's answer row asks of the player.
struct RowHooks {
    /// Judges a try at the question: its verdict shown, what it releases released.
    std::function<void(const lessons::AnswerTry&)> judge;
    /// The number typed in the row's box; nullopt when it is not one (said under it).
    std::function<std::optional<double>()> typedNumber;
};

/// The row of a kind answered by typing a number: the box with its `unit` on a line of its own
/// (the buttons beside it left it a few letters wide in a narrow column), Check and Show me
/// below (`showTip`: what Show me gives), then the verdict's line, under `prompt` in `layout`.
/// Check and Return in the box are the kind's to connect.
AnswerRow typedNumberRow(QLabel* prompt, QVBoxLayout* layout, const QString& unit,
                         const QString& showTip);

/// A question as the worksheet writes it: the sheet, and what a kind's lines may read besides
/// the question's own kind (the measured kind's key runs its step). The worksheet gives all of
/// it; a test of a kind that reads only `sheet` may give only that.
struct SheetQuestion {
    WorksheetKind sheet = WorksheetKind::Empty;
    const lessons::LessonStep* step = nullptr;   ///< the step it is asked in, as it ran
    const lessons::Question* question = nullptr; ///< the question whole (its prompt, its kind)
    std::span<const lessons::AnswerTry> tries;   ///< the student's tries at it, in order
    std::span<const lessons::Verdict> verdicts;  ///< the tries judged again, one per try
};

/// `value` in `unit` as the worksheet writes an answer or a measured value (the plain number
/// where there is no unit).
inline QString sheetQuantity(double value, const QString& unit)
{
    return unit.isEmpty() ? formatReadable(value) : formatQuantity(value, unit);
}

/// A line a kind writes on the worksheet under its question's prompt.
struct SheetLine {
    enum class Is {
        Text,        ///< `text`, in the sheet's font
        Bold,        ///< `text`, bold
        WritingLine, ///< a line to write on by hand
        Tries,       ///< the student's tries with their verdicts, a typed answer in `text`
    };
    Is is = Is::Text;
    QString text;
};

/// A kind's fields in the lesson editor, under every question's: shown for a question of its
/// kind, read back into the question's JSON on every change.
class KindPage : public QWidget {
public:
    using QWidget::QWidget;
    /// Shows the fields of question `q`, as the lesson's JSON holds it, asked in a step of
    /// `scene` (the step's scene as the JSON holds it, read even while the lesson has an error).
    virtual void showQuestion(const QJsonObject& q, const QJsonObject& scene) = 0;
    /// Writes its fields into `q`.
    virtual void applyTo(QJsonObject& q) const = 0;
    /// Called on each change the teacher makes in it (set by the editor).
    std::function<void()> edited;
};

/// The lesson editor's line under a question: what its right answer is, and the line's name
/// for a screen reader.
struct AnswerLine {
    QString name;
    QString text;
};

} // namespace rigidlab::ui
