// SPDX-License-Identifier: GPL-3.0-or-later
#include "window/screenshots.h"

#include "common/number_format.h"
#include "editor/edit_tools.h"
#include "instruments/instruments.h"
#include "instruments/instruments_panel.h"
#include "lesson_editor/lesson_editor.h"
#include "lesson_player/lesson_player.h"
#include "measure/measurement_session.h"
#include "plots/plot_widget.h"
#include "simulation/simulation_controller.h"
#include "window/class_results_dialog.h"
#include "window/demo_class.h"
#include "window/main_window.h"

#include "format/atomic_file.h"
#include "format/data_dirs.h"
#include "format/lesson.h"

#include <QAction>
#include <QBuffer>
#include <QCoreApplication>
#include <QDeadlineTimer>
#include <QDialog>
#include <QDir>
#include <QDockWidget>
#include <QFileInfo>
#include <QImage>
#include <QLayout>
#include <QMessageBox>
#include <QPainter>
#include <QPixmap>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>

#include <algorithm>
#include <cmath>

namespace rigidlab::ui {

namespace {

/// The translation context of the screenshot texts.
struct Screenshots {
    Q_DECLARE_TR_FUNCTIONS(Screenshots)
};

/// Runs the world for `seconds` of simulated time, one step at a time: the same steps on every
/// run, whatever the machine's speed (the window's clock is not used).
void runFor(SimulationController& controller, double seconds)
{
    controller.setRunning(false);
    const double dt = controller.world().def().dt;
    const long long steps = std::llround(seconds / dt);
    for (long long i = 0; i < steps; ++i)
        controller.stepForward();
}

/// Lets the window catch up: plots take their samples and replot, the status bar and the
/// layout follow, queued paints happen.
void settle(MainWindow& window)
{
    for (int round = 0; round < 3; ++round) {
        for (PlotWidget* plot : window.findChildren<PlotWidget*>())
            plot->drain();
        QMetaObject::invokeMethod(&window, "updateStatus");
        QCoreApplication::processEvents();
    }
}

/// Grabs the window as `size` device pixels, with `over` (a dialog) drawn where it stands, and
/// writes it as a PNG, atomically.
QString shoot(MainWindow& window, const QSize& size, const QString& path, QWidget* over)
{
    settle(window);
    QImage image = window.grab().toImage();
    if (over) {
        QCoreApplication::processEvents();
        QPainter painter(&image);
        const QPoint at = over->mapToGlobal(QPoint(0, 0)) - window.mapToGlobal(QPoint(0, 0));
        painter.drawPixmap(at * window.devicePixelRatioF(), over->grab());
    }
    // Window sizes are logical pixels; with a scale factor the grab has more device pixels.
    if (image.size() != size)
        image = image.copy(QRect(QPoint(0, 0), size));
    QByteArray bytes;
    QBuffer buffer(&bytes);
    buffer.open(QIODevice::WriteOnly);
    if (!image.save(&buffer, "PNG"))
        return Screenshots::tr("cannot encode %1 as PNG").arg(path);
    return lessons::writeFileAtomically(path, bytes);
}

/// How long a resize is waited for [ms].
constexpr int kResizeWaitMs = 1000;

/// Resizes the window so that it covers `size` device pixels. A window whose docks cannot be
/// that small is made so anyway (its content is clipped, as it would be on such a screen), and
/// the returned note says so; so does it when the window system gives another size.
QString fitWindow(MainWindow& window, const QSize& size)
{
    const qreal ratio = window.devicePixelRatioF();
    const QSize logical(static_cast<int>(std::ceil(size.width() / ratio)),
                        static_cast<int>(std::ceil(size.height() / ratio)));
    window.resize(logical);
    // A window system answers a resize when it will (X11: after the window manager framed
    // the window): the size asked for is waited for a moment before it is called refused.
    const auto settle = [&window, logical] {
        const QDeadlineTimer deadline(kResizeWaitMs);
        do
            QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
        while (window.size() != logical && !deadline.hasExpired());
    };
    settle();
    if (window.size() == logical)
        return QString();
    // "%1×%2 ... %3×%4": two sizes in a note.
    const auto sizes = [](const QString& note, const QSize& a, const QSize& b) {
        return note.arg(a.width()).arg(a.height()).arg(b.width()).arg(b.height());
    };
    const QSize minimum = window.minimumSizeHint();
    if (minimum.width() <= logical.width() && minimum.height() <= logical.height())
        return sizes(Screenshots::tr("the window system made the window %1×%2 (logical pixels), "
                                     "not the %3×%4 asked for"),
                     window.size(), logical);
    window.layout()->setSizeConstraint(QLayout::SetNoConstraint);
    window.setMinimumSize(0, 0);
    window.resize(logical);
    settle();
    return sizes(Screenshots::tr("the window needs at least %1×%2 (logical pixels) and was made "
                                 "%3×%4: its content is clipped"),
                 minimum, logical);
}

/// Points QSettings at a folder of its own while it lives, then back at the default (on Unix
/// the XDG config folder, which is where Qt keeps user settings unless told otherwise).
class SettingsElsewhere {
public:
    explicit SettingsElsewhere(const QString& folder) { point(folder); }
    ~SettingsElsewhere()
    {
        point(QStandardPaths::writableLocation(QStandardPaths::GenericConfigLocation));
    }
    SettingsElsewhere(const SettingsElsewhere&) = delete;
    SettingsElsewhere& operator=(const SettingsElsewhere&) = delete;

private:
    static void point(const QString& folder)
    {
        QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, folder);
        QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, folder);
    }
};

} // namespace

namespace {

/// Writes the PNGs into one folder and keeps the index of what each shows. The index is
/// prose for people in the window's language, so its numbers follow the language as on
/// screen ("po 0,5 s" in Czech); files for programs (CSV, JSON) keep the decimal point.
class Shooter {
public:
    Shooter(MainWindow& window, const ScreenshotOptions& options, ScreenshotResult& result)
        : m_window(window), m_options(options), m_result(result), m_folder(options.folder)
    {
    }
    /// Shoots the window (with `over`, a dialog of it, drawn where it stands) as `name`.
    bool write(const QString& name, const QString& what, QWidget* over = nullptr)
    {
        const QString error = shoot(m_window, m_options.size, m_folder.filePath(name), over);
        if (!error.isEmpty()) {
            m_result.error = error;
            return false;
        }
        m_result.files << name;
        m_index << name + QLatin1Char('\t') + what;
        return true;
    }
    /// Shoots `widget`, a window of its own (the lesson editor), at the screenshots' size.
    bool writeWindow(QWidget& widget, const QString& name, const QString& what)
    {
        const QSize asked = m_options.size / widget.devicePixelRatioF();
        const QSize least = widget.minimumSizeHint().expandedTo(widget.minimumSize());
        if (least.width() > asked.width() || least.height() > asked.height()) {
            // A window that does not fit the screen asked for would be shown cut.
            m_result.error = Screenshots::tr("%1 needs %2×%3 px, more than the %4×%5 asked for")
                                 .arg(name)
                                 .arg(least.width())
                                 .arg(least.height())
                                 .arg(asked.width())
                                 .arg(asked.height());
            return false;
        }
        widget.resize(asked);
        settle(m_window);
        QImage image = widget.grab().toImage();
        if (image.size() != m_options.size)
            image = image.copy(QRect(QPoint(0, 0), m_options.size));
        QByteArray bytes;
        QBuffer buffer(&bytes);
        buffer.open(QIODevice::WriteOnly);
        const QString error = image.save(&buffer, "PNG")
                                  ? lessons::writeFileAtomically(m_folder.filePath(name), bytes)
                                  : Screenshots::tr("cannot encode %1 as PNG").arg(name);
        if (!error.isEmpty()) {
            m_result.error = error;
            return false;
        }
        m_result.files << name;
        m_index << name + QLatin1Char('\t') + what;
        return true;
    }
    bool writeIndex()
    {
        const QString error = lessons::writeFileAtomically(
            m_folder.filePath(QStringLiteral("index.txt")),
            (m_index.join(QLatin1Char('\n')) + QLatin1Char('\n')).toUtf8());
        if (!error.isEmpty()) {
            m_result.error = error;
            return false;
        }
        m_result.files << QStringLiteral("index.txt");
        return true;
    }
    bool fail(const QString& error)
    {
        m_result.error = error;
        return false;
    }

private:
    MainWindow& m_window;
    const ScreenshotOptions& m_options;
    ScreenshotResult& m_result;
    QDir m_folder;
    QStringList m_index;
};

bool shootLessons(MainWindow& window, const ScreenshotOptions& options, Shooter& shooter)
{
    const QStringList lessonFiles =
        options.lessons ? *options.lessons : window.lessonPlayer().lessonPaths();
    for (const QString& path : lessonFiles) {
        if (const QString error = window.openLesson(path, true); !error.isEmpty())
            return shooter.fail(error);
        const lessons::Lesson& lesson = *window.lessonPlayer().lesson();
        const int count = static_cast<int>(lesson.steps.size());
        const int shots =
            options.maxStepsPerLesson > 0 ? std::min(count, options.maxStepsPerLesson) : count;
        for (int i = 0; i < shots; ++i) {
            window.lessonPlayer().goToStep(i);
            const lessons::LessonStep& step = lesson.steps[static_cast<std::size_t>(i)];
            runFor(window.controller(), step.exportTime);
            const QString name = QStringLiteral("%1-%2.png")
                                     .arg(QFileInfo(path).completeBaseName())
                                     .arg(i + 1, 2, 10, QLatin1Char('0'));
            if (!shooter.write(name, Screenshots::tr("%1, step %2 of %3: %4, after %5 s")
                                         .arg(lesson.title)
                                         .arg(i + 1)
                                         .arg(count)
                                         .arg(step.title, formatReadable(step.exportTime, 6))))
                return false;
        }
    }
    return true;
}

/// The views a teacher checks before a class: every panel of a lesson step at once, Help ›
/// Controls, the editor on a new scene, and presentation mode.
bool shootClassroom(MainWindow& window, Shooter& shooter)
{
    const QString lesson =
        QDir(MainWindow::lessonsFolder()).filePath(QStringLiteral("restitution.json"));
    if (const QString error = window.openLesson(lesson, true); !error.isEmpty())
        return shooter.fail(error);
    window.lessonPlayer().goToStep(2); // the collision table and the controls
    runFor(window.controller(), 1.0);
    for (const char* name : {"controls", "inspector", "collision"})
        if (QDockWidget* dock = window.dock(QLatin1String(name)); dock && dock->isHidden())
            dock->toggleViewAction()->trigger(); // as ticked in the View menu
    if (!shooter.write(QStringLiteral("90-panels.png"),
                       Screenshots::tr("a lesson step with the controls, the inspector and the "
                                       "collision table shown")))
        return false;
    if (QAction* help = window.findChild<QAction*>(QStringLiteral("help")))
        help->trigger();
    auto* helpDialog = window.findChild<QDialog*>(QStringLiteral("controlsHelpDialog"));
    const bool helpShot =
        shooter.write(QStringLiteral("91-help-controls.png"),
                      Screenshots::tr("Help › Controls over the window"), helpDialog);
    delete helpDialog;
    if (!helpShot)
        return false;
    window.setPresentation(true);
    const bool presented = shooter.write(QStringLiteral("92-presentation.png"),
                                         Screenshots::tr("the same step in presentation mode"));
    window.setPresentation(false);
    if (!presented)
        return false;
    window.setUnsavedAsker([] { return int(QMessageBox::Discard); });
    window.newScene();
    return shooter.write(QStringLiteral("93-editor.png"),
                         Screenshots::tr("the editor on a new scene"));
}

/// The shipped measured drop over the simulated one in the Measurement dock, its residuals
/// and e fitted to it (the lesson "Is the lab right?").
bool shootMeasurement(MainWindow& window, Shooter& shooter)
{
    const QString scene =
        QDir(MainWindow::scenesFolder()).filePath(QStringLiteral("lab_vs_measurement.json"));
    if (window.editTools().editing())
        window.editTools().setEditing(false);
    if (const QString error = window.openScene(scene, true); !error.isEmpty())
        return shooter.fail(error);
    // The classroom shot's panels make way.
    for (const char* name : {"controls", "inspector", "collision"})
        if (QDockWidget* dock = window.dock(QLatin1String(name)); dock && !dock->isHidden())
            dock->toggleViewAction()->trigger();
    MeasurementSession& measurement = window.measurement();
    if (const QString error = measurement.load(lessons::shippedDataDir() +
                                               QStringLiteral("/measure/samples/ball_tracker.csv"));
        !error.isEmpty())
        return shooter.fail(error);
    measurement.fitting().fit();
    runFor(window.controller(), 1.6);
    return shooter.write(QStringLiteral("94-measurement.png"),
                         Screenshots::tr("a measured drop over the simulated one, the residuals "
                                         "and e fitted to it"));
}

/// The instruments in use on the two balls' collision: the probe beside the ball hit and a
/// graph of both momenta with their sum; then the ruler across the track.
bool shootInstruments(MainWindow& window, Shooter& shooter)
{
    const QString scene =
        QDir(MainWindow::scenesFolder()).filePath(QStringLiteral("two_ball_collision.json"));
    if (const QString error = window.openScene(scene, true); !error.isEmpty())
        return shooter.fail(error);
    Instruments& instruments = window.instruments();
    InstrumentsPanel& panel = *instruments.panel();
    BodyGraphSpec spec;
    spec.quantity = BodyQuantity::Px;
    spec.bodies = {0, 1};
    spec.sum = true;
    PlotWidget* graph = instruments.showGraph(spec);
    instruments.dock()->show();
    runFor(window.controller(), 1.2);
    panel.tabs()->setCurrentIndex(InstrumentsPanel::ProbeTab);
    panel.setProbeBody(1);
    if (!shooter.write(QStringLiteral("95-instruments-probe.png"),
                       Screenshots::tr("the probe beside the ball hit and a graph of both "
                                       "momenta with their sum")))
        return false;
    panel.tabs()->setCurrentIndex(InstrumentsPanel::RulerTab);
    panel.setRuler({-1.5, 0}, {0.5, 0}); // the two balls' centres at the start
    const bool ruler =
        shooter.write(QStringLiteral("96-instruments-ruler.png"),
                      Screenshots::tr("the ruler between the two balls' starting centres"));
    // The classroom's shots show the window without them.
    instruments.dock()->hide();
    delete graph->parentWidget(); // its dock
    return ruler;
}

/// The lesson editor on the first shipped lesson (opened as a copy), at its first step and
/// that step's first question.
bool shootLessonEditor(MainWindow& window, Shooter& shooter)
{
    QString error;
    LessonEditor* editor = window.editLesson(window.lessonPlayer().lessonPaths().value(0), &error);
    if (editor == nullptr)
        return shooter.fail(error);
    editor->selectStep(0);
    const bool ok = shooter.writeWindow(*editor, QStringLiteral("lesson-editor.png"),
                                        Screenshots::tr("the lesson editor on a shipped lesson"));
    delete editor;
    return ok;
}

/// File › Class results… on a made-up class (demo_class.h) that handed in the restitution
/// lesson: its table, the summary row and the two files left out.
bool shootClassResults(MainWindow& window, Shooter& shooter)
{
    const QTemporaryDir folder;
    if (!folder.isValid())
        return shooter.fail(Screenshots::tr("cannot create a temporary folder for the class: %1")
                                .arg(folder.errorString()));
    if (const QString error = writeDemoClass(folder.path()); !error.isEmpty())
        return shooter.fail(error);
    ClassResultsDialog* dialog = window.showClassResults();
    dialog->setFolder(folder.path());
    const bool ok = shooter.write(QStringLiteral("97-class-results.png"),
                                  Screenshots::tr("File › Class results… on a class of five, "
                                                  "with a damaged file and another lesson's"),
                                  dialog);
    delete dialog;
    return ok;
}

} // namespace

ScreenshotResult writeScreenshots(const ScreenshotOptions& options)
{
    ScreenshotResult result;
    if (!QDir().mkpath(options.folder)) {
        result.error = Screenshots::tr("cannot create the folder %1")
                           .arg(QDir::toNativeSeparators(options.folder));
        return result;
    }
    // Settings of its own: the plain window, not the user's layout, and no recent files
    // written into the user's settings.
    const QTemporaryDir settingsFolder;
    if (!settingsFolder.isValid()) {
        result.error = Screenshots::tr("cannot create a temporary folder for the settings: %1")
                           .arg(settingsFolder.errorString());
        return result;
    }
    const SettingsElsewhere settings(settingsFolder.path());

    MainWindow window;
    // Arranged as on a screen of that size (a projector at 1024×768 tabs its plots).
    window.fitToScreen(QRect(QPoint(0, 0), options.size));
    if (options.setUp)
        options.setUp(window);
    window.show();
    if (const QString note = fitWindow(window, options.size); !note.isEmpty())
        result.notes << note;

    Shooter shooter(window, options, result);
    if (options.welcome) {
        const QString welcome =
            QDir(MainWindow::scenesFolder()).filePath(QStringLiteral("welcome.json"));
        if (const QString error = window.openScene(welcome, true); !error.isEmpty()) {
            result.error = error;
            return result;
        }
        runFor(window.controller(), options.welcomeSeconds);
        if (!shooter.write(QStringLiteral("00-welcome.png"),
                           Screenshots::tr("the welcome scene after %1 s")
                               .arg(formatReadable(options.welcomeSeconds, 6))))
            return result;
    }
    if (!shootLessons(window, options, shooter))
        return result;
    if (options.classroom && !shootInstruments(window, shooter))
        return result;
    if (options.classroom && !shootClassroom(window, shooter))
        return result;
    if (options.classroom && !shootMeasurement(window, shooter))
        return result;
    if (options.classroom && !shootLessonEditor(window, shooter))
        return result;
    if (options.classroom && !shootClassResults(window, shooter))
        return result;
    result.ok = shooter.writeIndex();
    return result;
}

} // namespace rigidlab::ui
