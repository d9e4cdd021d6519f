// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The lesson editor's page for what a step shows and lets the student change: its plots and
// panels (the step's "plots" and "panels"), the controls the student may change (its "allow":
// an unticked control is locked), the simulated time at which its plots are exported
// ("exportTime"), the time its run stops at ("endTime") and whether it waits for Play
// ("autoplay": false). Each tick or value is one undoable edit of the draft; what is shown is read
// back from it, so undo and redo show here too.

#include <QStringList>
#include <QWidget>

#include <string_view>
#include <vector>

class QCheckBox;
class QDoubleSpinBox;
class QGroupBox;

namespace rigidlab::ui {

class LessonDraft;

class StepSettingsEditor : public QWidget {
    Q_OBJECT
public:
    StepSettingsEditor(LessonDraft& draft, QWidget* parent = nullptr);

    /// Shows the settings of `step` (-1: none).
    void setStep(int step);
    /// Reads the step back from the draft (after any edit, undo or redo).
    void refresh();
    /// The tick box of a plot, panel or control by its name in the file ("energy", "sat",
    /// "dt"); null for an unknown name.
    QCheckBox* box(const QString& key, const QString& name) const;
    QCheckBox* waitForPlay() const { return m_waitForPlay; }
    QDoubleSpinBox* endTime() const { return m_endTime; }

private:
    struct Row {
        QString key;  ///< "plots", "panels" or "allow"
        QString name; ///< the name in the file
        QCheckBox* box = nullptr;
    };
    QGroupBox* group(const QString& title, const QString& key,
                     const std::vector<std::pair<std::string_view, QString>>& names);
    void ticked(const QString& key);

    LessonDraft& m_draft;
    int m_step = -1;
    bool m_refreshing = false;
    std::vector<Row> m_rows;
    QDoubleSpinBox* m_exportTime = nullptr;
    QDoubleSpinBox* m_endTime = nullptr; ///< 0: the run goes on
    QCheckBox* m_waitForPlay = nullptr;
};

} // namespace rigidlab::ui
