// SPDX-License-Identifier: GPL-3.0-or-later
// Everything in reach on a 1024×768 projector: every top-level window and dialog fits the
// screen (scrolling inside), F1 opens Help, the keyboard focus never walks into a control
// nobody can see, tab labels are whole, every panel a lesson step names is in sight, a panel
// ticked in the View menu shows, and File › Export plot offers the plots on screen.

#include "classroom_util.h"
#include "test_main.h"

#include <QDialog>
#include <QDialogButtonBox>
#include <QFileInfo>
#include <QMenu>
#include <QMessageBox>

using namespace rigidlab;
using rigidlab::test::atLeast;
using rigidlab::test::visitShippedSteps;
using rigidlab::ui::MainWindow;
using namespace rigidlab::test::classroom;

namespace {

/// The dock `w` is in, or nullptr.
const QDockWidget* dockOf(const QWidget* w)
{
    for (const QWidget* p = w; p; p = p->parentWidget())
        if (const auto* dock = qobject_cast<const QDockWidget*>(p))
            return dock;
    return nullptr;
}

/// Whether `dock` lies behind another dock's tab (Qt moves such a dock off the window).
bool behindTab(const QDockWidget* dock)
{
    return dock && !dock->isFloating() &&
           (dock->geometry().right() < 0 || dock->geometry().bottom() < 0);
}

/// The widgets Tab walks through, as QWidget::focusNextPrevChild picks them: visible to the
/// window, enabled, taking focus by Tab. Those nobody can see are described.
QStringList unseenInFocusChain(MainWindow& w)
{
    QStringList out;
    int walked = 0;
    QWidget* start = &w;
    for (QWidget* next = start->nextInFocusChain(); next != start && walked < 2000;
         next = next->nextInFocusChain(), ++walked) {
        if (!next->isVisibleTo(&w) || !next->isEnabled() || !(next->focusPolicy() & Qt::TabFocus) ||
            next->window() != &w)
            continue;
        const QDockWidget* dock = dockOf(next);
        const QRect r = reachableRect(next, &w);
        if (behindTab(dock) || (dock && dock->isHidden()) || !w.rect().intersects(r))
            out << QStringLiteral("%1 \"%2\" in %3 at %4,%5 %6x%7")
                       .arg(QString::fromLatin1(next->metaObject()->className()),
                            next->accessibleName().isEmpty() ? next->objectName()
                                                             : next->accessibleName(),
                            dock ? dock->objectName() : QStringLiteral("the window"))
                       .arg(r.x())
                       .arg(r.y())
                       .arg(r.width())
                       .arg(r.height());
    }
    return out;
}

/// The tab labels of the window's dock tab bars that are not shown whole.
QStringList cutTabs(const MainWindow& w)
{
    QStringList out;
    for (const QTabBar* bar : w.findChildren<QTabBar*>()) {
        if (!bar->isVisible() || bar->parentWidget() != &w)
            continue;
        for (int t = 0; t < bar->count(); ++t) {
            const QRect tab = bar->tabRect(t);
            const int need = bar->fontMetrics().horizontalAdvance(bar->tabText(t));
            if (!bar->rect().contains(tab) || tab.width() < need)
                out << QStringLiteral("\"%1\" %2 px of %3, bar %4 px")
                           .arg(bar->tabText(t))
                           .arg(tab.width())
                           .arg(need)
                           .arg(bar->width());
        }
    }
    return out;
}

/// Whether `dock` is shown in the window: not hidden, not behind a tab, with room to read.
bool inSight(const QDockWidget* dock)
{
    return dock && dock->isVisible() && !behindTab(dock) && !dock->visibleRegion().isEmpty() &&
           dock->height() >= 80 && dock->width() >= 120;
}

/// The top-level windows shown now, with their sizes, that are larger than `screen`.
QStringList tooLarge(const QSize& screen)
{
    QStringList out;
    for (QWidget* top : QApplication::topLevelWidgets())
        if (top->isVisible() && (top->frameGeometry().width() > screen.width() ||
                                 top->frameGeometry().height() > screen.height()))
            out << QStringLiteral("%1 \"%2\" %3x%4")
                       .arg(QString::fromLatin1(top->metaObject()->className()), top->windowTitle())
                       .arg(top->frameGeometry().width())
                       .arg(top->frameGeometry().height());
    return out;
}

/// The texts of `menu`'s entries, its submenus' titles included, after it is opened.
QStringList menuTexts(QMenu& menu)
{
    emit menu.aboutToShow();
    QStringList out;
    for (const QAction* a : menu.actions())
        if (!a->isSeparator() && a->isEnabled())
            out << a->text();
    return out;
}

} // namespace

class TestWindowReach : public QObject {
    Q_OBJECT
private slots:
    void everyWindowAndDialogFits()
    {
        MainWindow w;
        showOn(w, kProjector);
        QVERIFY(tooLarge(kProjector).isEmpty());
        QAction* help = w.findChild<QAction*>(QStringLiteral("help"));
        QVERIFY(help);
        help->trigger();
        auto* dialog = w.findChild<QDialog*>(QStringLiteral("controlsHelpDialog"));
        QVERIFY(dialog && dialog->isVisible());
        QVERIFY(QTest::qWaitForWindowExposed(dialog));
        // The help scrolls inside; its close button is in the dialog.
        auto* text = dialog->findChild<QTextBrowser*>();
        QVERIFY(text && text->document()->toPlainText().contains(QStringLiteral("F11")));
        const QStringList large = tooLarge(kProjector);
        QVERIFY2(large.isEmpty(), qPrintable(large.join(QStringLiteral("; "))));
        auto* close = dialog->findChild<QDialogButtonBox*>();
        QVERIFY(close &&
                dialog->rect().contains(QRect(close->mapTo(dialog, QPoint(0, 0)), close->size())));
        dialog->close();
        QTRY_VERIFY(!w.findChild<QDialog*>(QStringLiteral("controlsHelpDialog")));
        // About, and a message box with a long error.
        QMenu* helpMenu = help->associatedObjects().isEmpty()
                              ? nullptr
                              : qobject_cast<QMenu*>(help->associatedObjects().first());
        QVERIFY(helpMenu);
        for (QAction* a : helpMenu->actions())
            if (a != help && !a->isSeparator())
                a->trigger();
        auto* about = w.findChild<QMessageBox*>(QStringLiteral("aboutBox"));
        QVERIFY(about && about->isVisible());
        QVERIFY(w.openScene(QStringLiteral("/nonexistent/") + QString(200, QLatin1Char('x')) +
                                QStringLiteral(".json"),
                            false)
                    .size() > 0);
        QVERIFY(w.findChild<QMessageBox*>(QStringLiteral("sceneErrorBox")));
        QCoreApplication::processEvents();
        const QStringList boxes = tooLarge(kProjector);
        QVERIFY2(boxes.isEmpty(), qPrintable(boxes.join(QStringLiteral("; "))));
    }

    void f1OpensHelp()
    {
        MainWindow w;
        showOn(w, kProjector);
        w.view().setFocus();
        QTest::keyClick(&w.view(), Qt::Key_F1);
        QTRY_VERIFY(w.findChild<QDialog*>(QStringLiteral("controlsHelpDialog")));
        QVERIFY(w.findChild<QDialog*>(QStringLiteral("controlsHelpDialog"))->isVisible());
    }

    // Tab reaches only what can be seen: the plain lab and every lesson step.
    void noHiddenControlInTheFocusChain()
    {
        MainWindow w;
        showOn(w, kProjector);
        QStringList unseen = unseenInFocusChain(w);
        QVERIFY2(unseen.isEmpty(), qPrintable(unseen.join(QStringLiteral("; "))));
        // Tab pressed through the whole window lands only on what is in sight.
        w.view().setFocus();
        for (int i = 0; i < 80; ++i) {
            QTest::keyClick(QApplication::focusWidget(), Qt::Key_Tab);
            QWidget* focus = QApplication::focusWidget();
            QVERIFY(focus);
            QVERIFY2(!behindTab(dockOf(focus)),
                     qPrintable(QString::fromLatin1(focus->metaObject()->className())));
        }
        int steps = 0;
        const bool walked = visitShippedSteps(w, [&](const QString& path, int i,
                                                     const lessons::LessonStep&) {
            QCoreApplication::processEvents();
            const QStringList hidden = unseenInFocusChain(w);
            QVERIFY2(hidden.isEmpty(),
                     qPrintable(
                         QStringLiteral("%1 step %2: ").arg(QFileInfo(path).baseName()).arg(i + 1) +
                         hidden.join(QStringLiteral("; "))));
            ++steps;
        });
        if (walked)
            QVERIFY2(steps >= atLeast(20, 18), qPrintable(QString::number(steps)));
    }

    // Every panel a step names (controls, tables) is in sight, not behind a plot's tab, and
    // every tab label is whole.
    void everyStepPanelInSight()
    {
        MainWindow w;
        showOn(w, kProjector);
        QVERIFY(w.compactLayout());
        QStringList cut = cutTabs(w);
        QVERIFY2(cut.isEmpty(), qPrintable(cut.join(QStringLiteral("; "))));
        int panels = 0;
        const bool walked =
            visitShippedSteps(w, [&](const QString& path, int i, const lessons::LessonStep& step) {
                const QString where =
                    QStringLiteral("%1 step %2: ").arg(QFileInfo(path).baseName()).arg(i + 1);
                const QStringList held = w.lessonPlayer().heldBack();
                for (const QString& panel : step.panels) {
                    if (held.contains(QStringLiteral("panel:") + panel))
                        continue;
                    QVERIFY2(inSight(w.dock(panel)), qPrintable(where + panel));
                    ++panels;
                }
                const QStringList cutHere = cutTabs(w);
                QVERIFY2(cutHere.isEmpty(), qPrintable(where + cutHere.join(QStringLiteral("; "))));
                QVERIFY2(w.view().width() >= w.width() / 2, qPrintable(where));
            });
        if (walked)
            QVERIFY2(panels >= atLeast(20, 16), qPrintable(QString::number(panels)));
    }

    // Ticked in View, a panel shows in the plain lab and in a lesson step, whole.
    void viewMenuShowsThePanel_data()
    {
        QTest::addColumn<QString>("panel");
        QTest::addColumn<bool>("inLesson");
        for (const char* panel : {"collision", "inspector", "controls", "sat"}) {
            QTest::addRow("%s, plain lab", panel) << QString::fromLatin1(panel) << false;
            QTest::addRow("%s, lesson", panel) << QString::fromLatin1(panel) << true;
        }
    }
    void viewMenuShowsThePanel()
    {
        QFETCH(QString, panel);
        QFETCH(bool, inLesson);
        MainWindow w;
        showOn(w, kProjector);
        if (inLesson)
            QCOMPARE(w.openLesson(MainWindow::lessonsFolder() +
                                      QStringLiteral("/billiards_momentum.json"),
                                  true),
                     QString());
        QCoreApplication::processEvents();
        QDockWidget* dock = w.dock(panel);
        QVERIFY(dock);
        if (dock->isVisible() && !behindTab(dock))
            dock->toggleViewAction()->trigger(); // off first, then on as the teacher does
        if (dock->isVisible())
            dock->toggleViewAction()->trigger();
        QVERIFY(!dock->toggleViewAction()->isChecked());
        dock->toggleViewAction()->trigger();
        QCoreApplication::processEvents();
        QTRY_VERIFY2(inSight(dock), qPrintable(QStringLiteral("%1: %2x%3 at %4,%5")
                                                   .arg(panel)
                                                   .arg(dock->width())
                                                   .arg(dock->height())
                                                   .arg(dock->x())
                                                   .arg(dock->y())));
        QVERIFY(w.view().width() >= w.width() / 2);
        const QStringList cut = cutTabs(w);
        QVERIFY2(cut.isEmpty(), qPrintable(cut.join(QStringLiteral("; "))));
    }

    // File › Export plot: the plots on screen, the compared worlds' plots in a step that shows
    // them, never a plot the step hides.
    void exportOffersWhatIsOnScreen()
    {
        MainWindow w;
        showOn(w, kProjector);
        auto* menu = w.findChild<QMenu*>(QStringLiteral("exportMenu"));
        QVERIFY(menu);
        QStringList titles;
        for (const auto* plot : w.plots())
            titles << plot->title();
        QCOMPARE(menuTexts(*menu), titles);
        QCOMPARE(
            w.openLesson(MainWindow::lessonsFolder() + QStringLiteral("/energy_drift.json"), true),
            QString());
        QCoreApplication::processEvents();
        QVERIFY(!w.comparePlots().empty());
        QStringList compared;
        for (const ui::PlotWidget* plot : w.comparePlots())
            compared << plot->title();
        QCOMPARE(menuTexts(*menu), compared);
        // Each entry offers the four formats.
        QMenu* first = menu->actions().first()->menu();
        QVERIFY(first);
        QCOMPARE(first->actions().size(), 4);
        QVERIFY(first->actions().first()->text().endsWith(QChar(0x2026))); // "…", not "..."
    }

    // "…", not "...", in every text of the window's menus, actions and labels.
    void ellipsisIsOneCharacter()
    {
        MainWindow w;
        showOn(w, kProjector);
        QStringList dots;
        for (const QAction* a : w.findChildren<QAction*>())
            for (const QString& t : {a->text(), a->toolTip(), a->statusTip()})
                if (t.contains(QLatin1String("...")))
                    dots << t;
        for (const QLabel* l : w.findChildren<QLabel*>())
            if (l->text().contains(QLatin1String("...")))
                dots << l->text();
        for (const QAbstractButton* b : w.findChildren<QAbstractButton*>())
            if (b->text().contains(QLatin1String("...")))
                dots << b->text();
        QVERIFY2(dots.isEmpty(), qPrintable(dots.join(QStringLiteral("; "))));
        QVERIFY(w.findChildren<QAction*>().size() > 30);
    }
};

RIGIDLAB_TEST_MAIN(TestWindowReach)
#include "test_window_reach.moc"
