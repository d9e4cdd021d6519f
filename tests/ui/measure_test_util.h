// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What the window's measurement tests share: the shipped samples and the scene they were
// measured on.

#include "format/data_dirs.h"
#include "format/scene.h"

#include <QString>

namespace rigidlab::ui::test {

/// The ball's coefficient of restitution in the shipped ball_* samples
/// (lessons/measure/samples/make_samples.py: exact flights, seeded noise).
inline constexpr double kSampleE = 0.72;

inline QString sample(const char* name)
{
    return lessons::shippedDataDir() + QStringLiteral("/measure/samples/") + QLatin1String(name);
}

/// The scene the samples were measured on.
inline QString sceneFile()
{
    return lessons::shippedScenesDir() + QStringLiteral("/lab_vs_measurement.json");
}

inline physics::BodyId ballOf(const lessons::Scene& scene)
{
    return *scene.bodyIndex(QStringLiteral("ball"));
}

} // namespace rigidlab::ui::test
