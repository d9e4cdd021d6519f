// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Helpers of the lesson-physics tests (test_lesson_physics*.cpp).

#include "test_lesson.h"

#include <cmath>

namespace rigidlab::test {

inline const lessons::LessonStep& stepOf(const lessons::Lesson& lesson, std::size_t i)
{
    return lesson.steps.at(i);
}

inline physics::BodyId bodyId(const lessons::Scene& scene, const char* id)
{
    const auto index = scene.bodyIndex(QString::fromLatin1(id));
    Q_ASSERT(index);
    return *index;
}

/// The relative energy drift of a world since `e0` [%], as the lessons measure it.
inline double driftPercent(const physics::World& w, double e0)
{
    return (w.diagnostics().total - e0) / std::abs(e0) * 100.0;
}

} // namespace rigidlab::test
