// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What the lesson fuzz targets share (a lesson folder's .json, a .rlesson): the bytes read as
// a lesson file in the shipped lessons' folder, the loader's promise on any bytes (a lesson of
// 1 to 100 steps, or one error line naming the file), and the first step's worlds built as
// the window builds them when the lesson opens. (Apart from fuzz_check.h, which the targets
// without Qt include too.)

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

namespace rigidlab::fuzz {

/// The shipped lessons' folder, where a step naming "../scenes/NAME.json" finds a scene.
inline const QString& shippedLessonsFolder()
{
    static const QString folder =
        QFileInfo(QStringLiteral(RIGIDLAB_SOURCE_DIR "/lessons/lessons")).canonicalFilePath();
    return folder;
}

/// The fuzzer's bytes read as the lesson file `path`; checks what the loader promises.
inline lessons::LessonLoadResult loadFuzzedLesson(const std::uint8_t* data, std::size_t size,
                                                  const QString& path, QByteArray& bytes)
{
    bytes = QByteArray(reinterpret_cast<const char*>(data), static_cast<qsizetype>(size));
    lessons::LessonLoadResult r = lessons::loadLessonJson(bytes, path);
    if (!r.ok) {
        FUZZ_CHECK(r.error.startsWith(path + QStringLiteral(": ")));
        FUZZ_CHECK(!r.error.contains(u'\n'));
        return r;
    }
    FUZZ_CHECK(!r.lesson.steps.empty() && r.lesson.steps.size() <= 100);
    return r;
}

/// The first step's worlds, as the window builds them when the lesson opens: finite energy.
inline void checkFirstStepWorlds(const lessons::Lesson& lesson)
{
    for (physics::World& world : lessons::buildStepWorlds(lesson.steps.front())) {
        world.updateDiagnostics();
        FUZZ_CHECK(std::isfinite(world.diagnostics().total));
    }
}

} // namespace rigidlab::fuzz
