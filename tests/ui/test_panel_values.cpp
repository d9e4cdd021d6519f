// SPDX-License-Identifier: GPL-3.0-or-later
// What the panels show is what the lab holds, in numbers a student reads: the inspector's
// rounding noise is 0 (a box lying flat is at 0°), angles in degrees or radians, the speed
// beside the velocity; a physics setting changed in the control panel shows there, on the
// plots' marks and in the world, and going back in time shows the setting of that time.

#include "panels/control_panel.h"
#include "panels/inspector_panel.h"
#include "panels/number_field.h"
#include "plots/plot_widget.h"
#include "simulation/simulation_controller.h"
#include "window/main_window.h"

#include <qcustomplot.h>

#include <QComboBox>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

#include "test_files.h"
#include "test_main.h"

#include <cmath>

using namespace rigidlab;
using rigidlab::test::writeFile;
using rigidlab::ui::MainWindow;

namespace {

const QString kNbsp(QChar(0x00A0));

/// The floor, a box dropped 1 cm onto it (turned by rounding noise to begin with), and a
/// kinematic box far off to the side, turned by half a radian and spinning.
constexpr const char* kBoxes = R"({"rigidlab": 1,
  "world": {"gravity": [0, -9.81], "dt": 0.001, "solver": "sequential-impulse", "iterations": 10},
  "bodies": [
    {"id": "floor", "type": "static", "shape": {"type": "box", "width": 6, "height": 0.4},
     "position": [0, -0.2]},
    {"id": "flat", "shape": {"type": "box", "width": 1, "height": 0.5}, "position": [0, 0.26],
     "angle": 4.146e-7, "mass": 2},
    {"id": "turned", "type": "kinematic", "shape": {"type": "box", "width": 0.4, "height": 0.4},
     "position": [20, 5], "angle": 0.5, "angularVelocity": 1, "velocity": [3, 4]}]})";

bool openBoxes(MainWindow& w, QTemporaryDir& dir)
{
    const QString path = dir.filePath(QStringLiteral("boxes.json"));
    return writeFile(path, kBoxes) && w.openScene(path, true).isEmpty();
}

/// Every mark label of the window's plots, joined.
QString markTexts(MainWindow& w)
{
    QStringList texts;
    for (const ui::PlotWidget* plot : w.findChildren<ui::PlotWidget*>())
        for (int i = 0; i < plot->model().markCount(); ++i)
            texts << plot->markLabel(i)->text();
    return texts.join(u'|');
}

} // namespace

class TestPanelValues : public QObject {
    Q_OBJECT
private slots:
    void init() { QLocale::setDefault(QLocale(QLocale::English, QLocale::UnitedStates)); }
    void flatBoxShowsZero();
    void anglesInDegreesOrRadians();
    void emptyInspectorOffersNothingToActOn();
    void roundingNoiseOfSpeedsIsZero();
    void settingShownWhereItIsMade();
    void iterationsSayWhatTheyMean();
};

void TestPanelValues::flatBoxShowsZero()
{
    QTemporaryDir dir;
    MainWindow w;
    QVERIFY(openBoxes(w, dir));
    ui::SimulationController& c = w.controller();
    for (int i = 0; i < 1500; ++i) // it lands and settles
        c.stepForward();
    const double angle = c.world().body(1).angle;
    QVERIFY2(std::abs(angle) < 1e-4, qPrintable(QString::number(angle))); // lying flat
    w.inspector().setBody(1);
    QVERIFY(w.inspector().anglesInDegrees()); // the default
    QString text = w.inspector().text();
    QVERIFY2(text.contains(QStringLiteral("\n0°\n")), qPrintable(text));
    QVERIFY2(!QRegularExpression(QStringLiteral("\\d[eE][-+−]")).match(text).hasMatch(),
             qPrintable(text));
    w.inspector().setAnglesInDegrees(false);
    text = w.inspector().text();
    QVERIFY2(text.contains(QStringLiteral("\n0 rad\n")), qPrintable(text));
}

void TestPanelValues::anglesInDegreesOrRadians()
{
    QTemporaryDir dir;
    MainWindow w;
    QVERIFY(openBoxes(w, dir));
    ui::InspectorPanel& inspector = w.inspector();
    inspector.setBody(2);
    // 0.5 rad is 28.65°, to a tenth of a degree; 1 rad/s is 57.30 °/s.
    QString text = inspector.text();
    QVERIFY2(text.contains(QStringLiteral("\n28.6°\n")), qPrintable(text));
    QVERIFY2(text.contains("\n57.3" + kNbsp + "°/s"), qPrintable(text));
    // The choice is a combo box a keyboard reaches, with a name a screen reader says.
    auto* unit = inspector.findChild<QComboBox*>(QStringLiteral("angleUnit"));
    QVERIFY(unit);
    QVERIFY(!unit->accessibleName().isEmpty());
    QVERIFY(unit->focusPolicy() & Qt::TabFocus);
    unit->setCurrentIndex(1);
    QVERIFY(!inspector.anglesInDegrees());
    text = inspector.text();
    QVERIFY2(text.contains(QStringLiteral("\n0.5 rad\n")), qPrintable(text));
    QVERIFY2(text.contains(QStringLiteral("\n1 rad/s")), qPrintable(text));
    // The speed beside the components: |(3, 4)| = 5 m/s.
    QVERIFY2(text.contains(QStringLiteral("(3, 4) m/s\n5 m/s\n")), qPrintable(text));
}

void TestPanelValues::emptyInspectorOffersNothingToActOn()
{
    // No body chosen: one line says so, and no value's row nor a control that has nothing to
    // act on (a unit list, Graph…, a material's field).
    QTemporaryDir dir;
    MainWindow w;
    QVERIFY(openBoxes(w, dir));
    ui::InspectorPanel& inspector = w.inspector();
    inspector.setBody(-1);
    auto* unit = inspector.findChild<QComboBox*>(QStringLiteral("angleUnit"));
    auto* graph = inspector.findChild<QPushButton*>(QStringLiteral("inspectorGraph"));
    auto* kg = inspector.findChild<QLabel*>(QStringLiteral("massUnit"));
    QVERIFY(unit && graph && kg);
    QVERIFY(!unit->isVisibleTo(&inspector));
    QVERIFY(!kg->isVisibleTo(&inspector));
    QVERIFY(!graph->isVisibleTo(&inspector));
    QVERIFY(!inspector.restitutionField()->isVisibleTo(&inspector));
    QCOMPARE(inspector.text(), QStringLiteral("No body selected"));
    // A body chosen: the list is there, named, in the unit chosen before.
    inspector.setAnglesInDegrees(false);
    inspector.setBody(2);
    QVERIFY(unit->isVisibleTo(&inspector));
    QVERIFY(graph->isVisibleTo(&inspector) && graph->isEnabled());
    QVERIFY(inspector.restitutionField()->isVisibleTo(&inspector));
    QVERIFY(!kg->isVisibleTo(&inspector)); // a kinematic body's mass reads "infinite"
    QCOMPARE(unit->accessibleName(), QStringLiteral("Unit of angles"));
    QVERIFY2(inspector.text().contains(QStringLiteral("\n0.5 rad\n")),
             qPrintable(inspector.text()));
    inspector.setBody(1); // a dynamic one's is a field with its unit
    QVERIFY(kg->isVisibleTo(&inspector));
    inspector.setBody(-1);
    QVERIFY(!unit->isVisibleTo(&inspector));
    QVERIFY(!inspector.anglesInDegrees());
}

void TestPanelValues::roundingNoiseOfSpeedsIsZero()
{
    // A ball drifting at 1e-14 m/s and one at 1e-3 m/s, no gravity.
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("still.json"));
    QVERIFY(writeFile(path, R"({"rigidlab": 1, "world": {"gravity": [0, 0]}, "bodies": [
        {"id": "still", "shape": {"type": "circle", "radius": 0.1}, "position": [0, 0],
         "velocity": [1e-14, -3e-13], "angularVelocity": 1e-15, "mass": 1},
        {"id": "slow", "shape": {"type": "circle", "radius": 0.1}, "position": [5, 0],
         "velocity": [0.001, 0], "mass": 1}]})"));
    MainWindow w;
    QCOMPARE(w.openScene(path, true), QString());
    w.inspector().setAnglesInDegrees(false);
    w.inspector().setBody(0);
    QString text = w.inspector().text();
    QVERIFY2(text.contains(QStringLiteral("(0, 0) m/s\n0 m/s\n")), qPrintable(text));
    QVERIFY2(text.contains("\n0" + kNbsp + "J"), qPrintable(text));
    QVERIFY2(text.contains(QStringLiteral("\n0 rad/s")), qPrintable(text));
    QVERIFY2(!text.contains(QStringLiteral("e-")), qPrintable(text));
    w.inspector().setBody(1);
    text = w.inspector().text();
    QVERIFY2(text.contains(QStringLiteral("(0.001, 0) m/s\n0.001 m/s\n")), qPrintable(text));
    // ½ m v², the whole energy of the scene: in fixed notation, not "5e-07 J".
    QVERIFY2(text.contains("0.0000005" + kNbsp + "J"), qPrintable(text));
}

void TestPanelValues::settingShownWhereItIsMade()
{
    QTemporaryDir dir;
    MainWindow w;
    QVERIFY(openBoxes(w, dir));
    ui::SimulationController& c = w.controller();
    for (int i = 0; i < 100; ++i)
        c.stepForward();
    const long long before = c.world().stepCount();
    // Typed into the control panel: the world runs with it, the field and a mark say so.
    auto* iterations = w.controls().findChild<ui::NumberField*>(QStringLiteral("iterations"));
    QVERIFY(iterations);
    iterations->setFocus();
    iterations->selectAll();
    QTest::keyClicks(iterations, QStringLiteral("8"));
    QTest::keyClick(iterations, Qt::Key_Return);
    QCOMPARE(c.world().def().iterations, 8);
    QCOMPARE(iterations->text(), QStringLiteral("8"));
    QVERIFY2(markTexts(w).contains(QStringLiteral("8 iteration")), qPrintable(markTexts(w)));
    // Changed elsewhere (a lesson step, a test): the field follows.
    for (int i = 0; i < 100; ++i)
        c.stepForward();
    c.setIterations(12);
    QCOMPARE(iterations->text(), QStringLiteral("12"));
    QVERIFY2(markTexts(w).contains(QStringLiteral("12 iteration")), qPrintable(markTexts(w)));
    // Back to before both changes: the world and the field hold the scene's 10 again.
    c.seek(before - 10);
    QCOMPARE(c.world().def().iterations, 10);
    QCOMPARE(iterations->text(), QStringLiteral("10"));
}

void TestPanelValues::iterationsSayWhatTheyMean()
{
    // The iterations field is greyed only where the solver has none, and says why; under the
    // soft step it sets the bounce pass's sweeps, and says so. The tooltip and the screen
    // reader's description tell the same.
    QTemporaryDir dir;
    MainWindow w;
    QVERIFY(openBoxes(w, dir));
    ui::SimulationController& c = w.controller();
    auto* iterations = w.controls().findChild<ui::NumberField*>(QStringLiteral("iterations"));
    QVERIFY(iterations);
    const struct {
        physics::SolverKind solver;
        bool enabled;
        const char* word;
    } rows[] = {
        {physics::SolverKind::PaperImpulse, false, "once"},
        {physics::SolverKind::SequentialImpulse, true, "sequential-impulse"},
        {physics::SolverKind::SoftStep, true, "bounce pass"},
    };
    QStringList seen;
    for (const auto& row : rows) {
        c.setSolver(row.solver);
        const QString tip = iterations->toolTip();
        QCOMPARE(iterations->isEnabled(), row.enabled);
        QVERIFY2(tip.contains(QLatin1String(row.word)), qPrintable(tip));
        QCOMPARE(iterations->accessibleDescription(), tip);
        QVERIFY2(!seen.contains(tip), qPrintable(tip));
        seen << tip;
    }
    const QString soft = seen.last();
    QVERIFY2(soft.contains(QString::number(c.world().contactSettings().soft.substeps) +
                           QStringLiteral(" substeps")),
             qPrintable(soft));
}

RIGIDLAB_TEST_MAIN(TestPanelValues)
#include "test_panel_values.moc"
