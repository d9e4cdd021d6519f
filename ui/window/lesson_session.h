// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A lesson in the window: opening one, showing what each step names (its worlds, panels,
// plots, overlays, editor tools), holding back what its questions hide, leaving it, and
// exporting the step's plots. The lesson's text and questions are the player's
// (lesson_player/); this is what the rest of the window does for it.

#include <QList>
#include <QObject>
#include <QString>
#include <QStringList>

#include <array>
#include <vector>

class QDockWidget;
class QMainWindow;

namespace rigidlab::lessons {
struct Lesson;
struct LessonStep;
struct Scene;
} // namespace rigidlab::lessons

namespace rigidlab::ui {

class BouncePanel;
class CollisionPanel;
class ControlPanel;
class EditTools;
class LessonPlayer;
class PlotTurns;
class PlotWidget;
class SatPanel;
class SceneDocument;
class SimulationController;
class WindowActions;
class WindowDocuments;
class WindowLayout;
class WorldView;

class LessonSession : public QObject {
    Q_OBJECT
public:
    /// The parts of the window a lesson step sets up.
    struct Parts {
        QMainWindow& window;
        LessonPlayer& player;
        SimulationController& controller;
        SceneDocument& document;
        WindowDocuments& documents;
        EditTools& editTools;
        WindowLayout& layout;
        WindowActions& actions;
        WorldView& view;
        ControlPanel& controls;
        SatPanel& sat;
        BouncePanel& bounces;
        CollisionPanel& collision;
        QList<PlotWidget*> plots; ///< the window's own, each named by its row (plot_table.h)
        PlotTurns& plotTurns;     ///< the run's plots take turns to drain after its frames
    };
    explicit LessonSession(const Parts& parts);

    /// Opens a lesson at its first step; returns the error, empty on success.
    QString openLesson(const QString& path, bool quiet);
    void openLessonDialog();
    /// File › Lessons › Add a folder of lessons: a folder (a shared drive, say) whose lessons
    /// are listed from now on after the user's own (lessons::addLessonFolder).
    void addLessonFolderDialog();
    /// Adds `folder` to the listed ones and lists the lessons again.
    void addLessonFolder(const QString& folder);
    /// File › Lessons › Stop listing a folder: its lessons are no longer listed (the folder
    /// and its files stay as they are).
    void removeLessonFolder(const QString& folder);
    bool inLesson() const { return m_inLesson; }
    /// A question keeps the scene from running until it is answered.
    bool runHeld() const { return m_runHeld; }
    /// A lesson step is starting the document over: it loads its own worlds.
    bool loading() const { return m_loading; }
    /// Every plot comparing worlds in this step, in the order the step names them.
    const std::vector<PlotWidget*>& comparePlots() const { return m_comparePlots; }
    /// Writes the current step's plots (PNG, PDF, SVG, CSV) into a folder; returns errors.
    QStringList exportStepPlots(const QString& folder);
    /// The document changed (an edit, undo): the step's worlds, built from the scene as edited.
    void reloadStepWorlds();
    /// Edit mode on or off, in a lesson step: its worlds come back, built from the scene as
    /// edited, and leaving Edit mode runs them.
    void followEditing(bool editing);

signals:
    /// Whether a question holds the run back changed.
    void runHeldChanged(bool held);
    /// The lesson was left: the window shows the scene's title again.
    void left();

private:
    void applyStep(const lessons::Lesson& lesson, int index);
    /// Why the run paused by itself (a body off the stage, the step's end time): in the status
    /// bar and told to a screen reader.
    void tellPause(const QString& why);
    void frameStepAction(const lessons::LessonStep& step);
    /// The step's docks shown, grouped and in their columns, the window's size kept.
    void showStepDocks(const lessons::LessonStep& step, const QStringList& labels);
    /// The step's docks shown and every other hidden, grouped by kind, its first ones raised.
    void showOnlyStepDocks(const lessons::LessonStep& step, const QStringList& labels);
    void makeComparePlots(const lessons::LessonStep& step);
    void showStepOverlays(const lessons::LessonStep& step);
    void leave();
    void exportDialog();
    /// Hides what the step's questions still hold back, shows what they released.
    void applyHeldBack(const QStringList& held);
    QStringList loadStepWorlds(const lessons::LessonStep& step, const lessons::Scene& scene,
                               const QString& path);
    const lessons::LessonStep* currentStep() const;

    Parts m_parts;
    bool m_inLesson = false;
    bool m_runHeld = false;
    bool m_loading = false;
    std::vector<PlotWidget*> m_comparePlots; ///< in the layout's compare dock
};

} // namespace rigidlab::ui
