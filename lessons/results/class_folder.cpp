// SPDX-License-Identifier: GPL-3.0-or-later
#include "results/class_folder.h"

#include "format/lesson_catalog.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>

#include <algorithm>
#include <map>

namespace rigidlab::lessons {

namespace {

struct ClassResults {
    Q_DECLARE_TR_FUNCTIONS(ClassResults)
};

QString native(const QString& path)
{
    return QDir::toNativeSeparators(path);
}

/// The reader's line with the file's name where it names the whole path: the lines are read
/// as a list of one folder's files.
QString byName(const QString& line, const QString& path, const QString& name)
{
    return line.startsWith(path) ? name + line.mid(path.size()) : line;
}

/// The lesson files the answers name, the most answered first, then by name.
QStringList lessonsNamed(const std::vector<HandedIn>& read)
{
    std::map<QString, int> counts;
    for (const HandedIn& h : read)
        if (!h.answers.lessonFile.isEmpty())
            ++counts[h.answers.lessonFile];
    QStringList names;
    for (const auto& [name, count] : counts)
        names.append(name);
    std::stable_sort(names.begin(), names.end(), [&counts](const QString& a, const QString& b) {
        return counts[a] > counts[b];
    });
    return names;
}

/// The title the first answers file of lesson `file` gives it.
QString titleNamedIn(const std::vector<HandedIn>& read, const QString& file)
{
    for (const HandedIn& h : read)
        if (h.answers.lessonFile == file && !h.answers.lessonTitle.isEmpty())
            return h.answers.lessonTitle;
    return QString();
}

/// The lesson called `file` among the shipped lessons and the user's own; nullopt with
/// `error` set when there is none or it does not load.
std::optional<Lesson> findLesson(const QString& file, QString& error)
{
    for (const LessonEntry& entry : allLessonsInOrder()) {
        if (QFileInfo(entry.path).fileName() != file)
            continue;
        LessonLoadResult loaded = loadLessonFile(entry.path);
        if (!loaded.ok) {
            error = loaded.error;
            return std::nullopt;
        }
        return std::move(loaded.lesson);
    }
    error = ClassResults::tr("no lesson \"%1\" among the shipped lessons and your own (name its "
                             "file)")
                .arg(file);
    return std::nullopt;
}

/// One table per lesson to collect, with the question counts its answers must fit.
struct Collecting {
    Lesson lesson;
    ClassTable table;
    std::vector<int> counts;
};

Collecting startTable(Lesson lesson)
{
    Collecting c{std::move(lesson), {}, {}};
    c.table = emptyClassTable(c.lesson);
    c.counts = questionCounts(c.lesson);
    return c;
}

/// Sorts every file read into its lesson's table, or into the lines of those left out.
void fillTables(const std::vector<HandedIn>& read, std::vector<Collecting>& tables,
                QStringList& skipped)
{
    const QString main = tables.front().table.lessonFile;
    for (const HandedIn& h : read) {
        // Answers that name no lesson (an empty sheet's) go with the lesson asked for.
        const QString named = h.answers.lessonFile.isEmpty() ? main : h.answers.lessonFile;
        const auto into = std::find_if(tables.begin(), tables.end(), [&](const Collecting& c) {
            return c.table.lessonFile == named;
        });
        if (into == tables.end()) {
            skipped.append(ClassResults::tr("%1: answers to \"%2\", not to \"%3\": left out")
                               .arg(h.file, named, main));
            continue;
        }
        if (const QString bad = answersMismatch(h.answers, named, into->counts); !bad.isEmpty()) {
            skipped.append(
                ClassResults::tr("%1: %2 (the lesson has changed since?)").arg(h.file, bad));
            continue;
        }
        into->table.rows.push_back(studentRow(into->lesson, h.answers, h.file));
    }
}

} // namespace

ClassFolder readClassFolder(const QString& folder)
{
    ClassFolder out;
    const QFileInfo info(folder);
    if (folder.isEmpty() || !info.isDir()) {
        out.error = ClassResults::tr("%1: no such folder").arg(native(folder));
        return out;
    }
    const QDir dir(folder);
    const QStringList names =
        dir.entryList({QString::fromUtf16(kAnswersFilePattern)}, QDir::Files, QDir::Name);
    if (!dir.isReadable()) {
        out.error = ClassResults::tr("%1: the folder cannot be read").arg(native(folder));
        return out;
    }
    out.files = static_cast<int>(names.size());
    for (const QString& name : names) {
        const QString path = dir.filePath(name);
        AnswersLoadResult loaded = loadAnswersFile(path);
        if (loaded.ok)
            out.read.push_back({name, std::move(loaded.answers)});
        else
            out.damaged.append(byName(loaded.error, path, name));
    }
    out.ok = true;
    return out;
}

ClassCollection collectClass(const QString& folder, const ClassOptions& options)
{
    ClassCollection out;
    ClassFolder f = readClassFolder(folder);
    if (!f.ok) {
        out.error = f.error;
        return out;
    }
    if (f.files == 0) {
        out.error = ClassResults::tr("%1: no answers files (%2) in it")
                        .arg(native(folder), QString::fromUtf16(kAnswersFilePattern));
        return out;
    }
    out.skipped = f.damaged;
    out.lessonFiles = lessonsNamed(f.read);
    for (const QString& file : out.lessonFiles)
        out.lessonTitles.append(titleNamedIn(f.read, file));
    if (f.read.empty()) {
        out.error = ClassResults::tr("%1: none of its %2 answers files reads")
                        .arg(native(folder))
                        .arg(f.files);
        return out;
    }
    std::vector<Collecting> tables;
    if (!options.lessonPath.isEmpty()) {
        LessonLoadResult loaded = loadLessonFile(options.lessonPath);
        if (!loaded.ok) {
            out.error = loaded.error;
            return out;
        }
        tables.push_back(startTable(std::move(loaded.lesson)));
    } else {
        const QString file =
            options.lessonFile.isEmpty() ? out.lessonFiles.value(0) : options.lessonFile;
        if (file.isEmpty()) {
            out.error = ClassResults::tr("%1: its answers name no lesson (name the lesson's file)")
                            .arg(native(folder));
            return out;
        }
        QString error;
        std::optional<Lesson> lesson = findLesson(file, error);
        if (!lesson) {
            out.error = error;
            return out;
        }
        tables.push_back(startTable(std::move(*lesson)));
    }
    for (const QString& file : out.lessonFiles) {
        if (!options.allLessons || file == tables.front().table.lessonFile)
            continue;
        QString error;
        if (std::optional<Lesson> lesson = findLesson(file, error))
            tables.push_back(startTable(std::move(*lesson)));
        else
            out.skipped.append(error); // its files are then left out as of another lesson
    }
    fillTables(f.read, tables, out.skipped);
    for (Collecting& c : tables)
        out.tables.push_back(std::move(c.table));
    if (out.tables.front().rows.empty()) {
        out.error = ClassResults::tr("%1: no answers to \"%2\" in it")
                        .arg(native(folder), out.tables.front().lessonFile);
        return out;
    }
    out.ok = true;
    return out;
}

} // namespace rigidlab::lessons
