// SPDX-License-Identifier: GPL-3.0-or-later
// Fuzz target: the lesson loader (loadLessonJson) on any bytes, as a lesson file in the shipped
// lessons' folder, so that its scene paths can name the shipped scenes (and try to escape).
//
// Whatever the bytes, the loader returns: a lesson or one error line. A lesson it accepts has
// 1 to 100 steps, each with a scene within the limits, whose worlds build with finite energy;
// every scene file it read lies inside the data folder the lesson's folder is in (lessons/,
// holding scenes/ and lessons/).

#include "fuzz_check.h"

#include "format/lesson.h"
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
    static const QString path = QDir(folder).filePath(QStringLiteral("fuzz-input.json"));
    static const QString dataFolder =
        QFileInfo(QStringLiteral(RIGIDLAB_SOURCE_DIR "/lessons")).canonicalFilePath();
    const QByteArray bytes(reinterpret_cast<const char*>(data), static_cast<qsizetype>(size));
    const lessons::LessonLoadResult r = lessons::loadLessonJson(bytes, path);
    if (!r.ok) {
        FUZZ_CHECK(r.error.startsWith(path + QStringLiteral(": ")));
        FUZZ_CHECK(!r.error.contains(u'\n'));
        return 0;
    }
    FUZZ_CHECK(!r.lesson.steps.empty() && r.lesson.steps.size() <= 100);
    for (const lessons::LessonStep& step : r.lesson.steps) {
        if (!step.scenePath.isEmpty()) {
            const QString read = QFileInfo(step.scenePath).canonicalFilePath();
            FUZZ_CHECK(read.startsWith(dataFolder + u'/'));
        }
    }
    // The first step's worlds, as the window builds them when the lesson opens.
    for (physics::World& world : lessons::buildStepWorlds(r.lesson.steps.front())) {
        world.updateDiagnostics();
        FUZZ_CHECK(std::isfinite(world.diagnostics().total));
    }
    return 0;
}
