// SPDX-License-Identifier: GPL-3.0-or-later
// Fuzz target: the lesson loader (loadLessonJson) on any bytes, as a lesson file in the shipped
// lessons' folder, so that its scene paths can name the shipped scenes (and try to escape).
//
// Whatever the bytes, the loader returns: a lesson or one error line. A lesson it accepts has
// 1 to 100 steps, each with a scene within the limits, whose worlds build with finite energy;
// every scene file it read lies inside the data folder the lesson's folder is in (lessons/,
// holding scenes/ and lessons/).

#include "fuzz_lesson.h"

using namespace rigidlab;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    static const QString path =
        QDir(fuzz::shippedLessonsFolder()).filePath(QStringLiteral("fuzz-input.json"));
    static const QString dataFolder =
        QFileInfo(QStringLiteral(RIGIDLAB_SOURCE_DIR "/lessons")).canonicalFilePath();
    QByteArray bytes;
    const lessons::LessonLoadResult r = fuzz::loadFuzzedLesson(data, size, path, bytes);
    if (!r.ok)
        return 0;
    for (const lessons::LessonStep& step : r.lesson.steps) {
        if (!step.scenePath.isEmpty()) {
            const QString read = QFileInfo(step.scenePath).canonicalFilePath();
            FUZZ_CHECK(read.startsWith(dataFolder + u'/'));
        }
    }
    fuzz::checkFirstStepWorlds(r.lesson);
    return 0;
}
