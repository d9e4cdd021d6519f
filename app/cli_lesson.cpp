// SPDX-License-Identifier: GPL-3.0-or-later
#include "cli_lesson.h"

#include "cli_common.h"

#include "common/language.h"
#include "plots/lesson_export.h"

#include "format/data_dirs.h"
#include "format/languages.h"
#include "format/lesson.h"
#include "format/lesson_catalog.h"

#include <QDir>

#include <cstdio>

namespace rigidlab::cli {

namespace {

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

void addLanguageOption(CommandLine& args)
{
    args.addValue(QStringLiteral("lang"), QStringLiteral("language"));
}

bool applyLanguageOption(const CommandLine& args, QString& error)
{
    const auto lang = args.value(QStringLiteral("lang"));
    if (!lang)
        return true;
    if (!lessons::setLessonLanguage(*lang)) {
        error = QStringLiteral("--lang: unknown language \"%1\" (expected %2)")
                    .arg(*lang, lessons::shippedLanguageCodes());
        return false;
    }
    return true;
}

int commandLesson(const QStringList& words)
{
    CommandLine args(QStringLiteral("lesson"));
    args.addValue(QStringLiteral("export"), QStringLiteral("folder"));
    args.addValue(QStringLiteral("csv-dialect"), QStringLiteral("dialect"));
    addLanguageOption(args);
    if (!args.parse(words))
        return usageError(args.command(), args.error());
    QString languageError;
    if (!applyLanguageOption(args, languageError))
        return usageError(args.command(), languageError);
    const auto csv = csvOption(args, languageError);
    if (!csv)
        return usageError(args.command(), languageError);
    const auto exportDir = args.value(QStringLiteral("export"));
    if (exportDir && exportDir->isEmpty())
        return usageError(args.command(), QStringLiteral("--export: needs a folder"));
    const auto path = args.onlyFile(QStringLiteral("lesson file"));
    if (!path)
        return usageError(args.command(), args.error());

    const lessons::LessonLoadResult loaded = lessons::loadLessonFile(*path);
    printWarnings(loaded.warnings);
    if (!loaded.ok)
        return inputError(loaded.error);
    if (!exportDir) {
        printOutline(loaded.lesson);
        return kExitOk;
    }

    // The handouts speak the lesson's language (titles, axes, legends, captions, and the
    // locale's decimal comma on the axes); this program's own messages stay English, so the
    // translation comes in only now, after loading. The CSV's numbers follow --csv-dialect.
    if (const auto lang = args.value(QStringLiteral("lang")))
        ui::applyLanguage(*lang);
    ui::ExportOptions options;
    options.csv = *csv;
    const ui::PlotFilesResult written = ui::exportLessonPlots(loaded.lesson, *exportDir, options);
    for (const QString& file : written.files)
        printOut(QStringLiteral("wrote %1\n").arg(QDir::toNativeSeparators(file)));
    if (!written.ok)
        return outputError(written.error);
    return kExitOk;
}

int commandLessons(const QStringList& words)
{
    CommandLine args(QStringLiteral("lessons"));
    if (!args.parse(words))
        return usageError(args.command(), args.error());
    if (!args.positionals().isEmpty())
        return usageError(args.command(),
                          QStringLiteral("no files: it lists the shipped lessons and the user's"));
    if (lessons::shippedLessonsDir().isEmpty())
        return inputError(QStringLiteral("no shipped lessons found (installed data folder "
                                         "missing; RIGIDLAB_DATA_DIR names another)"));
    // The user's own lessons (lessons::userLessonsDir()) after the shipped ones, a third
    // column marking them.
    for (const lessons::LessonEntry& entry : lessons::allLessonsInOrder()) {
        printOut(entry.own ? QStringLiteral("%1\t%2\tyour own\n").arg(entry.path, entry.title)
                           : QStringLiteral("%1\t%2\n").arg(entry.path, entry.title));
    }
    return kExitOk;
}

} // namespace rigidlab::cli
