// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The list of lessons above the lesson: each by its number and short title, its whole menu line
// ("1. Title — description (≈N min)") in the open list and the tooltip. The arrow keys on the
// closed list open it rather than open each lesson they pass.

#include "format/lesson_catalog.h"

#include <QComboBox>
#include <QStringList>

#include <vector>

namespace rigidlab::ui {

class LessonList : public QComboBox {
    Q_OBJECT
public:
    explicit LessonList(QWidget* parent = nullptr);

    /// Lists these lessons, numbered in the order given, after "Choose a lesson…".
    void setLessons(const std::vector<lessons::LessonEntry>& entries);
    QStringList paths() const { return m_paths; }
    /// Per paths() entry, its menu line.
    QStringList menuTexts() const { return m_menuTexts; }
    /// The short line of the lesson at `path` ("1. Energy drift"); empty when it is not listed.
    QString shortText(const QString& path) const;
    /// Shows the lesson at `path` as the one chosen, when it is listed.
    void showChosen(const QString& path);
    /// Shows "Choose a lesson…".
    void showNone() { setCurrentIndex(0); }

signals:
    /// The student chose the lesson at `path`, or "Choose a lesson…" (empty).
    void lessonChosen(const QString& path);

protected:
    void keyPressEvent(QKeyEvent* event) override;

private:
    /// The tooltip: the chosen lesson's whole line, and what the list holds.
    void showCurrentTip();

    QStringList m_paths;
    QStringList m_menuTexts;
};

} // namespace rigidlab::ui
