// SPDX-License-Identifier: GPL-3.0-or-later
// What a screen reader finds in the lab, through QAccessible in process: every control a
// student operates has a name and a role (the main window, a lesson, the editor, the export
// dialog), a tab and a History entry say they are focused only where the keys go, a plot reads
// as its title, axes with units and series with values, the inspector's values say their rows,
// and the colours keep their contrast. What the scene's bodies say, and how often, is in
// test_scene_words.cpp.

#include "accessible_tree.h"
#include "common/focus_ring.h"
#include "common/language.h"
#include "common/theme.h"
#include "editor/edit_tools.h"
#include "editor/scene_document.h"
#include "lesson_player/lesson_player.h"
#include "panels/inspector_panel.h"
#include "plots/column_graph.h"
#include "plots/plot_accessible.h"
#include "plots/plot_exporter.h"
#include "plots/plot_widget.h"
#include "simulation/simulation_controller.h"
#include "view/world_view.h"
#include "window/main_window.h"

#include <QAccessible>
#include <QAction>
#include <QDialog>
#include <QDockWidget>
#include <QFileDialog>
#include <QFormLayout>
#include <QLabel>
#include <QMenu>
#include <QPalette>
#include <QTabBar>
#include <QTimer>
#include <QUndoStack>
#include <QUndoView>
#include <QtTest>
#include <qcustomplot.h>

#include "language_rows.h"
#include "projector_window.h"
#include "test_main.h"

using namespace rigidlab;
using rigidlab::test::shippedLessonFile;
using rigidlab::test::showOnProjector;
using rigidlab::test::unnamedInteractive;
using rigidlab::ui::MainWindow;

class TestAccessibility : public QObject {
    Q_OBJECT
private slots:
    /// Every control showing in the welcome window, each step of every lesson and Edit mode
    /// has a name and a role.
    void everyControlHasANameAndARole()
    {
        MainWindow w;
        showOnProjector(w);
        int interactive = 0;
        QStringList unnamed;
        // As a reader finds the window once it has settled (the window arranges its docks'
        // tab bars after the events that move them).
        QTRY_VERIFY2_WITH_TIMEOUT((unnamed = unnamedInteractive(w, &interactive)).isEmpty(),
                                  qPrintable(unnamed.join(QLatin1Char('\n'))), 2000);
        QVERIFY2(interactive > 20, qPrintable(QString::number(interactive)));

        const QDir dir(MainWindow::lessonsFolder());
        for (const QString& f : dir.entryList({QStringLiteral("*.json")}, QDir::Files)) {
            QCOMPARE(w.openLesson(dir.filePath(f), true), QString());
            const int steps = static_cast<int>(w.lessonPlayer().lesson()->steps.size());
            for (int i = 0; i < steps; ++i) {
                w.lessonPlayer().goToStep(i);
                QTRY_VERIFY2_WITH_TIMEOUT((unnamed = unnamedInteractive(w)).isEmpty(),
                                          qPrintable(f + QStringLiteral(" step %1:\n").arg(i + 1) +
                                                     unnamed.join(QLatin1Char('\n'))),
                                          2000);
            }
        }
        w.editTools().setEditing(true);
        QTRY_VERIFY2_WITH_TIMEOUT(
            (unnamed = unnamedInteractive(w)).isEmpty(),
            qPrintable(QStringLiteral("Edit mode:\n") + unnamed.join(QLatin1Char('\n'))), 2000);
    }

    /// The plot's export dialog names its controls too.
    void exportDialogHasNames()
    {
        MainWindow w;
        showOnProjector(w);
        QStringList unnamed;
        int interactive = 0;
        bool seen = false;
        QTimer::singleShot(0, this, [&] {
            auto* dialog = qobject_cast<QFileDialog*>(QApplication::activeModalWidget());
            if (!dialog)
                return;
            seen = true;
            unnamed = unnamedInteractive(*dialog, &interactive);
            dialog->reject();
        });
        w.plot(u"energy")->exporter().exportInteractively(ui::ExportFormat::Png);
        QVERIFY(seen);
        QVERIFY2(unnamed.isEmpty(), qPrintable(unnamed.join(QLatin1Char('\n'))));
        QVERIFY(interactive > 5);
    }

    /// A tab says it is focused only where the keys go: the current tab of the tab bar that
    /// has the focus, not the current tab of every tab bar (Qt's own interface says that).
    void onlyTheFocusedTabIsFocused()
    {
        MainWindow w;
        showOnProjector(w);
        w.view().setFocus();
        QCoreApplication::processEvents();
        const auto focusedTabs = [&w] {
            QStringList out;
            for (QTabBar* bar : w.findChildren<QTabBar*>()) {
                QAccessibleInterface* list = QAccessible::queryAccessibleInterface(bar);
                for (int i = 0; list && i < bar->count(); ++i)
                    if (QAccessibleInterface* tab = list->child(i);
                        tab && tab->role() == QAccessible::PageTab && tab->state().focused)
                        out << tab->text(QAccessible::Name);
            }
            return out;
        };
        QStringList tabs;
        for (QTabBar* bar : w.findChildren<QTabBar*>())
            if (bar->isVisible() && bar->count() > 1)
                tabs << bar->tabText(bar->currentIndex());
        QVERIFY2(!tabs.isEmpty(), "no tab bar with tabs shown"); // there is something to check
        QVERIFY2(focusedTabs().isEmpty(), qPrintable(focusedTabs().join(u',')));
        // Focused, a bar's current tab is the one focused, and it presses with its action.
        QTabBar* bar = nullptr;
        for (QTabBar* b : w.findChildren<QTabBar*>())
            if (b->isVisible() && b->count() > 1)
                bar = b;
        bar->setFocus(Qt::TabFocusReason);
        QCoreApplication::processEvents();
        QCOMPARE(focusedTabs(), QStringList{bar->tabText(bar->currentIndex()).remove(u'&')});
        QAccessibleInterface* list = QAccessible::queryAccessibleInterface(bar);
        const int other = bar->currentIndex() == 0 ? 1 : 0;
        QCOMPARE(list->child(other)->role(), QAccessible::PageTab);
        list->child(other)->actionInterface()->doAction(QAccessibleActionInterface::pressAction());
        QCOMPARE(bar->currentIndex(), other);
        QCOMPARE(list->focusChild(), list->child(other));
    }

    /// The History list's entry for the scene's state now says it is focused only while the
    /// list has the focus (Qt's list cells say it of the current item): with the keys in the
    /// scene, "Scene as opened" is selected, not focused; Tab into the list focuses it, and
    /// going in and out of the list undoes nothing.
    void historyEntryFocusedOnlyInTheList()
    {
        MainWindow w;
        showOnProjector(w);
        QVERIFY(w.newScene());
        if (!w.editTools().editing())
            w.editTools().editAction()->trigger();
        auto* dock = w.findChild<QDockWidget*>(QStringLiteral("historyDock"));
        auto* history = w.findChild<QUndoView*>(QStringLiteral("historyView"));
        QVERIFY(dock != nullptr && history != nullptr);
        dock->raise(); // a tab behind the Properties
        QCoreApplication::processEvents();
        QVERIFY(history->isVisible());
        QUndoStack& stack = *w.document()->undoStack();
        // Each entry's name and whether it says it is selected and focused: "name s f". The
        // list's interface is made again for each look: with no screen reader listening, Qt
        // does not tell it of its model's resets, and its cells would keep the old rows.
        const auto entries = [history] {
            QStringList out;
            if (QAccessibleInterface* old = QAccessible::queryAccessibleInterface(history))
                QAccessible::deleteAccessibleInterface(QAccessible::uniqueId(old));
            QAccessibleInterface* list = QAccessible::queryAccessibleInterface(history);
            for (int i = 0; list && i < list->childCount(); ++i)
                if (QAccessibleInterface* item = list->child(i)) {
                    const QAccessible::State state = item->state();
                    out << QStringLiteral("%1%2%3").arg(item->text(QAccessible::Name),
                                                        state.selected ? " s" : "",
                                                        state.focused ? " f" : "");
                }
            return out;
        };
        w.view().setFocus();
        QCoreApplication::processEvents();
        QVERIFY(!history->hasFocus());
        QCOMPARE(entries(), QStringList{QStringLiteral("Scene as opened s")});
        // An edit: its entry is the state now, selected and not focused either.
        stack.push(new QUndoCommand(QStringLiteral("An edit")));
        QCoreApplication::processEvents();
        QCOMPARE(entries(),
                 (QStringList{QStringLiteral("Scene as opened"), QStringLiteral("An edit s")}));
        history->setFocus(Qt::TabFocusReason);
        QCoreApplication::processEvents();
        QVERIFY(history->hasFocus());
        QCOMPARE(entries(),
                 (QStringList{QStringLiteral("Scene as opened"), QStringLiteral("An edit s f")}));
        QCOMPARE(stack.index(), 1);
        w.view().setFocus();
        QCoreApplication::processEvents();
        QCOMPARE(entries(),
                 (QStringList{QStringLiteral("Scene as opened"), QStringLiteral("An edit s")}));
        QCOMPARE(stack.index(), 1);
        // The keys still move through the list: Up goes back to the scene as opened.
        history->setFocus(Qt::TabFocusReason);
        QCoreApplication::processEvents();
        QTest::keyClick(history, Qt::Key_Up);
        QCOMPARE(stack.index(), 0);
        QCOMPARE(entries(),
                 (QStringList{QStringLiteral("Scene as opened s f"), QStringLiteral("An edit")}));
    }

    /// A plot reads as its title, its axes with units and its series with values now,
    /// least and greatest.
    void plotIsDescribed()
    {
        MainWindow w;
        showOnProjector(w);
        QCOMPARE(
            w.openScene(QDir(MainWindow::scenesFolder()).filePath(QStringLiteral("welcome.json")),
                        true),
            QString());
        for (int k = 0; k < 100; ++k)
            w.controller().stepForward();
        ui::PlotWidget* energy = w.plot(u"energy");
        energy->drain();
        QAccessibleInterface* a = QAccessible::queryAccessibleInterface(energy);
        QVERIFY(a);
        QCOMPARE(a->role(), QAccessible::Chart);
        QCOMPARE(a->text(QAccessible::Name), energy->title());
        const QString text = a->text(QAccessible::Description);
        QCOMPARE(text, ui::describePlot(*energy));
        QVERIFY2(text.contains(QLatin1String("[s]")) && text.contains(QLatin1String("[J]")),
                 qPrintable(text));
        for (int i = 0; i < energy->model().seriesCount(); ++i)
            QVERIFY2(text.contains(energy->model().seriesLegend(i) + QLatin1String(": now")),
                     qPrintable(text));
        QVERIFY2(text.contains(QLatin1String("greatest")), qPrintable(text));
    }

    /// Each of the inspector's values says its row to a screen reader: the row's label is a
    /// buddy of its value, and the value's name is "row: value".
    void inspectorValuesSayTheirRows()
    {
        MainWindow w;
        showOnProjector(w);
        QCOMPARE(w.openLesson(shippedLessonFile("restitution.json"), true), QString());
        int body = -1;
        for (int i = 0; i < static_cast<int>(w.controller().world().bodies().size()); ++i)
            if (w.controller().world().body(i).isDynamic())
                body = i;
        QVERIFY(body >= 0);
        w.inspector().setBody(body);
        auto* form = qobject_cast<QFormLayout*>(w.inspector().layout());
        QVERIFY(form);
        int values = 0;
        for (int row = 0; row < form->rowCount(); ++row) {
            QLayoutItem* labelItem = form->itemAt(row, QFormLayout::LabelRole);
            auto* label = labelItem ? qobject_cast<QLabel*>(labelItem->widget()) : nullptr;
            if (!label)
                continue;
            QVERIFY2(label->buddy(), qPrintable(label->text()));
            QVERIFY2(label->buddy()->isVisibleTo(&w.inspector()), qPrintable(label->text()));
            auto* value = qobject_cast<QLabel*>(label->buddy());
            if (!value)
                continue; // a field, named by its own label (test above)
            ++values;
            QAccessibleInterface* a = QAccessible::queryAccessibleInterface(value);
            const QString name = a->text(QAccessible::Name);
            QVERIFY2(name.startsWith(label->text()) && name.contains(value->text()) &&
                         !value->text().isEmpty(),
                     qPrintable(label->text() + QStringLiteral(" → ") + name));
        }
        QVERIFY2(values >= 8, qPrintable(QString::number(values)));
    }

    /// Without a body the inspector says so once, "No body selected", reached by Tab, rather
    /// than a row of dashes each read as "Angle θ: –"; with one, on a 1024×768 projector in
    /// each language, every value stands beside its label (the angle's had its unit list beside
    /// it, and went below its label).
    void inspectorSaysOnceThatNoBodyIsSelected_data() { test::addLanguageRows(); }
    void inspectorSaysOnceThatNoBodyIsSelected()
    {
        QFETCH(QString, language);
        QVERIFY(ui::applyLanguage(language));
        MainWindow w;
        showOnProjector(w);
        QCOMPARE(w.openLesson(shippedLessonFile("rotation_inertia.json"), true), QString());
        QCoreApplication::processEvents();
        ui::InspectorPanel& inspector = w.inspector();
        QVERIFY(inspector.isVisible());
        inspector.setBody(-1);
        QStringList shown;
        for (const QWidget* child : inspector.findChildren<QWidget*>())
            if (child->isVisibleTo(&inspector)) {
                const QAccessibleInterface* a =
                    QAccessible::queryAccessibleInterface(const_cast<QWidget*>(child));
                shown << (a ? a->text(QAccessible::Name) : QString());
            }
        const QString none =
            QCoreApplication::translate("rigidlab::ui::InspectorPanel", "No body selected");
        QVERIFY2(shown == QStringList{none}, qPrintable(shown.join(QStringLiteral(" | "))));
        auto* noBody = inspector.findChild<QLabel*>(QStringLiteral("noBody"));
        QVERIFY(noBody && (noBody->focusPolicy() & Qt::TabFocus));

        int body = -1;
        for (int i = 0; i < static_cast<int>(w.controller().world().bodies().size()); ++i)
            if (w.controller().world().body(i).isDynamic())
                body = i;
        QVERIFY(body >= 0);
        inspector.setBody(body);
        QCoreApplication::processEvents();
        QVERIFY(!noBody->isVisible());
        // The angle and the list of its units, each beside its label (a label's buddy).
        const auto unit = inspector.findChild<QWidget*>(QStringLiteral("angleUnit"));
        const QString angle =
            QCoreApplication::translate("rigidlab::ui::InspectorPanel", "Angle θ");
        QStringList wrapped;
        int checked = 0;
        for (const QLabel* label : inspector.findChildren<QLabel*>()) {
            if (!label->buddy() || (label->text() != angle && label->buddy() != unit))
                continue;
            ++checked;
            const QRect l(label->mapTo(&inspector, QPoint()), label->size());
            const QRect f(label->buddy()->mapTo(&inspector, QPoint()), label->buddy()->size());
            if (f.top() >= l.bottom() || f.left() <= l.right())
                wrapped << QStringLiteral("%1 at (%2, %3) %4×%5, its value at (%6, %7)")
                               .arg(label->text())
                               .arg(l.x())
                               .arg(l.y())
                               .arg(l.width())
                               .arg(l.height())
                               .arg(f.x())
                               .arg(f.y());
        }
        QCOMPARE(checked, 2);
        QVERIFY2(wrapped.isEmpty(), qPrintable(wrapped.join(u'\n')));
        QVERIFY(ui::applyLanguage(QStringLiteral("en")));
    }

    /// View › Reduced motion: the docks, menus, lists and tooltips no longer animate; the
    /// choice is kept for the next window, and undone the platform's effects come back.
    void reducedMotionStopsAnimations()
    {
        const bool menuBefore = QApplication::isEffectEnabled(Qt::UI_AnimateMenu);
        {
            MainWindow w;
            auto* reduced = w.findChild<QAction*>(QStringLiteral("reducedMotion"));
            QVERIFY(reduced && reduced->isCheckable() && !reduced->isChecked());
            QVERIFY(!reduced->text().isEmpty());
            bool inMenu = false;
            for (QObject* o : reduced->associatedObjects())
                inMenu = inMenu || qobject_cast<QMenu*>(o);
            QVERIFY(inMenu);
            QVERIFY(w.dockOptions().testFlag(QMainWindow::AnimatedDocks));
            reduced->trigger();
            QVERIFY(!w.dockOptions().testFlag(QMainWindow::AnimatedDocks));
            for (const Qt::UIEffect e : {Qt::UI_AnimateMenu, Qt::UI_FadeMenu, Qt::UI_AnimateCombo,
                                         Qt::UI_AnimateTooltip, Qt::UI_FadeTooltip})
                QVERIFY2(!QApplication::isEffectEnabled(e), qPrintable(QString::number(e)));
        }
        MainWindow again;
        auto* reduced = again.findChild<QAction*>(QStringLiteral("reducedMotion"));
        QVERIFY(reduced && reduced->isChecked());
        QVERIFY(!again.dockOptions().testFlag(QMainWindow::AnimatedDocks));
        reduced->trigger();
        QVERIFY(again.dockOptions().testFlag(QMainWindow::AnimatedDocks));
        QCOMPARE(QApplication::isEffectEnabled(Qt::UI_AnimateMenu), menuBefore);
    }

    /// Text at least 4.5:1 and lines and overlays at least 3:1 against what lies behind
    /// them, computed from the theme's colours, in the window and in presentation mode.
    void contrastFromTheTheme_data()
    {
        QTest::addColumn<bool>("presentation");
        QTest::newRow("window") << false;
        QTest::newRow("presentation") << true;
    }
    void contrastFromTheTheme()
    {
        QFETCH(bool, presentation);
        MainWindow w; // the window sets the application's readable palette
        namespace theme = ui::theme;
        theme::setPresentation(presentation);
        const auto check = [](const char* what, const QColor& a, const QColor& b, double least) {
            const double ratio = theme::contrastRatio(a, b);
            QVERIFY2(ratio >= least, qPrintable(QStringLiteral("%1: %2 on %3 is %4:1, below %5:1")
                                                    .arg(QLatin1String(what), a.name(), b.name())
                                                    .arg(ratio, 0, 'f', 2)
                                                    .arg(least)));
        };
        const QColor world = theme::worldBackground();
        const double text = theme::kMinTextContrast, line = theme::kMinOverlayContrast;
        check("text over the world", theme::worldText(), world, text);
        check("alert text over the world", theme::worldAlertText(), world, text);
        check("SAT gap label", theme::satGap(), theme::worldLabelBox(), text);
        check("SAT overlap label", theme::satOverlap(), theme::worldLabelBox(), text);
        check("banner text", theme::alertText(), theme::alertBackground(), text);
        check("SAT interval A", theme::satProjectionA(), world, line);
        check("SAT interval B", theme::satProjectionB(), world, line);
        check("SAT axis", theme::satAxis(), world, line);
        for (int i = 0; i < 7; ++i)
            check(qPrintable(QStringLiteral("plot line %1").arg(i)), ui::plotColor(i),
                  theme::plotBackground(), line);
        // The focus ring against the window and the panels, and its halo against the ring.
        const QPalette palette = QApplication::palette();
        for (const QColor& behind : {palette.color(QPalette::Window), palette.color(QPalette::Base),
                                     palette.color(QPalette::Button), world})
            check("focus ring", theme::focusRing(), behind, line);
        check("focus halo", theme::focusHalo(), theme::focusRing(), line);
        QVERIFY(ui::FocusRing::ringWidth() >= 2);
        // The answer field's placeholder text is text too (blended as it is drawn, if the
        // palette gives it transparent).
        const QColor base = palette.color(QPalette::Base);
        const QColor hint = palette.color(QPalette::PlaceholderText);
        const double a = hint.alphaF();
        const QColor drawn = QColor::fromRgbF(a * hint.redF() + (1 - a) * base.redF(),
                                              a * hint.greenF() + (1 - a) * base.greenF(),
                                              a * hint.blueF() + (1 - a) * base.blueF());
        check("placeholder text", drawn, base, text);
        theme::setPresentation(false);
    }

    /// Every series of a plot differs from the others in line style and in marker, so that
    /// the plots read in greyscale, on the window and in the exports alike.
    void plotsReadInGreyscale()
    {
        MainWindow w;
        for (ui::PlotWidget* plot : w.plots()) {
            for (int i = 0; i < plot->model().seriesCount(); ++i)
                for (int j = 0; j < i; ++j) {
                    QVERIFY2(
                        plot->graph(i)->pen().style() != plot->graph(j)->pen().style(),
                        qPrintable(plot->title() + QStringLiteral(": %1 and %2 have one line style")
                                                       .arg(plot->model().seriesName(i),
                                                            plot->model().seriesName(j))));
                    QVERIFY2(
                        plot->graph(i)->scatterStyle().shape() !=
                            plot->graph(j)->scatterStyle().shape(),
                        qPrintable(plot->title() + QStringLiteral(": %1 and %2 have one marker")
                                                       .arg(plot->model().seriesName(i),
                                                            plot->model().seriesName(j))));
                }
            for (int i = 0; i < plot->model().seriesCount(); ++i)
                QVERIFY(!plot->graph(i)->scatterStyle().isNone());
        }
    }
};

RIGIDLAB_TEST_MAIN(TestAccessibility)
#include "test_accessibility.moc"
