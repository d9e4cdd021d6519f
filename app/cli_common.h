// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What every rigidlab-cli command shares: its exit statuses, how it prints, and how it reads its
// command line (Qt's QCommandLineParser, one per command, with the messages of one style).
// Messages stay English: scripts read them.

#include "export/csv_dialect.h"

#include <QCommandLineParser>
#include <QString>
#include <QStringList>

#include <optional>
#include <vector>

namespace rigidlab::cli {

/// Exit statuses, as documented in the usage text.
enum ExitStatus : int {
    kExitOk = 0,
    kExitOutputError = 1, ///< an output file could not be written
    kExitBadInput = 2,    ///< bad input or usage
    kExitNonFinite = 3,   ///< the simulation diverged (nothing written)
    kExitVerdict = 4,     ///< a stress case ended with another verdict than documented
};

void printOut(const QString& text);
void printErr(const QString& text);
/// Each warning on its own line, "warning: ...", on standard error.
void printWarnings(const QStringList& warnings);

/// "rigidlab-cli: COMMAND: what" and a hint on standard error; returns kExitBadInput.
int usageError(const QString& command, const QString& what);
/// "error: what" on standard error (a file's own problem); returns kExitBadInput.
int inputError(const QString& what);
/// "error: what" on standard error (a file could not be written); returns kExitOutputError.
int outputError(const QString& what);

/// One command's words after its name, read by QCommandLineParser: `--name value` and
/// `--name=value`, each option at most once, `--` ends the options.
class CommandLine {
public:
    explicit CommandLine(QString command) : m_command(std::move(command)) {}

    /// An option that takes a value; `what` names it in "--name: needs a WHAT".
    void addValue(const QString& name, const QString& what = QStringLiteral("value"));
    /// An option without a value.
    void addSwitch(const QString& name);

    /// Reads the words; false with error() set when the command line is malformed.
    bool parse(const QStringList& words);
    /// Reads the words of a command that takes options only: also false, with error()
    /// "unexpected argument \"X\"", when a word is not an option.
    bool parseOptionsOnly(const QStringList& words);
    const QString& error() const { return m_error; }
    const QString& command() const { return m_command; }

    /// The value given for `--name`, or nothing.
    std::optional<QString> value(const QString& name) const;
    bool isSet(const QString& name) const { return m_parser.isSet(name); }
    QStringList positionals() const { return m_parser.positionalArguments(); }

    /// The one file the command works on, or nothing with error() set ("which WHAT?").
    std::optional<QString> onlyFile(const QString& what = QStringLiteral("file"));

private:
    QString m_command;
    QCommandLineParser m_parser;
    struct ValueOption {
        QString name;
        QString what; ///< "value", "folder": in "--name: needs a WHAT"
    };
    std::vector<ValueOption> m_values;
    QStringList m_switchNames;
    QString m_error;
};

/// A finite number from an option's text, or nothing with `error` set.
std::optional<double> finiteNumber(const QString& option, const QString& text, QString& error);
/// A positive finite number from an option's text, or nothing with `error` set.
std::optional<double> positiveNumber(const QString& option, const QString& text, QString& error);
/// A whole number in [min, max] from an option's text, or nothing with `error` set.
std::optional<long long> wholeNumber(const QString& option, const QString& text, long long min,
                                     long long max, QString& error);

/// The option `--lang CODE` of the commands that read lessons: the language their texts are
/// read in (format/languages.h). The CLI's own messages stay English.
void addLanguageOption(CommandLine& args);
/// Sets the lessons' language from `--lang`, if given; false with `error` set for a code the
/// lab does not ship.
bool applyLanguageOption(const CommandLine& args, QString& error);

/// `--lang CODE` and `--csv-dialect D`, of the commands that read lessons and write CSV.
void addLanguageAndCsvOptions(CommandLine& args);
/// The lessons' language set from --lang (applyLanguageOption), then the CSV dialect read in
/// its conventions (csvOption); nothing with `error` set when either is wrong.
std::optional<lessons::CsvConventions> lessonLanguageAndCsv(const CommandLine& args,
                                                            QString& error);

/// The CSV dialect of --csv-dialect plain|spreadsheet (plain when not given) in the language of
/// --lang (English when not given), or nothing with `error` set.
std::optional<lessons::CsvConventions> csvOption(const CommandLine& args, QString& error);

/// Puts --lang's language in effect for what the command writes (CSV heads, handouts), after
/// its input was read: its own messages stay English. True when --lang is not given; false for
/// a language the lab does not ship (`error` says so).
bool applyOutputLanguage(const CommandLine& args, QString& error);

} // namespace rigidlab::cli
