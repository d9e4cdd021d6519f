// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What a lesson step measures while the world runs (bounces, apexes, collisions, timed
// values), and whether a body left the stage (off_stage.h), kept in step with the
// controller's world: started over with the run, told of every step, rewound when the world
// goes back. The measurements are made only while something reads them: a lesson step (its
// questions and tables), or the bounce or collision table open in a scene that is no lesson.
// In a large scene that is no lesson they were a few per cent of every frame for nobody; a
// table opened later measures the run again from the history (SimulationController).

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
        m_stepWatches = true;
        restart(world);
    }
    /// Watches nothing more (a new scene); restart() then starts the events over.
    void forget()
    {
        m_watched.clear();
        m_stepWatches = false;
    }
    /// Whether a table shows the events (the bounces or the collision): then they are
    /// measured in a scene that is no lesson step too.
    void setShown(bool shown) { m_shown = shown; }
    /// Whether observe() measures: a lesson step watches, or a table shows the events.
    bool measuring() const { return m_stepWatches || m_shown; }
    /// Whether a step went unmeasured since the run started over (measuring() was off):
    /// the measurements then lack events until measured again (measureFrom()).
    bool behind() const { return m_behind; }
    /// Measures again from `start`, an earlier state of this run (the history's): the caller
    /// then gives replayed() every later state up to the present, and caughtUp() there. The
    /// present's steps meanwhile go unmeasured (behind() stays true).
    void measureFrom(const physics::World& start) { m_measurements.reset(start, m_watched); }
    void replayed(const physics::World& world) { m_measurements.observe(world); }
    void caughtUp() { m_behind = false; }
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
        m_behind = false;
        watchStage(m_stageOn, world);
    }
    /// After every step of `world`.
    void observe(const physics::World& world)
    {
        if (measuring() && !m_behind)
            m_measurements.observe(world);
        else
            m_behind = true;
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
    bool m_stepWatches = false; ///< a lesson step watches (watch() since forget())
    bool m_shown = false;       ///< see setShown()
    bool m_behind = false;      ///< see behind()
    bool m_stageOn = false;
    lessons::StageFloor m_floor;
    std::optional<lessons::OffStage> m_left;
};

} // namespace rigidlab::ui
