// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What a lesson step measures while the world runs (bounces, apexes, collisions, timed
// values), and whether a body left the stage (off_stage.h), kept in step with the
// controller's world: started over with the run, told of every step, rewound when the world
// goes back.

#include "run/measurements.h"
#include "run/off_stage.h"

#include "rigidlab/physics/world.h"

#include <optional>
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
    /// Watches, from `world` (the run's start) on, whether a body leaves the stage; off:
    /// never. Kept when another scene is watched (a lesson's steps all watch it).
    void watchStage(bool on, const physics::World& world)
    {
        m_stageOn = on;
        m_floor = on ? lessons::stageFloor(world) : lessons::StageFloor{};
        m_left.reset();
    }
    /// The run starts over from `world`.
    void restart(const physics::World& world)
    {
        m_measurements.reset(world, m_watched);
        watchStage(m_stageOn, world);
    }
    /// After every step of `world`.
    void observe(const physics::World& world)
    {
        m_measurements.observe(world);
        if (m_stageOn && !m_left)
            if (const auto body = lessons::offStage(world, m_floor))
                m_left = lessons::OffStage{*body, world.time()};
    }
    /// `world` went back in time: what happened after it is forgotten.
    void rewind(const physics::World& world)
    {
        m_measurements.rewind(world);
        if (m_left && m_left->time > world.time())
            m_left.reset();
    }

    const lessons::Measurements& measurements() const { return m_measurements; }
    /// The body that left the stage in this run, and when; nullopt while none has.
    const std::optional<lessons::OffStage>& leftStage() const { return m_left; }

private:
    lessons::Measurements m_measurements;
    std::vector<lessons::Measure> m_watched;
    bool m_stageOn = false;
    lessons::StageFloor m_floor;
    std::optional<lessons::OffStage> m_left;
};

} // namespace rigidlab::ui
