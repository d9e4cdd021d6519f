// SPDX-License-Identifier: GPL-3.0-or-later
// The lessons' tables in the window's narrow right column: at 200 px every cell of
// the bounce and collision tables is shown whole, inside the table, and a table of few rows
// is as tall as its rows; the bounce, collision and SAT tables export as CSV with a decimal
// point, numbers that read back exactly.

#include "common/language.h"
#include "lesson_player/lesson_panels.h"
#include "lesson_player/lesson_player.h"
#include "panels/fitting_table.h"
#include "panels/inspector_panel.h"
#include "panels/sat_panel.h"
#include "simulation/simulation_controller.h"
#include "window/main_window.h"

#include "format/lesson.h"
#include "format/scene.h"

#include <QAction>
#include <QDockWidget>
#include <QFile>
#include <QHeaderView>
#include <QLabel>
#include <QScopeGuard>
#include <QScrollBar>
#include <QTemporaryDir>
#include <QtTest>

#include "test_main.h"

using namespace rigidlab;
using rigidlab::ui::FittingTable;
using rigidlab::ui::MainWindow;

namespace {

/// The right column's width at 1024 × 768 [px].
constexpr int kNarrow = 200;

QString lesson(const char* name)
{
    return QDir(MainWindow::lessonsFolder())
        .filePath(QLatin1StringView(name) + QStringLiteral(".json"));
}

/// Why some cell of `table` is not shown whole, or an empty string: each cell's text, wrapped
/// at its width, must lie inside the cell, and the cell inside the viewport.
QString cellsNotShown(const FittingTable& table)
{
    const QRect viewport = table.viewport()->rect();
    QStringList problems;
    for (int r = 0; r < table.rowCount(); ++r) {
        for (int c = 0; c < table.columnCount(); ++c) {
            const QTableWidgetItem* item = table.item(r, c);
            if (!item || item->text().isEmpty())
                continue;
            const QModelIndex index = table.model()->index(r, c);
            const QRect cell = table.visualRect(index);
            if (!viewport.contains(cell))
                problems << QStringLiteral("(%1, %2) \"%3\": cell %4,%5 %6×%7 outside the viewport")
                                .arg(r)
                                .arg(c)
                                .arg(item->text())
                                .arg(cell.x())
                                .arg(cell.y())
                                .arg(cell.width())
                                .arg(cell.height());
            const QFontMetrics fm(item->font());
            // The style's cell margins: a few pixels on each side.
            const QRect inner = cell.adjusted(3, 0, -3, 0);
            const QRect text = fm.boundingRect(inner, Qt::TextWordWrap, item->text());
            if (text.width() > inner.width() || text.height() > cell.height())
                problems << QStringLiteral("(%1, %2) \"%3\" needs %4×%5 px in a cell of %6×%7")
                                .arg(r)
                                .arg(c)
                                .arg(item->text())
                                .arg(text.width())
                                .arg(text.height())
                                .arg(inner.width())
                                .arg(cell.height());
        }
    }
    // Rows no taller than their text: a cell's line measured to fit must not wrap.
    for (int r = 0; r < table.rowCount(); ++r) {
        int needs = 0;
        for (int c = 0; c < table.columnCount(); ++c) {
            const QTableWidgetItem* item = table.item(r, c);
            if (!item || item->text().isEmpty())
                continue;
            // A little narrower than the delegate's text: a line within a few pixels of the
            // edge may be measured on two lines by the table, and that is fine.
            const QRect inner = table.visualRect(table.model()->index(r, c)).adjusted(5, 0, -5, 0);
            needs = std::max(needs, QFontMetrics(item->font())
                                        .boundingRect(inner, Qt::TextWordWrap, item->text())
                                        .height());
        }
        if (table.rowHeight(r) > needs + 12)
            problems << QStringLiteral("row %1 is %2 px tall for %3 px of text")
                            .arg(r)
                            .arg(table.rowHeight(r))
                            .arg(needs);
    }
    for (int c = 0; c < table.columnCount(); ++c) {
        const QString header = table.horizontalHeaderItem(c)->text();
        const int needs = table.horizontalHeader()->fontMetrics().horizontalAdvance(header);
        if (needs > table.columnWidth(c))
            problems << QStringLiteral("header \"%1\" needs %2 px of %3")
                            .arg(header)
                            .arg(needs)
                            .arg(table.columnWidth(c));
    }
    if (table.horizontalScrollBar()->maximum() > 0)
        problems << QStringLiteral("scrolls sideways by %1 px")
                        .arg(table.horizontalScrollBar()->maximum());
    return problems.join(QStringLiteral("; "));
}

/// The panel alone at `width`, tall enough for its table; then the table's check.
template <typename Panel> QString checkAtWidth(Panel& panel, int width)
{
    panel.resize(width, 900);
    panel.show();
    if (!QTest::qWaitForWindowExposed(&panel))
        return QStringLiteral("not shown");
    QCoreApplication::processEvents();
    FittingTable& table = *panel.table();
    QString problems = cellsNotShown(table);
    // A table of few rows is as tall as its rows: no inner scroll bar.
    if (table.verticalScrollBar()->maximum() > 0)
        problems += QStringLiteral("; scrolls by %1 px in %2 px")
                        .arg(table.verticalScrollBar()->maximum())
                        .arg(table.height());
    return problems;
}

ui::CsvTable readBack(const QString& path)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return {};
    return ui::parseCsv(f.readAll());
}

} // namespace

class TestTables : public QObject {
    Q_OBJECT
private slots:
    void bouncesFitANarrowColumn();
    void collisionFitsANarrowColumn();
    void wideTableWhereThereIsRoom();
    void csvReadsBack();
    void bouncesCsvHasTheNumbers();
    void collisionCsvHoldsBackTheAfterColumn();
    void satCsvHasTheAxes();
    void tablesNameBodiesByTheirLabels();
};

void TestTables::bouncesFitANarrowColumn()
{
    MainWindow w;
    QCOMPARE(w.openLesson(lesson("restitution"), true), QString());
    w.lessonPlayer().showMe(0);
    w.lessonPlayer().showMe(1); // the heights are shown, not held back
    for (int k = 0; k < 3000; ++k)
        w.controller().stepForward();
    ui::BouncePanel panel(w.controller());
    QString problems = checkAtWidth(panel, kNarrow);
    QVERIFY2(problems.isEmpty(), qPrintable(problems));
    QVERIFY(panel.table()->isNarrow());
    // Four balls, each with its title, drop and four bounces; numbers filled in.
    QCOMPARE(panel.table()->rowCount(), 4 * 6);
    bool numbers = false;
    for (int r = 0; r < panel.table()->rowCount(); ++r)
        numbers = numbers || (panel.table()->item(r, 1) &&
                              panel.table()->item(r, 1)->text().contains(QLatin1Char('0')));
    QVERIFY(numbers);
    // Still whole when the column is narrower still.
    problems = checkAtWidth(panel, 170);
    QVERIFY2(problems.isEmpty(), qPrintable(problems));
}

void TestTables::collisionFitsANarrowColumn()
{
    // The off-centre hit has the most rows: both bodies, spins and the two predictions.
    for (int step : {1, 3}) {
        MainWindow w;
        QCOMPARE(w.openLesson(lesson("restitution"), true), QString());
        w.lessonPlayer().goToStep(step);
        for (int k = 0; k < 2000; ++k)
            w.controller().stepForward();
        QVERIFY(!w.controller().lessonWatch().measurements().collisions().empty());
        ui::CollisionPanel panel(w.controller());
        const QString problems = checkAtWidth(panel, kNarrow);
        QVERIFY2(problems.isEmpty(), qPrintable(QStringLiteral("step %1: ").arg(step) + problems));
        QVERIFY(panel.table()->isNarrow());
        QVERIFY(panel.table()->rowCount() >= 8);
    }
}

void TestTables::wideTableWhereThereIsRoom()
{
    MainWindow w;
    QCOMPARE(w.openLesson(lesson("restitution"), true), QString());
    w.lessonPlayer().goToStep(1);
    for (int k = 0; k < 2000; ++k)
        w.controller().stepForward();
    ui::CollisionPanel panel(w.controller());
    const QString problems = checkAtWidth(panel, 700);
    QVERIFY2(problems.isEmpty(), qPrintable(problems));
    QVERIFY(!panel.table()->isNarrow());
    QCOMPARE(panel.table()->columnCount(), 3);
    // Switching back and forth keeps the content.
    QVERIFY(checkAtWidth(panel, kNarrow).isEmpty());
    QVERIFY(panel.table()->isNarrow());
    QVERIFY(checkAtWidth(panel, 700).isEmpty());
    QVERIFY(!panel.table()->isNarrow());
}

void TestTables::csvReadsBack()
{
    ui::CsvTable t;
    t.headers = QStringList{QStringLiteral("name"), QStringLiteral("v [m/s]")};
    t.rows << QStringList{QStringLiteral("a, \"quoted\""), ui::csvNumber(0.1)};
    t.rows << QStringList{QStringLiteral("two\nlines"), ui::csvNumber(-1e-300)};
    t.rows << QStringList{QStringLiteral("gap"), ui::csvNumber(std::nan(""))};
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("t.csv"));
    QCOMPARE(ui::writeCsv(path, t), QString());
    const ui::CsvTable back = readBack(path);
    QCOMPARE(back.headers, t.headers);
    QCOMPARE(back.rows, t.rows);
    QCOMPARE(ui::csvNumber(0.1), QStringLiteral("0.1"));
    QCOMPARE(back.rows[1][1].toDouble(), -1e-300);
    QVERIFY(back.rows[2][1].isEmpty());
    // A folder that cannot be written: the reason, and nothing half written.
    const QString bad = dir.filePath(QStringLiteral("missing/t.csv"));
    QVERIFY(!ui::writeCsv(bad, t).isEmpty());
    QVERIFY(!QFile::exists(bad));
}

void TestTables::bouncesCsvHasTheNumbers()
{
    // In Czech the table shows decimal commas; the file has decimal points all the same.
    QLocale::setDefault(QLocale(QLocale::Czech));
    MainWindow w;
    QCOMPARE(w.openLesson(lesson("restitution"), true), QString());
    w.lessonPlayer().showMe(0);
    w.lessonPlayer().showMe(1);
    for (int k = 0; k < 3000; ++k)
        w.controller().stepForward();
    ui::BouncePanel panel(w.controller());
    panel.refresh();
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("bounces.csv"));
    QCOMPARE(panel.table()->exportCsv(path), QString());
    const ui::CsvTable back = readBack(path);
    QLocale::setDefault(QLocale::c());
    QCOMPARE(back.headers, panel.table()->csv().headers);
    QCOMPARE(back.rows, panel.table()->csv().rows);
    QCOMPARE(back.headers.size(), 3 + 2 * 4);
    QCOMPARE(back.rows.size(), 4);
    for (const QStringList& row : back.rows) {
        // e as the body has it, exactly.
        // The ball as the class reads it: its label (here in English), not its id.
        const auto& bodies = w.controller().world().bodies();
        const lessons::Scene& scene = w.controller().scene();
        const auto body = std::find_if(bodies.begin(), bodies.end(), [&](const auto& b) {
            const auto id = static_cast<physics::BodyId>(&b - bodies.data());
            return scene.hasLabel(id) && scene.bodyLabel(id) == row[0];
        });
        QVERIFY(body != bodies.end());
        bool ok = false;
        QCOMPARE(row[1].toDouble(&ok), body->restitution);
        QVERIFY(ok);
        // The first bounce's height: the measured apex, exactly.
        const auto& apexes = w.controller().lessonWatch().measurements().apexes(
            static_cast<int>(body - bodies.begin()));
        if (!apexes.empty()) {
            QCOMPARE(row[3].toDouble(&ok), apexes.front().y - apexes.front().bounceY);
            QVERIFY(ok);
        }
        for (const QString& cell : row)
            QVERIFY2(!cell.contains(QLatin1Char(',')), qPrintable(cell));
    }
}

void TestTables::collisionCsvHoldsBackTheAfterColumn()
{
    MainWindow w;
    QCOMPARE(w.openLesson(lesson("restitution"), true), QString());
    w.lessonPlayer().goToStep(1);
    for (int k = 0; k < 2000; ++k)
        w.controller().stepForward();
    ui::CollisionPanel& panel = w.collisionPanel();
    panel.refresh();
    const ui::CsvTable& held = panel.table()->csv();
    QVERIFY(held.rows.size() >= 6);
    for (const QStringList& row : held.rows) {
        QVERIFY2(row[2].isEmpty(), qPrintable(row.join(u',')));
        QVERIFY(!row[1].isEmpty() || row[0].contains(QStringLiteral("formula")));
    }
    // The narrow form holds it back too: its last column is "after".
    ui::CollisionPanel alone(w.controller());
    alone.setAfterHeld(true);
    QCOMPARE(checkAtWidth(alone, kNarrow), QString());
    QVERIFY(alone.table()->isNarrow());
    const ui::TableText& narrow = alone.table()->shownText();
    for (int r = 0; r < narrow.rows.size(); ++r)
        if (!narrow.isTitle(r))
            QVERIFY2(narrow.rows[r].last() == QStringLiteral("?"),
                     qPrintable(narrow.rows[r].join(u'|')));
    w.lessonPlayer().showMe(0);
    w.lessonPlayer().showMe(1);
    panel.refresh();
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("collision.csv"));
    QCOMPARE(panel.table()->exportCsv(path), QString());
    const ui::CsvTable back = readBack(path);
    QCOMPARE(back.headers, (QStringList{QStringLiteral("quantity"), QStringLiteral("before"),
                                        QStringLiteral("after")}));
    QCOMPARE(back.rows, panel.table()->csv().rows);
    // The momentum before and after, as the event recorded it, to the last bit.
    const lessons::CollisionEvent& e =
        w.controller().lessonWatch().measurements().collisions().front();
    const auto& world = w.controller().world();
    const double pBefore = world.body(e.a).mass * e.velocityBefore[0].x() +
                           world.body(e.b).mass * e.velocityBefore[1].x();
    bool found = false;
    for (const QStringList& row : back.rows)
        if (row[0] == QStringLiteral("momentum x [kg m/s]")) {
            QCOMPARE(row[1].toDouble(), pBefore);
            QVERIFY(!row[2].isEmpty());
            found = true;
        }
    QVERIFY(found);
}

void TestTables::satCsvHasTheAxes()
{
    MainWindow w;
    QCOMPARE(w.openLesson(lesson("separating_axis"), true), QString());
    const lessons::Lesson* l = w.lessonPlayer().lesson();
    int satStep = -1;
    for (std::size_t s = 0; s < l->steps.size() && satStep < 0; ++s)
        if (l->steps[s].sat)
            satStep = static_cast<int>(s);
    QVERIFY(satStep >= 0);
    w.lessonPlayer().goToStep(satStep);
    ui::SatPanel& panel = w.satPanel();
    panel.showAll();
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("sat.csv"));
    QCOMPARE(ui::writeCsv(path, panel.csv()), QString());
    const ui::CsvTable back = readBack(path);
    QCOMPARE(back.headers.first(), QStringLiteral("axis"));
    const auto& axes = panel.result().axes;
    QCOMPARE(back.rows.size(), static_cast<qsizetype>(axes.size()));
    QCOMPARE(back.rows.size(), static_cast<qsizetype>(panel.table().rowCount()));
    const int overlap = static_cast<int>(back.headers.indexOf(QStringLiteral("overlap [m]")));
    QVERIFY(overlap > 0);
    for (std::size_t i = 0; i < axes.size(); ++i) {
        QCOMPARE(back.rows[static_cast<qsizetype>(i)][overlap].toDouble(), axes[i].overlap);
        QCOMPARE(back.rows[static_cast<qsizetype>(i)][5].toDouble(), axes[i].minA);
    }
}

void TestTables::tablesNameBodiesByTheirLabels()
{
    // In Czech, the collision of the light and the heavy ball names them as the scene labels
    // them in Czech, in the caption, the table and its file; never by their ids.
    QVERIFY(ui::applyLanguage(QStringLiteral("cs")));
    const auto restoreEnglish = qScopeGuard([] { ui::applyLanguage(QStringLiteral("en")); });
    {
        MainWindow w;
        QCOMPARE(w.openLesson(lesson("restitution"), true), QString());
        w.lessonPlayer().goToStep(1);
        for (int k = 0; k < 2000; ++k)
            w.controller().stepForward();
        ui::CollisionPanel panel(w.controller());
        panel.refresh();
        QStringList shown;
        for (const QLabel* label : panel.findChildren<QLabel*>())
            shown << label->text();
        for (const QStringList& row : panel.table()->shownText().rows)
            shown << row;
        for (const QStringList& row : panel.table()->csv().rows)
            shown << row;
        const QString all = shown.join(u'|');
        QVERIFY2(all.contains(QStringLiteral("lehká koule")), qPrintable(all));
        QVERIFY2(all.contains(QStringLiteral("těžká koule")), qPrintable(all));
        QVERIFY2(!all.contains(QStringLiteral("light")), qPrintable(all));
        QVERIFY2(!all.contains(QStringLiteral("heavy")), qPrintable(all));
        // The inspector names a clicked body the same way (body 0 is the light ball).
        w.inspector().setBody(0);
        QStringList inspector;
        for (const QLabel* label : w.inspector().findChildren<QLabel*>())
            inspector << label->text();
        const QString shownThere = inspector.join(u'|');
        QVERIFY2(shownThere.contains(QStringLiteral("lehká koule (")), qPrintable(shownThere));
        QVERIFY2(!shownThere.contains(QStringLiteral("light")), qPrintable(shownThere));
    }
    {
        // The bounce table's groups are named by their e, as the lesson calls the balls
        // ("the ball with e = 0.8"), in the window's number format; not "e08".
        MainWindow w;
        QCOMPARE(w.openLesson(lesson("restitution"), true), QString());
        ui::BouncePanel panel(w.controller());
        QCOMPARE(checkAtWidth(panel, kNarrow), QString());
        QVERIFY(panel.table()->isNarrow());
        QStringList groups;
        const ui::TableText& narrow = panel.table()->shownText();
        for (int r = 0; r < narrow.rows.size(); ++r)
            if (narrow.isTitle(r))
                groups << narrow.rows[r].join(u' ');
        QCOMPARE(groups, (QStringList{QStringLiteral("e = 0,00 (e² = 0,000)"),
                                      QStringLiteral("e = 0,50 (e² = 0,250)"),
                                      QStringLiteral("e = 0,80 (e² = 0,640)"),
                                      QStringLiteral("e = 1,00 (e² = 1,000)")}));
        // The file names each ball by its Czech label (numbered from the left: e can be
        // changed, a name must not lie).
        const auto& rows = panel.table()->csv().rows;
        QCOMPARE(rows.size(), 4);
        QCOMPARE(rows[1][0], QStringLiteral("míček 2"));
    }
}

RIGIDLAB_TEST_MAIN(TestTables)
#include "test_tables.moc"
