// SPDX-License-Identifier: GPL-3.0-or-later
// The window's way into the lesson editor: File › New lesson and Edit lesson…, and Try as a
// student, which plays the editor's lesson here from its selected step. File › Back to the
// lesson editor leads back to it while one is open: to the step the student is on while its
// lesson plays, else to the editor opened last.
#include "common/modal_scope.h"
#include "editor/edit_tools.h"
#include "editor/scene_document.h"
#include "lesson_editor/lesson_editor.h"
#include "lesson_player/lesson_player.h"
#include "window/lesson_session.h"
#include "window/main_window.h"
#include "window/window_documents.h"

#include "common/shortcuts.h"

#include "format/data_dirs.h"

#include <QAction>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QLocale>
#include <QMenu>
#include <QMessageBox>
#include <QPushButton>
#include <QToolBar>

namespace rigidlab::ui {

namespace {

/// The lesson editor opened last that is still open (the editors are the window's children, in
/// the order they were made), or null.
LessonEditor* newestEditor(const QObject& window)
{
    const QList<LessonEditor*> editors =
        window.findChildren<LessonEditor*>(Qt::FindDirectChildrenOnly);
    return editors.isEmpty() ? nullptr : editors.back();
}

} // namespace

void MainWindow::addLessonEditorEntries(QMenu& file)
{
    QAction* create = file.addAction(tr("Ne&w lesson"), this, [this] {
        if (offerKeptLesson())
            editLesson(QString());
    });
    create->setObjectName(QStringLiteral("newLesson"));
    QAction* edit = file.addAction(tr("Edi&t lesson…"), this, [this] {
        if (!offerKeptLesson())
            return;
        const QString path = QFileDialog::getOpenFileName(
            this, tr("Edit lesson"), lessons::userLessonsDir(), tr("Lessons (*.rlesson *.json)"));
        QString error;
        if (!path.isEmpty() && editLesson(path, &error) == nullptr)
            QMessageBox::warning(this, tr("Edit lesson"), error);
    });
    edit->setObjectName(QStringLiteral("editLesson"));
    m_backToEditor =
        file.addAction(tr("&Back to the lesson editor"), this, &MainWindow::backToLessonEditor);
    m_backToEditor->setObjectName(QStringLiteral("backToLessonEditor"));
    m_backToEditor->setShortcuts(controlKeys("backToLessonEditor"));
    m_backToEditor->setVisible(false); // only while a lesson editor is open
    // Another lesson, or a scene (which leaves the lesson), ends the try.
    // (The action is the context: a window being destroyed has deleted it before the
    // editor, its child too, whose end would otherwise reach a half-destroyed window.)
    connect(m_session, &LessonSession::left, m_backToEditor, [this] { hideWayBack(); });
    connect(m_player, &LessonPlayer::stepActivated, m_backToEditor,
            [this](const lessons::Lesson& lesson) {
                if (m_triedFrom && lesson.path != m_triedPath)
                    hideWayBack();
            });
}

bool MainWindow::offerKeptLesson()
{
    const QString kept = LessonEditor::keptLessons().value(0); // the newest; others next time
    if (kept.isEmpty())
        return true; // nothing a crash left
    const ModalScope modal;
    QMessageBox box(
        QMessageBox::Question, tr("A lesson was not saved"),
        tr("RigidLab closed on %1 while a lesson was being written, before it was "
           "saved. Open what was kept?")
            .arg(QLocale().toString(QFileInfo(kept).lastModified(), QLocale::ShortFormat)),
        QMessageBox::NoButton, this);
    box.setObjectName(QStringLiteral("keptLessonBox"));
    QPushButton* open = box.addButton(tr("&Open it"), QMessageBox::AcceptRole);
    open->setObjectName(QStringLiteral("keptOpen"));
    QPushButton* remove = box.addButton(tr("&Delete it"), QMessageBox::DestructiveRole);
    remove->setObjectName(QStringLiteral("keptDelete"));
    // Cancel leaves it there, to be offered again.
    box.addButton(QMessageBox::Cancel)->setObjectName(QStringLiteral("keptCancel"));
    box.setDefaultButton(open);
    box.exec();
    if (box.clickedButton() == remove) {
        QFile::remove(kept);
        return true;
    }
    if (box.clickedButton() != open)
        return false;
    LessonEditor* editor = editLesson(QString());
    const QString error = editor->openKept(kept);
    if (!error.isEmpty()) {
        delete editor;
        QMessageBox::warning(this, tr("A lesson was not saved"),
                             tr("What was kept does not open: %1").arg(error));
    }
    return false;
}

void MainWindow::showWayBack(LessonEditor* editor)
{
    m_triedFrom = editor;
    m_triedPath = m_player->lesson() ? m_player->lesson()->path : QString();
    if (m_backBar == nullptr) {
        m_backBar = new QToolBar(tr("Trying a lesson"), this);
        m_backBar->setObjectName(QStringLiteral("backToLessonEditorBar"));
        m_backBar->setMovable(false);
        m_backBar->toggleViewAction()->setVisible(false);
        m_backBar->setToolButtonStyle(Qt::ToolButtonTextOnly);
        auto* note = new QLabel(tr("Trying the lesson as a student sees it."), m_backBar);
        note->setContentsMargins(6, 0, 12, 0);
        m_backBar->addWidget(note);
        m_backBar->addAction(m_backToEditor);
        addToolBarBreak(Qt::TopToolBarArea);
        addToolBar(Qt::TopToolBarArea, m_backBar);
    }
    const QString keys = m_backToEditor->shortcut().toString(QKeySequence::NativeText);
    m_backToEditor->setToolTip(tr("Back to the lesson editor (%1)").arg(keys));
    m_backToEditor->setVisible(true);
    m_backBar->show();
}

void MainWindow::hideWayBack()
{
    m_triedFrom = nullptr;
    m_triedPath.clear();
    m_backToEditor->setVisible(newestEditor(*this) != nullptr);
    if (m_backBar != nullptr)
        m_backBar->hide();
}

void MainWindow::backToLessonEditor()
{
    auto* editor = qobject_cast<LessonEditor*>(m_triedFrom.data());
    if (editor != nullptr) {
        editor->selectStep(m_player->stepIndex()); // the step the student is on
    } else {
        editor = newestEditor(*this);
        if (editor == nullptr) {
            hideWayBack();
            return;
        }
    }
    editor->show();
    editor->raise();
    editor->activateWindow();
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
    connect(editor, &LessonEditor::tryAsStudent, this,
            [this, editor](const QString& file, int step) {
                if (!openLesson(file, true).isEmpty())
                    return; // openLesson said what is wrong
                m_player->goToStep(step);
                showWayBack(editor);
                raise();
                activateWindow();
            });
    connect(editor, &QObject::destroyed, m_backToEditor, [this](QObject* gone) {
        if (!m_triedFrom || m_triedFrom.data() == gone)
            hideWayBack(); // the editor closed: there is nothing to go back to
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
    m_backToEditor->setVisible(true);
    return editor;
}

} // namespace rigidlab::ui
