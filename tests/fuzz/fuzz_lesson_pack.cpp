// SPDX-License-Identifier: GPL-3.0-or-later
// Fuzz target: a lesson in one file (.rlesson, loadLessonJson on a path ending in .rlesson) on
// any bytes. The file's path is in the shipped lessons' folder, so that a step naming a scene
// on disk ("../scenes/welcome.json") would find one: it must be refused all the same.
//
// Whatever the bytes, the loader returns a lesson or one error line naming the file. A lesson
// it accepts has 1 to 100 steps, none read from a scene file on disk, whose worlds build with
// finite energy; the file's structure reads back the same after lessonPackBytes (the writer
// and the reader agree), and what it writes loads to a lesson of as many steps.

#include "fuzz_lesson.h"

#include "format/lesson_pack.h"

using namespace rigidlab;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    static const QString path =
        QDir(fuzz::shippedLessonsFolder()).filePath(QStringLiteral("fuzz-input.rlesson"));
    QByteArray bytes;
    const lessons::LessonLoadResult r = fuzz::loadFuzzedLesson(data, size, path, bytes);
    if (!r.ok)
        return 0;
    for (const lessons::LessonStep& step : r.lesson.steps)
        FUZZ_CHECK(step.scenePath.isEmpty());

    // Written again and read again: the same structure, a lesson of as many steps.
    const lessons::LessonPackResult read = lessons::readLessonPack(bytes, path);
    FUZZ_CHECK(read.ok);
    const QByteArray written = lessons::lessonPackBytes(read.pack);
    const lessons::LessonPackResult reread = lessons::readLessonPack(written, path);
    FUZZ_CHECK(reread.ok);
    FUZZ_CHECK(lessons::lessonPackBytes(reread.pack) == written);
    const lessons::LessonLoadResult again = lessons::loadLessonJson(written, path);
    FUZZ_CHECK(again.ok && again.lesson.steps.size() == r.lesson.steps.size());

    fuzz::checkFirstStepWorlds(r.lesson);
    return 0;
}
