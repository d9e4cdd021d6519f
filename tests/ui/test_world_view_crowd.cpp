// SPDX-License-Identifier: GPL-3.0-or-later
// The world view with a crowd of bodies, all painted by one item (a pyramid of 325 boxes on
// the ground): a click still picks the body under the pointer, the topmost where they
// overlap, and empty space picks none; the selected body is drawn whole, grown to the
// readable size, with its outline over the others, while the rest keep their true size.

#include "simulation/simulation_controller.h"
#include "view/bodies_item.h"
#include "view/body_item.h"
#include "view/world_view.h"

#include "format/scene_loader.h"

#include <QImage>
#include <QtTest>

#include "test_main.h"

using namespace rigidlab;

namespace {

constexpr int kBase = 25; ///< boxes in the bottom row: 325 in all, a crowd

/// A pyramid of 1 m boxes, `base` in the bottom row, on a 120 m ground (body 0). Box k of row
/// r (from 0 at the bottom) stands at x = -(base - r - 1) / 2 + k, y = r + 0.5.
QByteArray pyramidJson(int base)
{
    QByteArray json = R"({"rigidlab": 1, "title": "crowd", "world": {"gravity": [0, -10]},
        "bodies": [{"id": "ground", "type": "static", "shape": {"type": "box", "width": 120, "height": 2},
                    "position": [0, -1]})";
    for (int row = 0; row < base; ++row)
        for (int k = 0; k < base - row; ++k)
            json += QStringLiteral(R"(, {"id": "r%1k%2", "shape": {"type": "box", "width": 1,
                                        "height": 1}, "position": [%3, %4]})")
                        .arg(row)
                        .arg(k)
                        .arg(-0.5 * (base - row - 1) + k)
                        .arg(row + 0.5)
                        .toUtf8();
    return json + "]}";
}

/// The body id of box k in row `row` of the pyramid (ids count rows from the bottom).
int boxId(int row, int k)
{
    int id = 1;
    for (int r = 0; r < row; ++r)
        id += kBase - r;
    return id + k;
}

struct Crowd {
    ui::SimulationController controller;
    ui::WorldView view{controller};

    Crowd()
    {
        const lessons::SceneLoadResult r =
            lessons::loadSceneJson(pyramidJson(kBase), QStringLiteral("crowd.json"));
        if (!r.ok)
            qFatal("%s", qPrintable(r.error));
        controller.loadScene(r.scene, QString());
        view.resize(800, 600);
        view.show();
    }
    QPoint at(double x, double y) const { return view.mapFromScene(QPointF(x, y)); }
    /// Where body `id` is drawn, in viewport pixels.
    QRect drawn(int id) const
    {
        return view.mapFromScene(view.itemFor(id)->sceneBox()).boundingRect();
    }
};

/// How many pixels of `image` inside `box` are exactly `colour`, and how many outside it.
std::pair<int, int> pixelsOf(const QImage& image, QRgb colour, const QRect& box)
{
    int in = 0, out = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            if (image.pixel(x, y) == colour)
                ++(box.contains(x, y) ? in : out);
    return {in, out};
}

} // namespace

class TestWorldViewCrowd : public QObject {
    Q_OBJECT
private slots:
    void picksTheBodyUnderThePointer_data();
    void picksTheBodyUnderThePointer();
    void aClickSelectsAndGrabs();
    void drawsTheSelectionOverTheCrowd();
    void followsABodyThatLeaves();
};

void TestWorldViewCrowd::followsABodyThatLeaves()
{
    // A row of 30 boxes at rest and a turning one that runs off to the right: frame by frame
    // the view widens to keep the runner whole in sight (within auto-fit's limit), however it
    // learns that the runner left (the exact outlines, or each body's reach about its origin).
    QByteArray json = R"({"rigidlab": 1, "title": "runner", "world": {"gravity": [0, 0]},
        "bodies": [{"id": "runner", "shape": {"type": "box", "width": 1, "height": 0.4},
                    "position": [15, 2], "velocity": [4, 0.5], "angularVelocity": 3})";
    for (int k = 0; k < 30; ++k)
        json += QStringLiteral(R"(, {"id": "b%1", "shape": {"type": "box", "width": 0.5,
                                    "height": 0.5}, "position": [%2, 0]})")
                    .arg(k)
                    .arg(k - 14.5)
                    .toUtf8();
    const lessons::SceneLoadResult r =
        lessons::loadSceneJson(json + "]}", QStringLiteral("runner.json"));
    QVERIFY2(r.ok, qPrintable(r.error));
    ui::SimulationController controller;
    ui::WorldView view{controller};
    controller.loadScene(r.scene, QString());
    view.resize(800, 600);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    view.fitScene();
    const double startZoom = view.zoom();
    for (int frame = 0; frame < 90; ++frame) { // 1.5 s at 60 frames a second
        for (int i = 0; i < 16; ++i)
            controller.stepForward();
        view.syncPoses();
        const QRectF shown = view.mapToScene(view.viewport()->rect()).boundingRect();
        const QRectF runner = view.itemFor(0)->sceneBox();
        QVERIFY2(shown.contains(runner),
                 qPrintable(QStringLiteral("frame %1: the runner at %2, %3 out of %4..%5")
                                .arg(frame)
                                .arg(runner.right())
                                .arg(runner.bottom())
                                .arg(shown.left())
                                .arg(shown.right())));
    }
    QVERIFY2(
        view.zoom() < 0.9 * startZoom, // the view did widen: the check above could fail
        qPrintable(QStringLiteral("%1 px/m, %2 at the start").arg(view.zoom()).arg(startZoom)));
}

void TestWorldViewCrowd::picksTheBodyUnderThePointer_data()
{
    QTest::addColumn<double>("x");
    QTest::addColumn<double>("y");
    QTest::addColumn<int>("body");
    const auto box = [](int row, int k) {
        return QPointF(-0.5 * (kBase - row - 1) + k, row + 0.5);
    };
    QTest::newRow("bottom row, first") << box(0, 0).x() << box(0, 0).y() << boxId(0, 0);
    QTest::newRow("bottom row, last")
        << box(0, kBase - 1).x() << box(0, kBase - 1).y() << boxId(0, kBase - 1);
    QTest::newRow("middle") << box(12, 6).x() << box(12, 6).y() << boxId(12, 6);
    QTest::newRow("apex") << box(kBase - 1, 0).x() << box(kBase - 1, 0).y() << boxId(kBase - 1, 0);
    // Off-centre in a box: a quarter of a metre right of and above row 3's box 2's centre.
    QTest::newRow("box, off centre") << box(3, 2).x() + 0.25 << box(3, 2).y() + 0.25 << boxId(3, 2);
    QTest::newRow("ground beside the pile") << 16.0 << -1.0 << 0;
    QTest::newRow("air above the apex") << 0.0 << kBase + 2.0 << -1;
    QTest::newRow("air beside the pile") << 12.0 << 8.5 << -1;
}

void TestWorldViewCrowd::picksTheBodyUnderThePointer()
{
    QFETCH(double, x);
    QFETCH(double, y);
    QFETCH(int, body);
    Crowd crowd;
    QVERIFY(QTest::qWaitForWindowExposed(&crowd.view));
    crowd.view.fitScene();
    // The bodies are painted by one item, not one each: picking cannot ask the scene.
    QVERIFY(!crowd.view.bodiesItem().antialiased());
    QVERIFY(!crowd.view.itemFor(1)->scene());
    const QPoint p = crowd.at(x, y);
    QVERIFY2(
        crowd.view.viewport()->rect().contains(p),
        qPrintable(QStringLiteral("(%1, %2) m at %3, %4 px").arg(x).arg(y).arg(p.x()).arg(p.y())));
    QCOMPARE(crowd.view.bodyAt(p), body);
}

void TestWorldViewCrowd::aClickSelectsAndGrabs()
{
    Crowd crowd;
    QVERIFY(QTest::qWaitForWindowExposed(&crowd.view));
    crowd.view.fitScene();
    const int id = boxId(10, 4);
    const physics::Vec2 centre = crowd.controller.world().body(id).position;
    QTest::mousePress(crowd.view.viewport(), Qt::LeftButton, {}, crowd.at(centre.x(), centre.y()));
    QCOMPARE(crowd.view.selectedBody(), id);
    QVERIFY(crowd.controller.grabSpring().body().has_value());
    QTest::mouseRelease(crowd.view.viewport(), Qt::LeftButton, {},
                        crowd.at(centre.x(), centre.y()));
    QVERIFY(!crowd.controller.grabSpring().body().has_value());
    // A press on empty space selects nothing and grabs nothing (it pans).
    QTest::mousePress(crowd.view.viewport(), Qt::LeftButton, {}, crowd.at(12, 8.5));
    QVERIFY(!crowd.controller.grabSpring().body().has_value());
    QTest::mouseRelease(crowd.view.viewport(), Qt::LeftButton, {}, crowd.at(12, 8.5));
}

void TestWorldViewCrowd::drawsTheSelectionOverTheCrowd()
{
    Crowd crowd;
    QVERIFY(QTest::qWaitForWindowExposed(&crowd.view));
    crowd.view.fitScene();
    // The selection's outline colour (BodyItem::draw): none of it before a body is selected,
    // drawn without antialiasing in a crowd, so its pixels are exactly that colour.
    const QRgb outline = qRgb(20, 20, 20);
    const int id = boxId(8, 3), neighbour = boxId(8, 4);
    const QRect pile = crowd.drawn(boxId(0, 0)) | crowd.drawn(boxId(kBase - 1, 0)) |
                       crowd.drawn(boxId(0, kBase - 1));
    const QImage before = crowd.view.viewport()->grab().toImage().copy(pile);
    QCOMPARE(pixelsOf(before, outline, before.rect()).first, 0);
    // In a crowd the bodies keep their true size (1 m), smaller than the readable 10 px here.
    const double metre = crowd.view.zoom();
    QVERIFY2(metre < 9, qPrintable(QStringLiteral("%1 px per metre").arg(metre)));
    QCOMPARE(crowd.view.itemFor(id)->sceneBox().width(), 1.0);

    const physics::Vec2 c = crowd.controller.world().body(id).position;
    QCOMPARE(crowd.view.bodyAt(crowd.at(c.x() + 0.7, c.y())), neighbour);
    crowd.view.selectBody(id);
    QVERIFY(crowd.view.itemFor(id)->selectedBody());
    QVERIFY(!crowd.view.itemFor(neighbour)->selectedBody());
    // The selected one is grown to the readable size, its neighbour not.
    const QRect selected = crowd.drawn(id);
    QVERIFY2(std::min(selected.width(), selected.height()) >= 9,
             qPrintable(QStringLiteral("%1 × %2 px").arg(selected.width()).arg(selected.height())));
    QCOMPARE(crowd.view.itemFor(neighbour)->sceneBox().width(), 1.0);
    // Where the grown body covers its neighbour, a click picks the one drawn on top.
    const QPoint overNeighbour = crowd.at(c.x() + 0.7, c.y());
    QVERIFY(crowd.view.itemFor(id)->containsScenePoint(crowd.view.mapToScene(overNeighbour)));
    QCOMPARE(crowd.view.bodyAt(overNeighbour), id);
    // Its outline is drawn, over the neighbours (painted last), and only around it: the
    // outline's pen (3 px) reaches at most 2 px beyond the body's box.
    const QImage after = crowd.view.viewport()->grab().toImage().copy(pile);
    const auto [in, out] =
        pixelsOf(after, outline, selected.adjusted(-2, -2, 2, 2).translated(-pile.topLeft()));
    QVERIFY2(in >= 2 * selected.width() + 2 * selected.height(),
             qPrintable(QStringLiteral("%1 outline pixels around a %2 × %3 px body")
                            .arg(in)
                            .arg(selected.width())
                            .arg(selected.height())));
    QCOMPARE(out, 0);

    // Selecting none takes the outline away again.
    crowd.view.selectBody(-1);
    const QImage none = crowd.view.viewport()->grab().toImage().copy(pile);
    QCOMPARE(pixelsOf(none, outline, none.rect()).first, 0);
}

RIGIDLAB_TEST_MAIN(TestWorldViewCrowd)
#include "test_world_view_crowd.moc"
