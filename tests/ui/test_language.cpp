// SPDX-License-Identifier: GPL-3.0-or-later
// Czech and English: the language chosen from --lang, the setting or the system, a switch
// that keeps the scene, the lesson step and the time, and the decimal comma in Czech. (The
// .ts files against the sources: test_translations.cpp.)

#include "common/language.h"
#include "format/scene_loader.h"
#include "lesson_player/lesson_player.h"
#include "panels/number_field.h"
#include "plots/plot_widget.h"
#include "simulation/simulation_controller.h"
#include "window/language_switch.h"
#include "window/main_window.h"

#include "first_question.h"
#include "near.h"
#include "shipped_lessons.h"
#include "test_main.h"

#include <qcustomplot.h>

#include <QAction>
#include <QApplication>
#include <QDialogButtonBox>
#include <QDir>
#include <QFile>
#include <QLibraryInfo>
#include <QLineEdit>
#include <QLocale>
#include <QMap>
#include <QMenu>
#include <QProcess>
#include <QPushButton>
#include <QSet>
#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTranslator>
#include <QXmlStreamReader>
#include <QtTest>

#include <cmath>
#include <memory>
#include <optional>

using namespace rigidlab;
using rigidlab::ui::MainWindow;

namespace {

QString shippedScene(const char* name)
{
    return QDir(MainWindow::scenesFolder()).filePath(QLatin1String(name));
}

/// Positions of every body of the window's world, for comparing two worlds exactly.
std::vector<double> bodyCoordinates(MainWindow& w)
{
    std::vector<double> out;
    for (const physics::Body& b : w.controller().world().bodies()) {
        out.push_back(b.position.x());
        out.push_back(b.position.y());
        out.push_back(b.angle);
    }
    return out;
}

/// Each plot's marks: the time of each, oldest first.
std::vector<std::vector<double>> markTimes(MainWindow& w)
{
    std::vector<std::vector<double>> out;
    for (auto* plot : w.plots()) {
        std::vector<double> times;
        for (int i = 0; i < plot->model().markCount(); ++i)
            times.push_back(plot->markLabel(i)->position->key());
        out.push_back(times);
    }
    return out;
}

} // namespace

class TestLanguage : public QObject {
    Q_OBJECT

private slots:
    void init() { ui::applyLanguage(QStringLiteral("en")); }
    void cleanupTestCase() { ui::applyLanguage(QStringLiteral("en")); }

    // --- Choosing and applying a language --------------------------------------------

    void choice_data()
    {
        QTest::addColumn<QString>("commandLine");
        QTest::addColumn<QString>("saved");
        QTest::addColumn<QString>("system");
        QTest::addColumn<QString>("expected");
        QTest::newRow("--lang beats the setting") << "cs"
                                                  << "en"
                                                  << "en_US"
                                                  << "cs";
        QTest::newRow("--lang en on a Czech system") << "en"
                                                     << ""
                                                     << "cs_CZ"
                                                     << "en";
        QTest::newRow("the setting beats the system") << ""
                                                      << "en"
                                                      << "cs_CZ"
                                                      << "en";
        QTest::newRow("a Czech system") << ""
                                        << ""
                                        << "cs_CZ"
                                        << "cs";
        QTest::newRow("a German system") << ""
                                         << ""
                                         << "de_DE"
                                         << "en";
        QTest::newRow("an English system") << ""
                                           << ""
                                           << "en_GB"
                                           << "en";
        QTest::newRow("unknown values are passed over") << "de"
                                                        << "xx"
                                                        << "cs_CZ"
                                                        << "cs";
    }
    void choice()
    {
        QFETCH(QString, commandLine);
        QFETCH(QString, saved);
        QFETCH(QString, system);
        QFETCH(QString, expected);
        QCOMPARE(ui::chooseLanguage(commandLine, saved, QLocale(system)), expected);
    }

    void settingPersists()
    {
        QCOMPARE(ui::savedLanguage(), QString());
        QVERIFY(ui::saveLanguage(QStringLiteral("cs")));
        QCOMPARE(ui::savedLanguage(), QStringLiteral("cs"));
        QCOMPARE(QSettings().value(QStringLiteral("language")).toString(), QStringLiteral("cs"));
        QVERIFY(!ui::saveLanguage(QStringLiteral("de"))); // no such language: nothing saved
        QCOMPARE(ui::savedLanguage(), QStringLiteral("cs"));
        QSettings().remove(QStringLiteral("language"));
    }

    void applyingSetsLocaleAndTranslators()
    {
        QVERIFY(!ui::applyLanguage(QStringLiteral("de")));
        QCOMPARE(ui::currentLanguage(), QStringLiteral("en"));
        QCOMPARE(QLocale().decimalPoint(), QStringLiteral("."));
        QVERIFY(ui::applyLanguage(QStringLiteral("cs")));
        QCOMPARE(ui::currentLanguage(), QStringLiteral("cs"));
        QCOMPARE(QLocale().language(), QLocale::Czech);
        QCOMPARE(QLocale().decimalPoint(), QStringLiteral(","));
        // RigidLab's Czech is built into the program.
        QTranslator lab;
        QVERIFY(lab.load(QStringLiteral(":/i18n/rigidlab_cs")));
        QCOMPARE(lab.language(), QStringLiteral("cs_CZ"));
        QVERIFY(QFile::exists(QStringLiteral(":/i18n/rigidlab_en.qm")));
        // Qt's own Czech (Debian's qt6-translations-l10n) for its standard buttons.
        const QString qtbase =
            QLibraryInfo::path(QLibraryInfo::TranslationsPath) + QStringLiteral("/qtbase_cs.qm");
        QVERIFY2(QFile::exists(qtbase), qPrintable(qtbase + QStringLiteral(" is missing")));
        {
            QDialogButtonBox box(QDialogButtonBox::Cancel);
            const QString cancel = box.button(QDialogButtonBox::Cancel)->text();
            QVERIFY2(!cancel.contains(QLatin1String("Cancel")), qPrintable(cancel));
        }
        QVERIFY(ui::applyLanguage(QStringLiteral("en")));
        QCOMPARE(QLocale().decimalPoint(), QStringLiteral("."));
        QDialogButtonBox box(QDialogButtonBox::Cancel);
        QVERIFY(box.button(QDialogButtonBox::Cancel)->text().contains(QLatin1String("Cancel")));
    }

    // --- Switching keeps what the window shows ----------------------------------------

    void menuSavesAndAsks()
    {
        auto* w = new MainWindow;
        const std::unique_ptr<MainWindow> owner(w);
        auto* cs = w->findChild<QAction*>(QStringLiteral("language-cs"));
        auto* en = w->findChild<QAction*>(QStringLiteral("language-en"));
        QVERIFY(cs && en);
        QVERIFY(en->isChecked());
        QVERIFY(!cs->isChecked());
        QCOMPARE(cs->text(), QStringLiteral("Čeština"));
        QSignalSpy chosen(w, &MainWindow::languageChosen);
        cs->trigger();
        QCOMPARE(chosen.size(), 1);
        QCOMPARE(chosen[0][0].toString(), QStringLiteral("cs"));
        QCOMPARE(ui::savedLanguage(), QStringLiteral("cs"));
        QSettings().remove(QStringLiteral("language"));
    }

    // The menu, as rigidlab wires it (followLanguageChoice): a new window replaces the old
    // one, and the one after it follows the menu too.
    void menuReplacesTheWindow()
    {
        auto* w = new MainWindow;
        w->setAttribute(Qt::WA_DeleteOnClose);
        QCOMPARE(w->openScene(shippedScene("ball_drop.json"), true), QString());
        w->show();
        ui::followLanguageChoice(w);
        QPointer<MainWindow> old = w;
        const auto windows = [] {
            QList<MainWindow*> out;
            for (QWidget* t : QApplication::topLevelWidgets())
                if (auto* m = qobject_cast<MainWindow*>(t))
                    out << m;
            return out;
        };
        w->findChild<QAction*>(QStringLiteral("language-cs"))->trigger();
        QTRY_VERIFY(old.isNull());
        QCOMPARE(ui::currentLanguage(), QStringLiteral("cs"));
        QCOMPARE(windows().size(), 1);
        MainWindow* czech = windows().front();
        QVERIFY(czech->isVisible());
        QCOMPARE(czech->controller().scenePath(), shippedScene("ball_drop.json"));
        old = czech;
        czech->findChild<QAction*>(QStringLiteral("language-en"))->trigger();
        QTRY_VERIFY(old.isNull());
        QCOMPARE(ui::currentLanguage(), QStringLiteral("en"));
        QCOMPARE(windows().size(), 1);
        QCOMPARE(ui::savedLanguage(), QStringLiteral("en"));
        delete windows().front();
        QSettings().remove(QStringLiteral("language"));
    }

    void switchKeepsLessonStepAndTime()
    {
        const QStringList lessons = test::shippedLessons();
        QVERIFY(!lessons.isEmpty());
        // A lesson with more than one step, at its second step.
        QString path;
        {
            MainWindow probe;
            for (const QString& p : lessons)
                if (probe.openLesson(p, true).isEmpty() &&
                    probe.lessonPlayer().lesson()->steps.size() > 1) {
                    path = p;
                    break;
                }
        }
        QVERIFY(!path.isEmpty());
        MainWindow* w = new MainWindow;
        w->setAttribute(Qt::WA_DeleteOnClose);
        QCOMPARE(w->openLesson(path, true), QString());
        w->lessonPlayer().goToStep(1);
        for (int i = 0; i < 77; ++i)
            w->controller().stepForward();
        w->show();
        QVERIFY(QTest::qWaitForWindowExposed(w));
        const double time = w->controller().world().time();
        const long long steps = w->controller().world().stepCount();
        const std::vector<double> bodies = bodyCoordinates(*w);
        QCOMPARE(steps, 77);
        QVERIFY(time > 0);

        QPointer<MainWindow> old = w;
        MainWindow* czech = ui::switchLanguage(w, QStringLiteral("cs"));
        QVERIFY(czech != w);
        QTRY_VERIFY(old.isNull()); // the old window is gone
        QVERIFY(czech->isVisible());
        QCOMPARE(ui::currentLanguage(), QStringLiteral("cs"));
        QVERIFY(czech->lessonPlayer().lesson());
        QCOMPARE(czech->lessonPlayer().lesson()->path, path);
        QCOMPARE(czech->lessonPlayer().stepIndex(), 1);
        QCOMPARE(czech->controller().world().stepCount(), steps);
        QCOMPARE(czech->controller().world().time(), time);
        QVERIFY(bodyCoordinates(*czech) == bodies); // the same run, replayed exactly
        auto* cs = czech->findChild<QAction*>(QStringLiteral("language-cs"));
        QVERIFY(cs && cs->isChecked());

        old = czech;
        MainWindow* english = ui::switchLanguage(czech, QStringLiteral("en"));
        QTRY_VERIFY(old.isNull());
        QCOMPARE(ui::currentLanguage(), QStringLiteral("en"));
        QCOMPARE(english->lessonPlayer().lesson()->path, path);
        QCOMPARE(english->lessonPlayer().stepIndex(), 1);
        QCOMPARE(english->controller().world().stepCount(), steps);
        QCOMPARE(english->controller().world().time(), time);
        QVERIFY(bodyCoordinates(*english) == bodies);
        delete english;
    }

    void switchKeepsAnswersMarksAndSettings()
    {
        // A lesson step with a question, measured; a wrong try, then the right one, then
        // something typed and not checked; the integrator and dt changed by hand mid-run.
        QString path;
        MeasuredQuestion question;
        MainWindow* w = new MainWindow;
        w->setAttribute(Qt::WA_DeleteOnClose);
        for (const QString& p : test::shippedLessons()) {
            QCOMPARE(w->openLesson(p, true), QString());
            question = runToFirstQuestion(*w);
            if (question.value && *question.value != 0) {
                path = p;
                break;
            }
        }
        QVERIFY(!path.isEmpty());
        ui::LessonPlayer& player = w->lessonPlayer();
        const QStringList heldAtFirst = player.heldBack();
        player.answer(0, QLocale().toString(*question.value * 3 + 1, 'g', 12));
        const QString wrong = player.result(0);
        QVERIFY(!wrong.isEmpty());
        player.answer(0, QLocale().toString(*question.value, 'g', 12));
        const QString right = player.result(0);
        QVERIFY(right != wrong);
        const QStringList held = player.heldBack();
        QVERIFY(held != heldAtFirst || heldAtFirst.isEmpty());
        auto* box = player.findChild<QLineEdit*>();
        QVERIFY(box);
        box->setText(QStringLiteral("12"));

        ui::SimulationController& controller = w->controller();
        const physics::IntegratorKind integrator =
            controller.world().def().integrator == physics::IntegratorKind::RK4
                ? physics::IntegratorKind::Verlet
                : physics::IntegratorKind::RK4;
        const double dt = controller.world().def().dt / 2;
        for (int i = 0; i < 10; ++i)
            controller.stepForward();
        controller.setIntegrator(integrator);
        for (int i = 0; i < 30; ++i)
            controller.stepForward();
        controller.setDt(dt);
        controller.setTimeScale(0.5);
        for (int i = 0; i < 20; ++i)
            controller.stepForward();
        QCOMPARE(controller.editLog().edits().size(), std::size_t(2));
        const std::vector<std::vector<double>> marks = markTimes(*w);
        QCOMPARE(marks.front().size(), std::size_t(2)); // the energy plot marks both changes
        const std::vector<double> bodies = bodyCoordinates(*w);
        const long long steps = controller.world().stepCount();
        const int step = player.stepIndex();
        const auto tries = player.work().tries;
        QCOMPARE(tries.front().size(), std::size_t(2));
        w->show();
        QVERIFY(QTest::qWaitForWindowExposed(w));

        MainWindow* czech = ui::switchLanguage(w, QStringLiteral("cs"));
        ui::LessonPlayer& cplayer = czech->lessonPlayer();
        QCOMPARE(cplayer.stepIndex(), step);
        QCOMPARE(cplayer.result(0).isEmpty(), false);
        QVERIFY(cplayer.result(0) != right); // the verdict, in Czech
        QCOMPARE(cplayer.heldBack(), held);  // what the answer released stays released
        QCOMPARE(cplayer.findChild<QLineEdit*>()->text(), QStringLiteral("12"));
        QVERIFY(cplayer.work().tries == tries);
        QCOMPARE(czech->controller().world().def().integrator, integrator);
        QCOMPARE(czech->controller().world().def().dt, dt);
        QCOMPARE(czech->controller().timeScale(), 0.5);
        QCOMPARE(czech->controller().world().stepCount(), steps);
        QVERIFY(bodyCoordinates(*czech) == bodies); // the same run, changes and all
        QVERIFY(markTimes(*czech) == marks);

        MainWindow* english = ui::switchLanguage(czech, QStringLiteral("en"));
        QCOMPARE(english->lessonPlayer().result(0), right); // the same verdict as before
        QCOMPARE(english->lessonPlayer().heldBack(), held);
        QCOMPARE(english->controller().world().def().integrator, integrator);
        QVERIFY(bodyCoordinates(*english) == bodies);
        QVERIFY(markTimes(*english) == marks);
        delete english;
    }

    // Settings changed by hand and then kept by a reset are the run's from its start: the
    // switch gives the same world, without a mark (nothing changed mid-run).
    void switchKeepsSettingsAcrossReset()
    {
        MainWindow* w = new MainWindow;
        QCOMPARE(w->openScene(shippedScene("ball_drop.json"), true), QString());
        ui::SimulationController& controller = w->controller();
        for (int i = 0; i < 15; ++i)
            controller.stepForward();
        const double dt = controller.world().def().dt / 4;
        controller.setDt(dt);
        controller.setRestitution(0.3);
        controller.reset();
        QCOMPARE(controller.editLog().edits().size(), std::size_t(2));
        for (int i = 0; i < 25; ++i)
            controller.stepForward();
        const std::vector<double> bodies = bodyCoordinates(*w);
        MainWindow* czech = ui::switchLanguage(w, QStringLiteral("cs"));
        QCOMPARE(czech->controller().world().def().dt, dt);
        QCOMPARE(czech->controller().world().def().restitution, 0.3);
        QCOMPARE(czech->controller().world().stepCount(), 25);
        QVERIFY(bodyCoordinates(*czech) == bodies);
        QCOMPARE(czech->plot(u"energy")->model().markCount(), 0);
        delete czech;
    }

    void switchKeepsSceneAndRunning()
    {
        MainWindow* w = new MainWindow;
        const QString path = shippedScene("ball_drop.json");
        QCOMPARE(w->openScene(path, true), QString());
        for (int i = 0; i < 40; ++i)
            w->controller().stepForward();
        const std::vector<double> bodies = bodyCoordinates(*w);
        w->controller().setRunning(true);
        MainWindow* czech = ui::switchLanguage(w, QStringLiteral("cs"));
        QVERIFY(!czech->lessonPlayer().lesson());
        QCOMPARE(czech->controller().scenePath(), path);
        QVERIFY(czech->controller().isRunning());
        czech->controller().setRunning(false);
        // Running may have taken a step or two since: the 40th is in the history.
        QVERIFY(czech->controller().world().stepCount() >= 40);
        czech->controller().seek(40);
        QVERIFY(bodyCoordinates(*czech) == bodies);
        QCOMPARE(ui::switchLanguage(czech, QStringLiteral("xx")), czech); // no such language
        delete czech;
    }

    void sceneTitlesFollowLanguage()
    {
        const QString path = shippedScene("ball_drop.json");
        const lessons::SceneLoadResult en =
            lessons::loadSceneFile(path, lessons::SceneLoadOptions{QStringLiteral("en")});
        const lessons::SceneLoadResult cs =
            lessons::loadSceneFile(path, lessons::SceneLoadOptions{QStringLiteral("cs")});
        QVERIFY(en.ok && cs.ok);
        QVERIFY(en.scene.title != cs.scene.title); // the shipped scene has a Czech title
        const auto hasAction = [](const MainWindow& window, const QString& text) {
            for (const QAction* a : window.findChildren<QAction*>()) {
                if (a->text() == text)
                    return true;
            }
            return false;
        };
        MainWindow* w = new MainWindow;
        QCOMPARE(w->openScene(path, true), QString());
        QVERIFY2(w->windowTitle().contains(en.scene.title), qPrintable(w->windowTitle()));
        QVERIFY(hasAction(*w, en.scene.title)); // File › Shipped scenes
        MainWindow* czech = ui::switchLanguage(w, QStringLiteral("cs"));
        QVERIFY2(czech->windowTitle().contains(cs.scene.title), qPrintable(czech->windowTitle()));
        QVERIFY(hasAction(*czech, cs.scene.title));
        QVERIFY(!hasAction(*czech, en.scene.title));
        delete czech;
    }

    // --- Numbers in Czech ------------------------------------------------------------

    void czechPluralForms()
    {
        // Czech has three forms (1 / 2–4 / 5 and more), English two; the counts pick them.
        const auto files = [](int n) {
            return QCoreApplication::translate("CommandLine", "%n file(s) written into %1", nullptr,
                                               n)
                .arg(QStringLiteral("D"));
        };
        const auto iterations = [](int n) {
            return QCoreApplication::translate("rigidlab::ui::SimulationController",
                                               "%n iteration(s)", nullptr, n);
        };
        QVERIFY(ui::applyLanguage(QStringLiteral("cs")));
        QCOMPARE(files(1), QStringLiteral("1 soubor zapsán do D"));
        QCOMPARE(files(3), QStringLiteral("3 soubory zapsány do D"));
        QCOMPARE(files(5), QStringLiteral("5 souborů zapsáno do D"));
        QCOMPARE(files(22), QStringLiteral("22 souborů zapsáno do D")); // not 22 like 2, in Czech
        QCOMPARE(iterations(1), QStringLiteral("1 iterace"));
        QCOMPARE(iterations(4), QStringLiteral("4 iterace"));
        QCOMPARE(iterations(10), QStringLiteral("10 iterací"));
        QVERIFY(ui::applyLanguage(QStringLiteral("en")));
        QCOMPARE(files(1), QStringLiteral("1 file written into D"));
        QCOMPARE(files(5), QStringLiteral("5 files written into D"));
        QCOMPARE(iterations(1), QStringLiteral("1 iteration"));
        QCOMPARE(iterations(10), QStringLiteral("10 iterations"));
    }

    void czechReadsCommaAndPoint()
    {
        QVERIFY(ui::applyLanguage(QStringLiteral("cs")));
        QCOMPARE(ui::formatNumber(0.0156), QStringLiteral("0,0156"));
        QCOMPARE(ui::parseNumber(QStringLiteral("0,0156")), std::optional<double>(0.0156));
        QCOMPARE(ui::parseNumber(QStringLiteral("0.0156")), std::optional<double>(0.0156));
        ui::NumberField field;
        field.setValue(0.0156);
        QCOMPARE(field.text(), QStringLiteral("0,0156"));
    }

    void czechAnswersTakeCommaAndPoint()
    {
        QVERIFY(ui::applyLanguage(QStringLiteral("cs")));
        MainWindow w;
        QCOMPARE(w.openLesson(
                     QDir(MainWindow::lessonsFolder()).filePath(QStringLiteral("restitution.json")),
                     true),
                 QString());
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        ui::LessonPlayer& player = w.lessonPlayer();
        const MeasuredQuestion measured = runToFirstQuestion(w);
        QVERIFY(measured.step >= 0);
        const std::optional<double> value = measured.value;
        QVERIFY(value);
        RL_VERIFY_NEAR(*value, 0.0, 1 && std::abs(*value) > 0.01, 0); // "0,4" misread as 4 fails
        const QString point = QString::number(*value, 'f', 4);
        QString comma = point;
        comma.replace(u'.', u',');
        player.answer(0, comma);
        const QString byComma = player.result(0);
        player.answer(0, point);
        const QString byPoint = player.result(0);
        QCOMPARE(byComma, byPoint);
        // The verdict quotes the answer the Czech way.
        QVERIFY2(byComma.contains(QLocale().toString(*value, 'f', 4).left(3)), qPrintable(byComma));
        player.answer(0, QString::number(*value * 3 + 0.5, 'f', 4).replace(u'.', u','));
        QVERIFY(player.result(0) != byPoint); // a wrong answer is judged, not misread
        player.answer(0, QStringLiteral("abc"));
        QVERIFY(player.result(0) != byPoint);
    }
};

RIGIDLAB_TEST_MAIN(TestLanguage)
#include "test_language.moc"
