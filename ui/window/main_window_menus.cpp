// SPDX-License-Identifier: GPL-3.0-or-later
// MainWindow's menus: each entry is an action of one of the window's parts.
#include "window/main_window.h"

#include "common/display_names.h"
#include "common/dock_names.h"
#include "common/shortcuts.h"
#include "editor/scene_document.h"
#include "instruments/instruments.h"
#include "lesson_player/lesson_player.h"
#include "measure/measurement_session.h"
#include "window/about_dialog.h"
#include "window/class_results_dialog.h"
#include "window/dock_tabs.h"
#include "window/help_dialog.h"
#include "window/language_switch.h"
#include "window/lesson_session.h"
#include "window/status_line.h"
#include "window/window_actions.h"
#include "window/window_documents.h"
#include "window/window_keyboard.h"
#include "window/window_layout.h"
#include "window/window_names.h"
#include "window/window_plots.h"

#include "format/data_dirs.h"
#include "format/lesson_catalog.h"
#include "format/scene_catalog.h"

#include <QAction>
#include <QDir>
#include <QDockWidget>
#include <QMenu>
#include <QMenuBar>
#include <QUndoStack>

namespace rigidlab::ui {

namespace {

/// Gives `action` its object name and the keys the key table lists under that name.
QAction* named(QAction* action, const char* name)
{
    action->setObjectName(QLatin1String(name));
    action->setShortcuts(controlKeys(name));
    return action;
}

} // namespace

void MainWindow::buildMenus()
{
    buildFileMenu();
    buildEditMenu();
    QMenu* sim = menuBar()->addMenu(tr("&Simulation"));
    for (QAction* a : {m_actions->play(), m_actions->step(), m_actions->back(), m_actions->reset()})
        sim->addAction(a);
    sim->addSeparator();
    for (QAction* a : m_actions->rotate())
        sim->addAction(a);
    m_keyboard->addToSimulationMenu(*sim);
    buildViewMenu();
    buildHelpMenu();
}

void MainWindow::buildFileMenu()
{
    // A table of entries: each names its action and takes its keys from the key table.
    QMenu* file = menuBar()->addMenu(tr("&File"));
    named(file->addAction(tr("&New scene"), this, &MainWindow::newScene), "newScene");
    named(file->addAction(tr("&Open scene…"), m_documents, &WindowDocuments::openDialog),
          "openScene");
    named(file->addAction(tr("O&pen lesson…"), m_session, &LessonSession::openLessonDialog),
          "openLesson");
    addLessonEditorEntries(*file);
    file->addAction(m_measurement->importAction());
    QMenu* lessonsMenu = file->addMenu(tr("&Lessons"));
    lessonsMenu->setObjectName(QStringLiteral("lessonsMenu"));
    // Filled as it opens: a folder of lessons added since lists its lessons at once.
    const auto fillLessons = [this, lessonsMenu] {
        lessonsMenu->clear();
        delete lessonsMenu->findChild<QMenu*>(QStringLiteral("stopListingFolder")); // clear() keeps
        for (int i = 0; i < m_player->lessonPaths().size(); ++i) {
            const QString path = m_player->lessonPaths()[i];
            lessonsMenu->addAction(menuEntryText(m_player->lessonMenuTexts()[i]), this,
                                   [this, path] { openLesson(path); });
        }
        lessonsMenu->addSeparator();
        lessonsMenu
            ->addAction(tr("&Add a folder of lessons…"), m_session,
                        &LessonSession::addLessonFolderDialog)
            ->setObjectName(QStringLiteral("addLessonFolder"));
        const QStringList added = lessons::addedLessonFolders();
        if (added.isEmpty())
            return;
        QMenu* stop = lessonsMenu->addMenu(tr("S&top listing a folder"));
        stop->setObjectName(QStringLiteral("stopListingFolder"));
        stop->setToolTipsVisible(true);
        for (const QString& folder : added) {
            QAction* a = stop->addAction(menuEntryText(QDir::toNativeSeparators(folder)), m_session,
                                         [this, folder] { m_session->removeLessonFolder(folder); });
            a->setToolTip(tr("Its lessons are no longer listed; the folder and its files stay"));
        }
    };
    fillLessons();
    connect(lessonsMenu, &QMenu::aboutToShow, this, fillLessons);
    m_player->addWorksheetActions(*file); // the open lesson's empty worksheet and its key
    named(file->addAction(tr("Class res&ults…"), this, &MainWindow::showClassResults),
          "classResults");
    QMenu* recentMenu = file->addMenu(tr("Open &recent"));
    recentMenu->setObjectName(QStringLiteral("recentMenu")); // file names: no language
    QMenu* scenesMenu = file->addMenu(tr("Shipped s&cenes"));
    for (const lessons::SceneEntry& scene : lessons::scenesIn(scenesFolder(), false))
        scenesMenu->addAction(menuEntryText(scene.title), this,
                              [this, p = scene.path] { openScene(p); });
    // The user's own scenes (lessons::userScenesDir()) go here when there are any.
    QAction* ownScenesBefore = file->addSeparator();
    named(file->addAction(tr("&Save"), this, &MainWindow::saveScene), "saveScene");
    named(file->addAction(tr("Save &as…"), this, &MainWindow::saveSceneAs), "saveSceneAs");
    file->addSeparator();
    m_documents->setMenus(recentMenu, file, ownScenesBefore);
    QMenu* exportMenu = file->addMenu(tr("&Export plot"));
    exportMenu->setObjectName(QStringLiteral("exportMenu"));
    fillExportMenu(*exportMenu, *this, [this] { return plotsOnScreen(); });
    file->addSeparator();
    named(file->addAction(tr("&Quit"), this, &QWidget::close), "quit");
}

void MainWindow::buildEditMenu()
{
    // Undo and redo of the scene's edits (the editor's tools add theirs here).
    QMenu* edit = menuBar()->addMenu(tr("&Edit"));
    edit->setObjectName(QStringLiteral("editMenu"));
    edit->addAction(named(m_document->undoStack()->createUndoAction(this, tr("&Undo")), "undo"));
    edit->addAction(named(m_document->undoStack()->createRedoAction(this, tr("&Redo")), "redo"));
}

void MainWindow::buildViewMenu()
{
    m_viewMenu = menuBar()->addMenu(tr("&View"));
    m_viewMenu->setObjectName(QStringLiteral("viewMenu"));
    m_viewMenu->addAction(m_actions->fit());
    m_presentAction = named(m_viewMenu->addAction(tr("&Presentation")), "presentation");
    m_presentAction->setCheckable(true);
    m_presentAction->setToolTip(
        tr("Full screen, larger text and thicker lines for a projector (F11)"));
    connect(m_presentAction, &QAction::toggled, m_layout, &WindowLayout::setPresentation);
    addAction(m_presentAction); // F11 works in full screen, where the menu bar may be hidden
    addLanguageMenu(m_viewMenu, *this);
    m_viewMenu->addSeparator();
    for (QAction* a : m_actions->overlays())
        m_viewMenu->addAction(a);
    m_viewMenu->addSeparator();
    // The panels in a menu of their own: with them the View menu had more entries than the
    // alphabet has letters to underline.
    QMenu* panels = m_viewMenu->addMenu(tr("Pa&nels"));
    panels->setObjectName(QStringLiteral("panelsMenu"));
    for (QDockWidget* dock : findChildren<QDockWidget*>()) {
        // Titled from its entry (nameDock): the entry is the title with its underlined letter.
        const PanelEntry* entry = panelEntry(dock->objectName());
        Q_ASSERT(entry); // every dock of the window has its entry
        if (entry)
            dock->toggleViewAction()->setText(panelEntryText(*entry));
        panels->addAction(dock->toggleViewAction());
        focusWhenAsked(*dock);
    }
    m_viewMenu->addAction(m_instruments->graphAction());
    m_viewMenu->addSeparator();
    m_viewMenu->addAction(m_status->detailsAction());
    m_keyboard->addToViewMenu(*m_viewMenu);
}

void MainWindow::buildHelpMenu()
{
    QMenu* help = menuBar()->addMenu(tr("&Help"));
    QAction* controls =
        named(help->addAction(tr("&Controls…"), this, &MainWindow::showControlsHelp), "help");
    addAction(controls); // F1 works in full screen too
    help->addAction(tr("&About RigidLab…"), this, [this] { showAbout(this); });
}

ClassResultsDialog* MainWindow::showClassResults()
{
    auto* dialog = findChild<ClassResultsDialog*>();
    if (dialog == nullptr) {
        dialog = new ClassResultsDialog(this);
        dialog->setAttribute(Qt::WA_DeleteOnClose);
    }
    dialog->show();
    dialog->raise();
    dialog->activateWindow();
    return dialog;
}

void MainWindow::showControlsHelp()
{
    ui::showControlsHelp(this, tr("Controls"), controlsHelpText());
}

QString MainWindow::controlsHelpText() const
{
    // The overlays' keys from their own table, kOverlayNames, and Tab from the scene to a
    // step's answer.
    QList<ControlHelpRow> extra;
    for (const OverlayNames& info : kOverlayNames)
        extra.push_back(
            {{QKeySequence(QString::fromLatin1(info.shortcut))},
             tr("Show or hide: %1").arg(windowNameText(info.text).remove(QLatin1Char('&')))});
    extra << WindowKeyboard::helpRows();
    return controlsHelpHtml(extra);
}

} // namespace rigidlab::ui
