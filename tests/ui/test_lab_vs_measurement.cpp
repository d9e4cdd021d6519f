// SPDX-License-Identifier: GPL-3.0-or-later
// Lesson 7, "Is the lab right?", agrees with itself: the Measurement panel is shown in every
// step whose text sends the student to it; the bounce times imported after the video's
// heights are added beside them, each named by its file, and a second file of the heights is
// plotted beside the first (the last one compared and fitted, and said to be); a question judges
// the scene as it is now (after a fitted e was applied to it, not the e the lesson file gives); a
// student who follows a hint exactly, rounded as a person writes it, is judged right.

#include "common/language.h"
#include "editor/scene_document.h"
#include "lesson_player/lesson_player.h"
#include "measure/measurement_panel.h"
#include "measure/measurement_session.h"
#include "plots/plot_shelf.h"
#include "plots/plot_widget.h"
#include "window/main_window.h"

#include <qcustomplot.h>

#include "format/data_dirs.h"
#include "format/lesson.h"
#include "run/measurements.h"

#include "near.h"
#include "test_main.h"

#include <QComboBox>
#include <QDockWidget>
#include <QLabel>
#include <QMessageBox>
#include <QtTest>

#include "question_kinds.h"
#include <cmath>

using rigidlab::test::measuredOf;

using namespace rigidlab;
using namespace rigidlab::ui;
using measure::Quantity;

namespace {

QString lessonFile()
{
    return lessons::shippedLessonsDir() + QStringLiteral("/lab_vs_measurement.json");
}

QString sample(const char* name)
{
    return lessons::shippedDataDir() + QStringLiteral("/measure/samples/") + QLatin1String(name);
}

/// The ball's bounce times, as step 2 asks them imported.
measure::MeasurementOptions bounceTimes()
{
    measure::MeasurementOptions options;
    options.mapping = {Quantity::BounceTime};
    options.bounceTimesOnly = true;
    return options;
}

/// The layout passes a change queues, done.
void settle()
{
    for (int pass = 0; pass < 4; ++pass)
        QCoreApplication::processEvents();
}

/// `v` rounded to `digits` decimals, as a student writes an answer.
double rounded(double v, int digits)
{
    const double scale = std::pow(10.0, digits);
    return std::round(v * scale) / scale;
}

} // namespace

class TestLabVsMeasurement : public QObject {
    Q_OBJECT
private slots:
    void measurementPanelWhereTheTextUsesIt_data();
    void measurementPanelWhereTheTextUsesIt();
    void secondImportIsAddedBesideTheFirst();
    void secondFileOfTheSameQuantityIsShownBeside();
    void questionJudgesTheSceneAsItIsNow();
    void hintsFollowedExactlyAreRight();
};

void TestLabVsMeasurement::measurementPanelWhereTheTextUsesIt_data()
{
    QTest::addColumn<QString>("language");
    QTest::addColumn<QString>("panelWord"); // how the step text names the Measurement dock
    QTest::newRow("en") << QStringLiteral("en") << QStringLiteral("Measurement");
    QTest::newRow("cs") << QStringLiteral("cs") << QStringLiteral("Měření");
}

void TestLabVsMeasurement::measurementPanelWhereTheTextUsesIt()
{
    QFETCH(QString, language);
    QFETCH(QString, panelWord);
    const lessons::LessonLoadResult loaded =
        lessons::loadLessonFile(lessonFile(), lessons::LessonLoadOptions{language});
    QVERIFY2(loaded.ok, qPrintable(loaded.error));
    QVERIFY(applyLanguage(language));
    MainWindow w;
    w.setUnsavedAsker([] { return int(QMessageBox::Discard); });
    QCOMPARE(w.openLesson(lessonFile(), true), QString());
    int using_ = 0;
    for (int s = 0; s < static_cast<int>(loaded.lesson.steps.size()); ++s) {
        const lessons::LessonStep& step = loaded.lesson.steps[static_cast<std::size_t>(s)];
        if (!step.text.contains(QStringLiteral("**%1**").arg(panelWord)) &&
            !step.text.contains(QStringLiteral("%1 dock").arg(panelWord)) &&
            !step.text.contains(QStringLiteral("panelu %1").arg(panelWord)) &&
            !step.text.contains(QStringLiteral("Panel **%1**").arg(panelWord)))
            continue;
        ++using_;
        w.lessonPlayer().goToStep(s);
        QVERIFY2(step.panels.contains(QStringLiteral("measurement")), qPrintable(step.title));
        auto* dock = w.findChild<QDockWidget*>(QStringLiteral("measurementDock"));
        QVERIFY2(dock && !dock->isHidden(), qPrintable(step.title));
    }
    QVERIFY2(using_ >= 2, "steps 1 and 2 send the student to the Measurement panel");
    applyLanguage(QStringLiteral("en"));
}

void TestLabVsMeasurement::secondImportIsAddedBesideTheFirst()
{
    MainWindow w;
    w.setUnsavedAsker([] { return int(QMessageBox::Discard); });
    QCOMPARE(w.openLesson(lessonFile(), true), QString());
    MeasurementSession& session = w.measurement();
    QCOMPARE(session.load(sample("ball_tracker.csv")), QString());
    const int measured =
        session.panel()->comparisonPlot()->model().pointCount(MeasurementPanel::kMeasured);
    QVERIFY(measured > 10);
    w.lessonPlayer().next();
    QCOMPARE(session.load(sample("ball_bounces_phyphox.csv"), bounceTimes()), QString());
    // Both kept: the heights still compared point by point, e from the bounce times beside.
    QVERIFY(session.measurement().find(Quantity::Y));
    QVERIFY(!session.measurement().bounces.empty());
    QCOMPARE(session.panel()->comparisonPlot()->model().pointCount(MeasurementPanel::kMeasured),
             measured);
    QVERIFY2(session.fitting().bounceFit().ok, qPrintable(session.fitting().bounceFit().error));
    // Each named by its file.
    const QString source = session.panel()->findChild<QLabel*>()->text();
    QVERIFY2(source.contains(QStringLiteral("ball_tracker.csv")) &&
                 source.contains(QStringLiteral("ball_bounces_phyphox.csv")),
             qPrintable(source));
    QVERIFY2(session.panel()->bounceFitText().contains(QStringLiteral("ball_bounces_phyphox.csv")),
             qPrintable(session.panel()->bounceFitText()));
    // A new file of the same quantity gives it from then on; the video keeps what only it has
    // (x), and each line says what is taken from its file.
    QCOMPARE(session.load(sample("ball_phyphox.csv")), QString());
    const QStringList lines = session.panel()->findChild<QLabel*>()->text().split(u'\n');
    QCOMPARE(lines.size(), 3);
    QVERIFY2(lines[0].startsWith(QStringLiteral("ball_tracker.csv")) &&
                 lines[0].contains(QStringLiteral("position x")) &&
                 !lines[0].contains(QStringLiteral("position y")),
             qPrintable(lines[0]));
    QVERIFY2(lines[2].startsWith(QStringLiteral("ball_phyphox.csv")) &&
                 lines[2].contains(QStringLiteral("position y")),
             qPrintable(lines[2]));
}

void TestLabVsMeasurement::secondFileOfTheSameQuantityIsShownBeside()
{
    MainWindow w;
    w.setUnsavedAsker([] { return int(QMessageBox::Discard); });
    // On a projector, where the legend's second row costs the plot height.
    w.fitToScreen(QRect(0, 0, 1024, 768));
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QCOMPARE(w.openLesson(lessonFile(), true), QString());
    MeasurementSession& session = w.measurement();
    QCOMPARE(session.load(sample("ball_tracker.csv")), QString());
    const measure::Series tracker = *session.measurement().find(Quantity::Y);
    settle(); // the dock shown and laid out, as a class sees it before the second import
    QCOMPARE(session.load(sample("ball_phyphox.csv")), QString());
    const measure::Series phone = *session.measurement().find(Quantity::Y);
    QVERIFY(tracker.value != phone.value);
    const PlotWidget& plot = *session.panel()->comparisonPlot();
    QCOMPARE(session.panel()->quantity(), Quantity::Y);
    // The heights of both files on the plot, each named by its file.
    int trackerSeries = -1;
    for (int i = 0; i < plot.model().seriesCount(); ++i)
        if (plot.model().seriesLegend(i) == QLatin1String("ball_tracker.csv"))
            trackerSeries = i;
    QVERIFY2(trackerSeries > MeasurementPanel::kSimulated,
             qPrintable(QString::number(trackerSeries)));
    const auto shown = plot.model().points(trackerSeries);
    QCOMPARE(shown.size(), tracker.t.size());
    for (std::size_t i = 0; i < shown.size(); ++i) {
        RL_VERIFY_NEAR(shown[i].x(), tracker.t[i], 0, 0);
        RL_VERIFY_NEAR(shown[i].y(), tracker.value[i], 0, 0);
    }
    QVERIFY(plot.graph(trackerSeries)->scatterStyle().shape() !=
            plot.graph(MeasurementPanel::kMeasured)->scatterStyle().shape());
    // Still a data area a class can read, the legend's rows taken from the plot's height.
    settle();
    plot.plot()->replot(QCustomPlot::rpImmediateRefresh);
    const QSize data = plotDataArea(plot);
    QVERIFY2(data.width() >= kLeastDataArea.width() && data.height() >= kLeastDataArea.height(),
             qPrintable(QStringLiteral("%1x%2").arg(data.width()).arg(data.height())));
    // The last file is the one compared: its points, its residuals, the fit's, and it says so.
    QCOMPARE(static_cast<std::size_t>(plot.model().pointCount(MeasurementPanel::kMeasured)),
             phone.t.size());
    QCOMPARE(plot.model().seriesLegend(MeasurementPanel::kMeasured),
             QStringLiteral("ball_phyphox.csv (fit, residuals)"));
    QCOMPARE(session.residuals().size(), phone.t.size());
    const measure::FitResult& fit = session.fitting().fit();
    QVERIFY2(fit.ok, qPrintable(fit.error));
    QCOMPARE(static_cast<std::size_t>(fit.points), phone.t.size());
    QVERIFY2(session.panel()->fitText().contains(QStringLiteral("ball_phyphox.csv")),
             qPrintable(session.panel()->fitText()));
    // x is in the video only: no other file beside it, the points just "measured".
    auto* quantity = session.panel()->findChildren<QComboBox*>().at(1);
    quantity->setCurrentIndex(quantity->findData(static_cast<int>(Quantity::X)));
    QCOMPARE(plot.model().seriesLegend(MeasurementPanel::kMeasured), QStringLiteral("measured"));
    QCOMPARE(plot.model().pointCount(trackerSeries), 0);
    QVERIFY(!plot.plot()->legend->hasItemWithPlottable(plot.graph(trackerSeries)));
}

void TestLabVsMeasurement::questionJudgesTheSceneAsItIsNow()
{
    MainWindow w;
    w.setUnsavedAsker([] { return int(QMessageBox::Discard); });
    QCOMPARE(w.openLesson(lessonFile(), true), QString());
    // Step 1: the measurement imported, e fitted and applied in the scene before answering.
    MeasurementSession& session = w.measurement();
    QCOMPARE(session.load(sample("ball_tracker.csv")), QString());
    QVERIFY(session.fitting().fit().ok);
    QCOMPARE(session.fitting().apply(), QString());
    const lessons::Scene& scene = w.document()->scene();
    const double e = scene.bodies[*scene.bodyIndex(QStringLiteral("ball"))].restitution;
    RL_VERIFY_NEAR(e, 0.72, 0.01, 0);
    // The run (held back until answered) will measure e² · 1 m with the applied e: that is
    // judged right, and the file's e = 0.8 (0.64 m) no longer is.
    LessonPlayer& player = w.lessonPlayer();
    player.answer(0, QString::number(0.64));
    QVERIFY2(!player.result(0).startsWith(QStringLiteral("Right")), qPrintable(player.result(0)));
    player.answer(0, QString::number(rounded(e * e, 2)));
    QVERIFY2(player.result(0).startsWith(QStringLiteral("Right")), qPrintable(player.result(0)));
    // And the run itself agrees: the bounces panel's first height, once run.
    const lessons::LessonStep& step = player.lesson()->steps[0];
    lessons::LessonStep now = step;
    now.scene = scene;
    const auto value = lessons::measureAhead(now, measuredOf(step.questions[0]).measure);
    QVERIFY(value);
    RL_VERIFY_NEAR(*value, e * e, 0, measuredOf(step.questions[0]).tolerance);
}

void TestLabVsMeasurement::hintsFollowedExactlyAreRight()
{
    const lessons::Lesson lesson = lessons::loadLessonFile(lessonFile()).lesson;
    // The hints' rules: step 1, e² · 1 m with e = 0.8; step 2, "multiply by e² twice", 0.72⁴ · 1 m.
    const double byHint[] = {0.8 * 0.8, std::pow(0.72, 4)};
    for (int s = 0; s < 2; ++s) {
        const lessons::LessonStep& step = lesson.steps[static_cast<std::size_t>(s)];
        const lessons::Question& q = step.questions.at(0);
        QVERIFY(!q.hint.isEmpty());
        const auto lab = lessons::measureAhead(step, measuredOf(q).measure);
        QVERIFY(lab);
        // Exactly, and as written to two decimals (0.27 m), on the first try.
        for (const double answer : {byHint[s], rounded(byHint[s], 2)}) {
            const lessons::Verdict v = lessons::judgeAttempt(q, answer, lab, 1);
            QVERIFY2(v.right, qPrintable(QStringLiteral("step %1: %2 against the lab's %3: %4")
                                             .arg(s + 1)
                                             .arg(answer)
                                             .arg(*lab)
                                             .arg(v.message)));
        }
        // And a guess a bounce off is not.
        QVERIFY(!lessons::judgeAttempt(q, byHint[s] * 0.64, lab, 1).right);
    }
}

RIGIDLAB_TEST_MAIN(TestLabVsMeasurement)
#include "test_lab_vs_measurement.moc"
