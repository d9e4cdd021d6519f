// SPDX-License-Identifier: GPL-3.0-or-later
// Every tab bar of the window answers a screen reader with the lab's interface
// (common/tab_bar_accessible.h), those made first too: Qt makes a widget's interface at its
// first accessibility event and keeps it, so a tab bar made before the factory was installed
// kept Qt's, whose current tab says it is focused wherever the keys are. The window's
// factories are all installed before its first widget (window/accessible_factories.h).
//
// Its own executable: Qt keeps interfaces for the whole process, and this must see the first
// window made in it.

#include "lesson_editor/lesson_editor.h"
#include "lesson_player/lesson_player.h"
#include "window/main_window.h"

#include <QAccessible>
#include <QTabBar>
#include <QtTest>

#include "projector_window.h"
#include "test_main.h"

using namespace rigidlab;
using rigidlab::test::shippedLessonFile;
using rigidlab::test::showOnProjector;
using rigidlab::ui::MainWindow;

namespace {

/// The tab bars under `root` whose interface is not the lab's, each as "object name: why";
/// `checked` counts the bars with tabs looked at. The lab's says a current tab is focused only
/// while its bar has the focus (Qt 6.4's says it always); a bar without tabs shows nothing.
QStringList barsWithQtsInterface(const QWidget& root, int& checked)
{
    QStringList out;
    for (QTabBar* bar : root.findChildren<QTabBar*>()) {
        if (bar->count() == 0 || bar->hasFocus())
            continue;
        ++checked;
        const QString where = (bar->objectName().isEmpty()
                                   ? QString::fromLatin1(bar->parent()->metaObject()->className())
                                   : bar->objectName()) +
                              QStringLiteral(" at ") +
                              bar->tabText(bar->currentIndex()).remove(u'&');
        QAccessibleInterface* list = QAccessible::queryAccessibleInterface(bar);
        QAccessibleInterface* current = list ? list->child(bar->currentIndex()) : nullptr;
        if (!list || list->role() != QAccessible::PageTabList || !current)
            out << where + QStringLiteral(": no page tab list");
        else if (current->state().focused)
            out << where + QStringLiteral(": its current tab says it is focused");
    }
    return out;
}

} // namespace

class TestTabBarInterfaces : public QObject {
    Q_OBJECT
private slots:
    /// The window as it opens, a lesson in it (its panels and plots in tabs), and the lesson
    /// editor's window.
    void everyTabBarIsTheLabs()
    {
        MainWindow w;
        showOnProjector(w);
        w.view().setFocus();
        QCoreApplication::processEvents();
        int checked = 0;
        QStringList wrong = barsWithQtsInterface(w, checked);
        QVERIFY2(wrong.isEmpty(), qPrintable(wrong.join(u'\n')));
        QVERIFY2(checked >= 2, qPrintable(QString::number(checked))); // something was checked

        QCOMPARE(w.openLesson(shippedLessonFile("restitution.json"), true), QString());
        QCoreApplication::processEvents();
        w.view().setFocus();
        QCoreApplication::processEvents();
        checked = 0;
        wrong = barsWithQtsInterface(w, checked);
        QVERIFY2(wrong.isEmpty(), qPrintable(wrong.join(u'\n')));
        QVERIFY2(checked >= 2, qPrintable(QString::number(checked)));

        QString error;
        ui::LessonEditor* editor = w.editLesson(shippedLessonFile("restitution.json"), &error);
        QVERIFY2(editor != nullptr, qPrintable(error));
        editor->show();
        QVERIFY(QTest::qWaitForWindowExposed(editor));
        checked = 0;
        wrong = barsWithQtsInterface(*editor, checked);
        QVERIFY2(wrong.isEmpty(), qPrintable(wrong.join(u'\n')));
        QVERIFY2(checked >= 1, qPrintable(QString::number(checked)));
        editor->close();
    }
};

RIGIDLAB_TEST_MAIN(TestTabBarInterfaces)
#include "test_tab_bar_interfaces.moc"
