// SPDX-License-Identifier: GPL-3.0-or-later
#include "simulation/simulation_controller.h"

#include "simulation/variant_layout.h"

#include "rigidlab/physics/limits.h"

#include "common/display_names.h"
#include "common/number_format.h"

#include "format/limits.h"
#include "format/scene_loader.h"
#include "format/view_text.h"

#include <QElapsedTimer>
#include <QLocale>

#include <algorithm>
#include <cmath>
#include <optional>

namespace rigidlab::ui {

namespace {

/// A setting's new value in a plot's change mark: on screen, so in the window's locale
/// ("0,005" in Czech), six significant digits in fixed notation ("0,00001", not "1E-05").
QString markNumber(double value)
{
    return formatReadable(value, 6);
}

constexpr int kFrameIntervalMs = 16; // about 60 frames per second

} // namespace

template <typename Fn> void SimulationController::forEachWorld(Fn&& fn)
{
    fn(m_world);
    for (physics::World& w : m_variants)
        fn(w);
}

SimulationController::SimulationController(QObject* parent) : RunView(parent)
{
    m_frameTimer.setTimerType(Qt::PreciseTimer);
    m_frameTimer.setInterval(kFrameIntervalMs);
    connect(&m_frameTimer, &QTimer::timeout, this, &SimulationController::advanceFrame);
    m_eventReplayTimer.setSingleShot(true);
    connect(&m_eventReplayTimer, &QTimer::timeout, this, &SimulationController::replayEventSlice);
}

void SimulationController::loadScene(const lessons::Scene& scene, const QString& path)
{
    std::vector<physics::World> worlds;
    worlds.push_back(lessons::buildWorld(scene));
    loadWorlds(scene, path, std::move(worlds), {}, physics::Vec2::Zero());
}

void SimulationController::loadWorlds(const lessons::Scene& scene, const QString& path,
                                      std::vector<physics::World> worlds, const QStringList& labels,
                                      const physics::Vec2& offset)
{
    setRunning(false);
    m_scene = scene;
    m_path = path;
    m_sceneGravity = scene.world.gravity;
    m_grab.release();
    m_world = std::move(worlds.front());
    m_worldStart = m_world;
    m_variants.assign(std::make_move_iterator(worlds.begin() + 1),
                      std::make_move_iterator(worlds.end()));
    m_variantStarts = m_variants;
    m_variantLabels = labels;
    m_variantOffset = m_variants.empty() ? offset : besideOffset(m_world, offset);
    m_watch.forget();
    m_edits.restart();
    resetClock();
    emit sceneLoaded();
    emit settingsChanged();
    emit worldChanged();
}

void SimulationController::reset()
{
    // Back to the start, keeping the settings the user chose since: made again, as edits at
    // step 0, in the worlds that follow each of them.
    const SettingEdits kept = editsAtStart(m_worldStart.def(), m_world.def());
    setRunning(false);
    m_grab.release();
    m_world = m_worldStart;
    m_variants = m_variantStarts;
    for (const SettingEdit& edit : kept) {
        lessons::schema::findField(lessons::schema::Object::World, edit.key)
            ->apply(m_world, edit.value);
        for (physics::World& w : m_variants)
            applyToComparedWorld(edit, w);
    }
    m_edits.restart(kept);
    resetClock();
    emit worldChanged();
}

void SimulationController::resetClock()
{
    forEachWorld([](physics::World& w) { w.updateDiagnostics(); });
    m_history.reset(m_world);
    m_previousPoses.clear();
    m_catchUp.reset();
    m_sampler.restart(m_world, m_variants);
    m_watch.restart(m_world);
    catchUpEvents(); // measured from here on, or not at all: no replay left to run
    emit samplesCleared();
    pushSample();
}

void SimulationController::watch(const std::vector<lessons::Measure>& measures)
{
    m_watch.watch(measures, m_world);
    catchUpEvents(); // a lesson step measures from here: a replay under way stops
}

void SimulationController::setEventsShown(bool shown)
{
    m_watch.setShown(shown);
    catchUpEvents();
}

void SimulationController::catchUpEvents()
{
    m_eventReplay.reset();
    m_eventReplayTimer.stop();
    if (!m_watch.measuring() || !m_watch.behind()) {
        setCatchingUp(false);
        return;
    }
    // Bit for bit the run's states (history.h), so the same events as if measured all along:
    // from the start while the history reaches back to it. The present steps on meanwhile,
    // unmeasured (LessonWatch::observe), until the replay reaches it.
    m_eventReplay = m_history.restore(m_history.earliest());
    m_watch.measureFrom(*m_eventReplay);
    replayEventSlice();
    // Said only for a replay that takes more than its first slice (a short run is measured
    // again before the window draws).
    setCatchingUp(m_eventReplay.has_value());
}

void SimulationController::setCatchingUp(bool on)
{
    if (on == m_catchingUp)
        return;
    m_catchingUp = on;
    emit eventsCatchingUpChanged(on);
}

void SimulationController::replayEventSlice()
{
    if (!m_eventReplay)
        return;
    physics::World& replayed = *m_eventReplay;
    const auto observe = [this](const physics::World& w) { m_watch.replayed(w); };
    QElapsedTimer slice;
    slice.start();
    do {
        const long long before = replayed.stepCount();
        if (before >= m_world.stepCount())
            break;
        m_history.replay(replayed, before + 1, observe);
        if (replayed.stepCount() == before)
            break; // the history holds no later step (never so while it records every step)
    } while (slice.elapsed() < m_eventReplaySliceMs);
    if (replayed.stepCount() < m_world.stepCount() && m_history.latest() > replayed.stepCount()) {
        m_eventReplayTimer.start(0);
        return;
    }
    m_eventReplay.reset();
    m_watch.caughtUp();
    setCatchingUp(false);
    emit worldChanged(); // the tables show the whole run
}

Pose SimulationController::drawPose(physics::BodyId id, const Pose* drawn) const
{
    const physics::Body& b = m_world.body(id);
    physics::Vec2 centre = b.position;
    double angle = b.angle;
    const auto i = static_cast<std::size_t>(id);
    if (m_running && i < m_previousPoses.size()) {
        // A rigid motion between the two steps: the centre of mass on a line, the body turning
        // about it.
        const double alpha = std::clamp(m_catchUp.owed() / m_world.def().dt, 0.0, 1.0);
        const auto& [beforeCentre, beforeAngle] = m_previousPoses[i];
        centre = beforeCentre + alpha * (centre - beforeCentre);
        angle = beforeAngle + alpha * (angle - beforeAngle);
    }
    if (drawn && drawn->centre == centre && drawn->angle == angle)
        return *drawn;
    // Body::transform()'s placement, at the pose drawn.
    const physics::Rotation q(angle);
    return {centre - q.apply(b.localCenter), angle, q, centre};
}

void SimulationController::setRunning(bool running)
{
    if (running == m_running)
        return;
    m_running = running;
    m_catchUp.reset();
    if (running) {
        m_timing.runStarted();
        m_frameTimer.start();
    } else {
        m_frameTimer.stop();
    }
    emit runningChanged(running);
    emit worldChanged();
}

void SimulationController::doStep()
{
    const long long step = m_world.stepCount();
    const bool replaying = step < m_history.latest();
    std::optional<UserInput> input = m_grab.input(m_world);
    if (input && replaying) {
        m_history.branchAt(m_world); // a new push makes a new future
        m_edits.dropAfter(step);
    } else if (!input && replaying) {
        if (const UserInput* logged = m_history.inputFor(step))
            input = *logged;
    }
    m_previousPoses.resize(m_world.bodies().size());
    for (std::size_t i = 0; i < m_world.bodies().size(); ++i)
        m_previousPoses[i] = {m_world.bodies()[i].position, m_world.bodies()[i].angle};
    if (input)
        applyInput(m_world, *input);
    m_world.step();
    for (physics::World& w : m_variants)
        w.step();
    m_history.recorded(m_world, input ? &*input : nullptr);
    m_watch.observe(m_world);
    m_timing.stepTaken();
    pushSample();
}

void SimulationController::pushSample()
{
    // Variant 0 is the main world; the others follow in order, as the lesson export samples.
    m_sampler.record(m_world, m_variants, !m_variantLabels.isEmpty());
}

void SimulationController::advanceFrame()
{
    advanceClock(m_timing.wallSinceLastFrame());
}

void SimulationController::advanceClock(double wallSeconds)
{
    m_timing.physicsStarted();
    const double h = m_world.def().dt;
    if (m_running && !m_stepsHeld) {
        m_catchUp.beginFrame(wallSeconds, m_timeScale);
        // Only a run that starts before the end time stops at it: Play once there runs on.
        const bool ends = m_endTime && m_world.time() < *m_endTime - 0.5 * h;
        // Likewise a run that leaves the stage stops there once, and runs on after Play.
        const bool onStage = !m_watch.leftStage();
        bool ended = false, left = false;
        while (!ended && m_catchUp.nextStep(h, m_timing.physicsElapsedMs())) {
            const double before = m_timing.physicsElapsedMs();
            doStep();
            m_catchUp.stepTaken(h, m_timing.physicsElapsedMs() - before);
            m_timing.simulated(h);
            left = onStage && m_watch.leftStage();
            ended = left || (ends && m_world.time() >= *m_endTime - 0.5 * h);
        }
        m_catchUp.endFrame(h);
        if (ended)
            setRunning(false);
        if (left)
            emit leftStage(m_watch.leftStage()->body, m_watch.leftStage()->time);
        else if (ended)
            emit endTimeReached(m_world.time());
    }
    const double counted = std::min(wallSeconds, CatchUp::kMaxGapSeconds);
    if (m_timing.frameDone(wallSeconds, counted))
        emit framesMeasured(m_timing.measuredFrameMs(), m_timing.measuredPhysicsMs());
    emit worldChanged();
    emit frameAdvanced();
}

void SimulationController::stepForward()
{
    if (m_stepsHeld)
        return;
    setRunning(false);
    doStep();
    emit worldChanged();
}

void SimulationController::stepBack()
{
    seek(m_world.stepCount() - 1);
}

void SimulationController::seek(long long step)
{
    if (m_stepsHeld)
        return;
    setRunning(false);
    step = std::clamp(step, m_history.earliest(), m_history.latest());
    if (step == m_world.stepCount())
        return;
    m_world = m_history.restore(step);
    m_world.updateDiagnostics();
    // The compared worlds have no history of their own: they are small (lesson scenes)
    // and replay from their start, deterministically, with the settings changed on the way
    // made again at the steps they were made at.
    const SettingEdits& edits = m_edits.edits();
    for (std::size_t i = 0; i < m_variants.size(); ++i) {
        physics::World w = m_variantStarts[i];
        auto edit = edits.begin();
        for (;; w.step()) {
            for (; edit != edits.end() && edit->step <= w.stepCount(); ++edit)
                applyToComparedWorld(*edit, w);
            if (w.stepCount() >= step)
                break;
        }
        w.updateDiagnostics();
        m_variants[i] = std::move(w);
    }
    m_watch.rewind(m_world);
    catchUpEvents(); // a replay under way, or events never measured, go again to this step
    m_previousPoses.clear();
    m_sampler.rewound(stepTime(m_world)); // sample again from here on
    emit rewound(stepTime(m_world));
    pushSample();
    emit worldChanged();
}

// The setters take only what a scene file may hold (lessons/limits.h): a value from outside
// (a typed number, a test, a lesson) that is out of range or not finite changes nothing.

void SimulationController::setTimeScale(double scale)
{
    if (!lessons::limits::kTimeScale.contains(scale))
        return;
    m_timeScale = scale;
    emit settingsChanged();
}

void SimulationController::applyEdit(const SettingEdit& edit)
{
    using lessons::schema::Object;
    const auto vec = [&] { return std::get<physics::Vec2>(edit.value); };
    if (edit.object == Object::World)
        setSetting(edit.key, edit.value);
    else if (edit.key == "mass")
        setBodyMass(edit.index, std::get<double>(edit.value));
    else if (edit.key == body_edit::kMaterial)
        setBodyMaterial(edit.index, vec().x(), vec().y());
    else if (edit.key == body_edit::kTurn)
        rotateBody(edit.index, std::get<double>(edit.value));
    else if (edit.key == body_edit::kMove)
        moveBody(edit.index, vec().x(), vec().y());
    else if (edit.key == body_edit::kPush)
        pushBody(edit.index, vec().x(), vec().y());
}

void SimulationController::setSetting(std::string_view key, const lessons::schema::Value& value)
{
    namespace schema = lessons::schema;
    const schema::Field* row = schema::findField(schema::Object::World, key);
    if (row == nullptr || row->apply == nullptr || !schema::takes(*row, value))
        return;
    lessons::Scene now;
    now.world = m_world.def();
    // A body row that falls back to this one ("restitution") may hold the body's own: the
    // world's value given again gives it back to every body.
    const auto bodyRows = schema::fields(schema::Object::Body);
    const bool resetsBodies =
        std::any_of(bodyRows.begin(), bodyRows.end(),
                    [&](const schema::Field& f) { return f.fallback == key; });
    if (!resetsBodies && row->get(now, 0) == value)
        return;
    const SettingEdit edit{0, schema::Object::World, 0, row->key, value};
    logEdit(edit);
    row->apply(m_world, value);
    for (physics::World& w : m_variants)
        applyToComparedWorld(edit, w);
    afterEdit(settingMark(*row, value));
}

QString SimulationController::settingMark(const lessons::schema::Field& row,
                                          const lessons::schema::Value& value) const
{
    namespace schema = lessons::schema;
    const double* number = std::get_if<double>(&value);
    if (row.key == "dt")
        return tr("dt = %1 s").arg(markNumber(*number));
    if (row.key == "restitution")
        return tr("e = %1").arg(markNumber(*number));
    if (row.key == "friction")
        return tr("μ = %1").arg(markNumber(*number));
    if (row.key == "iterations")
        return tr("%n iteration(s)", nullptr, std::get<int>(value));
    if (row.key == "gravity")
        return std::get<physics::Vec2>(value).isZero() ? tr("gravity off") : tr("gravity on");
    if (const QString* name = std::get_if<QString>(&value))
        return methodDisplayName(*name);
    // Any other setting: its label and value, as the file would hold it.
    return QStringLiteral("%1 = %2").arg(schema::label(row), schema::text(value));
}

void SimulationController::afterEdit(const QString& mark)
{
    m_history.branchAt(m_world);
    if (!mark.isEmpty() && m_world.stepCount() > 0)
        emit marked(stepTime(m_world), mark);
    emit settingsChanged();
    emit worldChanged();
}

void SimulationController::setDt(double dt)
{
    setSetting("dt", dt);
}

void SimulationController::setIntegrator(physics::IntegratorKind kind)
{
    setSetting("integrator", lessons::textFromView(physics::integratorName(kind)));
}

void SimulationController::setSolver(physics::SolverKind kind)
{
    setSetting("solver", lessons::textFromView(physics::solverName(kind)));
}

void SimulationController::setIterations(int iterations)
{
    setSetting("iterations", iterations);
}

void SimulationController::setRestitution(double e)
{
    setSetting("restitution", e);
}

void SimulationController::setFriction(double mu)
{
    setSetting("friction", mu);
}

void SimulationController::setGravityEnabled(bool on)
{
    // On: the scene's own gravity.
    setSetting("gravity", on ? m_sceneGravity : physics::Vec2::Zero());
}

void SimulationController::setBodyMaterial(physics::BodyId id, double restitution, double friction)
{
    if (id < 0 || id >= static_cast<physics::BodyId>(m_world.bodies().size()))
        return;
    if (!lessons::limits::kRestitution.contains(restitution) ||
        !lessons::limits::kFriction.contains(friction))
        return;
    logEdit({0, lessons::schema::Object::Body, id, body_edit::kMaterial,
             physics::Vec2(restitution, friction)});
    m_world.setBodyMaterial(id, restitution, friction);
    afterEdit(QString());
}

void SimulationController::setBodyMass(physics::BodyId id, double mass)
{
    if (id < 0 || id >= static_cast<physics::BodyId>(m_world.bodies().size()) ||
        !lessons::limits::kMass.contains(mass) || mass == m_world.body(id).mass)
        return;
    if (!m_world.setBodyMass(id, mass))
        return;
    logEdit({0, lessons::schema::Object::Body, id, "mass", mass});
    m_world.updateDiagnostics();
    afterEdit(tr("m = %1 kg").arg(markNumber(mass)));
}

void SimulationController::rotateBody(physics::BodyId id, double radians)
{
    if (id < 0 || id >= static_cast<physics::BodyId>(m_world.bodies().size()) ||
        !m_world.body(id).moves() || !std::isfinite(radians))
        return;
    const double angle = m_world.body(id).angle + radians;
    if (!physics::limits::kAngle.contains(angle))
        return;
    logEdit({0, lessons::schema::Object::Body, id, body_edit::kTurn, radians});
    m_world.setBodyAngle(id, angle); // about the centre of mass; wakes the body
    afterEdit(QString());
}

void SimulationController::moveBody(physics::BodyId id, double dx, double dy)
{
    if (id < 0 || id >= static_cast<physics::BodyId>(m_world.bodies().size()) ||
        !m_world.body(id).moves() || !std::isfinite(dx) || !std::isfinite(dy))
        return;
    const physics::Body& b = m_world.body(id);
    const physics::Vec2 origin = b.origin() + physics::Vec2(dx, dy);
    if (!physics::limits::kCoordinate.contains(origin.x()) ||
        !physics::limits::kCoordinate.contains(origin.y()))
        return;
    logEdit({0, lessons::schema::Object::Body, id, body_edit::kMove, physics::Vec2(dx, dy)});
    m_world.setBodyOrigin(id, origin, b.angle);
    afterEdit(QString());
}

void SimulationController::pushBody(physics::BodyId id, double dvx, double dvy)
{
    if (id < 0 || id >= static_cast<physics::BodyId>(m_world.bodies().size()) ||
        !m_world.body(id).isDynamic() || !std::isfinite(dvx) || !std::isfinite(dvy))
        return;
    const physics::Vec2 v = m_world.originVelocity(id) + physics::Vec2(dvx, dvy);
    if (!physics::limits::kVelocity.contains(v.x()) || !physics::limits::kVelocity.contains(v.y()))
        return;
    logEdit({0, lessons::schema::Object::Body, id, body_edit::kPush, physics::Vec2(dvx, dvy)});
    m_world.setBodyVelocity(id, v, m_world.body(id).angularVelocity);
    afterEdit(tr("v = (%1; %2) m/s").arg(markNumber(v.x()), markNumber(v.y())));
}

} // namespace rigidlab::ui
