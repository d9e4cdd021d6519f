// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The lesson's buttons below its questions: Back, Next, Restart step, Export plots and Hand in,
// two a row, so that they fit the narrow column of a 1024-pixel projector.

#include <QList>
#include <QWidget>

class QPushButton;

namespace rigidlab::ui {

class StepButtons : public QWidget {
    Q_OBJECT
public:
    explicit StepButtons(QWidget* parent = nullptr);

    /// What they offer on step `step` of `steps` (`plots`: the step has plots to export); with
    /// no lesson (`steps` 0), they are hidden.
    void showStep(int step, int steps, bool plots);
    /// The buttons in the order they are shown, for Tab.
    QList<QWidget*> tabStops() const;

signals:
    void backClicked();
    void nextClicked();
    void restartClicked();
    void exportClicked();
    void handInClicked();

private:
    QPushButton* m_back;
    QPushButton* m_restart;
    QPushButton* m_next;
    QPushButton* m_export;
    QPushButton* m_handIn;
};

} // namespace rigidlab::ui
