// SPDX-License-Identifier: GPL-3.0-or-later
// The separating-axis view shows its axis: for every shipped SAT case and
// every axis, the world view shows both projection intervals and the gap or overlap label,
// also after Fit scene and after a body was dragged away; the label is readable and the table
// fits the window's right column without a horizontal scroll bar.

#include "common/theme.h"
#include "lesson_player/lesson_player.h"
#include "panels/sat_panel.h"
#include "simulation/simulation_controller.h"
#include "view/sat_view_model.h"
#include "view/world_view.h"
#include "window/main_window.h"

#include "format/lesson.h"
#include "format/scene_loader.h"

#include <QGraphicsScene>

#include <QApplication>
#include <QHeaderView>
#include <QPushButton>
#include <QScrollArea>
#include <QScrollBar>
#include <QTableWidget>
#include <QtTest>

#include "test_main.h"

using namespace rigidlab;
using rigidlab::ui::MainWindow;
using rigidlab::ui::SatOverlayItem;

namespace {

/// Every step of a shipped lesson that sets a SAT pair: (lesson file, step index).
std::vector<std::pair<QString, int>> satSteps()
{
    std::vector<std::pair<QString, int>> out;
    const QDir dir(MainWindow::lessonsFolder());
    for (const QString& f : dir.entryList({QStringLiteral("*.json")}, QDir::Files, QDir::Name)) {
        const lessons::LessonLoadResult r = lessons::loadLessonFile(dir.filePath(f));
        for (std::size_t s = 0; s < r.lesson.steps.size(); ++s)
            if (r.ok && r.lesson.steps[s].sat)
                out.emplace_back(dir.filePath(f), static_cast<int>(s));
    }
    return out;
}

QRectF visibleWorld(ui::WorldView& view)
{
    return view.mapToScene(view.viewport()->rect()).boundingRect();
}

/// Why `g` is not wholly inside `visible`, or an empty string.
QString notShown(const SatOverlayItem::Geometry& g, const QRectF& visible)
{
    if (!g.valid)
        return QStringLiteral("no geometry");
    QStringList missing;
    const std::pair<const char*, QPointF> ends[] = {
        {"A's first end", g.projectionA.p1()}, {"A's last end", g.projectionA.p2()},
        {"B's first end", g.projectionB.p1()}, {"B's last end", g.projectionB.p2()},
        {"the span's first end", g.span.p1()}, {"the span's last end", g.span.p2()}};
    for (const auto& [what, p] : ends)
        if (!visible.contains(p))
            missing << QStringLiteral("%1 (%2, %3)").arg(what).arg(p.x()).arg(p.y());
    if (!visible.contains(g.labelRect))
        missing << QStringLiteral("the label");
    if (missing.isEmpty())
        return QString();
    return missing.join(QStringLiteral(", ")) + QStringLiteral(" outside [%1, %2] x [%3, %4]")
                                                    .arg(visible.left())
                                                    .arg(visible.right())
                                                    .arg(visible.top())
                                                    .arg(visible.bottom());
}

/// A window of a projector's size (1024 × 768), shown (offscreen), at a lesson's SAT step.
struct Window {
    MainWindow w;
    bool open(const QString& path, int step)
    {
        w.resize(1024, 768);
        w.show();
        if (!QTest::qWaitForWindowExposed(&w))
            return false;
        if (!w.openLesson(path, true).isEmpty())
            return false;
        w.lessonPlayer().goToStep(step);
        QCoreApplication::processEvents(); // the docks settle into their sizes
        return w.satPanel().active();
    }
};

} // namespace

class TestSatView : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { QVERIFY2(!satSteps().empty(), "no shipped lesson has a SAT step"); }

    void coloursAreTheirOwnAndReadable()
    {
        using namespace ui::theme;
        const QColor bg = worldBackground();
        for (const QColor& c : {satGap(), satOverlap()}) {
            QVERIFY2(contrastRatio(c, bg) >= kMinTextContrast, qPrintable(c.name()));
            QVERIFY(c != satProjectionA() && c != satProjectionB());
            // Distinct at a glance from both intervals, not just a different code.
            QVERIFY(contrastRatio(c, satProjectionA()) > 1.2 ||
                    std::abs(c.hueF() - satProjectionA().hueF()) > 0.1);
            QVERIFY(std::abs(c.hueF() - satProjectionB().hueF()) > 0.1);
        }
        QVERIFY(std::abs(satGap().hueF() - satOverlap().hueF()) > 0.1);
    }

    // The overlay draws from the view model alone, no panel (no widget) in sight: the view
    // layer needs nothing from the panels.
    void overlayReadsTheModelAlone()
    {
        const lessons::SceneLoadResult loaded = lessons::loadSceneJson(R"({"rigidlab": 1,
            "world": {"gravity": [0, 0]}, "bodies": [
            {"id": "a", "shape": {"type": "box", "width": 1, "height": 1}, "position": [0, 0]},
            {"id": "b", "shape": {"type": "box", "width": 1, "height": 1}, "position": [0.8, 0.3],
             "angle": 0.3}]})",
                                                                       QStringLiteral("pair.json"));
        QVERIFY2(loaded.ok, qPrintable(loaded.error));
        ui::SimulationController c;
        c.loadScene(loaded.scene, QString());
        ui::SatViewModel model(c);
        QGraphicsScene scene;
        auto* overlay = new SatOverlayItem(model);
        scene.addItem(overlay);
        QVERIFY(!overlay->geometry(0.01).valid); // no pair yet
        model.setBodies(0, 1);
        QVERIFY(model.active());
        QCOMPARE(model.shown(), 1);
        const physics::SatResult& r = model.result();
        QVERIFY(r.intersects);
        const int total = static_cast<int>(r.axes.size());
        QVERIFY(total >= 2);
        const SatOverlayItem::Geometry first = overlay->geometry(0.01);
        QVERIFY(first.valid);
        QVERIFY(!first.contact);
        model.showAll();
        QCOMPARE(model.shown(), total);
        QVERIFY(model.complete());
        const SatOverlayItem::Geometry last = overlay->geometry(0.01);
        QVERIFY(last.contact);
        QVERIFY(last.label.contains(QStringLiteral("least overlap")));
        model.previousAxis();
        QCOMPARE(model.shown(), total - 1);
        // Nothing moved: a refresh says so; an id the world does not hold is no pair.
        QVERIFY(!model.refresh());
        model.setBodies(0, 7);
        QVERIFY(!model.active());
        QVERIFY(!overlay->geometry(0.01).valid);
    }
    void panelAndOverlayShareTheModel()
    {
        Window win;
        const auto steps = satSteps();
        QVERIFY(win.open(steps.front().first, steps.front().second));
        const ui::SatPanel& sat = win.w.satPanel();
        QVERIFY(sat.active());
        QCOMPARE(sat.model().bodyA(), sat.bodyA());
        QCOMPARE(&sat.model().result(), &sat.result());
        win.w.satPanel().nextAxis();
        QCOMPARE(sat.model().shown(), sat.shown());
        QCOMPARE(sat.table().rowCount(), sat.model().shown());
    }
    void everyAxisIsInView_data()
    {
        QTest::addColumn<QString>("path");
        QTest::addColumn<int>("step");
        for (const auto& [path, step] : satSteps())
            QTest::newRow(qPrintable(
                QStringLiteral("%1 step %2").arg(QFileInfo(path).baseName()).arg(step + 1)))
                << path << step;
    }
    void everyAxisIsInView()
    {
        QFETCH(QString, path);
        QFETCH(int, step);
        Window win;
        QVERIFY(win.open(path, step));
        ui::SatPanel& sat = win.w.satPanel();
        ui::WorldView& view = win.w.view();
        const physics::SatResult& r = sat.result();
        const int total = static_cast<int>(r.axes.size());
        QVERIFY(total >= 1);
        for (int axis = 1; axis <= total; ++axis) {
            if (axis > 1)
                sat.nextAxis();
            QCOMPARE(sat.shown(), axis);
            const SatOverlayItem::Geometry g = sat.overlayItem().geometry();
            const QString why = notShown(g, visibleWorld(view));
            QVERIFY2(why.isEmpty(), qPrintable(QStringLiteral("axis %1: %2 (view %3 x %4 px)")
                                                   .arg(axis)
                                                   .arg(why)
                                                   .arg(view.viewport()->width())
                                                   .arg(view.viewport()->height())));
            // The overlay's bounding rect covers what it draws, so none of it is culled.
            QVERIFY(sat.overlayItem().sceneBoundingRect().contains(g.drawn));
            // The label gives the gap or overlap in metres, in the user's locale.
            const physics::SatAxis& ax = r.axes[static_cast<std::size_t>(axis - 1)];
            QVERIFY2(g.label.contains(QLocale().toString(std::abs(ax.overlap), 'f', 2)),
                     qPrintable(g.label));
            QCOMPARE(g.gap, ax.overlap < 0);
            QVERIFY(g.label.startsWith(ax.overlap < 0 ? QStringLiteral("gap")
                                                      : QStringLiteral("overlap")));
            QCOMPARE(g.label.contains(QStringLiteral("separating axis")),
                     axis - 1 == r.separatingAxis);
            // The test walks no further than it has to: the separating axis is the last.
            if (axis - 1 == r.separatingAxis)
                QCOMPARE(axis, total);
            // Fit scene (F) keeps the overlay in view too.
            view.fitScene();
            const QString afterFit = notShown(sat.overlayItem().geometry(), visibleWorld(view));
            QVERIFY2(
                afterFit.isEmpty(),
                qPrintable(QStringLiteral("axis %1 after Fit scene: %2").arg(axis).arg(afterFit)));
        }
        // At the verdict of an overlap, the canvas names the contact normal's axis.
        const SatOverlayItem::Geometry last = sat.overlayItem().geometry();
        QCOMPARE(last.contact, r.intersects && r.manifold.pointCount > 0);
        QCOMPARE(last.label.contains(QStringLiteral("least overlap")), r.intersects);
        if (r.intersects && r.leastAxis + 1 != total)
            QVERIFY(last.label.contains(QString::number(r.leastAxis + 1)));
        // And stepping back brings the view back to each axis.
        for (int axis = total - 1; axis >= 1; --axis) {
            sat.previousAxis();
            const QString why = notShown(sat.overlayItem().geometry(), visibleWorld(view));
            QVERIFY2(why.isEmpty(),
                     qPrintable(QStringLiteral("back at axis %1: %2").arg(axis).arg(why)));
        }
    }

    void viewFollowsADraggedBody()
    {
        const auto steps = satSteps();
        Window win;
        QVERIFY(win.open(steps.front().first, steps.front().second));
        ui::SatPanel& sat = win.w.satPanel();
        sat.showAll();
        auto& controller = win.w.controller();
        const physics::Vec2 start = controller.world().body(sat.bodyB()).position;
        controller.grab(sat.bodyB(), start);
        controller.dragTo(start + physics::Vec2(4.0, 3.0));
        for (int i = 0; i < 3000; ++i)
            controller.stepForward();
        controller.release();
        const physics::Vec2 end = controller.world().body(sat.bodyB()).position;
        QVERIFY2((end - start).norm() > 2.0, "the drag did not move the body");
        const QString why = notShown(sat.overlayItem().geometry(), visibleWorld(win.w.view()));
        QVERIFY2(why.isEmpty(), qPrintable(why));
    }

    // On a 1024×768 projector, normal and presentation: the table in the window's (enlarged)
    // font fits its dock without scrolling sideways, and Previous, Next and All show their
    // whole text.
    void panelFitsItsDock_data()
    {
        QTest::addColumn<bool>("present");
        QTest::newRow("normal") << false;
        QTest::newRow("presentation") << true;
    }
    void panelFitsItsDock()
    {
        QFETCH(bool, present);
        for (const auto& [path, step] : satSteps()) {
            Window win;
            QVERIFY(win.open(path, step));
            win.w.fitToScreen(QRect(0, 0, 1024, 768));
            if (present) {
                win.w.setPresentation(true);
                win.w.setWindowState(Qt::WindowNoState);
                win.w.resize(1024, 768);
            }
            win.w.show();
            QVERIFY(QTest::qWaitForWindowExposed(&win.w));
            win.w.lessonPlayer().goToStep(step);
            QCoreApplication::processEvents();
            const QString where =
                QStringLiteral("%1 step %2: ").arg(QFileInfo(path).baseName()).arg(step + 1);
            const ui::SatPanel& panel = win.w.satPanel();
            QVERIFY(panel.isVisible());
            const QTableWidget& table = panel.table();
            if (present)
                QVERIFY2(table.font().pointSizeF() >=
                             ui::theme::kPresentationFontScale *
                                     QApplication::font(&table).pointSizeF() -
                                 1e-6,
                         qPrintable(where + QStringLiteral("the table keeps its small font")));
            QVERIFY2(!table.horizontalScrollBar()->isVisible() &&
                         table.horizontalHeader()->length() <= table.viewport()->width(),
                     qPrintable(where + QStringLiteral("columns %1 px in %2 px")
                                            .arg(table.horizontalHeader()->length())
                                            .arg(table.viewport()->width())));
            for (const QWidget* p = panel.parentWidget(); p; p = p->parentWidget())
                if (const auto* scroll = qobject_cast<const QScrollArea*>(p))
                    QVERIFY2(!scroll->horizontalScrollBar()->isVisible(),
                             qPrintable(where + QStringLiteral("the panel scrolls sideways")));
            for (const QPushButton* b : panel.findChildren<QPushButton*>()) {
                const int text = b->fontMetrics().horizontalAdvance(b->text());
                QVERIFY2(b->width() >= text + 8,
                         qPrintable(where + QStringLiteral("%1: %2 px for %3 px of text")
                                                .arg(b->text())
                                                .arg(b->width())
                                                .arg(text)));
                // (The panel may scroll up and down in its dock: a button can be below.)
                QVERIFY2(b->height() >= b->sizeHint().height(),
                         qPrintable(where + b->text() + QStringLiteral(" is cut")));
            }
        }
    }

    void tableFitsTheRightColumn_data()
    {
        QTest::addColumn<int>("width");
        QTest::newRow("250 px") << 250;
        QTest::newRow("300 px") << 300;
    }
    void tableFitsTheRightColumn()
    {
        QFETCH(int, width);
        for (const auto& [path, step] : satSteps()) {
            Window win;
            QVERIFY(win.open(path, step));
            const ui::SatPanel& shown = win.w.satPanel();
            // A second panel on the same pair, alone at the column's width, every axis listed.
            ui::SatPanel panel(win.w.controller());
            panel.setBodies(shown.bodyA(), shown.bodyB());
            panel.showAll();
            panel.resize(width, 600);
            panel.show();
            QVERIFY(QTest::qWaitForWindowExposed(&panel));
            QCoreApplication::processEvents();
            QVERIFY2(panel.width() <= width + 1,
                     qPrintable(QStringLiteral("the panel needs %1 px").arg(panel.width())));
            const QTableWidget& table = panel.table();
            QCOMPARE(table.rowCount(), static_cast<int>(panel.result().axes.size()));
            QVERIFY2(table.horizontalScrollBar()->maximum() == 0,
                     qPrintable(QStringLiteral("%1 step %2: scrolls by %3 px")
                                    .arg(QFileInfo(path).baseName())
                                    .arg(step + 1)
                                    .arg(table.horizontalScrollBar()->maximum())));
            // Three columns, none wider than the table.
            QCOMPARE(table.columnCount(), 3);
            QVERIFY2(table.horizontalHeader()->length() <= table.viewport()->width(),
                     qPrintable(QStringLiteral("columns %1 px in %2 px")
                                    .arg(table.horizontalHeader()->length())
                                    .arg(table.viewport()->width())));
            // The verdict under the overlap says its word in full, and explains itself in
            // the tooltip.
            int notes = 0;
            for (int row = 0; row < table.rowCount(); ++row) {
                const QTableWidgetItem* overlap = table.item(row, 2);
                QVERIFY(overlap);
                const QStringList lines = overlap->text().split(QLatin1Char('\n'));
                if (lines.size() < 2)
                    continue;
                ++notes;
                QVERIFY(lines[1] == QLatin1String("separates") ||
                        lines[1] == QLatin1String("least overlap"));
                QVERIFY(overlap->toolTip().size() > overlap->text().size());
            }
            QCOMPARE(notes, 1); // the separating axis, or the one of least overlap
        }
    }
};

RIGIDLAB_TEST_MAIN(TestSatView)
#include "test_sat_view.moc"
