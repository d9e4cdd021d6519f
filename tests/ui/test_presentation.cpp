// SPDX-License-Identifier: GPL-3.0-or-later
// Presentation mode (F11) on a classroom projector: large and thick enough for the back of a
// room, every action in sight, the world with at least half of the screen and the panels'
// fields readable, and the layout given back when it ends.

#include "classroom_util.h"
#include "test_main.h"

#include <QDockWidget>
#include <QMessageBox>
#include <QToolBar>

using namespace rigidlab;
using rigidlab::test::shippedLessons;
using rigidlab::ui::MainWindow;
using namespace rigidlab::test::classroom;

namespace {

/// The tick labels of both axes of `plot` do not overlap.
void tickLabelsApart(QCustomPlot& plot)
{
    for (QCPAxis* axis : {plot.xAxis, plot.yAxis}) {
        const QVector<double> ticks = axis->tickVector();
        const QVector<QString> labels = axis->tickVectorLabels();
        QVERIFY(ticks.size() >= 2);
        const QFontMetrics fm(axis->tickLabelFont());
        for (qsizetype i = 1; i < ticks.size(); ++i) {
            const double apart =
                std::abs(axis->coordToPixel(ticks[i]) - axis->coordToPixel(ticks[i - 1]));
            const double needed =
                axis->orientation() == Qt::Horizontal
                    ? 0.5 * (fm.horizontalAdvance(labels[i - 1]) + fm.horizontalAdvance(labels[i]))
                    : fm.height();
            QVERIFY2(apart > needed,
                     qPrintable(labels[i - 1] + QStringLiteral(" and ") + labels[i]));
        }
    }
}

} // namespace

class TestPresentation : public QObject {
    Q_OBJECT
private slots:
    void presentationModeIsLargeAndRestores()
    {
        MainWindow w;
        showOn(w, QSize(1024, 768));
        QCOMPARE(w.openScene(MainWindow::scenesFolder() + QStringLiteral("/welcome.json"), true),
                 QString());
        for (int i = 0; i < 30; ++i)
            w.controller().stepForward();
        for (int i = 0; i < 3; ++i) // the layout's queued passes: the column shared
            QCoreApplication::processEvents();
        const QList<DockPlace> before = dockPlaces(w);
        const QRect geometry = w.geometry();
        const QFont font = w.font();
        w.setPresentation(true);
        QCoreApplication::processEvents();
        QVERIFY(w.isFullScreen());
        QVERIFY(w.font().pointSizeF() >= 1.5 * font.pointSizeF() - 1e-9);
        QVERIFY(ui::theme::lineWidth(1.0) >= ui::theme::kPresentationMinLinePx);
        for (auto* shown : w.plots()) {
            QCustomPlot* plot = shown->plot();
            QVERIFY(plot->xAxis->labelFont().pointSizeF() >= 18);
            QVERIFY(plot->yAxis->labelFont().pointSizeF() >= 18);
            QVERIFY(plot->graphCount() > 0);
            for (int g = 0; g < plot->graphCount(); ++g)
                QVERIFY2(plot->graph(g)->pen().widthF() >= 3.0, qPrintable(plot->graph(g)->name()));
        }
        // A high-contrast palette: text on the window's background at least 7:1 (WCAG AAA).
        QVERIFY(ui::theme::contrastRatio(w.palette().color(QPalette::WindowText),
                                         w.palette().color(QPalette::Window)) >= 7.0);
        w.setPresentation(false);
        QCoreApplication::processEvents();
        QVERIFY(!w.isFullScreen());
        QVERIFY(!ui::theme::presentation());
        QCOMPARE(w.font(), font);
        QTRY_COMPARE(w.geometry(), geometry);
        // Every dock where it was, as large as it was (to a few pixels: the splitters are
        // laid out again at the restored size).
        QTRY_VERIFY2(samePlaces(dockPlaces(w), before),
                     qPrintable(describe(dockPlaces(w), before)));
        for (auto* plot : w.plots())
            QVERIFY(plot->plot()->xAxis->labelFont().pointSizeF() < 18);
    }

    // A dock opened during presentation mode (the inspector, to show the class a value) stays
    // open when it ends, and one closed during it stays closed: the layout comes back, the
    // student's latest choices with it.
    void docksShownDuringPresentationStay()
    {
        MainWindow w;
        showOn(w, QSize(1024, 768));
        QCOMPARE(w.openScene(MainWindow::scenesFolder() + QStringLiteral("/welcome.json"), true),
                 QString());
        QCoreApplication::processEvents();
        QDockWidget* opened = nullptr;
        QDockWidget* closed = nullptr;
        for (QDockWidget* dock : w.findChildren<QDockWidget*>()) {
            if (dock->isFloating())
                continue;
            if (dock->isHidden() && !opened)
                opened = dock;
            else if (!dock->isHidden() && !closed)
                closed = dock;
        }
        QVERIFY2(opened && closed, "a dock hidden and one shown to begin with");
        w.setPresentation(true);
        QCoreApplication::processEvents();
        opened->toggleViewAction()->trigger();
        closed->toggleViewAction()->trigger();
        QCoreApplication::processEvents();
        QVERIFY(!opened->isHidden());
        QVERIFY(closed->isHidden());
        w.setPresentation(false);
        for (int i = 0; i < 5; ++i) // the state is restored again once the size is back
            QCoreApplication::processEvents();
        QTRY_VERIFY(!w.isFullScreen());
        QVERIFY2(!opened->isHidden(), qPrintable(opened->objectName()));
        QVERIFY2(closed->isHidden(), qPrintable(closed->objectName()));
    }

    // A new scene made right after presentation mode ends, before the window has its size
    // back, keeps the editor's tools and its Properties panel: the layout's second pass, once
    // the size is back, leaves what was opened since.
    void editorRightAfterPresentationKeepsItsTools()
    {
        MainWindow w;
        showOn(w, QSize(1024, 768));
        QCOMPARE(w.openScene(MainWindow::scenesFolder() + QStringLiteral("/welcome.json"), true),
                 QString());
        QCoreApplication::processEvents();
        w.setPresentation(true);
        QCoreApplication::processEvents();
        w.setPresentation(false);
        w.setUnsavedAsker([] { return int(QMessageBox::Discard); });
        QVERIFY(w.newScene()); // a new scene opens in Edit mode
        auto* tools = w.findChild<QToolBar*>(QStringLiteral("editToolbar"));
        auto* properties = w.findChild<QDockWidget*>(QStringLiteral("propertiesDock"));
        QVERIFY(tools && properties);
        QVERIFY(!tools->isHidden());
        QVERIFY(!properties->isHidden());
        // The window's size comes back, and the layout's second pass with it.
        w.resize(w.size() - QSize(1, 1));
        for (int i = 0; i < 5; ++i)
            QCoreApplication::processEvents();
        QTRY_VERIFY(!w.isFullScreen());
        QVERIFY2(!tools->isHidden(), "the edit toolbar");
        QVERIFY2(!properties->isHidden(), "the Properties panel");
    }

    // Presentation mode at 1024×768: every toolbar action has its button in sight (none in
    // the "»" menu), the status line is not cut, and the plots' tick labels do not overlap
    // nor the legend take the curves' height.
    void presentationFitsAProjector()
    {
        MainWindow w;
        presentOn(w, QSize(1024, 768));
        QCOMPARE(w.openScene(MainWindow::scenesFolder() + QStringLiteral("/welcome.json"), true),
                 QString());
        runFor(w.controller(), 2.0);
        QMetaObject::invokeMethod(&w, "updateStatus");
        for (auto* plot : w.plots())
            plot->drain();
        QCoreApplication::processEvents();
        QVERIFY(w.presentation());
        QCOMPARE(w.frameGeometry(), QRect(0, 0, 1024, 768)); // as full screen covers it

        // Every visible toolbar's actions in sight, when running and in Edit mode (where the
        // scene editor's tools get a row of their own).
        const auto everyActionInSight = [&w] {
            for (const QToolBar* bar : w.findChildren<QToolBar*>()) {
                if (!bar->isVisible())
                    continue;
                for (QAction* a : bar->actions()) {
                    if (a->isSeparator() || !a->isVisible())
                        continue;
                    const QWidget* button = bar->widgetForAction(a);
                    QVERIFY2(button && button->isVisible() &&
                                 bar->rect().contains(QRect(button->pos(), button->size())),
                             qPrintable(bar->objectName() + QStringLiteral(": ") + a->text()));
                }
                const auto* more =
                    bar->findChild<QWidget*>(QStringLiteral("qt_toolbar_ext_button"));
                QVERIFY2(!more || !more->isVisible(), qPrintable(bar->objectName()));
            }
        };
        everyActionInSight();
        if (QTest::currentTestFailed())
            return;
        auto* tools = w.findChild<QToolBar*>(QStringLiteral("editToolbar"));
        QVERIFY(tools);
        QVERIFY(!tools->isVisible());
        w.editTools().setEditing(true);
        QCoreApplication::processEvents();
        QVERIFY(tools->isVisible());
        everyActionInSight();
        if (QTest::currentTestFailed())
            return;
        w.editTools().setEditing(false);
        QCoreApplication::processEvents();

        QVERIFY(!w.statusText().isEmpty());
        for (const QLabel* label : w.statusBar()->findChildren<QLabel*>()) {
            if (!label->isVisible() || label->text().isEmpty())
                continue;
            const QRect r(label->mapTo(&w, QPoint(0, 0)), label->size());
            QVERIFY2(label->width() >= label->sizeHint().width() && w.rect().contains(r),
                     qPrintable(QStringLiteral("\"%1\": %2 of %3 px")
                                    .arg(label->text())
                                    .arg(label->width())
                                    .arg(label->sizeHint().width())));
        }

        QCustomPlot* energy = w.plot(u"energy")->plot();
        QVERIFY(energy->isVisible());
        energy->replot();
        energy->replot(); // the ticks follow the labels' width measured by the replot before
        tickLabelsApart(*energy);
        if (QTest::currentTestFailed())
            return;
        QVERIFY2(energy->legend->outerRect().height() <= energy->height() / 4,
                 qPrintable(QStringLiteral("legend %1 of %2 px")
                                .arg(energy->legend->outerRect().height())
                                .arg(energy->height())));
        QVERIFY(energy->legend->outerRect().right() <= energy->width());
    }
};

RIGIDLAB_TEST_MAIN(TestPresentation)
#include "test_presentation.moc"
