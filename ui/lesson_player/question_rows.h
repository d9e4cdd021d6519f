// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The step's questions as the student answers them: each prompt with the answer row its kind
// builds (ui/question_kinds/), and the verdicts under them. It only shows: what a row hands in
// goes to the hooks it was built with, and the verdicts come from the lesson player.

#include "question_kinds/kind_ui.h"

#include "format/lesson.h"
#include "format/verdict.h"

#include <QStringList>
#include <QWidget>

#include <cstddef>
#include <functional>
#include <optional>
#include <vector>

class QVBoxLayout;

namespace rigidlab::ui {

class QuestionRows : public QWidget {
    Q_OBJECT
public:
    explicit QuestionRows(QWidget* parent = nullptr);

    /// Shows `questions` (none: empty), question i's row handing in to `hooks(i)`.
    void build(const std::vector<lessons::Question>& questions,
               const std::function<RowHooks(std::size_t)>& hooks);
    std::size_t count() const { return m_rows.size(); }

    /// The number typed in question i's box, checked; nullopt when it is none (said under it).
    std::optional<double> typedNumber(std::size_t i);
    /// Says under question i what to do before it can be judged; nothing is counted.
    void askFirst(std::size_t i, const QString& text);
    /// Shows `verdict` on `attempt` under question i and scrolls it into sight; `tell`: a
    /// screen reader is told it too.
    void showVerdict(std::size_t i, const lessons::Verdict& verdict,
                     const lessons::AnswerTry& attempt, bool tell);
    /// Question i's value has been given: its Show me is off.
    void setGiven(std::size_t i);
    /// Per question, what its box holds, or the option chosen by its index.
    QStringList typed() const;
    /// Fills question i's box, or chooses its option (by index) as typed() gave it.
    void setTyped(std::size_t i, const QString& typed);
    /// The rows' widgets that Tab reaches, in the order shown.
    QList<QWidget*> tabStops() const;
    /// The first answer that can be given now, where Tab puts the focus in it: a question's box,
    /// or its option chosen (else its first); null when every row is shut or there is none.
    QWidget* firstAnswer() const;

    /// What a student does (for tests): types `text` in question i's box and presses Return;
    /// chooses `option` and presses Check; presses Show me. And question i's verdict line.
    void answer(int question, const QString& text);
    void choose(int question, int option);
    void showMe(int question);
    QString result(int question) const;

private:
    /// Row `question`, if there is one.
    const AnswerRow* row(int question) const;
    /// Scrolls question i's verdict into sight in the area the questions are shown in.
    void revealResult(std::size_t i);

    QVBoxLayout* m_layout;
    std::vector<AnswerRow> m_rows;
};

} // namespace rigidlab::ui
