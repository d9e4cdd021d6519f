// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What a question asks the student to set before the run it measures (its "set",
// LESSON_FORMAT.md): a setting chosen from the step's settings (by the scene format's own rows
// and labels) and its value, a number field or a list as the setting needs. "Nothing" leaves
// the question on the step's own settings. Settings the file gives beyond the one shown are
// kept as they are.

#include <QJsonObject>
#include <QWidget>

class QComboBox;
class QStackedWidget;

namespace rigidlab::ui {

class NumberField;

class QuestionSetEditor : public QWidget {
    Q_OBJECT
public:
    explicit QuestionSetEditor(QWidget* parent = nullptr);

    /// Shows a question's "set" (an empty object: nothing).
    void show(const QJsonObject& set);
    /// The "set" as edited (an empty object: nothing).
    QJsonObject value() const { return m_set; }

signals:
    /// The teacher changed it.
    void edited();

private:
    void choose();
    void valueChosen();

    QJsonObject m_set;
    QComboBox* m_key = nullptr;
    QStackedWidget* m_pages = nullptr;
    NumberField* m_number = nullptr;
    QComboBox* m_choice = nullptr;
    bool m_showing = false;
};

} // namespace rigidlab::ui
