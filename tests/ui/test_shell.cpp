// SPDX-License-Identifier: GPL-3.0-or-later
// The window's shell (the classroom-window issue): the command line of rigidlab, the
// screenshot command, Help › Controls and About, and the status bar.

#include "build_paths.h"
#include "common/language.h"
#include "simulation/simulation_controller.h"
#include "window/about_dialog.h"
#include "window/main_window.h"
#include "window/screenshots.h"

#include "rigidlab/physics/profile.h"
#include "rigidlab/version.h"

#include <Eigen/Core>
#include <QAction>
#include <QFile>
#include <QImage>
#include <QProcess>
#include <QRegularExpression>
#include <QSet>
#include <QSettings>
#include <QTemporaryDir>
#include <QtTest>
#include <qcustomplot.h>

#include "run_gui.h"
#include "test_main.h"

using namespace rigidlab;
using rigidlab::test::runGui;
using rigidlab::ui::MainWindow;

namespace {

QString lesson(const char* name)
{
    return rigidlab::test::sourcePath(u"/lessons/lessons/") + QLatin1String(name);
}

/// The keys named in Help › Controls: the bold first cell of each row, split at " or ".
QSet<QString> helpKeys(const QString& html)
{
    QSet<QString> keys;
    const QRegularExpression cell(QStringLiteral("<tr><td[^>]*><b>(.*?)</b></td>"));
    for (auto it = cell.globalMatch(html); it.hasNext();)
        for (const QString& k : it.next().captured(1).split(QStringLiteral(" or ")))
            keys.insert(k);
    return keys;
}

int distinctColours(const QImage& image)
{
    QSet<QRgb> colours;
    for (int y = 0; y < image.height(); y += 2)
        for (int x = 0; x < image.width(); x += 2)
            colours.insert(image.pixel(x, y));
    return static_cast<int>(colours.size());
}

} // namespace

class TestShell : public QObject {
    Q_OBJECT
private slots:
    void screenshotsHaveTheSizeAskedFor()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        ui::ScreenshotOptions options;
        options.folder = dir.filePath(QStringLiteral("shots"));
        options.size = QSize(1024, 768);
        options.welcomeSeconds = 0.5;
        options.lessons = QStringList{lesson("restitution.json")};
        options.maxStepsPerLesson = 2;
        options.classroom = false; // its views are shot by the command (see test_window_reach)
        const QString settingsFile = QSettings().fileName();
        const ui::ScreenshotResult r = ui::writeScreenshots(options);
        QVERIFY2(r.ok, qPrintable(r.error));
        // The plain window, with settings of its own: the user's are neither read nor written.
        QCOMPARE(QSettings().fileName(), settingsFile);
        QVERIFY(!QSettings().contains(QStringLiteral("recentFiles")));
        const QStringList pngs{QStringLiteral("00-welcome.png"),
                               QStringLiteral("restitution-01.png"),
                               QStringLiteral("restitution-02.png")};
        QCOMPARE(r.files, pngs + QStringList{QStringLiteral("index.txt")});

        QFile index(dir.filePath(QStringLiteral("shots/index.txt")));
        QVERIFY(index.open(QIODevice::ReadOnly));
        const QStringList lines =
            QString::fromUtf8(index.readAll()).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
        QCOMPARE(lines.size(), pngs.size());
        QImage previous;
        for (int i = 0; i < pngs.size(); ++i) {
            QVERIFY2(lines[i].startsWith(pngs[i] + QLatin1Char('\t')), qPrintable(lines[i]));
            QVERIFY(lines[i].size() > pngs[i].size() + 10); // says what it shows
            const QImage image(dir.filePath(QStringLiteral("shots/") + pngs[i]));
            QVERIFY2(!image.isNull(), qPrintable(pngs[i]));
            QCOMPARE(image.size(), QSize(1024, 768));
            // A drawn window, not a blank or single-coloured one.
            QVERIFY2(distinctColours(image) > 64, qPrintable(pngs[i]));
            QVERIFY(image != previous); // each view is its own
            previous = image;
        }
        QVERIFY(lines[1].contains(QStringLiteral("step 1 of")));
    }

    void screenshotIndexNumbersFollowTheLanguage()
    {
        // The index is prose in the window's language: in Czech "po 0,5 s", as on screen.
        QVERIFY(ui::applyLanguage(QStringLiteral("cs")));
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        ui::ScreenshotOptions options;
        options.folder = dir.filePath(QStringLiteral("shots"));
        options.size = QSize(1024, 768);
        options.welcomeSeconds = 0.5;
        options.lessons = QStringList{};
        options.classroom = false;
        const ui::ScreenshotResult r = ui::writeScreenshots(options);
        QVERIFY(ui::applyLanguage(QStringLiteral("en")));
        QVERIFY2(r.ok, qPrintable(r.error));
        QFile index(dir.filePath(QStringLiteral("shots/index.txt")));
        QVERIFY(index.open(QIODevice::ReadOnly));
        const QString text = QString::fromUtf8(index.readAll());
        QVERIFY2(text.contains(QStringLiteral("0,5")) && !text.contains(QStringLiteral("0.5")),
                 qPrintable(text));
    }

    void commandLineRefusesBadValues_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("flag");
        QTest::newRow("size without height")
            << QStringList{QStringLiteral("--size"), QStringLiteral("12")}
            << QStringLiteral("--size");
        QTest::newRow("size too small")
            << QStringList{QStringLiteral("--size"), QStringLiteral("12x12")}
            << QStringLiteral("--size");
        QTest::newRow("size missing")
            << QStringList{QStringLiteral("--size")} << QStringLiteral("--size");
        QTest::newRow("scale zero") << QStringList{QStringLiteral("--scale"), QStringLiteral("0")}
                                    << QStringLiteral("--scale");
        QTest::newRow("scale text") << QStringList{QStringLiteral("--scale"), QStringLiteral("abc")}
                                    << QStringLiteral("--scale");
        QTest::newRow("scale nan") << QStringList{QStringLiteral("--scale"), QStringLiteral("nan")}
                                   << QStringLiteral("--scale");
        QTest::newRow("lang") << QStringList{QStringLiteral("--lang"), QStringLiteral("de")}
                              << QStringLiteral("--lang");
        QTest::newRow("step") << QStringList{QStringLiteral("--step"), QStringLiteral("x")}
                              << QStringLiteral("--step");
        QTest::newRow("unknown") << QStringList{QStringLiteral("--colour")}
                                 << QStringLiteral("colour");
    }

    void commandLineRefusesBadValues()
    {
        QFETCH(QStringList, args);
        QFETCH(QString, flag);
        QString out, err;
        QCOMPARE(runGui(args, test::offscreenEnvironment(), out, err), 2);
        QVERIFY2(err.startsWith(QStringLiteral("rigidlab: ")) && err.contains(flag),
                 qPrintable(err));
        QCOMPARE(err.count(QLatin1Char('\n')), 1); // one line
        QVERIFY(out.isEmpty());
    }

    void commandLineHelpAndVersion()
    {
        // Neither needs a display.
        QProcessEnvironment none = QProcessEnvironment::systemEnvironment();
        for (const char* name : {"DISPLAY", "WAYLAND_DISPLAY", "QT_QPA_PLATFORM"})
            none.remove(QLatin1String(name));
        QString out, err;
        QCOMPARE(runGui({QStringLiteral("--version")}, none, out, err), 0);
        QCOMPARE(out.trimmed(), QStringLiteral("rigidlab " RIGIDLAB_VERSION));
        QCOMPARE(runGui({QStringLiteral("--help")}, none, out, err), 0);
        for (const char* flag : {"--step", "--measure-frames", "--screenshots", "--size", "--scale",
                                 "--present", "--lang", "--version"})
            QVERIFY2(out.contains(QLatin1String(flag)), flag);
        // Accepted flags, but no display: said in one line, before Qt would abort.
        QCOMPARE(
            runGui({QStringLiteral("--present"), QStringLiteral("--lang"), QStringLiteral("cs"),
                    QStringLiteral("--screenshots"), QStringLiteral("/nonexistent/shots")},
                   none, out, err),
            2);
        QVERIFY2(err.contains(QStringLiteral("DISPLAY")), qPrintable(err));
        QCOMPARE(err.count(QLatin1Char('\n')), 1);
    }

    // The arguments are read in the language they ask for: a mistake, Qt's own word for an
    // unknown option, the help and the lack of a display, all in Czech with --lang cs (and
    // still in English with --lang en).
    void commandLineSpeaksTheLanguageAskedFor_data()
    {
        QTest::addColumn<QString>("lang");
        QTest::newRow("cs") << QStringLiteral("cs");
        QTest::newRow("en") << QStringLiteral("en");
    }
    void commandLineSpeaksTheLanguageAskedFor()
    {
        QFETCH(QString, lang);
        QVERIFY(ui::applyLanguage(lang));
        const auto said = [](const char* context, const char* text) {
            return QCoreApplication::translate(context, text);
        };
        const QString stepWrong =
            said("CommandLine", "--%1 needs %2, got \"%3\"")
                .arg(QStringLiteral("step"), said("CommandLine", "a whole number from 1"),
                     QStringLiteral("x"));
        const QString unknown =
            said("QCommandLineParser", "Unknown option '%1'.").arg(QStringLiteral("colour"));
        const QString helpLine = said("CommandLine", "Show this text and quit.");
        const QString noDisplay =
            said("CommandLine", "no display to open the window on: set DISPLAY (an X "
                                "server, or Xvfb) or WAYLAND_DISPLAY, or "
                                "QT_QPA_PLATFORM=offscreen");
        QVERIFY(ui::applyLanguage(QStringLiteral("en")));
        if (lang == QLatin1String("cs")) // the test would notice English
            for (const QString& text : {stepWrong, unknown, helpLine, noDisplay})
                QVERIFY2(!text.contains(QStringLiteral("needs")) &&
                             !text.contains(QStringLiteral("Unknown")) &&
                             !text.contains(QStringLiteral("Show")) &&
                             !text.contains(QStringLiteral("no display")),
                         qPrintable(text));

        const QProcessEnvironment env = test::offscreenEnvironment();
        QString out, err;
        // The flag before --lang and after it: both are read in its language.
        QCOMPARE(
            runGui({QStringLiteral("--step"), QStringLiteral("x"), QStringLiteral("--lang"), lang},
                   env, out, err),
            2);
        QCOMPARE(err.trimmed(), QStringLiteral("rigidlab: ") + stepWrong);
        QCOMPARE(
            runGui({QStringLiteral("--lang=") + lang, QStringLiteral("--colour")}, env, out, err),
            2);
        QVERIFY2(err.contains(unknown), qPrintable(err));
        QCOMPARE(runGui({QStringLiteral("--lang"), lang, QStringLiteral("--help")}, env, out, err),
                 0);
        QVERIFY2(out.contains(helpLine), qPrintable(out));
        // The usage line names the program, not the path it was started by.
        QVERIFY2(out.section(QLatin1Char('\n'), 0, 0).contains(QStringLiteral(" rigidlab ")),
                 qPrintable(out));
        QProcessEnvironment none = QProcessEnvironment::systemEnvironment();
        for (const char* name : {"DISPLAY", "WAYLAND_DISPLAY", "QT_QPA_PLATFORM"})
            none.remove(QLatin1String(name));
        QCOMPARE(runGui({QStringLiteral("--lang"), lang}, none, out, err), 2);
        QCOMPARE(err.trimmed(), QStringLiteral("rigidlab: ") + noDisplay);
    }

    void controlsHelpListsEveryShortcut()
    {
        MainWindow w;
        const QString help = w.controlsHelpText();
        const QSet<QString> keys = helpKeys(help);
        int shortcuts = 0;
        for (const QAction* a : w.findChildren<QAction*>())
            for (const QKeySequence& k : a->shortcuts()) {
                ++shortcuts;
                QVERIFY2(keys.contains(k.toString(QKeySequence::NativeText).toHtmlEscaped()),
                         qPrintable(a->text() + QStringLiteral(": ") + k.toString()));
            }
        // Space, S, →, ←, Backspace, R, F, Q, E, V C B M T J, Ctrl+O, Ctrl+L, Ctrl+Q.
        QVERIFY2(shortcuts >= 18, qPrintable(QString::number(shortcuts)));
        // And the mouse.
        for (const char* gesture : {"Drag a body", "Mouse wheel", "Drag the timeline"})
            QVERIFY2(help.contains(QLatin1String(gesture)), gesture);
    }

    void aboutNamesVersionsLicenceAndPaper()
    {
        const QString about = ui::aboutText();
        for (const QString& part :
             {QStringLiteral(RIGIDLAB_VERSION), QStringLiteral("GPL-3.0-or-later"),
              QString::fromLatin1(qVersion()), QStringLiteral(QCUSTOMPLOT_VERSION_STR),
              QStringLiteral("%1.%2.%3")
                  .arg(EIGEN_WORLD_VERSION)
                  .arg(EIGEN_MAJOR_VERSION)
                  .arg(EIGEN_MINOR_VERSION),
              QStringLiteral("Simulace mechaniky tuhých těles v reálném čase"),
              QStringLiteral("Real-time simulation of rigid-body mechanics")})
            QVERIFY2(about.contains(part), qPrintable(part));
        QVERIFY(QFile::exists(rigidlab::test::sourcePath(u"/LICENSE")));
    }

    void statusBarSaysOnlyWhatIsCurrent()
    {
        QLocale::setDefault(QLocale(QLocale::German, QLocale::Germany));
        MainWindow w;
        QVERIFY(!w.statusDetailsAction()->isChecked()); // off by default
        QCOMPARE(w.openScene(rigidlab::test::sourcePath(u"/lessons/scenes/box_stack.json"), true),
                 QString());
        ui::SimulationController& c = w.controller();
        c.setRunning(false);
        for (int i = 0; i < 30; ++i)
            c.stepForward();
        const auto status = [&w] {
            QMetaObject::invokeMethod(&w, "updateStatus");
            return w.statusText();
        };
        const auto hasStageName = [](const QString& text) {
            for (int k = 0; k < physics::kStageCount; ++k)
                if (text.contains(
                        QLatin1String(physics::stageName(static_cast<physics::Stage>(k)))))
                    return true;
            return false;
        };
        // Paused: no rate, and the numbers in the locale's own way.
        QString text = status();
        QVERIFY2(text.contains(QStringLiteral("paused")), qPrintable(text));
        QVERIFY2(!text.contains(QStringLiteral("steps/s")), qPrintable(text));
        QVERIFY2(!hasStageName(text), qPrintable(text));
        const QString t = QLocale().toString(c.world().time(), 'f', 3);
        QVERIFY2(t.contains(QLatin1Char(',')) && text.contains(t), qPrintable(text));

        // Details on: the last step's stages, but still no rate while paused.
        w.statusDetailsAction()->setChecked(true);
        text = status();
        QVERIFY2(hasStageName(text), qPrintable(text));
        QVERIFY2(!text.contains(QStringLiteral("steps/s")), qPrintable(text));
        // Remembered for the next window.
        QVERIFY(QSettings().value(QStringLiteral("status/details")).toBool());

        // Running: the rate, in simulated seconds per wall second once a second has passed.
        c.setRunning(true);
        QVERIFY2(status().contains(QStringLiteral("steps/s")), qPrintable(status()));
        QTRY_VERIFY_WITH_TIMEOUT(c.timing().realTimeFactor().has_value(), 10000);
        text = status();
        QVERIFY2(text.contains(QStringLiteral("× real time")), qPrintable(text));
        QVERIFY(*c.timing().realTimeFactor() > 0.0);

        // Details off: no stage names even while running.
        w.statusDetailsAction()->setChecked(false);
        text = status();
        QVERIFY2(!hasStageName(text), qPrintable(text));
        QVERIFY2(!text.contains(QStringLiteral("steps/s")), qPrintable(text));
        // Paused again: the rate goes, it does not stay stale.
        c.setRunning(false);
        text = status();
        QVERIFY2(text.contains(QStringLiteral("paused")), qPrintable(text));
        QVERIFY2(!text.contains(QStringLiteral("× real time")), qPrintable(text));
        QLocale::setDefault(QLocale::c());
    }
};

RIGIDLAB_TEST_MAIN(TestShell)
#include "test_shell.moc"
