// SPDX-License-Identifier: GPL-3.0-or-later
// rigidlab-cli lesson pack / unpack: a lesson folder's lesson into one .rlesson file and back
// (lessons/format/RLESSON_FORMAT.md). Argument handling only; the work is in
// format/lesson_pack.h.

#include "cli_lesson.h"

#include "cli_common.h"

#include "format/atomic_file.h"
#include "format/lesson_pack.h"

#include <QDate>
#include <QDir>
#include <QFileInfo>

namespace rigidlab::cli {

namespace {

int commandPack(const QStringList& words)
{
    CommandLine args(QStringLiteral("lesson pack"));
    args.addValue(QStringLiteral("o"), QStringLiteral("file"));
    args.addValue(QStringLiteral("author"), QStringLiteral("name"));
    args.addValue(QStringLiteral("date"), QStringLiteral("date"));
    if (!args.parse(words))
        return usageError(args.command(), args.error());
    const auto path = args.onlyFile(QStringLiteral("lesson file"));
    if (!path)
        return usageError(args.command(), args.error());
    const auto out = args.value(QStringLiteral("o"));
    if (!out || out->isEmpty())
        return usageError(args.command(), QStringLiteral("-o: which .rlesson file to write?"));
    if (!lessons::isLessonPackPath(*out))
        return usageError(args.command(),
                          QStringLiteral("-o: \"%1\" does not end in .rlesson").arg(*out));
    lessons::LessonPackInfo info;
    info.author = args.value(QStringLiteral("author")).value_or(QString());
    info.date = args.value(QStringLiteral("date")).value_or(QString());
    if (info.author.contains(u'\n'))
        return usageError(args.command(), QStringLiteral("--author: must be one line"));
    if (!info.date.isEmpty() && !QDate::fromString(info.date, Qt::ISODate).isValid())
        return usageError(args.command(),
                          QStringLiteral("--date: must be YYYY-MM-DD, got \"%1\"").arg(info.date));
    const lessons::LessonPackResult packed = lessons::packLesson(*path, info);
    printWarnings(packed.warnings);
    if (!packed.ok)
        return inputError(packed.error);
    const QString error = lessons::writeFileAtomically(*out, lessons::lessonPackBytes(packed.pack));
    if (!error.isEmpty())
        return outputError(error);
    printOut(QStringLiteral("wrote %1 (%2 scenes inside)\n")
                 .arg(QDir::toNativeSeparators(*out))
                 .arg(packed.pack.scenes.size()));
    return kExitOk;
}

int commandUnpack(const QStringList& words)
{
    CommandLine args(QStringLiteral("lesson unpack"));
    args.addValue(QStringLiteral("o"), QStringLiteral("folder"));
    if (!args.parse(words))
        return usageError(args.command(), args.error());
    const auto path = args.onlyFile(QStringLiteral(".rlesson file"));
    if (!path)
        return usageError(args.command(), args.error());
    const auto out = args.value(QStringLiteral("o"));
    if (!out || out->isEmpty())
        return usageError(args.command(), QStringLiteral("-o: which folder to write into?"));
    if (!lessons::isLessonPackPath(*path))
        return usageError(args.command(),
                          QStringLiteral("\"%1\" does not end in .rlesson").arg(*path));
    // Only a file that loads as a lesson is unpacked: what comes out is a lesson that works.
    const lessons::LessonLoadResult loaded = lessons::loadLessonFile(*path);
    printWarnings(loaded.warnings);
    if (!loaded.ok)
        return inputError(loaded.error);
    const lessons::LessonPackResult packed = lessons::packLesson(*path);
    if (!packed.ok)
        return inputError(packed.error);
    QStringList written;
    const QString error =
        lessons::unpackLesson(packed.pack, *out, QFileInfo(*path).completeBaseName(), written);
    for (const QString& file : written)
        printOut(QStringLiteral("wrote %1\n").arg(QDir::toNativeSeparators(file)));
    if (!error.isEmpty())
        return outputError(error);
    return kExitOk;
}

} // namespace

std::optional<int> commandLessonPacking(const QStringList& words)
{
    if (words.isEmpty())
        return std::nullopt;
    if (words.front() == u"pack")
        return commandPack(words.mid(1));
    if (words.front() == u"unpack")
        return commandUnpack(words.mid(1));
    return std::nullopt;
}

} // namespace rigidlab::cli
