// SPDX-License-Identifier: GPL-3.0-or-later
// rigidlab: the lab window. `rigidlab [FILE.json|FILE.rlesson] [--step N]` opens that scene or
// lesson (at step N), or the welcome scene and the lesson list. `rigidlab --measure-frames N
// SCENE.json` runs the scene in the window for N frames and prints their times
// (ui/window/frame_measurement.h).
// `rigidlab --screenshots DIR` writes a PNG of the window on every shipped view
// (ui/window/screenshots.h). `rigidlab --help` lists the rest.

#include "common/language.h"
#include "lesson_player/lesson_player.h"
#include "simulation/simulation_controller.h"
#include "window/accessible_factories.h"
#include "window/frame_measurement.h"
#include "window/language_switch.h"
#include "window/main_window.h"
#include "window/screenshots.h"

#include "format/data_dirs.h"
#include "format/languages.h"
#include "format/lesson_pack.h"

#include "rigidlab/version.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QDir>
#include <QFileInfo>
#include <QLocale>
#include <QPointer>
#include <QSize>
#include <QTextStream>

#include <array>
#include <cmath>
#include <cstdio>
#include <optional>

#ifdef Q_OS_WIN
#include <windows.h>

#include <shellapi.h>
#endif

namespace {

/// The translation context of the command line's texts.
struct CommandLine {
    Q_DECLARE_TR_FUNCTIONS(CommandLine)
};

/// Window sizes --size accepts [px].
constexpr int kMinSide = 320, kMaxSide = 7680;
/// Scale factors --scale accepts.
constexpr double kMaxScale = 4.0;

/// What the command line asks for.
struct Options {
    QString file;
    int step = 1;          ///< 1 = the lesson's first step
    int measureFrames = 0; ///< 0: do not measure
    QString screenshots;   ///< folder, empty: no screenshots
    std::optional<QSize> size;
    std::optional<double> scale;
    bool present = false;
    QString lang;
};

/// A whole number from 1, or nothing.
std::optional<int> positiveInt(const QString& text)
{
    bool ok = false;
    const int n = text.toInt(&ok);
    return ok && n >= 1 ? std::optional<int>(n) : std::nullopt;
}

/// "WIDTHxHEIGHT" with both sides in [kMinSide, kMaxSide], or nothing.
std::optional<QSize> parseSize(const QString& text)
{
    const QStringList parts = text.toLower().split(QLatin1Char('x'));
    if (parts.size() != 2)
        return std::nullopt;
    bool okW = false, okH = false;
    const int w = parts[0].toInt(&okW), h = parts[1].toInt(&okH);
    if (!okW || !okH || w < kMinSide || w > kMaxSide || h < kMinSide || h > kMaxSide)
        return std::nullopt;
    return QSize(w, h);
}

/// A finite number in (0, kMaxScale], written with a decimal point, or nothing.
std::optional<double> parseScale(const QString& text)
{
    bool ok = false;
    const double f = QLocale::c().toDouble(text, &ok);
    if (!ok || !std::isfinite(f) || f <= 0.0 || f > kMaxScale)
        return std::nullopt;
    return f;
}

/// The codes of the shipped languages as --lang's value name: "en|cs".
QString languageChoices()
{
    QStringList codes;
    for (const rigidlab::lessons::Language& l : rigidlab::lessons::kLanguages)
        codes << l.code.toString();
    return codes.join(QLatin1Char('|'));
}

/// rigidlab's options, and what each option's value must be (said the same way whether it is
/// missing or wrong).
struct OptionSet {
    QCommandLineOption help{{QStringLiteral("h"), QStringLiteral("help")},
                            CommandLine::tr("Show this text and quit.")};
    QCommandLineOption version{QStringLiteral("version"),
                               CommandLine::tr("Show the version and quit.")};
    QCommandLineOption step{QStringLiteral("step"),
                            CommandLine::tr("With a lesson: start at step N (1 = first)."),
                            QStringLiteral("N")};
    QCommandLineOption measure{
        QStringLiteral("measure-frames"),
        CommandLine::tr("Run the scene for N frames, print the median and 95th-percentile "
                        "frame time and the physics share, and quit."),
        QStringLiteral("N")};
    QCommandLineOption screenshots{
        QStringLiteral("screenshots"),
        CommandLine::tr("Write a PNG of the window on the welcome scene and on every step of "
                        "every shipped lesson into DIR, with DIR/index.txt, and quit."),
        QStringLiteral("DIR")};
    QCommandLineOption size{QStringLiteral("size"),
                            CommandLine::tr("Window (and screenshot) size in pixels, e.g. 1024x768 "
                                            "(screenshots: 1280x720 unless given)."),
                            QStringLiteral("WxH")};
    QCommandLineOption scale{
        QStringLiteral("scale"),
        CommandLine::tr("Scale factor of the whole interface (QT_SCALE_FACTOR), e.g. 1.5."),
        QStringLiteral("F")};
    QCommandLineOption present{QStringLiteral("present"),
                               CommandLine::tr("Presentation mode: full screen, large type "
                                               "and thick lines for a projector (F11).")};
    QCommandLineOption lang{
        QStringLiteral("lang"),
        CommandLine::tr("Language of the interface, one of %1 (View › Language saves a "
                        "choice; without either, the system's language).")
            .arg(rigidlab::lessons::shippedLanguageCodes()),
        languageChoices()};

    QString stepNeeds = CommandLine::tr("a whole number from 1");
    QString sizeNeeds =
        CommandLine::tr("WIDTHxHEIGHT in pixels, each from %1 to %2").arg(kMinSide).arg(kMaxSide);
    QString scaleNeeds = CommandLine::tr("a number greater than 0 and at most %1").arg(kMaxScale);
    QString langNeeds = CommandLine::tr("one of %1").arg(rigidlab::lessons::shippedLanguageCodes());
    QString dirNeeds = CommandLine::tr("a folder");

    /// The options that take a value, with what the value must be.
    std::array<std::pair<const QCommandLineOption*, QString>, 6> valueRules() const
    {
        return {{{&step, stepNeeds},
                 {&measure, stepNeeds},
                 {&size, sizeNeeds},
                 {&scale, scaleNeeds},
                 {&lang, langNeeds},
                 {&screenshots, dirNeeds}}};
    }
};

/// "--NAME needs WHAT, got "GOT"": a value missing or wrong.
QString needs(const QString& name, const QString& what, const QString& got)
{
    return CommandLine::tr("--%1 needs %2, got \"%3\"").arg(name, what, got);
}

void describe(QCommandLineParser& parser, const OptionSet& o)
{
    parser.setApplicationDescription(
        CommandLine::tr("RigidLab %1: a lab for 2D rigid-body mechanics.")
            .arg(QStringLiteral(RIGIDLAB_VERSION)));
    parser.addPositionalArgument(
        QStringLiteral("FILE.json"),
        CommandLine::tr("A scene or a lesson (FILE.json, or FILE.rlesson) to open."),
        QStringLiteral("[FILE.json]"));
    for (const QCommandLineOption* option :
         {&o.help, &o.version, &o.step, &o.measure, &o.screenshots, &o.size, &o.scale, &o.present,
          &o.lang})
        parser.addOption(*option);
}

/// Reads the options' values into `options`. Returns -1 to go on, else 2 with the mistake in
/// `message`.
int readValues(const QCommandLineParser& parser, const OptionSet& o, Options& options,
               QString& message)
{
    const auto value = [&](const QCommandLineOption& option) { return parser.value(option); };
    const auto refuse = [&](const char* name, const QString& what, const QString& got) {
        message = needs(QLatin1String(name), what, got);
        return 2;
    };
    if (parser.isSet(o.step)) {
        const auto n = positiveInt(value(o.step));
        if (!n)
            return refuse("step", o.stepNeeds, value(o.step));
        options.step = *n;
    }
    if (parser.isSet(o.measure)) {
        const auto n = positiveInt(value(o.measure));
        if (!n)
            return refuse("measure-frames", o.stepNeeds, value(o.measure));
        options.measureFrames = *n;
    }
    if (parser.isSet(o.size) && !(options.size = parseSize(value(o.size))))
        return refuse("size", o.sizeNeeds, value(o.size));
    if (parser.isSet(o.scale) && !(options.scale = parseScale(value(o.scale))))
        return refuse("scale", o.scaleNeeds, value(o.scale));
    if (parser.isSet(o.lang)) {
        options.lang = value(o.lang);
        if (!rigidlab::lessons::isShippedLanguage(options.lang))
            return refuse("lang", o.langNeeds, options.lang);
    }
    if (parser.isSet(o.screenshots)) {
        options.screenshots = value(o.screenshots);
        if (options.screenshots.isEmpty())
            return refuse("screenshots", o.dirNeeds, QString());
    }
    options.present = parser.isSet(o.present);
    return -1;
}

/// Reads the file named and checks that the options go together. Returns -1 to go on, else 2
/// with the mistake in `message`.
int readFile(const QCommandLineParser& parser, Options& options, QString& message)
{
    const QStringList files = parser.positionalArguments();
    if (files.size() > 1) {
        message = CommandLine::tr("one file at a time (got %1 and %2)").arg(files[0], files[1]);
        return 2;
    }
    options.file = files.value(0);
    if (options.measureFrames > 0 && options.file.isEmpty()) {
        message = CommandLine::tr("--measure-frames needs a scene to run");
        return 2;
    }
    if (!options.screenshots.isEmpty() && (!options.file.isEmpty() || options.measureFrames)) {
        message = CommandLine::tr("--screenshots shoots the shipped scenes and lessons: "
                                  "give it no FILE and no --measure-frames");
        return 2;
    }
    return -1;
}

/// Fills `options` from the arguments. Returns -1 to go on, else the exit status (0 after
/// --help or --version, 2 after a mistake, said on one line in `message`).
int parseArguments(const QStringList& args, Options& options, QString& message)
{
    const OptionSet o;
    QCommandLineParser parser;
    describe(parser, o);
    if (!parser.parse(QStringList{QStringLiteral("rigidlab")} + args)) {
        // A value option last, without its value: say what the value should be.
        for (const auto& [option, what] : o.valueRules())
            if (!args.isEmpty() && args.last() == QStringLiteral("--") + option->names().first()) {
                message = needs(option->names().first(), what, QString());
                return 2;
            }
        message = CommandLine::tr("%1 (try rigidlab --help)").arg(parser.errorText());
        return 2;
    }
    if (parser.isSet(o.help)) {
        message = parser.helpText();
        return 0;
    }
    if (parser.isSet(o.version)) {
        message = QStringLiteral("rigidlab " RIGIDLAB_VERSION);
        return 0;
    }
    if (const int status = readValues(parser, o, options, message); status >= 0)
        return status;
    return readFile(parser, options, message);
}

/// Whether Qt has somewhere to show a window: a display, or a platform chosen explicitly
/// (QT_QPA_PLATFORM=offscreen for tests and headless machines). Windows always has its desktop.
bool haveDisplay()
{
#ifdef Q_OS_WIN
    return true;
#else
    return !qEnvironmentVariableIsEmpty("DISPLAY") ||
           !qEnvironmentVariableIsEmpty("WAYLAND_DISPLAY") ||
           !qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM");
#endif
}

/// The arguments after the program's name. On Windows argv is in the ANSI code page, which
/// lacks letters of most languages (a lesson named "Srážka.rlesson" on a Western code page):
/// the command line's UTF-16 has them all.
QStringList programArguments(int argc, char** argv)
{
    QStringList args;
#ifdef Q_OS_WIN
    Q_UNUSED(argc)
    Q_UNUSED(argv)
    int count = 0;
    if (wchar_t** wide = CommandLineToArgvW(GetCommandLineW(), &count)) {
        for (int i = 1; i < count; ++i)
            args << QString::fromWCharArray(wide[i]);
        LocalFree(wide);
    }
#else
    for (int i = 1; i < argc; ++i)
        args << QString::fromLocal8Bit(argv[i]);
#endif
    return args;
}

/// Windows starts a GUI program without a console: --help, --version and mistakes then go to
/// the console it was started from (cmd, PowerShell), unless its output is redirected.
void useParentConsole()
{
#ifdef Q_OS_WIN
    if (GetFileType(GetStdHandle(STD_OUTPUT_HANDLE)) != FILE_TYPE_UNKNOWN)
        return; // redirected to a file or a pipe: write there
    if (AttachConsole(ATTACH_PARENT_PROCESS)) {
        std::freopen("CONOUT$", "w", stdout);
        std::freopen("CONOUT$", "w", stderr);
        SetConsoleOutputCP(CP_UTF8); // QTextStream writes UTF-8
    }
#endif
}

/// rigidlab --screenshots: the shipped views as PNGs, then the exit status.
int writeScreenshots(const Options& options)
{
    rigidlab::ui::ScreenshotOptions shots;
    shots.folder = options.screenshots;
    if (options.size)
        shots.size = *options.size;
    if (options.present)
        shots.setUp = [](rigidlab::ui::MainWindow& w) {
            // Fonts, lines and palette of presentation mode, at the projector's size given by
            // --size rather than this display's.
            w.setPresentation(true);
            w.setWindowState(Qt::WindowNoState);
        };
    const rigidlab::ui::ScreenshotResult r = rigidlab::ui::writeScreenshots(shots);
    for (const QString& note : r.notes)
        QTextStream(stderr) << "rigidlab: " << note << '\n';
    if (!r.ok) {
        QTextStream(stderr) << "rigidlab: " << r.error << '\n';
        return 1;
    }
    QTextStream(stdout) << CommandLine::tr("%n file(s) written into %1", nullptr,
                                           static_cast<int>(r.files.size()))
                               .arg(QDir::toNativeSeparators(options.screenshots))
                        << '\n';
    return 0;
}

/// Opens the welcome scene, then the file asked for (a scene or a lesson, at its step).
void openFirstDocument(rigidlab::ui::MainWindow& window, const Options& options)
{
    const QString welcome =
        QDir(rigidlab::ui::MainWindow::scenesFolder()).filePath(QStringLiteral("welcome.json"));
    // Open the welcome scene first, so that a broken file leaves something alive behind the
    // error dialog.
    window.openScene(welcome, !options.file.isEmpty());
    if (options.file.isEmpty())
        return;
    // A lesson says so with its top-level key or its suffix (.rlesson); anything else is read
    // as a scene.
    const bool lesson = rigidlab::lessons::isLessonDocument(options.file);
    const QString error = lesson ? window.openLesson(options.file) : window.openScene(options.file);
    if (!error.isEmpty())
        QTextStream(stderr) << error << '\n';
    else if (lesson && options.step > 1)
        window.lessonPlayer().goToStep(options.step - 1);
}

/// The window as the command line asks for it, running unless a lesson waits for Run. Returns
/// -1 to go on, else the exit status.
int openWindow(const Options& options)
{
    // On the heap: View › Language replaces it with a new window (language_switch.h).
    auto* window = new rigidlab::ui::MainWindow;
    window->setAttribute(Qt::WA_DeleteOnClose);
    // The window sizes itself for the screen it is on (MainWindow::fitToScreen); --size
    // overrides that.
    if (options.size)
        window->resize(*options.size);
    openFirstDocument(*window, options);
    window->show();
    if (options.present)
        window->setPresentation(true);
    rigidlab::ui::followLanguageChoice(window);
    const bool opened = window->lastError().isEmpty();
    // A lesson waits for the student to press Run; a measurement runs it at once.
    if (opened && (!window->lessonPlayer().lesson() || options.measureFrames > 0))
        window->controller().setRunning(true);
    if (options.measureFrames > 0) {
        if (!opened) {
            QTextStream(stderr) << "rigidlab: --measure-frames needs a scene that opens\n";
            return 2;
        }
        rigidlab::ui::measureFrames(window->controller(), options.measureFrames);
    }
    return -1;
}

/// Deletes the windows left: they are on the heap, and the last one may still be open after
/// QApplication::exit.
void deleteWindows()
{
    QList<QPointer<rigidlab::ui::MainWindow>> windows;
    for (QWidget* w : QApplication::topLevelWidgets())
        if (auto* main = qobject_cast<rigidlab::ui::MainWindow*>(w))
            windows << main;
    for (const QPointer<rigidlab::ui::MainWindow>& w : windows)
        delete w.data();
}

/// The language the command line asks for (--lang CODE or --lang=CODE), read before the
/// options are, so that what they say about a mistake is said in it; empty when none is asked.
QString languageAsked(const QStringList& args)
{
    const QString flag = QStringLiteral("--lang");
    QString asked;
    for (qsizetype i = 0; i < args.size(); ++i) {
        if (args[i] == flag && i + 1 < args.size())
            asked = args[i + 1];
        else if (args[i].startsWith(flag + QLatin1Char('=')))
            asked = args[i].mid(flag.size() + 1);
    }
    return asked;
}

/// Reads the arguments, in the language they ask for (else the saved one, else the system's),
/// and says --help, --version, a mistake or the lack of a display. Returns -1 to go on, else
/// the exit status.
int readArguments(const QStringList& args, Options& options)
{
    // Translations need an application, and the window's needs a display that --help and a
    // mistake must not: a core application for the time it takes to read the arguments.
    // Named as the help's usage line names the program, whatever path started it.
    int readerArgc = 1;
    char readerName[] = "rigidlab";
    char* readerArgv[] = {readerName, nullptr};
    QCoreApplication reader(readerArgc, readerArgv);
    rigidlab::ui::applyLanguage(rigidlab::ui::chooseLanguage(
        languageAsked(args), rigidlab::ui::savedLanguage(), QLocale::system()));
    QString message;
    if (const int status = parseArguments(args, options, message); status >= 0) {
        if (status == 0)
            QTextStream(stdout) << message << '\n';
        else
            QTextStream(stderr) << "rigidlab: " << message << '\n';
        return status;
    }
    if (!haveDisplay()) {
        QTextStream(stderr) << "rigidlab: "
                            << CommandLine::tr("no display to open the window on: set DISPLAY "
                                               "(an X server, or Xvfb) or WAYLAND_DISPLAY, or "
                                               "QT_QPA_PLATFORM=offscreen")
                            << '\n';
        return 2;
    }
    return -1;
}

} // namespace

int main(int argc, char** argv)
{
    useParentConsole();
    rigidlab::lessons::useSettingsFiles();
    // Before any application: the saved language is read with them, and the process's locale
    // is set once, when the first application starts. Qt's file dialog writes its dates in
    // that locale, not the one the window sets: --lang sets the date conventions too
    // ("3. 12." in Czech, not "3 Dec").
    QCoreApplication::setOrganizationName(QStringLiteral("RigidLab"));
    QCoreApplication::setApplicationName(QStringLiteral("RigidLab"));
    QCoreApplication::setApplicationVersion(QStringLiteral(RIGIDLAB_VERSION));
    const QStringList args = programArguments(argc, argv);
    if (const auto* language = rigidlab::ui::findLanguage(languageAsked(args)))
        qputenv("LC_TIME", language->locale.toString().toLatin1() + ".UTF-8");

    // Arguments first: --help, --version and mistakes must not need a display.
    Options options;
    if (const int status = readArguments(args, options); status >= 0)
        return status;
    // Read when the application starts; every widget is scaled by it.
    if (options.scale)
        qputenv("QT_SCALE_FACTOR", QByteArray::number(*options.scale));

    QApplication app(argc, argv);
    // Before any window: a widget keeps the interface it was first given (the main window
    // installs them too, for the windows a test makes).
    rigidlab::ui::installAccessibleFactories();
    // --lang, else View › Language's saved choice, else the system's language.
    rigidlab::ui::applyLanguage(rigidlab::ui::chooseLanguage(
        options.lang, rigidlab::ui::savedLanguage(), QLocale::system()));

    if (!options.screenshots.isEmpty())
        return writeScreenshots(options);
    if (const int status = openWindow(options); status >= 0)
        return status;
    const int status = QApplication::exec();
    deleteWindows();
    return status;
}
