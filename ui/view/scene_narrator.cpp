// SPDX-License-Identifier: GPL-3.0-or-later
#include "view/scene_narrator.h"

#include "common/announcer.h"
#include "common/spoken_numbers.h"
#include "simulation/run_view.h"
#include "view/scene_words.h"
#include "view/world_view.h"
#include "view/world_view_accessible.h"

#include "rigidlab/physics/touching.h"

#include <QAccessible>
#include <QMetaMethod>

#include <algorithm>

namespace rigidlab::ui {

SceneNarrator::SceneNarrator(const RunView& run, WorldView& view)
    : QObject(&view), m_run(run), m_view(view)
{
    m_tick.setInterval(kValueIntervalMs);
    connect(&m_tick, &QTimer::timeout, this, [this] {
        tellValues();
        flush();
    });
    connect(&run, &RunView::runningChanged, this, [this](bool running) {
        if (running)
            m_tick.start();
        else
            m_tick.stop();
        // Play and pause told, with the time the run stopped at.
        announce(m_view, running
                             ? tr("Running.")
                             : tr("Paused at %1.")
                                   .arg(spokenQuantity(m_run.time(), QStringLiteral("s"), 3, 1.0)));
    });
    m_settle.setSingleShot(true);
    m_settle.setInterval(kSettleMs);
    connect(&m_settle, &QTimer::timeout, this, [this] {
        const auto count = static_cast<int>(m_run.world().bodies().size());
        if (m_moved < 0 || m_moved >= count)
            return;
        const physics::World& world = m_run.world();
        const physics::Vec2 o = world.body(m_moved).origin();
        const physics::Vec2 v = world.originVelocity(m_moved);
        announce(m_view, tr("%1: position %2, velocity %3.")
                             .arg(m_run.scene().bodyLabel(m_moved),
                                  spokenPair(o.x(), o.y(), QStringLiteral("m"), 3, 1.0),
                                  spokenPair(v.x(), v.y(), QStringLiteral("m/s"), 3, 1.0)));
    });
    connect(&run, &RunView::worldChanged, this, &SceneNarrator::onWorldChanged);
    connect(&run, &RunView::sceneLoaded, this, &SceneNarrator::onSceneLoaded);
    connect(&run, &RunView::samplesCleared, this, &SceneNarrator::onSceneLoaded);
    m_sinceTold.start();
}

void SceneNarrator::onSceneLoaded()
{
    m_toldValues.clear();
    m_touched = false;
    m_moving = false;
    m_diverged = false;
    m_pending.clear();
}

void SceneNarrator::onWorldChanged()
{
    const physics::World& world = m_run.world();
    if (!m_touched) {
        // The first pair that touches (physics/touching.h), not one the step looked ahead for.
        const auto touching =
            std::find_if(world.contacts().begin(), world.contacts().end(),
                         [](const physics::Contact& c) { return physics::touches(c); });
        if (touching != world.contacts().end()) {
            m_touched = true;
            note(tr("%1 and %2 touch.")
                     .arg(m_run.scene().bodyLabel(touching->a),
                          m_run.scene().bodyLabel(touching->b)));
        }
    }
    double fastest = 0;
    for (std::size_t i = 0; i < world.bodies().size(); ++i)
        if (world.body(static_cast<physics::BodyId>(i)).isDynamic())
            fastest =
                std::max(fastest, world.body(static_cast<physics::BodyId>(i)).velocity.norm());
    if (fastest > kMovingSpeed)
        m_moving = true;
    else if (m_moving && fastest < kRestSpeed && m_run.isRunning()) {
        m_moving = false;
        note(tr("Everything has come to rest."));
    }
    if (world.divergence() && !m_diverged) {
        m_diverged = true;
        note(tr("The simulation diverged and stopped."));
        // Told at once, not only in the status: the run is over.
        announce(m_view, tr("The simulation diverged and stopped."));
    }
    // Paused, a step or a seek is the student's own doing: tell its result at once, but
    // never faster than the calm rate.
    if (m_tick.isActive())
        return;
    if (m_sinceTold.elapsed() >= kValueIntervalMs) {
        tellValues();
        flush();
    } else if (!m_pending.isEmpty()) {
        const int wait = kValueIntervalMs - static_cast<int>(m_sinceTold.elapsed());
        QTimer::singleShot(wait, this, &SceneNarrator::flush);
    }
}

void SceneNarrator::note(const QString& event)
{
    if (!m_pending.contains(event))
        m_pending << event;
}

void SceneNarrator::flush()
{
    if (m_pending.isEmpty())
        return;
    m_status = m_pending.join(QLatin1Char(' '));
    m_pending.clear();
    ++m_changes;
    m_sinceTold.restart();
    tell(WorldViewAccessible::Status, m_status);
}

void SceneNarrator::tell(int child, const QString& value)
{
    emit told(child, value);
    if (QAccessible::isActive())
        tellSceneItemChanged(m_view, child);
}

void SceneNarrator::tellValues()
{
    m_sinceTold.restart();
    // Nobody listens (no assistive technology, nothing connected to told()): the words of
    // thousands of bodies would cost the window a frame every second for nothing. The values
    // not told are told at the first tick someone listens (none was told, so all changed).
    if (!QAccessible::isActive() &&
        !isSignalConnected(QMetaMethod::fromSignal(&SceneNarrator::told)))
        return;
    // Only what changed: a body at rest, a floor, says the same as a second ago.
    const auto count = static_cast<physics::BodyId>(m_run.world().bodies().size());
    const std::vector<std::vector<physics::BodyId>> touches = scene_words::touchingBodies(m_run);
    for (physics::BodyId id = 0; id < count; ++id) {
        const QString value =
            scene_words::bodyValue(m_run, id, touches[static_cast<std::size_t>(id)]);
        if (m_toldValues.value(id) == value)
            continue;
        m_toldValues.insert(id, value);
        tell(WorldViewAccessible::FirstBody + id, value);
    }
}

void SceneNarrator::tellChosen(int id)
{
    if (id < 0 || id >= static_cast<int>(m_run.world().bodies().size()))
        return;
    const physics::Vec2 v = m_run.world().originVelocity(id);
    announce(m_view, tr("%1, speed %2.")
                         .arg(m_run.scene().bodyLabel(id),
                              spokenQuantity(v.norm(), QStringLiteral("m/s"), 3, 1.0)));
}

void SceneNarrator::tellMoved(int id)
{
    m_moved = id;
    m_settle.start();
}

} // namespace rigidlab::ui
