// SPDX-License-Identifier: GPL-3.0-or-later
// Underlined letters, in English and in Czech: in each menu a letter opens one entry, and in
// the window Alt and a letter reach one control (the menu bar's titles among them), at start
// and on each shipped lesson's first step. (The lesson editor's: test_lesson_editor.)

#include "common/language.h"
#include "window/main_window.h"

#include "mnemonics.h"
#include "shipped_lessons.h"
#include "test_main.h"

#include <QAction>
#include <QDockWidget>
#include <QFileInfo>
#include <QMenu>
#include <QMenuBar>
#include <QtTest>

#include <string_view>
#include <vector>

using namespace rigidlab;
using rigidlab::ui::MainWindow;

namespace {

/// Every menu of the menu bar and their submenus, each filled as when it opens; in each, the
/// entries that share a mnemonic letter ("File: k: Nová le&kce, &Klíč pro učitele…").
QStringList mnemonicClashes(MainWindow& window)
{
    QStringList clashes;
    std::vector<QMenu*> menus;
    QMap<QChar, QStringList> bar;
    for (QAction* a : window.menuBar()->actions()) {
        if (QMenu* m = a->menu())
            menus.push_back(m);
        if (const QChar c = test::mnemonicOf(a->text()); !c.isNull())
            bar[c] << a->text();
    }
    for (const QString& line : test::sharedLetters(bar))
        clashes << QStringLiteral("menu bar: ") + line;
    for (std::size_t i = 0; i < menus.size(); ++i) {
        QMenu* menu = menus[i];
        emit menu->aboutToShow(); // menus filled as they open (Lessons, Open recent)
        QMap<QChar, QStringList> letters;
        for (QAction* a : menu->actions()) {
            if (!a->isVisible() || a->isSeparator())
                continue;
            if (QMenu* sub = a->menu())
                menus.push_back(sub);
            if (const QChar c = test::mnemonicOf(a->text()); !c.isNull())
                letters[c] << a->text();
        }
        for (const QString& line : test::sharedLetters(letters))
            clashes << menu->title() + QStringLiteral(": ") + line;
    }
    return clashes;
}

/// The entries of `menu` shown, by their underlined letters, and those without one.
struct MenuLetters {
    QMap<QChar, QStringList> letters;
    QStringList without;
};

MenuLetters menuLetters(QMenu& menu)
{
    emit menu.aboutToShow();
    MenuLetters out;
    for (QAction* a : menu.actions()) {
        if (!a->isVisible() || a->isSeparator())
            continue;
        if (const QChar c = test::mnemonicOf(a->text()); !c.isNull())
            out.letters[c] << a->text();
        else
            out.without << a->text();
    }
    return out;
}

} // namespace

class TestMnemonics : public QObject {
    Q_OBJECT

private slots:
    void cleanupTestCase() { ui::applyLanguage(QStringLiteral("en")); }

    // In every menu, in each language, a letter opens one entry: two entries sharing their
    // underlined letter make the key only move between them.
    void menuMnemonicsAreUnique_data()
    {
        QTest::addColumn<QString>("language");
        QTest::newRow("en") << QStringLiteral("en");
        QTest::newRow("cs") << QStringLiteral("cs");
    }
    void menuMnemonicsAreUnique()
    {
        QFETCH(QString, language);
        QVERIFY(ui::applyLanguage(language));
        MainWindow w;
        const QStringList clashes = mnemonicClashes(w);
        QVERIFY2(clashes.isEmpty(), qPrintable(clashes.join(u'\n')));
    }

    // Every entry of the View menu and of its Panels menu has an underlined letter (a dock's
    // entry, named by its title, had none), and no two of one menu share one: Alt+V and a letter
    // or two show or hide anything there, in each language, in a lesson too.
    void viewMenuEntriesHaveLettersOfTheirOwn_data() { menuMnemonicsAreUnique_data(); }
    void viewMenuEntriesHaveLettersOfTheirOwn()
    {
        QFETCH(QString, language);
        QVERIFY(ui::applyLanguage(language));
        MainWindow w;
        auto* view = w.findChild<QMenu*>(QStringLiteral("viewMenu"));
        auto* panels = w.findChild<QMenu*>(QStringLiteral("panelsMenu"));
        QVERIFY(view && panels);
        QCOMPARE(panels->menuAction()->associatedObjects().contains(view), true);
        for (const char* where : {"at start", "in a lesson"}) {
            if (where != std::string_view("at start"))
                QCOMPARE(
                    w.openLesson(MainWindow::lessonsFolder() + QStringLiteral("/energy_drift.json"),
                                 true),
                    QString());
            QStringList problems;
            for (QMenu* menu : {view, panels}) {
                const MenuLetters letters = menuLetters(*menu);
                for (const QString& text : letters.without)
                    problems
                        << QStringLiteral("%1, %2: no letter: %3").arg(where, menu->title(), text);
                for (const QString& line : test::sharedLetters(letters.letters))
                    problems << QStringLiteral("%1, %2: %3").arg(where, menu->title(), line);
            }
            // Each dock's entry is in Panels, and says its title.
            int docks = 0;
            for (QDockWidget* dock : w.findChildren<QDockWidget*>()) {
                QAction* entry = dock->toggleViewAction();
                if (!entry->associatedObjects().contains(panels))
                    continue;
                ++docks;
                if (QString(entry->text()).remove(u'&') != dock->windowTitle())
                    problems << QStringLiteral("%1: %2 for %3")
                                    .arg(where, entry->text(), dock->windowTitle());
            }
            QVERIFY2(problems.isEmpty(), qPrintable(problems.join(u'\n')));
            QVERIFY2(docks >= 12, qPrintable(QString::number(docks)));
        }
    }

    // The window's own controls (the docks' labels and buttons shown at start) and the menu
    // bar's titles: Alt and a letter reach one of them.
    void windowMnemonicsAreUnique_data() { menuMnemonicsAreUnique_data(); }
    void windowMnemonicsAreUnique()
    {
        QFETCH(QString, language);
        QVERIFY(ui::applyLanguage(language));
        MainWindow w;
        w.show();
        QMap<QChar, QStringList> titles;
        for (QAction* a : w.menuBar()->actions())
            if (const QChar c = test::mnemonicOf(a->text()); !c.isNull())
                titles[c] << a->text();
        // Two of the window's controls, or a control and a menu's title, sharing a letter.
        const auto clashesNow = [&w, &titles](const QString& where) {
            QMap<QChar, QStringList> letters = test::windowMnemonics(w);
            for (auto it = titles.cbegin(); it != titles.cend(); ++it)
                letters[it.key()] << it.value();
            QStringList out;
            for (const QString& line : test::sharedLetters(letters))
                out << where + QStringLiteral(": ") + line;
            return out;
        };
        QStringList clashes = clashesNow(QStringLiteral("at start"));
        // Each shipped lesson's first step shows its own controls (answers, hand-in, panels).
        for (const QString& path : test::shippedLessons()) {
            QCOMPARE(w.openLesson(path, true), QString());
            clashes << clashesNow(QFileInfo(path).fileName());
        }
        clashes.removeDuplicates();
        QVERIFY2(clashes.isEmpty(), qPrintable(clashes.join(u'\n')));
    }
};

RIGIDLAB_TEST_MAIN(TestMnemonics)
#include "test_mnemonics.moc"
