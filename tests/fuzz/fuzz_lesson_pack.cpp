// SPDX-License-Identifier: GPL-3.0-or-later
// Fuzz target: a lesson in one file (.rlesson, loadLessonJson on a path ending in .rlesson) on
// any bytes. The file's path is in the shipped lessons' folder, so that a step naming a scene
// on disk ("../scenes/welcome.json") would find one: it must be refused all the same.
//
// Whatever the bytes, the loader returns a lesson or one error line naming the file. A lesson
// it accepts has 1 to 100 steps, none read from a scene file on disk, whose worlds build with
// finite energy; the file's structure reads back the same after lessonPackBytes (the writer
// and the reader agree), and what it writes loads to a lesson of as many steps.

#include "fuzz_check.h"

#include "format/lesson.h"
#include "format/lesson_pack.h"
#include "rigidlab/physics/world.h"

#include <QByteArray>
#include <QDir>
#include <QFileInfo>
#include <QString>

#include <cmath>
#include <cstddef>
#include <cstdint>

using namespace rigidlab;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    static const QString folder =
        QFileInfo(QStringLiteral(RIGIDLAB_SOURCE_DIR "/lessons/lessons")).canonicalFilePath();
    static const QString path = QDir(folder).filePath(QStringLiteral("fuzz-input.rlesson"));
    const QByteArray bytes(reinterpret_cast<const char*>(data), static_cast<qsizetype>(size));
    const lessons::LessonLoadResult r = lessons::loadLessonJson(bytes, path);
    if (!r.ok) {
        FUZZ_CHECK(r.error.startsWith(path + QStringLiteral(": ")));
        FUZZ_CHECK(!r.error.contains(u'\n'));
        return 0;
    }
    FUZZ_CHECK(!r.lesson.steps.empty() && r.lesson.steps.size() <= 100);
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

    // The first step's worlds, as the window builds them when the lesson opens.
    for (physics::World& world : lessons::buildStepWorlds(r.lesson.steps.front())) {
        world.updateDiagnostics();
        FUZZ_CHECK(std::isfinite(world.diagnostics().total));
    }
    return 0;
}
