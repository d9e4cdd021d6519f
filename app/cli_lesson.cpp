#include "cli_lesson.h"

#include "lesson_export.h"

#include "rigidlab/lessons/lesson.h"

#include <QDir>

#include <cstdio>

namespace rigidlab::cli {

namespace {

constexpr int kExitOk = 0;
constexpr int kExitOutputError = 1;
constexpr int kExitBadInput = 2;

void printOut(const QString& text)
{
    std::fputs(text.toLocal8Bit().constData(), stdout);
}

void printErr(const QString& text)
{
    std::fputs(text.toLocal8Bit().constData(), stderr);
}

int usageError(const QString& what)
{
    printErr(QStringLiteral("rigidlab-cli: lesson: ") + what +
             QStringLiteral("\nTry 'rigidlab-cli --help'.\n"));
    return kExitBadInput;
}

/// The steps, each with what it shows and asks: for a teacher preparing a class.
void printOutline(const lessons::Lesson& lesson)
{
    printOut(QStringLiteral("%1 (%2 min, %3)\n")
                 .arg(lesson.title)
                 .arg(lesson.minutes)
                 .arg(lesson.level.isEmpty() ? QStringLiteral("any level") : lesson.level));
    for (std::size_t i = 0; i < lesson.steps.size(); ++i) {
        const lessons::LessonStep& step = lesson.steps[i];
        QStringList parts;
        if (!step.plots.isEmpty())
            parts.append(QStringLiteral("plots: ") + step.plots.join(QStringLiteral(", ")));
        if (!step.panels.isEmpty())
            parts.append(QStringLiteral("panels: ") + step.panels.join(QStringLiteral(", ")));
        if (!step.questions.empty())
            parts.append(QStringLiteral("%1 question(s)").arg(step.questions.size()));
        printOut(QStringLiteral("%1. %2%3\n")
                     .arg(QString::number(i + 1), step.title,
                          parts.isEmpty()
                              ? QString()
                              : QStringLiteral(" (") + parts.join(QStringLiteral("; ")) + u')'));
    }
}

} // namespace

int commandLesson(const QStringList& words)
{
    QString path;
    QString exportDir;
    bool haveExport = false;
    for (qsizetype i = 0; i < words.size(); ++i) {
        const QString& word = words[i];
        if (word == u"--export" || word.startsWith(QStringLiteral("--export="))) {
            if (haveExport)
                return usageError(QStringLiteral("--export: given twice"));
            haveExport = true;
            if (word.startsWith(QStringLiteral("--export="))) {
                exportDir = word.mid(9);
            } else if (i + 1 < words.size()) {
                exportDir = words[++i];
            } else {
                return usageError(QStringLiteral("--export: needs a folder"));
            }
            if (exportDir.isEmpty())
                return usageError(QStringLiteral("--export: needs a folder"));
        } else if (word.startsWith(u'-') && word.size() > 1) {
            return usageError(QStringLiteral("unknown option %1").arg(word));
        } else if (path.isEmpty()) {
            path = word;
        } else {
            return usageError(QStringLiteral("one lesson file only"));
        }
    }
    if (path.isEmpty())
        return usageError(QStringLiteral("which lesson file?"));

    const lessons::LessonLoadResult loaded = lessons::loadLessonFile(path);
    for (const QString& w : loaded.warnings)
        printErr(QStringLiteral("warning: ") + w + u'\n');
    if (!loaded.ok) {
        printErr(QStringLiteral("error: ") + loaded.error + u'\n');
        return kExitBadInput;
    }
    if (!haveExport) {
        printOutline(loaded.lesson);
        return kExitOk;
    }

    const ui::PlotFilesResult written = ui::exportLessonPlots(loaded.lesson, exportDir);
    for (const QString& file : written.files)
        printOut(QStringLiteral("wrote %1\n").arg(QDir::toNativeSeparators(file)));
    if (!written.ok) {
        printErr(QStringLiteral("error: ") + written.error + u'\n');
        return kExitOutputError;
    }
    return kExitOk;
}

} // namespace rigidlab::cli
