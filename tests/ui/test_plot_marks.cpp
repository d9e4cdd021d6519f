// SPDX-License-Identifier: GPL-3.0-or-later
// The plots' marks and exports: the labels of marks close together stacked or merged;
// exports start in the documents folder and remember the last one chosen.
#include "build_paths.h"
#include "common/display_names.h"
#include "common/export_folder.h"
#include "lesson_player/lesson_player.h"
#include "plots/lesson_export.h"
#include "plots/plot_export.h"
#include "plots/plot_exporter.h"
#include "plots/plot_table.h"
#include "plots/plot_widget.h"
#include "simulation/sample_buffer.h"
#include "window/main_window.h"

#include "format/lesson.h"

#include <qcustomplot.h>

#include <QApplication>
#include <QFileDialog>
#include <QLabel>
#include <QLineEdit>
#include <QSettings>
#include <QSlider>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTimer>
#include <QtTest>

#include "sourced_plot.h"
#include "test_main.h"

#include <cmath>
#include <memory>

using namespace rigidlab;
using namespace rigidlab::ui;
using rigidlab::test::SourcedPlot;

namespace {

constexpr double kDt = 1.0 / 64; // [s] between samples, exact in binary

Sample sampleAt(double t)
{
    Sample s;
    s.t = t;
    s.kinetic = 1.5 + std::sin(t);
    s.potential = 2.25 - std::sin(t);
    s.total = s.kinetic + s.potential;
    s.px = 0.5 * t;
    s.py = 1.0 - 0.25 * t;
    s.angularMomentum = 0.1 + t * t;
    s.driftPercent = 1e-3 * t;
    return s;
}

/// Samples t = first, first + kDt, ..., up to and with last, drained as they come.
void feed(SampleBuffer& buffer, PlotWidget& plot, double first, double last)
{
    for (int i = 0; first + i * kDt <= last + 1e-12; ++i) {
        buffer.push(sampleAt(first + i * kDt));
        if (i % 256 == 255)
            plot.drain();
    }
    plot.drain();
}

QString lessonPath(const char* name)
{
    return rigidlab::test::sourcePath(u"/lessons/lessons/%1.json").arg(QLatin1String(name));
}

/// The rectangle a mark's label takes on screen [px].
QRectF labelRect(const QCPItemText* label)
{
    return QRectF(label->topLeft->pixelPosition(), label->bottomRight->pixelPosition());
}

/// Answers the next modal file dialog: records where it opened, then chooses `choose` (a
/// file or folder name typed into its name field), or cancels if empty.
void answerFileDialog(QString* openedIn, const QString& choose)
{
    QTimer::singleShot(0, [openedIn, choose] {
        auto* dialog = qobject_cast<QFileDialog*>(QApplication::activeModalWidget());
        if (!dialog) {
            answerFileDialog(openedIn, choose); // not shown yet
            return;
        }
        *openedIn = dialog->directory().absolutePath();
        if (choose.isEmpty()) {
            dialog->reject();
            return;
        }
        auto* name = dialog->findChild<QLineEdit*>(QStringLiteral("fileNameEdit"));
        if (name)
            name->setText(choose);
        static_cast<QDialog*>(dialog)->accept(); // as its Save or Choose button
    });
}

} // namespace

class TestPlotMarks : public QObject {
    Q_OBJECT
private slots:
    void closeMarksStack();
    void coincidingMarksMerge();
    void exportFolderDefaultsAndRemembers();
    void plotExportDialogStartsThere();
    void lessonExportDialogStartsThere();
};

void TestPlotMarks::closeMarksStack()
{
    std::unique_ptr<PlotWidget> plot(makeEnergyPlot(nullptr));
    plot->resize(640, 360);
    plot->show();
    QVERIFY(QTest::qWaitForWindowExposed(plot.get()));
    SampleBuffer buffer;
    plot->model().setSource(&buffer);
    feed(buffer, *plot, 0.0, 10.0);
    // A few tenths of a second apart: lines pixels apart, labels wider than that.
    const double times[] = {4.0, 4.2, 4.4, 4.6};
    for (const double t : times)
        plot->model().addMark(t, QStringLiteral("dt = %1 ms").arg(t));
    plot->plot()->replot();
    QCOMPARE(plot->model().markCount(), 4);
    int visible = 0;
    for (int i = 0; i < plot->model().markCount(); ++i) {
        QCPItemText* a = plot->markLabel(i);
        if (!a->visible())
            continue;
        ++visible;
        for (int j = 0; j < i; ++j) {
            QCPItemText* b = plot->markLabel(j);
            if (b->visible())
                QVERIFY2(!labelRect(a).intersects(labelRect(b)),
                         qPrintable(QStringLiteral("labels %1 and %2 overlap: %3,%4 %5x%6 and "
                                                   "%7,%8 %9x%10")
                                        .arg(j)
                                        .arg(i)
                                        .arg(labelRect(b).x())
                                        .arg(labelRect(b).y())
                                        .arg(labelRect(b).width())
                                        .arg(labelRect(b).height())
                                        .arg(labelRect(a).x())
                                        .arg(labelRect(a).y())
                                        .arg(labelRect(a).width())
                                        .arg(labelRect(a).height())));
        }
        // Above the plot, where it hides no curve.
        QVERIFY(labelRect(a).bottom() <= plot->plot()->axisRect()->top() + 1);
        QVERIFY(labelRect(a).top() >= 0);
    }
    // Stacked on the rows there are, the one more merged into its neighbour's label: every
    // change is still said.
    QCOMPARE(visible, PlotWidget::kMarkRows);
    QString said;
    for (int i = 0; i < plot->model().markCount(); ++i)
        if (plot->markLabel(i)->visible())
            said += plot->markLabel(i)->text() + u'|';
    for (const double t : times)
        QVERIFY2(said.contains(QStringLiteral("dt = %1 ms").arg(t)), qPrintable(said));

    // In an export of another width too.
    QTemporaryDir dir;
    QVERIFY(exportPlot(*plot, dir.filePath(QStringLiteral("marks.svg")), ExportFormat::Svg).ok);
    plot->plot()->replot();
    for (int i = 1; i < plot->model().markCount(); ++i)
        QVERIFY(!labelRect(plot->markLabel(i)).intersects(labelRect(plot->markLabel(i - 1))));
}

void TestPlotMarks::coincidingMarksMerge()
{
    std::unique_ptr<PlotWidget> plot(makeEnergyPlot(nullptr));
    plot->resize(640, 360);
    plot->show();
    QVERIFY(QTest::qWaitForWindowExposed(plot.get()));
    SampleBuffer buffer;
    plot->model().setSource(&buffer);
    feed(buffer, *plot, 0.0, 10.0);
    // Two changes in one moment (a lesson step's settings), and one a pixel later.
    plot->model().addMark(5.0, QStringLiteral("dt = 5 ms"));
    plot->model().addMark(5.0, QStringLiteral("Runge–Kutta 4"));
    plot->model().addMark(5.005, QStringLiteral("e = 0.5"));
    plot->model().addMark(8.0, QStringLiteral("μ = 0.3"));
    plot->plot()->replot();
    QStringList shown;
    for (int i = 0; i < plot->model().markCount(); ++i)
        if (plot->markLabel(i)->visible())
            shown << plot->markLabel(i)->text();
    QCOMPARE(shown.size(), 2);
    QVERIFY(shown[0].contains(QStringLiteral("dt = 5 ms")));
    QVERIFY(shown[0].contains(QStringLiteral("Runge–Kutta 4")));
    QVERIFY(shown[0].contains(QStringLiteral("e = 0.5")));
    QCOMPARE(shown[1], QStringLiteral("μ = 0.3"));

    // Zoomed in, they are apart again: each its own label.
    plot->plot()->xAxis->setRange(4.99, 5.01);
    plot->plot()->replot();
    int visible = 0;
    for (int i = 0; i < 3; ++i)
        visible += plot->markLabel(i)->visible() ? 1 : 0;
    QCOMPARE(visible, 2); // the two at exactly 5 s still share one
}

void TestPlotMarks::exportFolderDefaultsAndRemembers()
{
    QSettings().remove(QLatin1String(kExportFolderKey));
    const QString documents = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
    QVERIFY(!documents.isEmpty());
    QVERIFY(QDir().mkpath(documents));
    QCOMPARE(exportFolder(), documents);

    QTemporaryDir chosen;
    rememberExportFolder(QDir(chosen.path()).filePath(QStringLiteral("energy.png")));
    QCOMPARE(exportFolder(), QDir(chosen.path()).absolutePath());
    // Remembered across runs: in the settings.
    QCOMPARE(QSettings().value(QLatin1String(kExportFolderKey)).toString(),
             QDir(chosen.path()).absolutePath());

    // A folder since removed falls back to the documents.
    const QString gone = QDir(chosen.path()).filePath(QStringLiteral("gone"));
    QVERIFY(QDir().mkpath(gone));
    rememberExportFolder(gone);
    QCOMPARE(exportFolder(), gone);
    QVERIFY(QDir(gone).removeRecursively());
    QCOMPARE(exportFolder(), documents);
    QSettings().remove(QLatin1String(kExportFolderKey));
}

void TestPlotMarks::plotExportDialogStartsThere()
{
    QSettings().remove(QLatin1String(kExportFolderKey));
    const QString documents = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
    QVERIFY(QDir().mkpath(documents));
    std::unique_ptr<PlotWidget> plot(makeEnergyPlot(nullptr));
    QSignalSpy exported(&plot->exporter(), &PlotExporter::exported);

    QString openedIn;
    QTemporaryDir chosen;
    const QString file = QDir(chosen.path()).filePath(QStringLiteral("mine.csv"));
    answerFileDialog(&openedIn, file);
    plot->exporter().exportInteractively(ExportFormat::Csv);
    QCOMPARE(openedIn, QDir(documents).absolutePath());
    QCOMPARE(exported.count(), 1);
    QVERIFY(QFileInfo::exists(file));

    // The next dialog, of this plot or another, opens where the last export went.
    std::unique_ptr<PlotWidget> other(makeDriftPlot(nullptr));
    answerFileDialog(&openedIn, QString());
    other->exporter().exportInteractively(ExportFormat::Png);
    QCOMPARE(openedIn, QDir(chosen.path()).absolutePath());
    QSettings().remove(QLatin1String(kExportFolderKey));
}

void TestPlotMarks::lessonExportDialogStartsThere()
{
    QSettings().remove(QLatin1String(kExportFolderKey));
    const QString documents = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
    QVERIFY(QDir().mkpath(documents));
    ui::MainWindow w;
    QCOMPARE(w.openLesson(lessonPath("energy_drift"), true), QString());

    QString openedIn;
    QTemporaryDir chosen;
    answerFileDialog(&openedIn, chosen.path());
    emit w.lessonPlayer().exportRequested();
    QCOMPARE(openedIn, QDir(documents).absolutePath());
    QCOMPARE(exportFolder(), QDir(chosen.path()).absolutePath());
    QVERIFY(!QDir(chosen.path()).entryList(QDir::Files).isEmpty());

    answerFileDialog(&openedIn, QString());
    emit w.lessonPlayer().exportRequested();
    QCOMPARE(openedIn, QDir(chosen.path()).absolutePath());
    QSettings().remove(QLatin1String(kExportFolderKey));
}

RIGIDLAB_TEST_MAIN(TestPlotMarks)
#include "test_plot_marks.moc"
