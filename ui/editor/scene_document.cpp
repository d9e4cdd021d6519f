// SPDX-License-Identifier: GPL-3.0-or-later
#include "editor/scene_document.h"

#include "rigidlab/physics/shape.h"

#include <QUndoCommand>
#include <QUndoStack>

namespace rigidlab::ui {

/// One edit: the scene before and after, whole.
class SceneEditCommand : public QUndoCommand {
public:
    SceneEditCommand(SceneDocument& document, const QString& what, lessons::Scene before,
                     lessons::Scene after, int mergeId)
        : QUndoCommand(what), m_document(document), m_before(std::move(before)),
          m_after(std::move(after)), m_mergeId(mergeId)
    {
    }

    void undo() override { m_document.setScene(m_before); }
    void redo() override { m_document.setScene(m_after); }
    int id() const override { return m_mergeId; }
    bool mergeWith(const QUndoCommand* other) override
    {
        // Only called by QUndoStack when id() == other->id() and id() >= 0.
        m_after = static_cast<const SceneEditCommand*>(other)->m_after;
        return true;
    }

private:
    SceneDocument& m_document;
    lessons::Scene m_before;
    lessons::Scene m_after;
    int m_mergeId;
};

SceneDocument::SceneDocument(QObject* parent) : QObject(parent), m_undo(new QUndoStack(this))
{
    connect(m_undo, &QUndoStack::cleanChanged, this,
            [this](bool clean) { emit modifiedChanged(!clean); });
}

bool SceneDocument::isModified() const
{
    return !m_undo->isClean();
}

void SceneDocument::reset(const lessons::Scene& scene, const QString& path)
{
    m_undo->clear(); // clear() leaves the stack clean
    m_scene = scene;
    if (m_path != path) {
        m_path = path;
        emit pathChanged(m_path);
    }
    emit sceneReset();
    emit sceneChanged();
}

void SceneDocument::apply(const QString& what, const lessons::Scene& edited, int mergeId)
{
    // push() calls redo(), which sets the scene and emits sceneChanged().
    m_undo->push(new SceneEditCommand(*this, what, m_scene, edited, mergeId));
}

void SceneDocument::markSaved(const QString& path)
{
    if (m_path != path) {
        m_path = path;
        emit pathChanged(m_path);
    }
    m_undo->setClean();
}

lessons::Scene SceneDocument::newScene(const QString& title)
{
    lessons::Scene scene;
    scene.title = title;
    physics::BodyDef ground;
    ground.name = "ground";
    ground.type = physics::BodyType::Static;
    ground.shape = physics::makePolygonShape(physics::makeBox(kNewGroundLength, 0.5));
    ground.position = physics::Vec2(0.0, -0.25);
    scene.bodies.push_back(ground);
    scene.originalVertices.resize(scene.bodies.size());
    scene.colours.resize(scene.bodies.size());
    return scene;
}

QRectF SceneDocument::newSceneFrame()
{
    // 12 m of the ground's middle and 5 m above it (the view adds its margin).
    return {-6.0, -0.5, 12.0, 5.5};
}

void SceneDocument::setScene(const lessons::Scene& scene)
{
    m_scene = scene;
    emit sceneChanged();
}

} // namespace rigidlab::ui
