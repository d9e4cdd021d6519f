// SPDX-License-Identifier: GPL-3.0-or-later
#include "format/lesson_catalog.h"

#include "format/data_dirs.h"
#include "format/json_reader.h"
#include "format/lesson.h"
#include "format/lesson_pack.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QDir>
#include <QFileInfo>
#include <QSettings>

#include <algorithm>
#include <limits>
#include <memory>

namespace rigidlab::lessons {

namespace {

const QString kFoldersKey = QStringLiteral("lessons/folders");

/// The window's settings, also from rigidlab-cli (which names no organisation of its own), so
/// that both list the same added folders.
std::unique_ptr<QSettings> settings()
{
    if (QCoreApplication::organizationName().isEmpty())
        return std::make_unique<QSettings>(QSettings::defaultFormat(), QSettings::UserScope,
                                           QStringLiteral("RigidLab"), QStringLiteral("RigidLab"));
    return std::make_unique<QSettings>();
}

/// A .rlesson's author and date, as its file says.
LessonPackInfo packInfo(const QString& path)
{
    const detail::FileBytes file = detail::readFileBytes(path, kMaxLessonPackBytes);
    return file.ok ? readLessonPack(file.bytes, path).pack.info : LessonPackInfo{};
}

/// lessonsInOrder(folder), each marked own, with its author and date.
void appendOwn(const QString& folder, std::vector<LessonEntry>& entries)
{
    for (LessonEntry& entry : lessonsInOrder(folder)) {
        entry.own = true;
        // A lesson in one file is shared: the list says whose and from when.
        if (isLessonPackPath(entry.path)) {
            const LessonPackInfo info = packInfo(entry.path);
            entry.author = info.author;
            entry.date = info.date;
            if (entry.date.isEmpty())
                entry.date = QFileInfo(entry.path).lastModified().date().toString(Qt::ISODate);
        }
        entries.push_back(std::move(entry));
    }
}

} // namespace

std::vector<LessonEntry> lessonsInOrder(const QString& folder)
{
    std::vector<LessonEntry> entries;
    if (folder.isEmpty())
        return entries;
    const QDir dir(folder);
    // By name first, so that the stable sort below keeps lessons without an order, and any
    // two with the same one, in file-name order.
    for (const QFileInfo& info : dir.entryInfoList(
             {QStringLiteral("*.json"), QStringLiteral("*.rlesson")}, QDir::Files, QDir::Name)) {
        const LessonLoadResult r = loadLessonFile(info.absoluteFilePath());
        if (!r.ok)
            continue;
        LessonEntry entry;
        entry.path = info.absoluteFilePath();
        entry.title = r.lesson.title;
        entry.description = r.lesson.description;
        entry.order = r.lesson.order;
        entry.minutes = r.lesson.minutes;
        entries.push_back(std::move(entry));
    }
    std::stable_sort(entries.begin(), entries.end(),
                     [](const LessonEntry& a, const LessonEntry& b) {
                         // 0 (no order) sorts after every given order.
                         const auto key = [](int order) {
                             return order > 0 ? order : std::numeric_limits<int>::max();
                         };
                         return key(a.order) < key(b.order);
                     });
    return entries;
}

std::vector<LessonEntry> shippedLessonsInOrder()
{
    return lessonsInOrder(shippedLessonsDir());
}

std::vector<LessonEntry> allLessonsInOrder()
{
    std::vector<LessonEntry> entries = shippedLessonsInOrder();
    appendOwn(userLessonsDir(), entries);
    for (const QString& folder : addedLessonFolders())
        if (QDir(folder) != QDir(userLessonsDir()))
            appendOwn(folder, entries);
    return entries;
}

QStringList addedLessonFolders()
{
    return settings()->value(kFoldersKey).toStringList();
}

bool addLessonFolder(const QString& folder)
{
    QStringList folders = addedLessonFolders();
    const QString clean = QDir::cleanPath(QFileInfo(folder).absoluteFilePath());
    if (folders.contains(clean))
        return false;
    folders.append(clean);
    settings()->setValue(kFoldersKey, folders);
    return true;
}

bool removeLessonFolder(const QString& folder)
{
    QStringList folders = addedLessonFolders();
    if (folders.removeAll(QDir::cleanPath(folder)) == 0)
        return false;
    settings()->setValue(kFoldersKey, folders);
    return true;
}

QString lessonMenuText(const LessonEntry& entry, int position)
{
    QString text =
        QCoreApplication::translate("rigidlab::lessons", "%1. %2").arg(position).arg(entry.title);
    if (!entry.description.isEmpty())
        text += QCoreApplication::translate("rigidlab::lessons", " — %1").arg(entry.description);
    if (entry.minutes > 0)
        text += QCoreApplication::translate("rigidlab::lessons", " (≈%1 min)").arg(entry.minutes);
    if (entry.own) {
        QStringList about;
        if (!entry.author.isEmpty())
            about.append(entry.author);
        if (!entry.date.isEmpty())
            about.append(entry.date);
        text += about.isEmpty()
                    ? QCoreApplication::translate("rigidlab::lessons", " (your own)")
                    : QCoreApplication::translate("rigidlab::lessons", " (your own: %1)")
                          .arg(about.join(QStringLiteral(", ")));
    }
    return text;
}

} // namespace rigidlab::lessons
