// SPDX-License-Identifier: GPL-3.0-or-later
// A few drawings: the error-vs-run-time panel on a 1024 × 768 screen, its
// order labels apart and in words where no order can be measured; the compared worlds drawn
// with their floors; velocity arrows only where they have a length; the billiards break big
// and slow enough to watch; springs whose coils stay apart with presentation mode's thick lines.

#include "common/theme.h"
#include "lesson_player/lesson_player.h"
#include "panels/error_panel.h"
#include "plots/work_precision_plot.h"
#include "simulation/simulation_controller.h"
#include "view/body_item.h"
#include "view/label_layout.h"
#include "view/overlays.h"
#include "view/world_view.h"
#include "window/main_window.h"

#include "format/lesson.h"
#include "numerics/error_vs_time.h"

#include <QDockWidget>
#include <QImage>
#include <QPainter>
#include <QtTest>

#include <qcustomplot.h>

#include <cmath>

#include "near.h"
#include "test_main.h"

using namespace rigidlab;
using rigidlab::ui::MainWindow;

namespace {

QString lesson(const char* name)
{
    return QDir(MainWindow::lessonsFolder())
        .filePath(QLatin1StringView(name) + QStringLiteral(".json"));
}

/// Rows of one integrator whose error falls as dt^order, its CPU time as 1/dt.
std::vector<lessons::SweepRow> rowsOf(const QString& integrator, double order, double scale,
                                      int count = 4)
{
    std::vector<lessons::SweepRow> rows;
    double dt = 0.1;
    for (int i = 0; i < count; ++i, dt /= 2) {
        lessons::SweepRow r;
        r.problem = QStringLiteral("oscillator");
        r.integrator = integrator;
        r.dt = dt;
        r.error = scale * std::pow(dt, order);
        r.seconds = 1e-4 / dt;
        rows.push_back(r);
    }
    return rows;
}

} // namespace

class TestDrawings : public QObject {
    Q_OBJECT
private slots:
    void errorPanelOpensOnASmallScreen();
    void orderLabelsApartAndInWords();
    void ghostWorldsDrawTheirFloor();
    void velocityArrowsOnlyWithALength_data();
    void velocityArrowsOnlyWithALength();
    void billiardsBallsBigAndBreakSlow();
    void bodiesLargeEnoughAfterTheStep_data();
    void bodiesLargeEnoughAfterTheStep();
    void springCoilsStayApart_data();
    void springCoilsStayApart();
    void labelsPlacedApartAndInside();
    void bodyLabelsInSightAndApart();
};

void TestDrawings::errorPanelOpensOnASmallScreen()
{
    const QRect screen(0, 0, 1024, 768);
    MainWindow w;
    w.fitToScreen(screen);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QDockWidget* dock = w.dock(QStringLiteral("error"));
    QVERIFY(dock);
    dock->show();
    QCoreApplication::processEvents();
    QVERIFY(dock->isFloating());
    QVERIFY2(screen.contains(dock->frameGeometry()),
             qPrintable(QStringLiteral("%1,%2 %3×%4")
                            .arg(dock->frameGeometry().x())
                            .arg(dock->frameGeometry().y())
                            .arg(dock->frameGeometry().width())
                            .arg(dock->frameGeometry().height())));
    auto* plot = dock->findChild<ui::WorkPrecisionPlot*>();
    QVERIFY(plot);
    QVERIFY2(plot->height() >= ui::WorkPrecisionPlot::kMinPlotHeight,
             qPrintable(QString::number(plot->height())));
    plot->plot()->replot();
    // The y label stands whole beside the axis.
    QCPAxis* y = plot->plot()->yAxis;
    const int labelLength = QFontMetrics(y->labelFont()).horizontalAdvance(y->label());
    QVERIFY2(labelLength <= y->axisRect()->height(),
             qPrintable(
                 QStringLiteral("%1 px beside %2").arg(labelLength).arg(y->axisRect()->height())));

    // On a roomy screen it stays in the bottom dock area.
    MainWindow roomy;
    roomy.fitToScreen(QRect(0, 0, 1920, 1080));
    QVERIFY(!roomy.dock(QStringLiteral("error"))->isFloating());
}

void TestDrawings::orderLabelsApartAndInWords()
{
    ui::WorkPrecisionPlot plot;
    plot.resize(520, ui::WorkPrecisionPlot::kMinPlotHeight);
    plot.show();
    QVERIFY(QTest::qWaitForWindowExposed(&plot));
    // Five integrators whose most accurate points coincide: their labels would sit on top of
    // one another. One more at round-off everywhere, and one with a single run.
    const QStringList names = lessons::sweepIntegratorNames();
    QVERIFY(names.size() >= 7);
    std::vector<lessons::SweepRow> rows;
    for (int i = 0; i < 5; ++i) {
        // The same last point (dt = 0.0125) for all: error 1e-6 there.
        const double order = 1.0 + i * 0.5;
        const auto mine = rowsOf(names[i], order, 1e-6 / std::pow(0.0125, order));
        rows.insert(rows.end(), mine.begin(), mine.end());
    }
    const auto roundOff = rowsOf(names[5], 4.0, 1e-14 / std::pow(0.1, 4.0));
    rows.insert(rows.end(), roundOff.begin(), roundOff.end());
    const auto single = rowsOf(names[6], 2.0, 1.0, 1);
    rows.insert(rows.end(), single.begin(), single.end());
    plot.setRows(rows);
    plot.plot()->replot();

    QCOMPARE(plot.orderLabel(names[0]),
             QStringLiteral("p = %1").arg(QLocale().toString(1.0, 'f', 1)));
    QVERIFY2(plot.orderLabel(names[5]).contains(QStringLiteral("round-off")),
             qPrintable(plot.orderLabel(names[5])));
    QVERIFY2(plot.orderLabel(names[6]).contains(QStringLiteral("second run")),
             qPrintable(plot.orderLabel(names[6])));
    for (const QString& name : names.mid(0, 7))
        QVERIFY2(!plot.orderLabel(name).contains(QLatin1Char('?')), qPrintable(name));

    const auto& boxes = plot.labelBoxes();
    QCOMPARE(boxes.size(), std::size_t(7));
    const QRectF area = plot.plot()->axisRect()->rect();
    for (auto a = boxes.begin(); a != boxes.end(); ++a) {
        QVERIFY2(area.contains(a->second), qPrintable(a->first));
        for (auto b = std::next(a); b != boxes.end(); ++b)
            QVERIFY2(!a->second.intersects(b->second),
                     qPrintable(QStringLiteral("%1 and %2").arg(a->first, b->first)));
    }

    // lessons::orderGap says which: a run that blew up makes the errors too large.
    auto blown = rowsOf(QStringLiteral("x"), 1.0, 1.0);
    for (auto& r : blown)
        r.error = r.error > 0.5 ? NAN : 0.5;
    QCOMPARE(lessons::orderGap(blown, QStringLiteral("oscillator"), QStringLiteral("x")),
             lessons::OrderGap::TooLarge);
    QCOMPARE(lessons::orderGap(rows, QStringLiteral("oscillator"), names[0]),
             lessons::OrderGap::None);
}

void TestDrawings::ghostWorldsDrawTheirFloor()
{
    MainWindow w;
    QCOMPARE(w.openLesson(lesson("stacks"), true), QString());
    const lessons::Lesson* l = w.lessonPlayer().lesson();
    int checked = 0;
    for (std::size_t s = 0; s < l->steps.size(); ++s) {
        const lessons::LessonStep& step = l->steps[s];
        if (!step.compare)
            continue;
        w.lessonPlayer().goToStep(static_cast<int>(s));
        const ui::SimulationController& c = w.controller();
        QVERIFY(!c.variantOffset().isZero());
        for (int v = 0; v < c.variantCount(); ++v) {
            const auto items = w.view().ghostItems(v);
            QCOMPARE(items.size(), c.variant(v).bodies().size());
            bool floor = false;
            for (const ui::BodyItem* item : items) {
                const physics::Body& b = c.variant(v).body(item->bodyId());
                floor = floor || !b.moves();
                // Drawn where the compared world is: shifted by its offset.
                const physics::Vec2 at = b.origin() + (v + 1) * c.variantOffset();
                const QPointF origin = item->frame().map(QPointF(0, 0)); // the body's origin
                RL_VERIFY_NEAR(origin.x(), at.x(), 1e-9, 0);
                RL_VERIFY_NEAR(origin.y(), at.y(), 1e-9, 0);
            }
            QVERIFY2(floor, "the compared stack stands on a drawn floor");
        }
        // Side by side, not across each other: no world's floor or wall meets another's.
        std::vector<std::vector<QRectF>> statics(static_cast<std::size_t>(c.variantCount()) + 1);
        for (std::size_t i = 0; i < c.world().bodies().size(); ++i)
            if (!c.world().bodies()[i].moves())
                statics[0].push_back(w.view().itemFor(static_cast<int>(i))->sceneBox());
        for (int v = 0; v < c.variantCount(); ++v)
            for (const ui::BodyItem* item : w.view().ghostItems(v))
                if (!c.variant(v).body(item->bodyId()).moves())
                    statics[static_cast<std::size_t>(v) + 1].push_back(item->sceneBox());
        for (std::size_t a = 0; a < statics.size(); ++a)
            for (std::size_t b = a + 1; b < statics.size(); ++b)
                for (const QRectF& ra : statics[a])
                    for (const QRectF& rb : statics[b])
                        QVERIFY2(!ra.intersects(rb),
                                 qPrintable(QStringLiteral("step %1: worlds %2 and %3 overlap")
                                                .arg(s + 1)
                                                .arg(a)
                                                .arg(b)));
        QVERIFY(!statics[0].empty());
        ++checked;
    }
    QVERIFY(checked > 0);
}

void TestDrawings::velocityArrowsOnlyWithALength_data()
{
    QTest::addColumn<double>("vx");
    QTest::addColumn<double>("vy");
    QTest::addColumn<double>("metresPerPixel");
    QTest::addColumn<bool>("shown");
    // An arrow is 0.25 s of motion long.
    QTest::newRow("at rest, round-off") << 4e-19 << -3e-19 << 0.01 << false;
    QTest::newRow("exactly zero") << 0.0 << 0.0 << 0.01 << false;
    QTest::newRow("2 px") << 0.08 << 0.0 << 0.01 << false;
    QTest::newRow("4 px") << 0.0 << -0.16 << 0.01 << true;
    QTest::newRow("1 m/s at 100 px/m") << 0.6 << 0.8 << 0.01 << true;
    QTest::newRow("slow, zoomed in far") << 1e-6 << 0.0 << 1e-8 << true;
    QTest::newRow("not finite") << double(NAN) << 0.0 << 0.01 << false;
}

void TestDrawings::velocityArrowsOnlyWithALength()
{
    QFETCH(double, vx);
    QFETCH(double, vy);
    QFETCH(double, metresPerPixel);
    QFETCH(bool, shown);
    QCOMPARE(ui::OverlayItem::velocityArrowShown(physics::Vec2(vx, vy), metresPerPixel), shown);
}

void TestDrawings::billiardsBallsBigAndBreakSlow()
{
    // At 1024 × 768, every step of the billiards lesson: the balls at least 8 px across while
    // the break happens, and the cue ball's run to the rack at least a second on the clock
    // (the steps run in slow motion).
    MainWindow w;
    w.fitToScreen(QRect(0, 0, 1024, 768));
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QCOMPARE(w.openLesson(lesson("billiards_momentum"), true), QString());
    const lessons::Lesson* l = w.lessonPlayer().lesson();
    int breaks = 0;
    for (std::size_t s = 0; s < l->steps.size(); ++s) {
        // The step built in the editor is a two-ball collision, not a break.
        if (l->steps[s].editor)
            continue;
        ++breaks;
        w.lessonPlayer().goToStep(static_cast<int>(s));
        ui::SimulationController& c = w.controller();
        c.setRunning(false);
        QCoreApplication::processEvents();
        const physics::World& world = c.world();
        double radius = 0;
        int cue = -1;
        for (std::size_t i = 0; i < world.bodies().size(); ++i)
            if (world.bodies()[i].moves()) {
                const physics::Circle* ball = world.bodies()[i].shape.asCircle();
                QVERIFY(ball);
                radius = ball->radius;
                if (world.bodies()[i].name == "cue")
                    cue = static_cast<int>(i);
            }
        QVERIFY(cue >= 0);
        // Until the first collision (the break), then half a second more.
        double breakTime = -1;
        while (c.world().time() < 3.0) {
            c.stepForward();
            if (breakTime < 0 && !c.lessonWatch().measurements().collisions().empty())
                breakTime = c.world().time();
            if (breakTime >= 0 && c.world().time() > breakTime + 0.5)
                break;
        }
        QVERIFY(breakTime > 0);
        w.view().syncPoses();
        QCoreApplication::processEvents();
        const double diameterPx = 2 * radius * w.view().zoom();
        QVERIFY2(
            diameterPx >= 8.0,
            qPrintable(QStringLiteral("step %1: balls %2 px across").arg(s + 1).arg(diameterPx)));
        // Where the cushions are gone, the view widens to follow the balls that leave: at
        // 2 s (the step's handout time) they are still more than dots.
        while (c.world().time() < 2.0)
            c.stepForward();
        w.view().syncPoses();
        QVERIFY2(2 * radius * w.view().zoom() >= 5.0,
                 qPrintable(QStringLiteral("step %1 at 2 s: balls %2 px across")
                                .arg(s + 1)
                                .arg(2 * radius * w.view().zoom())));
        const double timeScale = l->steps[s].settings.get<double>("timeScale").value_or(1.0);
        QVERIFY2(breakTime / timeScale >= 1.0,
                 qPrintable(QStringLiteral("step %1: the break after %2 s on the clock")
                                .arg(s + 1)
                                .arg(breakTime / timeScale)));
    }
    QVERIFY(breaks >= 3);
}

void TestDrawings::bodiesLargeEnoughAfterTheStep_data()
{
    QTest::addColumn<QString>("name");
    QTest::addColumn<int>("step");
    QTest::addColumn<bool>("present");
    // Four pendulums side by side (10 cm bobs in a scene 10 m wide) and a break whose cue
    // balls run off: the bodies were 4 to 7 px dots.
    QTest::newRow("energy_drift 3") << QStringLiteral("energy_drift") << 2 << false;
    QTest::newRow("energy_drift 3, presentation") << QStringLiteral("energy_drift") << 2 << true;
    QTest::newRow("billiards 3") << QStringLiteral("billiards_momentum") << 2 << false;
    QTest::newRow("billiards 3, presentation") << QStringLiteral("billiards_momentum") << 2 << true;
}

void TestDrawings::bodiesLargeEnoughAfterTheStep()
{
    // At 1024 × 768, after the step's own time: every moving body of every world, as drawn,
    // at least 10 px across, and most of them inside the view (only runaways may leave).
    QFETCH(QString, name);
    QFETCH(int, step);
    QFETCH(bool, present);
    MainWindow w;
    w.fitToScreen(QRect(0, 0, 1024, 768));
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QCOMPARE(w.openLesson(lesson(qPrintable(name)), true), QString());
    if (present)
        w.setPresentation(true);
    w.lessonPlayer().goToStep(step);
    ui::SimulationController& c = w.controller();
    c.setRunning(false);
    QCoreApplication::processEvents();
    const double seconds =
        w.lessonPlayer().lesson()->steps[static_cast<std::size_t>(step)].exportTime;
    QVERIFY(seconds > 0);
    while (c.world().time() < seconds - 1e-9)
        c.stepForward();
    w.view().syncPoses();
    QCoreApplication::processEvents();

    std::vector<const ui::BodyItem*> moving;
    for (std::size_t i = 0; i < c.world().bodies().size(); ++i)
        if (c.world().bodies()[i].moves())
            moving.push_back(w.view().itemFor(static_cast<int>(i)));
    for (int v = 0; v < c.variantCount(); ++v)
        for (const ui::BodyItem* item : w.view().ghostItems(v))
            if (c.variant(v).body(item->bodyId()).moves())
                moving.push_back(item);
    QVERIFY(moving.size() >= 4);
    const double minPx = present ? 14.0 : 10.0;
    const QRect viewport = w.view().viewport()->rect();
    std::size_t inside = 0;
    for (const ui::BodyItem* item : moving) {
        QVERIFY(item);
        const QRectF onScreen = w.view().mapFromScene(item->sceneBox()).boundingRect().toRectF();
        QVERIFY2(std::min(onScreen.width(), onScreen.height()) >= minPx - 1,
                 qPrintable(QStringLiteral("body %1: %2 × %3 px")
                                .arg(item->bodyId())
                                .arg(onScreen.width())
                                .arg(onScreen.height())));
        inside += viewport.contains(onScreen.center().toPoint()) ? 1 : 0;
    }
    QVERIFY2(
        inside * 10 >= moving.size() * 8,
        qPrintable(QStringLiteral("%1 of %2 bodies in the view").arg(inside).arg(moving.size())));
}

void TestDrawings::springCoilsStayApart_data()
{
    QTest::addColumn<bool>("presentation");
    QTest::addColumn<double>("lengthPx");
    for (const bool presentation : {false, true})
        for (const double length : {30.0, 60.0, 120.0, 400.0})
            QTest::addRow("%s, %g px", presentation ? "presentation" : "window", length)
                << presentation << length;
}

void TestDrawings::springCoilsStayApart()
{
    // Presentation mode drew a short spring as a solid black bar: its 12 coils, 3 px thick,
    // filled the 60 px between the anchors. Each half-turn now keeps 2.5 pen widths along
    // the spring, so that background shows between the strokes.
    QFETCH(bool, presentation);
    QFETCH(double, lengthPx);
    ui::theme::setPresentation(presentation);
    const double pen = ui::theme::lineWidth(1.5); // as the overlay draws springs
    ui::theme::setPresentation(false);
    constexpr double px = 0.01; // [m per pixel]
    const QPointF a(1, 2), b = a + QPointF(lengthPx * px, 0);
    const QPolygonF zig = ui::OverlayItem::springZigzag(a, b, px, pen);
    QCOMPARE(zig.front(), a);
    QCOMPARE(zig.back(), b);
    const int halfTurns = static_cast<int>(zig.size()) - 1;
    QVERIFY2(halfTurns >= 2 && halfTurns <= 24, qPrintable(QString::number(halfTurns)));
    const double step = lengthPx / halfTurns; // [px] along the spring
    QVERIFY2(step >= 2.5 * pen || halfTurns == 2,
             qPrintable(QStringLiteral("%1 px per half-turn, pen %2 px").arg(step).arg(pen)));
    if (lengthPx >= 24 * 2.5 * pen) // a long spring keeps every coil
        QCOMPARE(halfTurns, 24);

    // Drawn: the band the coils take is not mostly ink.
    QImage image(static_cast<int>(lengthPx) + 40, 80, QImage::Format_RGB32);
    image.fill(Qt::white);
    {
        QPainter p(&image);
        p.setRenderHint(QPainter::Antialiasing);
        p.translate(20 - a.x() / px, 40 + a.y() / px);
        p.scale(1 / px, -1 / px);
        QPen ink(Qt::black, pen);
        ink.setCosmetic(true);
        p.setPen(ink);
        p.drawPolyline(zig);
    }
    double amplitude = 0; // [px]
    for (const QPointF& q : zig)
        amplitude = std::max(amplitude, std::abs(q.y() - a.y()) / px);
    int inked = 0, all = 0;
    for (int x = 20 + static_cast<int>(step); x < 20 + static_cast<int>(lengthPx - step); ++x)
        for (int y = 40 - static_cast<int>(amplitude / 2); y <= 40 + amplitude / 2; ++y, ++all)
            inked += qGray(image.pixel(x, y)) < 128 ? 1 : 0;
    QVERIFY(all > 0);
    QVERIFY2(inked < 0.6 * all,
             qPrintable(QStringLiteral("%1 of %2 pixels inked").arg(inked).arg(all)));
}

void TestDrawings::labelsPlacedApartAndInside()
{
    const QRect area(0, 0, 400, 300);
    const QSize size(80, 16);
    // Alone, in the middle: centred above its body.
    const QRect body(180, 140, 40, 40);
    const std::vector<QRect> one = ui::placeLabels({{size, body}}, area);
    QCOMPARE(one.size(), std::size_t{1});
    QCOMPARE(one[0].center().x(), body.center().x());
    QVERIFY2(one[0].bottom() < body.top(), "above the body");
    // At the right edge (a fast ball about to leave): slid inside, still above its body.
    const QRect edge(390, 140, 20, 20);
    const QRect cut = ui::placeLabels({{size, edge}}, area)[0];
    QVERIFY2(area.contains(cut), qPrintable(QStringLiteral("x %1..%2, y %3..%4 inside 400 × 300")
                                                .arg(cut.left())
                                                .arg(cut.right())
                                                .arg(cut.top())
                                                .arg(cut.bottom())));
    QVERIFY(cut.bottom() < edge.top());
    // At the top edge: inside too.
    QVERIFY(area.contains(ui::placeLabels({{size, QRect(100, 0, 20, 20)}}, area)[0]));
    // Two bodies close together, three too: no label over another, each still near its body.
    const std::vector<ui::LabelWish> close = {{size, QRect(150, 150, 30, 30)},
                                              {size, QRect(185, 150, 30, 30)},
                                              {size, QRect(170, 152, 30, 30)}};
    const std::vector<QRect> apart = ui::placeLabels(close, area);
    for (std::size_t i = 0; i < apart.size(); ++i) {
        QVERIFY(area.contains(apart[i]));
        QVERIFY(std::abs(apart[i].center().x() - close[i].body.center().x()) < size.width());
        for (std::size_t j = 0; j < i; ++j)
            QVERIFY2(!apart[i].intersects(apart[j]),
                     qPrintable(QStringLiteral("labels %1 and %2 overlap").arg(i).arg(j)));
    }
    // A box already taken (the legend) is kept free as well.
    const QRect legend(140, 100, 120, 40);
    for (const QRect& r : ui::placeLabels(close, area, {legend}))
        QVERIFY(!r.intersects(legend));
}

void TestDrawings::bodyLabelsInSightAndApart()
{
    // At 1024 × 768: the tunnelling lesson's balls, the fastest flying off to the right, and
    // the two balls that collide; every frame, each label whole in the view and none over
    // another.
    MainWindow w;
    w.fitToScreen(QRect(0, 0, 1024, 768));
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    const auto check = [&](const char* what, int frames) {
        ui::SimulationController& c = w.controller();
        c.setRunning(true);
        std::size_t labelled = 0;
        for (int f = 0; f < frames; ++f) {
            c.advanceClock(1.0 / 60.0);
            QCoreApplication::processEvents();
            const QRect area = w.view().viewport()->rect();
            const auto labels = w.view().bodyLabelRects();
            labelled = std::max(labelled, labels.size());
            for (std::size_t i = 0; i < labels.size(); ++i) {
                const QRect& r = labels[i].second;
                QVERIFY2(area.contains(r),
                         qPrintable(QStringLiteral("%1, frame %2: the label of body %3 at "
                                                   "x %4..%5, y %6..%7, the view %8 × %9")
                                        .arg(QLatin1String(what))
                                        .arg(f)
                                        .arg(labels[i].first)
                                        .arg(r.left())
                                        .arg(r.right())
                                        .arg(r.top())
                                        .arg(r.bottom())
                                        .arg(area.width())
                                        .arg(area.height())));
                for (std::size_t j = 0; j < i; ++j)
                    QVERIFY2(!r.intersects(labels[j].second),
                             qPrintable(QStringLiteral("%1, frame %2: the labels of bodies %3 "
                                                       "and %4 overlap")
                                            .arg(QLatin1String(what))
                                            .arg(f)
                                            .arg(labels[i].first)
                                            .arg(labels[j].first)));
            }
        }
        c.setRunning(false);
        QVERIFY2(labelled >= 2, what);
    };
    QCOMPARE(w.openLesson(lesson("tunnelling"), true), QString());
    w.lessonPlayer().goToStep(0);
    check("tunnelling, step 1", 40);
    if (QTest::currentTestFailed())
        return;
    QCOMPARE(
        w.openScene(
            QDir(MainWindow::scenesFolder()).filePath(QStringLiteral("two_ball_collision.json")),
            true),
        QString());
    check("two balls colliding", 90);
}

RIGIDLAB_TEST_MAIN(TestDrawings)
#include "test_drawings.moc"
