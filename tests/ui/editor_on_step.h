// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The lesson editor as the tests of a question kind written in it start: a new lesson of one
// step with the four balls' scene, shown at 1024×768 on that step, and its widgets found by
// name.

#include "build_paths.h"
#include "lesson_editor/lesson_draft.h"
#include "lesson_editor/lesson_editor.h"

#include "format/scene_loader.h"

#include <QJsonArray>
#include <QJsonObject>
#include <QWidget>
#include <QtGlobal>

namespace rigidlab::test {

/// The child of `parent` named `name`; null, said in a warning, when it has none.
template <typename W> W* child(QWidget& parent, const QString& name)
{
    W* w = parent.findChild<W*>(name);
    if (!w)
        qWarning("no child named %s", qPrintable(name));
    return w;
}

struct EditorOnStep {
    ui::LessonEditor ed;

    /// Starts the new lesson and shows the editor on its step; the scene loader's error, empty
    /// when the scene loaded.
    QString open()
    {
        const lessons::SceneLoadResult scene =
            lessons::loadSceneFile(rigidlab::test::sourcePath(u"/lessons/scenes/four_balls.json"));
        if (!scene.ok)
            return scene.error;
        ed.newLesson(scene.scene);
        ed.resize(1024, 768);
        ed.show();
        ed.selectStep(0);
        return {};
    }
    /// The step's first question as the draft holds it.
    QJsonObject question()
    {
        return ed.draft().value(0, QStringLiteral("questions")).toArray().at(0).toObject();
    }
};

} // namespace rigidlab::test
