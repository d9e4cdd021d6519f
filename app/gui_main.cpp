// rigidlab: the lab window. `rigidlab [SCENE.json]` opens that scene, or the welcome scene.

#include "main_window.h"
#include "simulation_controller.h"

#include <QApplication>
#include <QDir>
#include <QFileInfo>
#include <QTextStream>

int main(int argc, char** argv)
{
    QApplication app(argc, argv);
    QApplication::setOrganizationName(QStringLiteral("RigidLab"));
    QApplication::setApplicationName(QStringLiteral("RigidLab"));

    const QStringList args = QApplication::arguments().mid(1);
    QString file;
    for (const QString& a : args) {
        if (a == QLatin1String("--help") || a == QLatin1String("-h")) {
            QTextStream(stdout) << "usage: rigidlab [SCENE.json]\n";
            return 0;
        }
        if (a.startsWith(QLatin1Char('-'))) {
            QTextStream(stderr) << "rigidlab: unknown option " << a
                                << " (usage: rigidlab [SCENE.json])\n";
            return 2;
        }
        if (!file.isEmpty()) {
            QTextStream(stderr) << "rigidlab: one scene at a time (got " << file << " and " << a
                                << ")\n";
            return 2;
        }
        file = a;
    }

    rigidlab::ui::MainWindow window;
    window.resize(1500, 920);
    const QString welcome =
        QDir(rigidlab::ui::MainWindow::scenesFolder()).filePath(QStringLiteral("welcome.json"));
    if (!file.isEmpty()) {
        // Open the welcome scene first, so that a broken file leaves something alive behind
        // the error dialog.
        window.openScene(welcome, true);
        const QString error = window.openScene(file);
        if (!error.isEmpty())
            QTextStream(stderr) << error << '\n';
    } else {
        window.openScene(welcome);
    }
    window.show();
    if (window.lastError().isEmpty())
        window.controller().setRunning(true);
    return QApplication::exec();
}
