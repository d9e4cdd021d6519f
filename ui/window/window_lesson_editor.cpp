// SPDX-License-Identifier: GPL-3.0-or-later
// The window's way into the lesson editor: File › New lesson and Edit lesson…, and Try as a
// student, which plays the editor's lesson here from its selected step.
#include "editor/edit_tools.h"
#include "editor/scene_document.h"
#include "lesson_editor/lesson_editor.h"
#include "lesson_player/lesson_player.h"
#include "window/main_window.h"
#include "window/window_documents.h"

#include "format/data_dirs.h"

#include <QAction>
#include <QFileDialog>
#include <QMenu>
#include <QMessageBox>

namespace rigidlab::ui {

void MainWindow::addLessonEditorEntries(QMenu& file)
{
    QAction* create = file.addAction(tr("Ne&w lesson"), this, [this] { editLesson(QString()); });
    create->setObjectName(QStringLiteral("newLesson"));
    QAction* edit = file.addAction(tr("Edi&t lesson…"), this, [this] {
        const QString path = QFileDialog::getOpenFileName(
            this, tr("Edit lesson"), lessons::userLessonsDir(), tr("Lessons (*.rlesson *.json)"));
        QString error;
        if (!path.isEmpty() && editLesson(path, &error) == nullptr)
            QMessageBox::warning(this, tr("Edit lesson"), error);
    });
    edit->setObjectName(QStringLiteral("editLesson"));
}

LessonEditor* MainWindow::editLesson(const QString& path, QString* error)
{
    auto* editor = new LessonEditor(this);
    editor->setAttribute(Qt::WA_DeleteOnClose);
    if (path.isEmpty()) {
        editor->newLesson(m_document->scene());
    } else {
        const QString e = editor->open(path);
        if (!e.isEmpty()) {
            if (error != nullptr)
                *error = e;
            delete editor;
            return nullptr;
        }
    }
    connect(editor, &LessonEditor::tryAsStudent, this, [this](const QString& file, int step) {
        if (!openLesson(file, true).isEmpty())
            return; // openLesson said what is wrong
        m_player->goToStep(step);
        raise();
        activateWindow();
    });
    // The step's scene drawn in this window's scene editor, and taken back from it.
    connect(editor, &LessonEditor::editStepScene, this, [this](const lessons::Scene& scene) {
        if (!m_documents->confirmLeaveScene())
            return;
        adoptDocument(scene, QString(), false, false);
        m_editTools->setEditing(true);
        raise();
        activateWindow();
    });
    connect(editor, &LessonEditor::stepSceneWanted, editor,
            [this, editor](int step) { editor->draft().setStepScene(step, m_document->scene()); });
    editor->resize(1000, 700);
    editor->show();
    return editor;
}

} // namespace rigidlab::ui
