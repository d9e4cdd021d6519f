// SPDX-License-Identifier: GPL-3.0-or-later
// The fit in the window: it runs in a thread of its own with a busy bar and a Cancel button
// (the window answers meanwhile), gives back the shipped sample's true e within its interval,
// says "cannot be determined from these data" where the data cannot as the command line does, and
// is applied as an edit that Undo takes back; e from the bounce times alike.

#include "editor/scene_document.h"
#include "measure/import_dialog.h"
#include "measure/measurement_panel.h"
#include "measure/measurement_session.h"
#include "window/main_window.h"

#include "measure_test_util.h"
#include "near.h"
#include "test_main.h"

#include <QComboBox>
#include <QFile>
#include <QProgressBar>
#include <QPushButton>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QUndoStack>

#include <cmath>

using namespace rigidlab;
using namespace rigidlab::ui;
using namespace rigidlab::ui::test;
using measure::Quantity;

namespace {

/// The longest a fit of the samples may take in the worker [ms] (well under a second alone).
constexpr int kFitMs = 60000;

/// Clicks Fit and waits for the worker's result, the window's events running meanwhile.
bool clickFit(MeasurementSession& session)
{
    QSignalSpy finished(&session.fitting(), &MeasurementFit::fitFinished);
    session.panel()->fitButton()->click();
    return !finished.isEmpty() || finished.wait(kFitMs);
}

} // namespace

class TestMeasureFitWindow : public QObject {
    Q_OBJECT
private slots:
    void init() { QLocale::setDefault(QLocale::c()); }
    void fitIsAppliedAsAnUndoableEdit();
    void bounceTimesGiveE();
    void fitRunsInAWorkerAndCancels();
    void runningFitOfChangedDataIsDropped_data();
    void runningFitOfChangedDataIsDropped();
    void undeterminedIsSaidNotGuessed();

private:
    QTemporaryDir m_dir;
};

void TestMeasureFitWindow::fitIsAppliedAsAnUndoableEdit()
{
    MainWindow w;
    QCOMPARE(w.openScene(sceneFile(), true), QString());
    MeasurementSession& session = w.measurement();
    QCOMPARE(session.load(sample("ball_tracker.csv")), QString());
    MeasurementPanel& panel = *session.panel();
    const physics::BodyId ball = ballOf(w.document()->scene());
    const double before = w.document()->scene().bodies[ball].restitution;
    RL_VERIFY_NEAR(before, 0.8, 0, 0);
    QVERIFY(!panel.applyButton()->isEnabled());
    QVERIFY(clickFit(session));
    const measure::FitResult& fit = session.fitting().lastFit();
    QVERIFY2(fit.ok, qPrintable(fit.error));
    // The sample's true e (an exact model, make_samples.py) within the 95 % interval, which
    // is a few thousandths wide at 2 mm of noise.
    QVERIFY(fit.values[0].halfWidth95 > 0 && fit.values[0].halfWidth95 < 0.01);
    RL_VERIFY_NEAR(fit.values[0].value, kSampleE, fit.values[0].halfWidth95, 0);
    QVERIFY2(panel.fitText().contains(QStringLiteral("e = ")), qPrintable(panel.fitText()));
    QVERIFY(panel.fitText().contains(QStringLiteral("±")));
    QVERIFY(panel.applyButton()->isEnabled());
    const double rmsBefore = [&] {
        double s = 0;
        for (double r : session.residuals())
            s += r * r;
        return std::sqrt(s / static_cast<double>(session.residuals().size()));
    }();

    QUndoStack& undo = *w.document()->undoStack();
    const int edits = undo.count();
    panel.applyButton()->click();
    QCOMPARE(undo.count(), edits + 1);
    RL_VERIFY_NEAR(w.document()->scene().bodies[ball].restitution, fit.values[0].value, 0, 0);
    double s = 0;
    for (double r : session.residuals())
        s += r * r;
    const double rmsAfter = std::sqrt(s / static_cast<double>(session.residuals().size()));
    // The comparison follows: the fit's RMS (exact flights) plus the scene step's own error.
    RL_VERIFY_AT_MOST(fit.rms * (1 - 1e-9), rmsAfter);
    QVERIFY2(rmsAfter < rmsBefore / 5,
             qPrintable(QStringLiteral("%1 %2").arg(rmsAfter).arg(rmsBefore)));
    undo.undo();
    RL_VERIFY_NEAR(w.document()->scene().bodies[ball].restitution, before, 0, 0);
    undo.redo();
    RL_VERIFY_NEAR(w.document()->scene().bodies[ball].restitution, fit.values[0].value, 0, 0);

    // Two parameters: e and the initial vy (the ball was dropped from rest).
    panel.setFitChoice(3, true);
    QVERIFY(clickFit(session));
    QVERIFY2(session.fitting().lastFit().ok, qPrintable(session.fitting().lastFit().error));
    QCOMPARE(session.fitting().lastFit().values.size(), std::size_t{2});
    RL_VERIFY_NEAR(session.fitting().lastFit().values[1].value, 0.0, 0.05, 0);
    // Nothing ticked: said, and nothing to apply.
    panel.setFitChoice(0, false);
    panel.setFitChoice(3, false);
    QVERIFY(clickFit(session));
    QVERIFY(!session.fitting().lastFit().ok);
    QVERIFY(!panel.applyButton()->isEnabled());
    QVERIFY(!session.fitting().apply().isEmpty());
}

void TestMeasureFitWindow::bounceTimesGiveE()
{
    MainWindow w;
    QCOMPARE(w.openScene(sceneFile(), true), QString());
    MeasurementSession& session = w.measurement();
    measure::MeasurementOptions options;
    options.mapping = {Quantity::BounceTime};
    options.bounceTimesOnly = true;
    QCOMPARE(session.load(sample("ball_bounces_phyphox.csv"), options), QString());
    const measure::BounceFit& fit = session.fitting().bounceFit();
    QVERIFY2(fit.ok, qPrintable(fit.error));
    // The true e of the sample's exact bounces (1 ms of noise) within the 95 % interval.
    RL_VERIFY_NEAR(fit.e.value, kSampleE, fit.e.halfWidth95, 0);
    // Each flight is e times the one before, as the panel says.
    const std::vector<double>& T = fit.flightTimes;
    RL_VERIFY_NEAR(T[1] / T[0], fit.e.value, 0.02, 0);
    QVERIFY2(session.panel()->bounceFitText().contains(QStringLiteral("e = ")),
             qPrintable(session.panel()->bounceFitText()));
    QVERIFY(session.panel()->applyBounceButton()->isEnabled());
    // Applied as an edit, taken back by Undo.
    const physics::BodyId ball = ballOf(w.document()->scene());
    session.panel()->applyBounceButton()->click();
    RL_VERIFY_NEAR(w.document()->scene().bodies[ball].restitution, fit.e.value, 0, 0);
    w.document()->undoStack()->undo();
    RL_VERIFY_NEAR(w.document()->scene().bodies[ball].restitution, 0.8, 0, 0);
    // The dialog maps a single column to bounce times as the user says.
    MeasurementImportDialog d(sample("ball_bounces_phyphox.csv"));
    d.setMapping(0, Quantity::BounceTime);
    QCOMPARE(d.error(), QString());
    QCOMPARE(d.measurement().bounces.size(), fit.flightTimes.size() + 1);
}

void TestMeasureFitWindow::fitRunsInAWorkerAndCancels()
{
    // The box's friction in the lab's own engine: hundreds of runs and step halvings, seconds
    // of work, while the window's events go on.
    MainWindow w;
    QCOMPARE(w.openScene(sample("box_slide.json"), true), QString());
    MeasurementSession& session = w.measurement();
    measure::MeasurementOptions xOnly; // the box's x (its y stays on the floor)
    xOnly.mapping = {Quantity::Time, Quantity::X, Quantity::Ignored};
    QCOMPARE(session.load(sample("box_plain.csv"), xOnly), QString());
    MeasurementPanel& panel = *session.panel();
    panel.setFitChoice(0, false);
    panel.setFitChoice(1, true);
    QSignalSpy finished(&session.fitting(), &MeasurementFit::fitFinished);
    panel.fitButton()->click();
    // Started, not done: the click returned at once, with the busy bar and Cancel shown.
    QVERIFY(session.fitting().fitRunning());
    QVERIFY(finished.isEmpty());
    QVERIFY(panel.fitRunning());
    QVERIFY(!panel.fitProgress()->isHidden());
    QVERIFY(!panel.cancelFitButton()->isHidden());
    QVERIFY(panel.fitButton()->isHidden());
    QVERIFY(!panel.cancelFitButton()->accessibleName().isEmpty());
    QVERIFY2(panel.fitText().startsWith(QStringLiteral("Fitting")), qPrintable(panel.fitText()));
    panel.cancelFitButton()->click();
    QVERIFY(finished.wait(kFitMs));
    QVERIFY(session.fitting().lastFit().cancelled);
    QVERIFY(!session.fitting().lastFit().ok);
    QVERIFY2(panel.fitText().contains(QStringLiteral("cancelled")), qPrintable(panel.fitText()));
    QVERIFY(!panel.applyButton()->isEnabled());
    QVERIFY(panel.fitProgress()->isHidden() && !panel.fitButton()->isHidden());

    // Run to its end: the panel fits the box's own μ, which its contact mixes with the
    // floor's 0.4 as √(μ · 0.4); the slide the sample was made of (an exact model) had 0.33,
    // within the interval, at the step the fit names.
    QVERIFY(clickFit(session));
    const measure::FitResult& fit = session.fitting().lastFit();
    QVERIFY2(fit.ok, qPrintable(fit.error));
    QVERIFY(fit.runs > 10);
    const double mixed = std::sqrt(fit.values[0].value * 0.4);
    RL_VERIFY_NEAR(mixed, 0.33, fit.values[0].halfWidth95 * 0.4 / (2 * mixed), 0);
    QVERIFY2(panel.fitText().contains(QStringLiteral("dt = ")), qPrintable(panel.fitText()));
    QVERIFY(panel.applyButton()->isEnabled());
}

void TestMeasureFitWindow::runningFitOfChangedDataIsDropped_data()
{
    QTest::addColumn<QString>("change");
    QTest::addColumn<QString>("said");
    QTest::newRow("another file imported")
        << QStringLiteral("import") << QStringLiteral("another measurement was imported");
    QTest::newRow("another quantity compared")
        << QStringLiteral("compare") << QStringLiteral("another body or quantity is compared");
    QTest::newRow("the scene edited")
        << QStringLiteral("edit") << QStringLiteral("the scene changed");
}

void TestMeasureFitWindow::runningFitOfChangedDataIsDropped()
{
    // A fit of the box's friction (seconds of work) is running when what it fits changes: its
    // result, of the data before, is neither shown nor applied, and the panel says why.
    QFETCH(QString, change);
    QFETCH(QString, said);
    MainWindow w;
    QCOMPARE(w.openScene(sample("box_slide.json"), true), QString());
    MeasurementSession& session = w.measurement();
    measure::MeasurementOptions options; // the box's x; its y, on the floor, to switch to
    options.mapping = {Quantity::Time, Quantity::X, Quantity::Y};
    QCOMPARE(session.load(sample("box_plain.csv"), options), QString());
    MeasurementPanel& panel = *session.panel();
    QComboBox* quantity = nullptr; // the list of quantities, each with its Quantity as data
    const int y = static_cast<int>(Quantity::Y);
    for (QComboBox* list : panel.findChildren<QComboBox*>())
        if (list->findData(y) >= 0)
            quantity = list;
    QVERIFY(quantity);
    const auto compareX = [&] {
        quantity->setCurrentIndex(quantity->findData(static_cast<int>(Quantity::X)));
        return panel.quantity() == Quantity::X;
    };
    QVERIFY(compareX());
    panel.setFitChoice(0, false);
    panel.setFitChoice(1, true);
    QSignalSpy finished(&session.fitting(), &MeasurementFit::fitFinished);
    panel.fitButton()->click();
    QVERIFY(session.fitting().fitRunning());
    QVERIFY(panel.fitRunning());
    const int edits = w.document()->undoStack()->count();
    if (change == QLatin1String("import")) {
        QCOMPARE(session.load(sample("box_plain.csv"), options), QString());
    } else if (change == QLatin1String("compare")) {
        quantity->setCurrentIndex(quantity->findData(y));
        QCOMPARE(panel.quantity(), Quantity::Y);
    } else {
        lessons::Scene edited = w.document()->scene();
        edited.bodies.back().mass *= 2;
        w.document()->apply(QStringLiteral("heavier box"), edited);
    }
    // Said at once, with Fit back in place of Cancel and nothing to apply.
    QVERIFY2(panel.fitText().startsWith(QStringLiteral("Fit stopped: ") + said),
             qPrintable(panel.fitText()));
    QVERIFY(!panel.fitRunning());
    QVERIFY(panel.fitProgress()->isHidden() && !panel.fitButton()->isHidden());
    QVERIFY(!panel.applyButton()->isEnabled());
    // The worker stops at its next run; nothing it found reaches the panel or the scene.
    QTRY_VERIFY_WITH_TIMEOUT(!session.fitting().fitRunning(), kFitMs);
    QCoreApplication::processEvents(); // a result the worker delivered would be shown by now
    QVERIFY(finished.isEmpty());
    QVERIFY(!session.fitting().lastFit().ok);
    QVERIFY2(panel.fitText().startsWith(QStringLiteral("Fit stopped: ") + said),
             qPrintable(panel.fitText()));
    QVERIFY(!panel.applyButton()->isEnabled());
    QVERIFY(!session.fitting().apply().isEmpty());
    QCOMPARE(w.document()->undoStack()->count(), edits + (change == QLatin1String("edit") ? 1 : 0));
    // Fit again (x: the box's y on the floor says nothing of its friction): the data compared
    // now are fitted, and can be applied.
    QVERIFY(compareX());
    QVERIFY(clickFit(session));
    QVERIFY2(session.fitting().lastFit().ok, qPrintable(session.fitting().lastFit().error));
    QVERIFY(panel.applyButton()->isEnabled());
}

void TestMeasureFitWindow::undeterminedIsSaidNotGuessed()
{
    // The drop filmed only until just after its first bounce, in noise of half a metre: e
    // values far apart fit alike. The panel refuses in the command line's words (fitScene's
    // one message), with no number to apply.
    QByteArray rows = "t,y\n";
    for (int i = 0; i <= 36; ++i)
        rows += QByteArray::number(i / 60.0) + ',' +
                QByteArray::number(0.5 + 0.5 * std::sin(2.3 * i)) + '\n';
    const QString path = m_dir.filePath(QStringLiteral("noisy.csv"));
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly) && file.write(rows) == rows.size());
    file.close();
    MainWindow w;
    QCOMPARE(w.openScene(sceneFile(), true), QString());
    MeasurementSession& session = w.measurement();
    QCOMPARE(session.load(path), QString());
    QVERIFY(clickFit(session));
    QVERIFY(!session.fitting().lastFit().ok);
    QVERIFY2(session.panel()->fitText().startsWith(
                 QStringLiteral("e cannot be determined from these data")),
             qPrintable(session.panel()->fitText()));
    QVERIFY(!session.panel()->fitText().contains(QStringLiteral("±")));
    QVERIFY(!session.panel()->applyButton()->isEnabled());
}

RIGIDLAB_TEST_MAIN(TestMeasureFitWindow)
#include "test_measure_fit_window.moc"
