// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The lesson editor's options of a choice question (lessons/LESSON_FORMAT.md, "A choice
// question"), the page of its kind (choice.h): a table of the options' texts, Czech and English
// side by side, buttons to add, remove and reorder them, and the right one chosen from a list.
// It edits the question's JSON only; the question editor stores each change as one undoable
// edit of the draft.

#include <QJsonObject>
#include <QWidget>

class QComboBox;
class QPushButton;
class QTableWidget;

namespace rigidlab::ui {

class ChoiceEditor : public QWidget {
    Q_OBJECT
public:
    explicit ChoiceEditor(QWidget* parent = nullptr);

    /// Shows the options and the right one of the choice question `q`.
    void setQuestion(const QJsonObject& q);
    /// `q` with the options and the right one as they are shown.
    QJsonObject applyTo(QJsonObject q) const;

    /// The name a new option gets, "Option N" (1-based) in the window's language.
    static QString optionName(int n);
    /// Adds an option after the last one, named "Option N" in `language`.
    void addOption(const QString& language);
    /// Removes the selected option (a question keeps at least two).
    void removeOption();
    /// Moves the selected option up (-1) or down (+1); the right answer moves with it.
    void moveOption(int by);

    QTableWidget* table() const { return m_table; }

signals:
    /// The teacher changed an option, their order or the right one: applyTo() has it.
    void edited();

private:
    /// The options as the table shows them, each an object of the languages written.
    QJsonArray options() const;
    void showOptions(const QJsonArray& options, int right);
    void showButtons();

    QTableWidget* m_table = nullptr;
    QComboBox* m_right = nullptr;
    QPushButton* m_add = nullptr;
    QPushButton* m_remove = nullptr;
    QPushButton* m_up = nullptr;
    QPushButton* m_down = nullptr;
    bool m_showing = false;
};

} // namespace rigidlab::ui
