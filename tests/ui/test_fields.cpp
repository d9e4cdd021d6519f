// SPDX-License-Identifier: GPL-3.0-or-later
// Typed values are never lost: the number fields of the control panel and the inspector, and
// the lesson's answer boxes, typed into key by key while the simulation runs, in an English
// and a Czech locale. Offscreen, driven as a user would.

#include "common/number_format.h"
#include "lesson_player/lesson_player.h"
#include "panels/control_panel.h"
#include "panels/inspector_panel.h"
#include "panels/number_field.h"
#include "simulation/simulation_controller.h"
#include "view/world_view.h"
#include "window/main_window.h"

#include "format/limits.h"
#include "format/scene_schema.h"

#include "fields_util.h"
#include "first_question.h"
#include "near.h"
#include "test_files.h"
#include "test_main.h"

#include <QDockWidget>
#include <QLineEdit>
#include <QLocale>
#include <QRegularExpression>
#include <QSignalSpy>
#include <QtTest>

#include <cmath>

using namespace rigidlab;
using rigidlab::test::writeFile;
using rigidlab::ui::MainWindow;
using rigidlab::ui::NumberField;

using namespace rigidlab::test::fields;

class TestFields : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { m_locale = QLocale(); }

    void cleanup() { QLocale::setDefault(m_locale); }

    void parsesPointAndComma_data()
    {
        QTest::addColumn<QString>("locale");
        QTest::addColumn<QString>("text");
        QTest::addColumn<bool>("ok");
        QTest::addColumn<double>("value");
        const struct {
            const char* text;
            bool ok;
            double value;
        } rows[] = {
            {"6,4", true, 6.4},       {"6.4", true, 6.4},    {"0,0156", true, 0.0156},
            {"0.0156", true, 0.0156}, {" 2.5 ", true, 2.5},  {"-2e-3", true, -2e-3},
            {"1E3", true, 1000.0},    {",5", true, 0.5},     {"5.", true, 5.0},
            {"+3", true, 3.0},        {"-0", true, 0.0},     {"1,5e2", true, 150.0},
            {"abc", false, 0},        {"1,2,3", false, 0},   {"1.2.3", false, 0},
            {"nan", false, 0},        {"inf", false, 0},     {"-inf", false, 0},
            {"1e999", false, 0},      {"-1e309", false, 0},  {"1e-400", false, 0},
            {"0x10", false, 0},       {"", false, 0},        {"--", false, 0},
            {"1 000", false, 0},      {"1,000.5", false, 0}, {"e5", false, 0},
            {".", false, 0},          {"5e", false, 0},      {"☃", false, 0},
        };
        for (const char* locale : {"en_US", "cs_CZ", "de_DE"})
            for (const auto& r : rows)
                QTest::newRow(qPrintable(QStringLiteral("%1 «%2»").arg(locale, r.text)))
                    << QString::fromLatin1(locale) << QString::fromUtf8(r.text) << r.ok << r.value;
    }
    void parsesPointAndComma()
    {
        QFETCH(QString, locale);
        QFETCH(QString, text);
        QFETCH(bool, ok);
        QFETCH(double, value);
        QLocale::setDefault(QLocale(locale));
        const std::optional<double> v = ui::parseNumber(text);
        QCOMPARE(v.has_value(), ok);
        if (ok) {
            QCOMPARE(*v, value);
            QVERIFY(!std::signbit(*v) || *v < 0); // "-0" is plain 0
        }
    }

    void whatIsShownReadsBack_data()
    {
        QTest::addColumn<QString>("locale");
        for (const char* l : {"en_US", "cs_CZ", "de_DE", "ar_EG", "sv_SE", "fa_IR"})
            QTest::newRow(l) << QString::fromLatin1(l);
    }
    void whatIsShownReadsBack()
    {
        QFETCH(QString, locale);
        QLocale::setDefault(QLocale(locale));
        for (double v : {6.4, -2.5, 0.0156, 1e-7, 1234567.0, -3e12, 0.0}) {
            const QString shown = ui::formatNumber(v);
            const std::optional<double> back = ui::parseNumber(shown);
            QVERIFY2(back && near(*back, v),
                     qPrintable(QStringLiteral("%1 shown as %2").arg(v).arg(shown)));
        }
        // No group separators: 1234567 is one number, not a list.
        QVERIFY(!ui::formatNumber(1234567.0).contains(QLocale(locale).groupSeparator()));
    }

    void typingWhileRunningKeepsEveryDigit_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<QString>("typed");
        QTest::addColumn<double>("expected"); // in the field's unit
        QTest::newRow("restitution 0.6")
            << QStringLiteral("restitution") << QStringLiteral("0.6") << 0.6;
        QTest::newRow("restitution 0,35")
            << QStringLiteral("restitution") << QStringLiteral("0,35") << 0.35;
        QTest::newRow("dt 2.5 ms") << QStringLiteral("dt") << QStringLiteral("2.5") << 2.5;
        QTest::newRow("dt 6,4 ms") << QStringLiteral("dt") << QStringLiteral("6,4") << 6.4;
        QTest::newRow("friction 0.45")
            << QStringLiteral("friction") << QStringLiteral("0.45") << 0.45;
        QTest::newRow("time scale 2,5")
            << QStringLiteral("timeScale") << QStringLiteral("2,5") << 2.5;
        QTest::newRow("iterations 25")
            << QStringLiteral("iterations") << QStringLiteral("25") << 25.0;
        QTest::newRow("mass 2,5 kg") << QStringLiteral("mass") << QStringLiteral("2,5") << 2.5;
    }
    void typingWhileRunningKeepsEveryDigit()
    {
        QFETCH(QString, name);
        QFETCH(QString, typed);
        QFETCH(double, expected);
        MainWindow w;
        QVERIFY(openBallDrop(w));
        auto& c = w.controller();
        NumberField* f = field(w, name);
        QVERIFY2(f, qPrintable(name));
        showDockOf(f); // the Inspector shares its place with the Controls: its tab is clicked
        QVERIFY(f->isVisible() && f->isEnabled());
        QVERIFY(!near(held(w, name, 1), expected)); // the test would notice no change
        c.setRunning(true);
        f->setFocus();
        QTRY_VERIFY(f->hasFocus());
        f->selectAll();
        QString sofar;
        for (const QChar ch : typed) {
            QTest::keyClick(f, ch.toLatin1());
            sofar += ch;
            // Frames go by, and every panel is redrawn, between two keys.
            QVERIFY(nextFrame(c));
            QVERIFY(nextFrame(c));
            w.controls().refresh();
            w.inspector().refresh();
            QCOMPARE(f->text(), sofar);
        }
        QVERIFY(c.isRunning());
        QTest::keyClick(f, Qt::Key_Return);
        QVERIFY2(near(held(w, name, 1), expected),
                 qPrintable(QStringLiteral("%1 holds %2").arg(name).arg(held(w, name, 1))));
        QCOMPARE(f->error(), QString());
        QVERIFY(nextFrame(c));
        QCOMPARE(f->text(), ui::formatNumber(expected)); // shown as the locale writes it
        QVERIFY(c.isRunning());
        c.setRunning(false);
    }

    void leavingTheFieldTakesTheValue()
    {
        MainWindow w;
        QVERIFY(openBallDrop(w));
        NumberField* f = field(w, QStringLiteral("dt"));
        f->setFocus();
        QTRY_VERIFY(f->hasFocus());
        f->selectAll();
        QTest::keyClicks(f, QStringLiteral("4"));
        QVERIFY(near(w.controller().world().def().dt, 0.001)); // not yet
        w.view().setFocus();
        QTRY_VERIFY(!f->hasFocus());
        QVERIFY(near(w.controller().world().def().dt, 0.004));
    }

    void outOfRangeIsRefusedOutLoud_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<QString>("typed");
        QTest::addColumn<double>("min"); // the range the message must name, in the field's unit
        QTest::addColumn<double>("max");
        QTest::addColumn<QString>("unit");
        namespace limits = lessons::limits;
        const double dtMin = limits::kDt.min * 1e3, dtMax = limits::kDt.max * 1e3;
        QTest::newRow("dt -5") << QStringLiteral("dt") << QStringLiteral("-5") << dtMin << dtMax
                               << QStringLiteral("ms");
        QTest::newRow("dt 1e9") << QStringLiteral("dt") << QStringLiteral("1e9") << dtMin << dtMax
                                << QStringLiteral("ms");
        QTest::newRow("dt abc") << QStringLiteral("dt") << QStringLiteral("abc") << dtMin << dtMax
                                << QStringLiteral("ms");
        QTest::newRow("dt 1e999") << QStringLiteral("dt") << QStringLiteral("1e999") << dtMin
                                  << dtMax << QStringLiteral("ms");
        QTest::newRow("restitution 1.5")
            << QStringLiteral("restitution") << QStringLiteral("1.5") << limits::kRestitution.min
            << limits::kRestitution.max << QString();
        QTest::newRow("restitution 1,2,3")
            << QStringLiteral("restitution") << QStringLiteral("1,2,3") << limits::kRestitution.min
            << limits::kRestitution.max << QString();
        QTest::newRow("friction -1") << QStringLiteral("friction") << QStringLiteral("-1")
                                     << limits::kFriction.min << limits::kFriction.max << QString();
        QTest::newRow("iterations 2.5")
            << QStringLiteral("iterations") << QStringLiteral("2.5") << limits::kIterations.min
            << limits::kIterations.max << QString();
        QTest::newRow("mass 0") << QStringLiteral("mass") << QStringLiteral("0")
                                << limits::kMass.min << limits::kMass.max << QStringLiteral("kg");
        QTest::newRow("mass 1e13")
            << QStringLiteral("mass") << QStringLiteral("1e13") << limits::kMass.min
            << limits::kMass.max << QStringLiteral("kg");
    }
    void outOfRangeIsRefusedOutLoud()
    {
        QFETCH(QString, name);
        QFETCH(QString, typed);
        QFETCH(double, min);
        QFETCH(double, max);
        QFETCH(QString, unit);
        MainWindow w;
        QVERIFY(openBallDrop(w));
        NumberField* f = field(w, name);
        QVERIFY(f);
        const double before = held(w, name, 1);
        const QString shownBefore = f->text();
        const physics::Body ballBefore = w.controller().world().body(1);
        QSignalSpy controls(&w.controls(), &ui::ControlPanel::inputRefused);
        QSignalSpy inspector(&w.inspector(), &ui::InspectorPanel::inputRefused);
        f->setFocus();
        QTRY_VERIFY(f->hasFocus());
        f->selectAll();
        QTest::keyClicks(f, typed);
        QTest::keyClick(f, Qt::Key_Return);
        // Refused: the message went out once, naming the range and its unit.
        QCOMPARE(controls.size() + inspector.size(), 1);
        const QString message =
            (controls.isEmpty() ? inspector : controls).first().first().toString();
        // A message is read, not typed back: its numbers as the window writes them, a power
        // of ten where the field's own form would have an exponent ("1E-09").
        const auto said = [](double x) {
            const QString plain = ui::formatNumber(x);
            return plain.contains(u'E', Qt::CaseInsensitive) ? ui::formatPowerOfTen(x, 12) : plain;
        };
        const QString lo = said(min), hi = said(max);
        const QString range = unit.isEmpty()
                                  ? QStringLiteral("from %1 to %2").arg(lo, hi)
                                  : QStringLiteral("from %1 %3 to %2 %3").arg(lo, hi, unit);
        QVERIFY2(message.contains(range), qPrintable(message + QStringLiteral(" / ") + range));
        QVERIFY2(!message.contains(QRegularExpression(QStringLiteral("\\d[eE][-+]?\\d"))),
                 qPrintable(message));
        QCOMPARE(f->error(), message);
        QCOMPARE(f->toolTip(), message);
        QVERIFY(f->property("refused").toBool());
        QVERIFY(!f->styleSheet().isEmpty()); // marked
        // The old value stays, nothing clamped; the typed text stays to be corrected.
        QCOMPARE(held(w, name, 1), before);
        QCOMPARE(w.controller().world().body(1).inertia, ballBefore.inertia);
        QCOMPARE(f->text(), typed);
        // Leaving the field shows the value in force again; the mark stays until the next edit.
        w.view().setFocus();
        QTRY_VERIFY(!f->hasFocus());
        QCOMPARE(f->text(), shownBefore);
        QCOMPARE(held(w, name, 1), before);
        QVERIFY(f->property("refused").toBool());
        f->setFocus();
        QTRY_VERIFY(f->hasFocus());
        QTest::keyClick(f, Qt::Key_End);
        QTest::keyClick(f, Qt::Key_Backspace);
        QVERIFY(!f->property("refused").toBool());
        QVERIFY(f->styleSheet().isEmpty());
    }

    void escapeRestores()
    {
        MainWindow w;
        QVERIFY(openBallDrop(w));
        auto& c = w.controller();
        NumberField* f = field(w, QStringLiteral("restitution"));
        const QString shown = f->text();
        const double before = c.world().def().restitution;
        c.setRunning(true);
        f->setFocus();
        QTRY_VERIFY(f->hasFocus());
        f->selectAll();
        QTest::keyClicks(f, QStringLiteral("0.9"));
        QVERIFY(nextFrame(c));
        QTest::keyClick(f, Qt::Key_Escape);
        QCOMPARE(f->text(), shown);
        QTest::keyClick(f, Qt::Key_Return); // nothing typed any more: nothing changes
        QCOMPARE(c.world().def().restitution, before);
        // Escape also clears a refusal.
        f->selectAll();
        QTest::keyClicks(f, QStringLiteral("7"));
        QTest::keyClick(f, Qt::Key_Return);
        QVERIFY(!f->error().isEmpty());
        QTest::keyClick(f, Qt::Key_Escape);
        QCOMPARE(f->text(), shown);
        QCOMPARE(f->error(), QString());
        QCOMPARE(c.world().def().restitution, before);
        c.setRunning(false);
    }

    // Long decimals are rounded on screen, never in force: 1/60 s reads "16,6667" ms in
    // Czech, and no field in the window shows more than NumberField::kShownDigits digits of a
    // value the program holds. Leaving the field untouched keeps 1/60 s; a value typed while
    // it runs is held as typed and shown with every digit typed, frame after frame.
    void longDecimalsAreRoundedOnScreenOnly_data()
    {
        QTest::addColumn<QString>("locale");
        QTest::addColumn<QString>("shown"); // 1/60 s in ms
        QTest::addColumn<QString>("typed");
        QTest::newRow("cs") << QStringLiteral("cs_CZ") << QStringLiteral("16,6667")
                            << QStringLiteral("4,1666667");
        QTest::newRow("en") << QStringLiteral("en_US") << QStringLiteral("16.6667")
                            << QStringLiteral("4.1666667");
    }
    void longDecimalsAreRoundedOnScreenOnly()
    {
        QFETCH(QString, locale);
        QFETCH(QString, shown);
        QFETCH(QString, typed);
        QLocale::setDefault(QLocale(locale));
        MainWindow w;
        QVERIFY(openBallDrop(w));
        auto& c = w.controller();
        c.setDt(1.0 / 60.0);
        c.setRestitution(1.0 / 3.0);
        c.setFriction(2.0 / 3.0);
        c.setTimeScale(1.0 / 3.0);
        c.setBodyMass(1, std::sqrt(2.0));
        w.inspector().refresh();
        NumberField* dt = field(w, QStringLiteral("dt"));
        QCOMPARE(dt->text(), shown);
        for (NumberField* f : w.findChildren<NumberField*>()) {
            const QString digits = f->text()
                                       .remove(QRegularExpression(QStringLiteral("[^0-9]")))
                                       .remove(QRegularExpression(QStringLiteral("^0+")));
            QVERIFY2(digits.size() <= NumberField::kShownDigits,
                     qPrintable(f->objectName() + QStringLiteral(" shows ") + f->text()));
        }
        // In and out without typing: the value in force is not the rounded one shown.
        dt->setFocus();
        QTRY_VERIFY(dt->hasFocus());
        QTest::keyClick(dt, Qt::Key_Return);
        w.view().setFocus();
        QTRY_VERIFY(!dt->hasFocus());
        QCOMPARE(c.world().def().dt, 1.0 / 60.0);
        // Typed while it runs: held to the last digit, and shown so.
        c.setRunning(true);
        dt->setFocus();
        QTRY_VERIFY(dt->hasFocus());
        dt->selectAll();
        QTest::keyClicks(dt, typed);
        QVERIFY(nextFrame(c));
        QTest::keyClick(dt, Qt::Key_Return);
        QVERIFY2(near(c.world().def().dt, 4.1666667e-3, 1e-15),
                 qPrintable(QString::number(c.world().def().dt, 'g', 17)));
        for (int frame = 0; frame < 3; ++frame) {
            QVERIFY(nextFrame(c));
            w.controls().refresh();
            QCOMPARE(dt->text(), typed);
        }
        // Escape brings back the value in force as it was typed, not rounded.
        dt->selectAll();
        QTest::keyClicks(dt, QStringLiteral("7"));
        QTest::keyClick(dt, Qt::Key_Escape);
        QCOMPARE(dt->text(), typed);
        c.setRunning(false);
        // A value from elsewhere is rounded again.
        c.setDt(1.0 / 60.0);
        QCOMPARE(dt->text(), shown);
    }

    void windowShortcutsStayOutOfTheField()
    {
        MainWindow w;
        QVERIFY(openBallDrop(w));
        auto& c = w.controller();
        NumberField* f = field(w, QStringLiteral("dt"));
        f->setFocus();
        QTRY_VERIFY(f->hasFocus());
        const QString shown = f->text();
        const long long step = c.world().stepCount();
        QTest::keyClick(f, Qt::Key_Space);
        QVERIFY(!c.isRunning());
        QCOMPARE(f->text(), shown); // a space neither plays nor erases the number
        for (Qt::Key key : {Qt::Key_S, Qt::Key_Right, Qt::Key_Left, Qt::Key_Backspace, Qt::Key_R,
                            Qt::Key_F, Qt::Key_Q, Qt::Key_E, Qt::Key_V, Qt::Key_Up, Qt::Key_Down})
            QTest::keyClick(f, key);
        QVERIFY(!c.isRunning());
        QCOMPARE(c.world().stepCount(), step);
        QVERIFY(f->hasFocus());
        QTest::keyClick(f, Qt::Key_Escape);
        QCOMPARE(f->text(), shown);
        // The same keys on the view do act: the test above could fail.
        w.view().setFocus();
        QTest::keyClick(&w.view(), Qt::Key_S);
        QCOMPARE(c.world().stepCount(), step + 1);
        QTest::keyClick(&w.view(), Qt::Key_Space);
        QVERIFY(c.isRunning());
        // While running, typing into a field and Space there leave it running.
        f->setFocus();
        QTRY_VERIFY(f->hasFocus());
        QTest::keyClick(f, Qt::Key_Space);
        QVERIFY(c.isRunning());
        c.setRunning(false);
    }

    void numbersFollowTheLocale()
    {
        QLocale::setDefault(QLocale(QLocale::Czech, QLocale::Czechia));
        MainWindow w;
        QVERIFY(openBallDrop(w));
        // ball_drop: e = 0.5, μ = 0.3; dt = 1 ms.
        QCOMPARE(field(w, QStringLiteral("restitution"))->text(), QStringLiteral("0,5"));
        QCOMPARE(field(w, QStringLiteral("friction"))->text(), QStringLiteral("0,3"));
        // Point or comma, both are read.
        NumberField* dt = field(w, QStringLiteral("dt"));
        dt->setFocus();
        QTRY_VERIFY(dt->hasFocus());
        dt->selectAll();
        QTest::keyClicks(dt, QStringLiteral("0.0156"));
        QTest::keyClick(dt, Qt::Key_Return);
        QVERIFY(near(w.controller().world().def().dt, 0.0156e-3));
        QCOMPARE(dt->text(), QStringLiteral("0,0156"));
        const QString text = w.inspector().text();
        QVERIFY2(text.contains(QStringLiteral("0,5 kg")), qPrintable(text));
    }

    void answersTakePointAndComma_data()
    {
        QTest::addColumn<QString>("locale");
        QTest::newRow("en_US") << QStringLiteral("en_US");
        QTest::newRow("cs_CZ") << QStringLiteral("cs_CZ");
        QTest::newRow("de_DE") << QStringLiteral("de_DE");
    }
    void answersTakePointAndComma()
    {
        QFETCH(QString, locale);
        QLocale::setDefault(QLocale(locale));
        MainWindow w;
        QCOMPARE(w.openLesson(lesson("restitution.json"), true), QString());
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        ui::LessonPlayer& player = w.lessonPlayer();
        const MeasuredQuestion measured = runToFirstQuestion(w);
        QVERIFY(measured.step >= 0);
        const std::optional<double> value = measured.value;
        QVERIFY(value);
        // A value below 1, so that a dropped separator (0.4096 read as 4096) would be wrong.
        RL_VERIFY_NEAR(*value, 0.0, 1 && std::abs(*value) > 0.01, 0);
        // (The questions sit below the lesson's scrolling text, in the dock.)
        const auto* questions = w.findChild<QWidget*>(QStringLiteral("lessonQuestions"));
        QVERIFY(questions);
        QLineEdit* edit = questions->findChildren<QLineEdit*>().value(0);
        QVERIFY(edit);
        auto typeAnswer = [&](const QString& text) {
            edit->setFocus();
            edit->selectAll();
            QTest::keyClick(edit, Qt::Key_Delete);
            QTest::keyClicks(edit, text);
            QCOMPARE(edit->text(), text); // every key typed is kept
            QTest::keyClick(edit, Qt::Key_Return);
        };
        const QString point = QString::number(*value, 'f', 4);
        QString comma = point;
        comma.replace(u'.', u',');
        typeAnswer(point);
        const QString byPoint = player.result(0);
        QVERIFY2(byPoint.startsWith(QStringLiteral("Right")), qPrintable(byPoint));
        typeAnswer(comma);
        QCOMPARE(player.result(0), byPoint);
        // A wrong answer stays wrong with either separator.
        QString wrong = QString::number(*value * 3 + 0.5, 'f', 4);
        typeAnswer(wrong);
        QVERIFY2(player.result(0).startsWith(QStringLiteral("Not quite")),
                 qPrintable(player.result(0)));
        typeAnswer(wrong.replace(u'.', u','));
        QVERIFY2(player.result(0).startsWith(QStringLiteral("Not quite")),
                 qPrintable(player.result(0)));
        typeAnswer(QStringLiteral("1,2,3"));
        QCOMPARE(player.result(0), QStringLiteral("Type a number first."));
    }

    void massEditGoesThroughTheWorld()
    {
        MainWindow w;
        QVERIFY(openBallDrop(w));
        auto& c = w.controller();
        const physics::Body before = c.world().body(1);
        // ball_drop's balls: circles of radius 0.1 m, 0.5 kg: I = m r² / 2.
        QVERIFY(before.shape.asCircle());
        const double r = before.shape.asCircle()->radius;
        QVERIFY(near(before.inertia, 0.5 * before.mass * r * r));
        for (int i = 0; i < 300; ++i) // falling, then asleep or not: wake-up is checked below
            c.stepForward();
        const physics::Vec2 v = c.world().body(1).velocity;
        NumberField* m = w.inspector().massField();
        m->setFocus();
        QTRY_VERIFY(m->hasFocus());
        m->selectAll();
        QTest::keyClicks(m, QStringLiteral("1,75"));
        QTest::keyClick(m, Qt::Key_Return);
        const physics::Body& after = c.world().body(1);
        QCOMPARE(after.mass, 1.75);
        QVERIFY(near(after.invMass, 1 / 1.75));
        QVERIFY(near(after.inertia, 0.5 * 1.75 * r * r));
        QVERIFY(near(after.invInertia, 1 / (0.5 * 1.75 * r * r)));
        QVERIFY(after.awake);
        QVERIFY(after.velocity == v); // velocities stay; momentum grows with the mass
        QVERIFY(near(c.world().diagnostics().momentum.y(),
                     1.75 * v.y() +
                         0.5 * (c.world().body(2).velocity.y() + c.world().body(3).velocity.y()),
                     1e-9));
        // The other balls are untouched, and the inspector shows the new mass and inertia.
        QCOMPARE(c.world().body(2).mass, before.mass);
        QVERIFY2(w.inspector().text().contains(ui::formatNumber(0.5 * 1.75 * r * r, 4)),
                 qPrintable(w.inspector().text()));
        // A static body has no mass to edit.
        w.inspector().setBody(0);
        QVERIFY(!m->isVisible());
        QVERIFY(w.inspector().text().contains(QStringLiteral("infinite")));
        // Straight to the controller: out of range or not dynamic changes nothing.
        c.setBodyMass(0, 2.0);
        c.setBodyMass(1, 0.0);
        c.setBodyMass(1, std::nan(""));
        c.setBodyMass(1, 1e300);
        QCOMPARE(c.world().body(0).mass, 0.0);
        QCOMPARE(c.world().body(1).mass, 1.75);
    }

    void everySettingHasItsControl()
    {
        // A lesson step locks the settings of the table, each by its own control.
        ui::SimulationController c;
        ui::ControlPanel panel(c);
        panel.setAllowed(QStringList{});
        for (const lessons::schema::Field& f : lessons::schema::settings()) {
            const QString key = QString::fromLatin1(f.key.data(), qsizetype(f.key.size()));
            auto* control = panel.findChild<QWidget*>(key, Qt::FindDirectChildrenOnly);
            QVERIFY2(control, qPrintable(key));
            QVERIFY2(!control->isEnabled() && control->property("locked").toBool(),
                     qPrintable(key));
            panel.setAllowed(QStringList{key});
            QVERIFY2(!control->property("locked").toBool(), qPrintable(key));
            panel.setAllowed(QStringList{});
        }
    }

private:
    QLocale m_locale;
};

RIGIDLAB_TEST_MAIN(TestFields)
#include "test_fields.moc"
