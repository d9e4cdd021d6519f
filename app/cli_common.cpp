// SPDX-License-Identifier: GPL-3.0-or-later
#include "cli_common.h"

#include "common/language.h"
#include "format/languages.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace rigidlab::cli {

void printOut(const QString& text)
{
    std::fputs(text.toLocal8Bit().constData(), stdout);
}

void printErr(const QString& text)
{
    std::fputs(text.toLocal8Bit().constData(), stderr);
}

void printWarnings(const QStringList& warnings)
{
    for (const QString& w : warnings)
        printErr(QStringLiteral("warning: ") + w + u'\n');
}

int usageError(const QString& command, const QString& what)
{
    const QString where = command.isEmpty() ? QString() : command + QStringLiteral(": ");
    printErr(QStringLiteral("rigidlab-cli: ") + where + what +
             QStringLiteral("\nTry 'rigidlab-cli --help'.\n"));
    return kExitBadInput;
}

int inputError(const QString& what)
{
    printErr(QStringLiteral("error: ") + what + u'\n');
    return kExitBadInput;
}

int outputError(const QString& what)
{
    printErr(QStringLiteral("error: ") + what + u'\n');
    return kExitOutputError;
}

void CommandLine::addValue(const QString& name, const QString& what)
{
    m_parser.addOption(QCommandLineOption(name, QString(), QStringLiteral("value")));
    m_values.push_back({name, what});
}

void CommandLine::addSwitch(const QString& name)
{
    m_parser.addOption(QCommandLineOption(name));
    m_switchNames.append(name);
}

namespace {

/// The option as the user typed it ("-t", "--colour"), for a name the parser reports.
QString spelled(const QStringList& words, const QString& name)
{
    for (const QString& word : words) {
        if (word == u"--")
            break;
        QString bare = word.section(u'=', 0, 0);
        while (bare.startsWith(u'-'))
            bare.remove(0, 1);
        if (bare == name && word.startsWith(u'-'))
            return word.section(u'=', 0, 0);
    }
    return QStringLiteral("--") + name;
}

} // namespace

bool CommandLine::parseOptionsOnly(const QStringList& words)
{
    if (!parse(words))
        return false;
    if (const QStringList extra = positionals(); !extra.isEmpty()) {
        m_error = QStringLiteral("unexpected argument \"%1\"").arg(extra.front());
        return false;
    }
    return true;
}

bool CommandLine::parse(const QStringList& words)
{
    m_error.clear();
    // Long names only, with one or two dashes: "-t" is an unknown option, not "t" compacted.
    m_parser.setSingleDashWordOptionMode(QCommandLineParser::ParseAsLongOptions);
    // A value option as the last word: said in this tool's words, not the parser's.
    const qsizetype end = words.indexOf(QStringLiteral("--"));
    const QStringList options = end < 0 ? words : words.first(end);
    if (!options.isEmpty()) {
        const QString last = options.back();
        for (const ValueOption& option : m_values) {
            if (last == QStringLiteral("--") + option.name) {
                m_error = QStringLiteral("%1: needs a %2").arg(last, option.what);
                return false;
            }
        }
    }
    if (!m_parser.parse(QStringList{QStringLiteral("rigidlab-cli")} + words)) {
        const QStringList unknown = m_parser.unknownOptionNames();
        if (!unknown.isEmpty()) {
            m_error = QStringLiteral("unknown option %1").arg(spelled(words, unknown.front()));
            return false;
        }
        for (const QString& name : m_switchNames) {
            const QString given = QStringLiteral("--") + name + u'=';
            if (std::any_of(options.cbegin(), options.cend(),
                            [&](const QString& w) { return w.startsWith(given); })) {
                m_error = QStringLiteral("--%1: takes no value").arg(name);
                return false;
            }
        }
        m_error = m_parser.errorText();
        return false;
    }
    const QStringList seen = m_parser.optionNames(); // in order, repeats included
    for (const QString& name : seen) {
        if (seen.count(name) > 1) {
            m_error = QStringLiteral("%1: given twice").arg(spelled(words, name));
            return false;
        }
    }
    return true;
}

std::optional<QString> CommandLine::value(const QString& name) const
{
    if (!m_parser.isSet(name))
        return std::nullopt;
    return m_parser.value(name);
}

std::optional<QString> CommandLine::onlyFile(const QString& what)
{
    const QStringList files = positionals();
    if (files.size() == 1)
        return files.front();
    m_error = files.isEmpty() ? QStringLiteral("which %1?").arg(what)
                              : QStringLiteral("one %1 only, got %2").arg(what).arg(files.size());
    return std::nullopt;
}

std::optional<double> finiteNumber(const QString& option, const QString& text, QString& error)
{
    bool ok = false;
    const double value = text.trimmed().toDouble(&ok);
    if (!ok || !std::isfinite(value)) {
        error = QStringLiteral("%1: must be a finite number, got \"%2\"").arg(option, text);
        return std::nullopt;
    }
    return value;
}

std::optional<double> positiveNumber(const QString& option, const QString& text, QString& error)
{
    bool ok = false;
    const double value = text.trimmed().toDouble(&ok);
    if (!ok || !std::isfinite(value) || value <= 0) {
        error = QStringLiteral("%1: must be a positive number, got \"%2\"").arg(option, text);
        return std::nullopt;
    }
    return value;
}

std::optional<long long> wholeNumber(const QString& option, const QString& text, long long min,
                                     long long max, QString& error)
{
    bool ok = false;
    const long long value = text.trimmed().toLongLong(&ok);
    if (!ok || value < min || value > max) {
        error = QStringLiteral("%1: must be a whole number from %2 to %3, got \"%4\"")
                    .arg(option)
                    .arg(min)
                    .arg(max)
                    .arg(text);
        return std::nullopt;
    }
    return value;
}

namespace {

QString unknownLanguage(const QString& lang)
{
    return QStringLiteral("--lang: unknown language \"%1\" (expected %2)")
        .arg(lang, lessons::shippedLanguageCodes());
}

/// --lang, when given, put in effect by `apply`; false with `error` set for a language the lab
/// does not ship (which `apply` refuses).
bool applyLang(const CommandLine& args, QString& error, bool (*apply)(const QString&))
{
    const auto lang = args.value(QStringLiteral("lang"));
    if (lang && !apply(*lang)) {
        error = unknownLanguage(*lang);
        return false;
    }
    return true;
}

} // namespace

std::optional<lessons::CsvConventions> csvOption(const CommandLine& args, QString& error)
{
    const auto lang = args.value(QStringLiteral("lang"));
    if (lang && !lessons::isShippedLanguage(*lang)) {
        error = unknownLanguage(*lang);
        return std::nullopt;
    }
    const QString language = lang.value_or(lessons::kFallbackLanguage.toString());
    const auto name = args.value(QStringLiteral("csv-dialect"));
    if (!name) {
        // A language with a decimal comma (Czech) asks for its spreadsheet's file: plain CSV
        // there opens with every number as text. --csv-dialect plain still gives the plain one.
        const bool spreadsheet = lang && lessons::usesDecimalComma(language);
        return lessons::csvConventions(
            spreadsheet ? lessons::CsvDialect::Spreadsheet : lessons::CsvDialect::Plain, language);
    }
    const auto dialect = lessons::csvDialectFromName(*name);
    if (!dialect) {
        error = QStringLiteral("--csv-dialect: unknown dialect \"%1\" (expected %2)")
                    .arg(*name, lessons::csvDialectNames());
        return std::nullopt;
    }
    return lessons::csvConventions(*dialect, language);
}

bool applyOutputLanguage(const CommandLine& args, QString& error)
{
    return applyLang(args, error, ui::applyLanguage);
}

void addLanguageOption(CommandLine& args)
{
    args.addValue(QStringLiteral("lang"), QStringLiteral("language"));
}

bool applyLanguageOption(const CommandLine& args, QString& error)
{
    return applyLang(args, error, lessons::setLessonLanguage);
}

void addLanguageAndCsvOptions(CommandLine& args)
{
    args.addValue(QStringLiteral("csv-dialect"), QStringLiteral("dialect"));
    addLanguageOption(args);
}

std::optional<lessons::CsvConventions> lessonLanguageAndCsv(const CommandLine& args, QString& error)
{
    if (!applyLanguageOption(args, error))
        return std::nullopt;
    return csvOption(args, error);
}

} // namespace rigidlab::cli
