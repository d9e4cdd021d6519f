// SPDX-License-Identifier: GPL-3.0-or-later
#include "cli_results.h"

#include "cli_common.h"

#include "common/language.h"
#include "worksheet/class_results_pdf.h"

#include "format/atomic_file.h"
#include "format/languages.h"
#include "results/class_folder.h"
#include "results/class_table_files.h"

#include <QDir>
#include <QFileInfo>

namespace rigidlab::cli {

namespace {

enum class ResultsFormat { Text, Csv, Pdf };

/// The output's format by its name's suffix, or nothing with `error` set.
std::optional<ResultsFormat> formatOf(const std::optional<QString>& out, QString& error)
{
    if (!out)
        return ResultsFormat::Text;
    const QString suffix = QFileInfo(*out).suffix().toLower();
    if (suffix == u"csv")
        return ResultsFormat::Csv;
    if (suffix == u"pdf")
        return ResultsFormat::Pdf;
    error = QStringLiteral("-o: \"%1\" is neither .csv nor .pdf").arg(*out);
    return std::nullopt;
}

int writeResults(const lessons::ClassCollection& collected, ResultsFormat format,
                 const std::optional<QString>& out, const lessons::CsvConventions& csv)
{
    switch (format) {
    case ResultsFormat::Text:
        for (const lessons::ClassTable& table : collected.tables)
            printOut(lessons::classTableText(table) + u'\n');
        return kExitOk;
    case ResultsFormat::Csv: {
        const std::string bytes = lessons::classTablesCsv(collected.tables, csv);
        if (const QString error = lessons::writeFileAtomically(
                *out, QByteArray(bytes.data(), static_cast<qsizetype>(bytes.size())));
            !error.isEmpty())
            return outputError(error);
        break;
    }
    case ResultsFormat::Pdf: {
        const ui::ClassResultsPdf written =
            ui::writeClassResultsPdf(collected.tables, collected.skipped, *out);
        if (!written.ok)
            return outputError(written.error);
        break;
    }
    }
    std::size_t students = 0;
    for (const lessons::ClassTable& table : collected.tables)
        students += table.rows.size();
    printOut(QStringLiteral("wrote %1 (%2 students)\n")
                 .arg(QDir::toNativeSeparators(*out))
                 .arg(students));
    return kExitOk;
}

} // namespace

int commandResults(const QStringList& words)
{
    CommandLine args(QStringLiteral("results"));
    args.addValue(QStringLiteral("lesson"), QStringLiteral("lesson file"));
    args.addValue(QStringLiteral("o"), QStringLiteral("file"));
    args.addSwitch(QStringLiteral("all-lessons"));
    addLanguageAndCsvOptions(args);
    if (!args.parse(words))
        return usageError(args.command(), args.error());
    QString error;
    const auto csv = lessonLanguageAndCsv(args, error);
    if (!csv)
        return usageError(args.command(), error);
    const auto folder = args.onlyFile(QStringLiteral("folder"));
    if (!folder)
        return usageError(args.command(), args.error());
    const auto out = args.value(QStringLiteral("o"));
    const auto format = formatOf(out, error);
    if (!format)
        return usageError(args.command(), error);
    if (args.isSet(QStringLiteral("csv-dialect")) && *format != ResultsFormat::Csv)
        return usageError(args.command(), QStringLiteral("--csv-dialect: only with -o OUT.csv"));
    const auto lesson = args.value(QStringLiteral("lesson"));
    if (lesson && lesson->isEmpty())
        return usageError(args.command(), QStringLiteral("--lesson: needs a lesson file"));

    lessons::ClassOptions options;
    options.lessonPath = lesson.value_or(QString());
    options.allLessons = args.isSet(QStringLiteral("all-lessons"));
    const lessons::ClassCollection collected = lessons::collectClass(*folder, options);
    // Every file left out, one line each, whether or not a table follows.
    for (const QString& line : collected.skipped)
        printErr(QStringLiteral("skipped: ") + line + u'\n');
    if (!collected.ok)
        return inputError(collected.error);
    // The heads, verdicts and numbers speak --lang (English without it, whatever the
    // system's locale) from here on; the lines above, this program's own, stay English.
    ui::applyLanguage(
        args.value(QStringLiteral("lang")).value_or(lessons::kFallbackLanguage.toString()));
    return writeResults(collected, *format, out, *csv);
}

} // namespace rigidlab::cli
