// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What a lesson step measures while the world runs (bounces, apexes, collisions, timed
// values), kept in step with the controller's world: started over with the run, told of
// every step, rewound when the world goes back.

#include "run/measurements.h"

#include "rigidlab/physics/world.h"

#include <vector>

namespace rigidlab::ui {

class LessonWatch {
public:
    /// Watches these measures from `world` as it is now (none: the events alone).
    void watch(const std::vector<lessons::Measure>& measures, const physics::World& world)
    {
        m_watched = measures;
        restart(world);
    }
    /// Watches nothing more (a new scene); restart() then starts the events over.
    void forget() { m_watched.clear(); }
    /// The run starts over from `world`.
    void restart(const physics::World& world) { m_measurements.reset(world, m_watched); }
    /// After every step of `world`.
    void observe(const physics::World& world) { m_measurements.observe(world); }
    /// `world` went back in time: what happened after it is forgotten.
    void rewind(const physics::World& world) { m_measurements.rewind(world); }

    const lessons::Measurements& measurements() const { return m_measurements; }

private:
    lessons::Measurements m_measurements;
    std::vector<lessons::Measure> m_watched;
};

} // namespace rigidlab::ui
