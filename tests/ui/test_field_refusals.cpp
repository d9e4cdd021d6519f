// SPDX-License-Identifier: GPL-3.0-or-later
// What a teacher typing into the Inspector meets while the welcome scene runs, by keys only
// (] ] chooses the wrecking ball, Return puts the focus on its mass): the mass typed key by key
// keeps every key whatever the frames redraw, written either way in each language ("6,5" or
// "6.5"); a value refused says where (the field's name), what (the range and its unit) and
// what stays (the value in force), on screen and to a screen reader, and changes nothing.

#include "common/announcer.h"
#include "common/language.h"
#include "panels/control_panel.h"
#include "panels/inspector_panel.h"
#include "panels/number_field.h"
#include "simulation/simulation_controller.h"
#include "window/main_window.h"

#include "format/limits.h"

#include <QApplication>
#include <QtTest>

#include "fields_util.h"
#include "projector_window.h"
#include "test_main.h"

using namespace rigidlab;
using rigidlab::test::fields::near;
using rigidlab::test::fields::nextFrame;
using rigidlab::ui::MainWindow;
using rigidlab::ui::NumberField;

namespace {

/// The welcome scene running in the window, shown and active, with the focus on the wrecking
/// ball's mass as the keys put it there; the ball's body, or -1.
int focusRunningBallsMass(MainWindow& w)
{
    const QString welcome =
        QDir(MainWindow::scenesFolder()).filePath(QStringLiteral("welcome.json"));
    if (!w.openScene(welcome, true).isEmpty() || !test::showActiveOnProjector(w))
        return -1;
    w.controller().setRunning(true);
    const int body = test::askWreckingBallNumbers(w);
    NumberField* mass = w.inspector().massField();
    if (body < 0 || !mass || !QTest::qWaitFor([&] { return mass->hasFocus(); }, 5000))
        return -1;
    return body;
}

} // namespace

class TestFieldRefusals : public QObject {
    Q_OBJECT
private slots:
    void cleanup() { ui::applyLanguage(QStringLiteral("en")); }

    void typedMassSurvivesTheFrames_data()
    {
        QTest::addColumn<QString>("language");
        QTest::addColumn<QString>("typed");
        QTest::newRow("en 6.5") << QStringLiteral("en") << QStringLiteral("6.5");
        QTest::newRow("en 6,5") << QStringLiteral("en") << QStringLiteral("6,5");
        QTest::newRow("cs 6,5") << QStringLiteral("cs") << QStringLiteral("6,5");
        QTest::newRow("cs 6.5") << QStringLiteral("cs") << QStringLiteral("6.5");
    }
    void typedMassSurvivesTheFrames()
    {
        QFETCH(QString, language);
        QFETCH(QString, typed);
        QVERIFY(ui::applyLanguage(language));
        MainWindow w;
        const int body = focusRunningBallsMass(w);
        QVERIFY(body >= 0);
        auto& c = w.controller();
        NumberField* mass = w.inspector().massField();
        mass->selectAll();
        QString sofar;
        for (const QChar ch : typed) {
            QTest::keyClick(mass, ch.toLatin1());
            sofar += ch;
            // Frames go by between two keys, the ball swings, the Inspector is redrawn.
            QVERIFY(nextFrame(c));
            QVERIFY(nextFrame(c));
            w.inspector().refresh();
            QCOMPARE(mass->text(), sofar);
        }
        QTest::keyClick(mass, Qt::Key_Return);
        QVERIFY2(near(c.world().body(body).mass, 6.5),
                 qPrintable(QStringLiteral("mass %1, 6.5 typed").arg(c.world().body(body).mass)));
        QCOMPARE(mass->error(), QString());
        QVERIFY(nextFrame(c));
        QCOMPARE(mass->text(), ui::formatNumber(6.5)); // as the language writes it
        QVERIFY(c.isRunning());
    }

    void aRefusalSaysWhereWhatAndWhatStays_data()
    {
        QTest::addColumn<QString>("typed");
        QTest::addColumn<bool>("named"); // the message quotes what was typed
        QTest::newRow("letters") << QStringLiteral("abc") << true;
        QTest::newRow("negative") << QStringLiteral("-3") << false;
        QTest::newRow("zero") << QStringLiteral("0") << false;
        // A number no double holds is out of range, not "not a number".
        QTest::newRow("1e999") << QStringLiteral("1e999") << false;
        QTest::newRow("empty") << QString() << false;
        QTest::newRow("two commas") << QStringLiteral("6,5,1") << true;
    }
    void aRefusalSaysWhereWhatAndWhatStays()
    {
        QFETCH(QString, typed);
        QFETCH(bool, named);
        QVERIFY(ui::applyLanguage(QStringLiteral("en")));
        MainWindow w;
        const int body = focusRunningBallsMass(w);
        QVERIFY(body >= 0);
        auto& c = w.controller();
        NumberField* mass = w.inspector().massField();
        const double before = c.world().body(body).mass;
        const QString shown = mass->text();
        QCOMPARE(shown, QStringLiteral("6"));
        QSignalSpy refused(&w.inspector(), &ui::InspectorPanel::inputRefused);
        mass->selectAll();
        QTest::keyClick(mass, Qt::Key_Delete);
        QTest::keyClicks(mass, typed);
        QVERIFY(nextFrame(c));
        QTest::keyClick(mass, Qt::Key_Return);
        QCOMPARE(refused.size(), 1);
        const QString message = refused.first().first().toString();
        // Where, what and what stays.
        namespace limits = lessons::limits;
        // Read, not typed back: powers of ten as the window writes them, never "1E-09".
        QCOMPARE(limits::kMass.min, 1e-9);
        QCOMPARE(limits::kMass.max, 1e12);
        const QString range = QStringLiteral("from 1 × 10⁻⁹ kg to 1 × 10¹² kg");
        QVERIFY2(message.startsWith(
                     named ? QStringLiteral("“%1” is not a number: Mass m must be ").arg(typed)
                           : QStringLiteral("Mass m must be ")) &&
                     message.contains(range) &&
                     message.endsWith(QStringLiteral(". It stays 6 kg.")),
                 qPrintable(message));
        QCOMPARE(mass->error(), message);
        QCOMPARE(mass->toolTip(), message);
        // A reader hears it too: the window's announcer says it.
        QWidget* told = ui::announcer(w);
        QVERIFY(told);
        QCOMPARE(told->accessibleName(), message);
        // Nothing changed; the typed text stays to be corrected while the frames go by.
        QVERIFY(nextFrame(c));
        w.inspector().refresh();
        QCOMPARE(c.world().body(body).mass, before);
        QCOMPARE(mass->text(), typed);
        // Left, the field shows the value in force again, as the message said, and a reader
        // is not told the refusal a second time (what the announcer says stays as it was).
        const QString other = QStringLiteral("something else since");
        ui::announce(w, other);
        w.view().setFocus();
        QTRY_VERIFY(!mass->hasFocus());
        QCOMPARE(mass->text(), shown);
        QCOMPARE(told->accessibleName(), other);
        QCOMPARE(c.world().body(body).mass, before);
        QVERIFY(c.isRunning());
    }
};

RIGIDLAB_TEST_MAIN(TestFieldRefusals)
#include "test_field_refusals.moc"
