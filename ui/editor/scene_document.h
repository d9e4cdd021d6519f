// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The scene being edited: its description, the file it came from and its history of edits.
// Every edit replaces the whole scene by an edited copy, so undoing all of them gives back the
// scene as it was opened, bit for bit, and nothing in the editor touches a world directly: the
// window rebuilds its world from scene() whenever sceneChanged() is emitted.

#include "format/scene.h"

#include <QObject>
#include <QRectF>
#include <QString>

class QUndoStack;

namespace rigidlab::ui {

class SceneDocument : public QObject {
    Q_OBJECT
public:
    explicit SceneDocument(QObject* parent = nullptr);

    const lessons::Scene& scene() const { return m_scene; }
    /// The file the scene was opened from or last saved to; empty for a new scene.
    const QString& path() const { return m_path; }
    /// Edited since it was opened or last saved.
    bool isModified() const;
    QUndoStack* undoStack() const { return m_undo; }

    /// Starts over with this scene (opened from path, or a new one when path is empty): the
    /// history is cleared and the document counts as unmodified.
    void reset(const lessons::Scene& scene, const QString& path);
    /// An undoable edit named `what` (Edit › Undo "what", the History view) that replaces the
    /// scene by `edited`. Consecutive edits with the same mergeId >= 0 (one mouse drag, one
    /// field being typed into) merge into a single step of the history.
    void apply(const QString& what, const lessons::Scene& edited, int mergeId = -1);
    /// After a save to path: remembers the path and marks the present state as saved.
    void markSaved(const QString& path);

    /// A new scene titled `title`: the default world (physics::WorldDef) and a long static
    /// ground, its top at y = 0 and kNewGroundLength long, so that a cart pushed at a few m/s
    /// from the middle rolls for seconds before it reaches an end.
    static lessons::Scene newScene(const QString& title);
    /// The length of a new scene's ground [m].
    static constexpr double kNewGroundLength = 40.0;
    /// What the view shows of a new scene first [m]: the middle of its ground and room above
    /// it, at a zoom that draws on a 1 m grid or so (the whole ground would make it coarse).
    static QRectF newSceneFrame();

signals:
    /// After every apply, undo, redo and reset.
    void sceneChanged();
    /// reset(): another scene (a file, a new one, a lesson's step) starts over; emitted just
    /// before its sceneChanged.
    void sceneReset();
    void modifiedChanged(bool modified);
    void pathChanged(const QString& path);

private:
    friend class SceneEditCommand;
    void setScene(const lessons::Scene& scene);

    lessons::Scene m_scene;
    QString m_path;
    QUndoStack* m_undo = nullptr;
};

} // namespace rigidlab::ui
