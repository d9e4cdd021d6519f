// rigidlab: the lab window. `rigidlab [FILE.json] [--step N]` opens that scene or lesson
// (at step N), or the welcome scene and the lesson list.

#include "lesson_player.h"
#include "main_window.h"
#include "simulation_controller.h"

#include <QApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTextStream>

int main(int argc, char** argv)
{
    // Arguments first: --help and mistakes must not need a display.
    QStringList args;
    for (int i = 1; i < argc; ++i)
        args << QString::fromLocal8Bit(argv[i]);
    const QString usage =
        QStringLiteral("usage: rigidlab [FILE.json] [--step N]\n"
                       "  FILE.json  a scene or a lesson to open\n"
                       "  --step N   with a lesson: start at step N (1 = first)\n");
    QString file;
    int step = 1;
    for (qsizetype i = 0; i < args.size(); ++i) {
        const QString& a = args[i];
        if (a == QLatin1String("--help") || a == QLatin1String("-h")) {
            QTextStream(stdout) << usage;
            return 0;
        }
        if (a == QLatin1String("--step")) {
            bool ok = false;
            step = i + 1 < args.size() ? args[i + 1].toInt(&ok) : 0;
            if (!ok || step < 1) {
                QTextStream(stderr) << "rigidlab: --step needs a whole number from 1, got \""
                                    << (i + 1 < args.size() ? args[i + 1] : QString()) << "\"\n";
                return 2;
            }
            ++i;
            continue;
        }
        if (a.startsWith(QLatin1Char('-'))) {
            QTextStream(stderr) << "rigidlab: unknown option " << a << "\n" << usage;
            return 2;
        }
        if (!file.isEmpty()) {
            QTextStream(stderr) << "rigidlab: one file at a time (got " << file << " and " << a
                                << ")\n";
            return 2;
        }
        file = a;
    }

    QApplication app(argc, argv);
    QApplication::setOrganizationName(QStringLiteral("RigidLab"));
    QApplication::setApplicationName(QStringLiteral("RigidLab"));
    rigidlab::ui::MainWindow window;
    window.resize(1500, 920);
    const QString welcome =
        QDir(rigidlab::ui::MainWindow::scenesFolder()).filePath(QStringLiteral("welcome.json"));
    // Open the welcome scene first, so that a broken file leaves something alive behind the
    // error dialog.
    window.openScene(welcome, file.isEmpty() ? false : true);
    if (!file.isEmpty()) {
        // A lesson says so with its top-level key; anything else is read as a scene.
        QFile f(file);
        const bool lesson =
            f.open(QIODevice::ReadOnly) && QJsonDocument::fromJson(f.read(8 << 20))
                                               .object()
                                               .contains(QLatin1String("rigidlab-lesson"));
        const QString error = lesson ? window.openLesson(file) : window.openScene(file);
        if (!error.isEmpty())
            QTextStream(stderr) << error << '\n';
        else if (lesson && step > 1)
            window.lessonPlayer().goToStep(step - 1);
    }
    window.show();
    if (window.lastError().isEmpty() && !window.lessonPlayer().lesson())
        window.controller().setRunning(true);
    return QApplication::exec();
}
