// SPDX-License-Identifier: GPL-3.0-or-later
#include "format/lesson_catalog.h"

#include "format/data_dirs.h"
#include "format/lesson.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>

#include <algorithm>
#include <limits>

namespace rigidlab::lessons {

std::vector<LessonEntry> lessonsInOrder(const QString& folder)
{
    std::vector<LessonEntry> entries;
    if (folder.isEmpty())
        return entries;
    const QDir dir(folder);
    // By name first, so that the stable sort below keeps lessons without an order, and any
    // two with the same one, in file-name order.
    for (const QFileInfo& info :
         dir.entryInfoList({QStringLiteral("*.json")}, QDir::Files, QDir::Name)) {
        const LessonLoadResult r = loadLessonFile(info.absoluteFilePath());
        if (!r.ok)
            continue;
        entries.push_back({info.absoluteFilePath(), r.lesson.title, r.lesson.description,
                           r.lesson.order, r.lesson.minutes});
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
    std::vector<LessonEntry> own = lessonsInOrder(userLessonsDir());
    for (LessonEntry& entry : own) {
        entry.own = true;
        entries.push_back(std::move(entry));
    }
    return entries;
}

QString lessonMenuText(const LessonEntry& entry, int position)
{
    QString text =
        QCoreApplication::translate("rigidlab::lessons", "%1. %2").arg(position).arg(entry.title);
    if (!entry.description.isEmpty())
        text += QCoreApplication::translate("rigidlab::lessons", " — %1").arg(entry.description);
    if (entry.minutes > 0)
        text += QCoreApplication::translate("rigidlab::lessons", " (≈%1 min)").arg(entry.minutes);
    if (entry.own)
        text += QCoreApplication::translate("rigidlab::lessons", " (your own)");
    return text;
}

} // namespace rigidlab::lessons
