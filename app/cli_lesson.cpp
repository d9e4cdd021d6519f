// SPDX-License-Identifier: GPL-3.0-or-later
#include "cli_lesson.h"

#include "cli_common.h"

#include "common/language.h"
#include "plots/lesson_export.h"
#include "worksheet/worksheet.h"

#include "format/answers_file.h"
#include "format/data_dirs.h"
#include "format/languages.h"
#include "format/lesson.h"
#include "format/lesson_catalog.h"

#include <QDir>
#include <QFileInfo>

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

/// `--worksheet OUT.pdf`: the empty sheet, the key (--key) or a student's sheet from the
/// answers the window saved (--answers), in --lang or else the language the answers were
/// given in.
int writeWorksheetCommand(const CommandLine& args, const QString& lessonPath, const QString& out)
{
    lessons::Answers answers;
    const auto answersPath = args.value(QStringLiteral("answers"));
    if (answersPath) {
        const lessons::AnswersLoadResult read = lessons::loadAnswersFile(*answersPath);
        if (!read.ok)
            return inputError(read.error);
        answers = read.answers;
    }
    // --lang was checked; the answers' language by their reader. English without either.
    QString language = args.value(QStringLiteral("lang")).value_or(answers.language);
    if (language.isEmpty())
        language = lessons::kFallbackLanguage.toString();
    lessons::setLessonLanguage(language);
    const lessons::LessonLoadResult loaded = lessons::loadLessonFile(lessonPath);
    printWarnings(loaded.warnings);
    if (!loaded.ok)
        return inputError(loaded.error);
    if (const QString bad =
            lessons::answersMismatch(answers, QFileInfo(loaded.lesson.path).fileName(),
                                     lessons::questionCounts(loaded.lesson));
        !bad.isEmpty())
        return inputError(QStringLiteral("%1: %2 (answers for another lesson?)")
                              .arg(answersPath.value_or(QString()), bad));
    if (const auto student = args.value(QStringLiteral("student"))) {
        // The same limits as the answers file's student: one line of the sheet's header.
        if (const QString problem = lessons::answerTextProblem(*student); !problem.isEmpty())
            return usageError(args.command(), QStringLiteral("--student: ") + problem);
        answers.student = *student;
    }
    // The sheet speaks the lesson's language; the program's own messages stay English.
    ui::applyLanguage(language);
    const ui::WorksheetKind kind = args.isSet(QStringLiteral("key")) ? ui::WorksheetKind::Key
                                   : answersPath                     ? ui::WorksheetKind::Answers
                                                                     : ui::WorksheetKind::Empty;
    const ui::WorksheetResult written = ui::writeWorksheet(loaded.lesson, answers, kind, out);
    if (!written.ok)
        return outputError(written.error);
    printOut(QStringLiteral("wrote %1 (%2 pages)\n")
                 .arg(QDir::toNativeSeparators(out))
                 .arg(written.pages));
    return kExitOk;
}

} // namespace

int commandLesson(const QStringList& words)
{
    if (const auto packing = commandLessonPacking(words))
        return *packing;
    CommandLine args(QStringLiteral("lesson"));
    args.addSwitch(QStringLiteral("validate"));
    args.addValue(QStringLiteral("export"), QStringLiteral("folder"));
    args.addValue(QStringLiteral("worksheet"), QStringLiteral("PDF file"));
    args.addValue(QStringLiteral("student"), QStringLiteral("name"));
    args.addValue(QStringLiteral("answers"), QStringLiteral("answers file"));
    args.addSwitch(QStringLiteral("key"));
    addLanguageAndCsvOptions(args);
    if (!args.parse(words))
        return usageError(args.command(), args.error());
    QString languageError;
    const auto csv = lessonLanguageAndCsv(args, languageError);
    if (!csv)
        return usageError(args.command(), languageError);
    const auto exportDir = args.value(QStringLiteral("export"));
    if (exportDir && exportDir->isEmpty())
        return usageError(args.command(), QStringLiteral("--export: needs a folder"));
    const auto path = args.onlyFile(QStringLiteral("lesson file"));
    if (!path)
        return usageError(args.command(), args.error());
    const auto worksheet = args.value(QStringLiteral("worksheet"));
    if (worksheet && worksheet->isEmpty())
        return usageError(args.command(), QStringLiteral("--worksheet: needs a PDF file"));
    if (worksheet && exportDir)
        return usageError(args.command(),
                          QStringLiteral("--worksheet and --export: one at a time"));
    if (args.isSet(QStringLiteral("validate")) && (worksheet || exportDir))
        return usageError(args.command(),
                          QStringLiteral("--validate: alone (not with --export or --worksheet)"));
    for (const char* option : {"student", "answers", "key"})
        if (!worksheet && args.isSet(QLatin1StringView(option)))
            return usageError(
                args.command(),
                QStringLiteral("--%1: only with --worksheet").arg(QLatin1StringView(option)));
    if (args.isSet(QStringLiteral("key")) && args.isSet(QStringLiteral("student")))
        return usageError(args.command(), QStringLiteral("--key: the key has no student"));
    if (worksheet)
        return writeWorksheetCommand(args, *path, *worksheet);

    const lessons::LessonLoadResult loaded = lessons::loadLessonFile(*path);
    printWarnings(loaded.warnings);
    if (!loaded.ok)
        return inputError(loaded.error);
    if (args.isSet(QStringLiteral("validate"))) {
        const std::size_t steps = loaded.lesson.steps.size();
        printOut(QStringLiteral("ok: %1: lesson \"%2\", %3 %4\n")
                     .arg(*path, loaded.lesson.title)
                     .arg(steps)
                     .arg(steps == 1 ? QStringLiteral("step") : QStringLiteral("steps")));
        return kExitOk;
    }
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
