// SPDX-License-Identifier: GPL-3.0-or-later
#include "simulation/simulation_controller.h"

#include "rigidlab/physics/limits.h"

#include "common/display_names.h"
#include "plots/step_sampler.h"

#include "format/limits.h"
#include "format/scene_loader.h"

#include <QLocale>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <optional>

namespace rigidlab::ui {

namespace {

/// A setting's new value in a plot's change mark: on screen, so in the window's locale
/// ("0,005" in Czech), six significant digits as QString::arg gives.
QString markNumber(double value)
{
    QLocale locale;
    locale.setNumberOptions(QLocale::OmitGroupSeparator);
    return locale.toString(value, 'g', 6);
}

constexpr int kFrameIntervalMs = 16;      // about 60 frames per second
constexpr double kMaxFrameSeconds = 0.1;  // a longer gap (a paused debugger) counts as this
constexpr double kPhysicsBudgetMs = 12.0; // physics may take this much of a frame
constexpr double kGrabFrequency = 3.0;    // the grab spring's natural frequency [Hz]

/// The box [m] around a world's static bodies (floor, walls); empty when it has none.
/// corners: min x, min y, max x, max y.
std::optional<std::array<double, 4>> staticExtent(const physics::World& world)
{
    std::optional<std::array<double, 4>> box;
    auto add = [&box](const physics::Vec2& p) {
        if (!std::isfinite(p.x()) || !std::isfinite(p.y()))
            return;
        if (!box) {
            box = std::array<double, 4>{p.x(), p.y(), p.x(), p.y()};
            return;
        }
        auto& b = *box;
        b = {std::min(b[0], p.x()), std::min(b[1], p.y()), std::max(b[2], p.x()),
             std::max(b[3], p.y())};
    };
    for (const physics::Body& b : world.bodies()) {
        if (b.moves())
            continue;
        const physics::Transform t = b.transform();
        b.shape.visit(physics::Overloaded{[&](const physics::Circle& circle) {
                                              const physics::Vec2 c = t.apply(circle.center);
                                              const double r = circle.radius;
                                              add(c - physics::Vec2(r, r));
                                              add(c + physics::Vec2(r, r));
                                          },
                                          [&](const physics::Polygon& polygon) {
                                              for (const physics::Vec2& v : polygon.vertices)
                                                  add(t.apply(v));
                                          }});
    }
    return box;
}

/// The shift between compared worlds drawn beside each other: the lesson's, or, where their
/// floors and walls would overlap at it (a stack's floor is wider than the shift), as far in
/// the same direction as the main world's static bodies are long, plus a gap. Never shorter
/// than the lesson's. It only moves the drawing: the compared worlds run where they are.
physics::Vec2 besideOffset(const physics::World& main, const physics::Vec2& offset)
{
    const double length = offset.norm();
    const auto box = staticExtent(main);
    if (!(length > 0) || !std::isfinite(length) || !box)
        return offset;
    const auto& b = *box;
    const double w = b[2] - b[0], h = b[3] - b[1];
    const bool overlap = std::abs(offset.x()) < w && std::abs(offset.y()) < h;
    if (!overlap)
        return offset;
    // The box's length along the shift's direction, so that the shifted box clears it.
    const physics::Vec2 dir = offset / length;
    const double alongX = std::abs(dir.x()) > 1e-12 ? w / std::abs(dir.x()) : HUGE_VAL;
    const double alongY = std::abs(dir.y()) > 1e-12 ? h / std::abs(dir.y()) : HUGE_VAL;
    const double extent = std::min(alongX, alongY);
    const double gap = std::max(0.5, 0.1 * extent);
    return dir * std::max(length, extent + gap);
}

} // namespace

template <typename Fn> void SimulationController::forEachWorld(Fn&& fn)
{
    fn(m_world);
    for (physics::World& w : m_variants)
        fn(w);
}

SimulationController::SimulationController(QObject* parent) : QObject(parent)
{
    m_frameTimer.setTimerType(Qt::PreciseTimer);
    m_frameTimer.setInterval(kFrameIntervalMs);
    connect(&m_frameTimer, &QTimer::timeout, this, &SimulationController::advanceFrame);
    m_rateClock.start();
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
    m_grab.reset();
    m_world = std::move(worlds.front());
    m_worldStart = m_world;
    m_variants.assign(std::make_move_iterator(worlds.begin() + 1),
                      std::make_move_iterator(worlds.end()));
    m_variantStarts = m_variants;
    m_variantLabels = labels;
    m_variantOffset = m_variants.empty() ? offset : besideOffset(m_world, offset);
    m_watched.clear();
    m_edits.clear();
    resetClock();
    emit sceneLoaded();
    emit settingsChanged();
    emit worldChanged();
}

void SimulationController::reset()
{
    // Back to the start, keeping the settings the user chose since.
    const physics::WorldDef settings = m_world.def();
    setRunning(false);
    m_grab.reset();
    m_world = m_worldStart;
    m_world.setDt(settings.dt);
    m_world.setIntegrator(settings.integrator);
    m_world.setSolver(settings.solver);
    m_world.setIterations(settings.iterations);
    if (settings.restitution != m_worldStart.def().restitution)
        m_world.setRestitution(settings.restitution);
    if (settings.friction != m_worldStart.def().friction)
        m_world.setFriction(settings.friction);
    m_variants = m_variantStarts;
    forEachWorld([&](physics::World& w) {
        w.setDt(settings.dt);
        w.setGravity(settings.gravity);
    });
    // The run starts again with the settings kept: edits at step 0, made as just above.
    using Kind = SettingEdit::Kind;
    const physics::WorldDef& start = m_worldStart.def();
    m_edits.clear();
    if (settings.dt != start.dt)
        m_edits.push_back({0, Kind::Dt, -1, settings.dt, 0.0, 0});
    if (settings.integrator != start.integrator)
        m_edits.push_back(
            {0, Kind::Integrator, -1, 0.0, 0.0, static_cast<int>(settings.integrator)});
    if (settings.solver != start.solver)
        m_edits.push_back({0, Kind::Solver, -1, 0.0, 0.0, static_cast<int>(settings.solver)});
    if (settings.iterations != start.iterations)
        m_edits.push_back({0, Kind::Iterations, -1, 0.0, 0.0, settings.iterations});
    if (settings.restitution != start.restitution)
        m_edits.push_back({0, Kind::Restitution, -1, settings.restitution, 0.0, 0});
    if (settings.friction != start.friction)
        m_edits.push_back({0, Kind::Friction, -1, settings.friction, 0.0, 0});
    if (settings.gravity != start.gravity)
        m_edits.push_back({0, Kind::Gravity, -1, 0.0, 0.0, settings.gravity.isZero() ? 0 : 1});
    resetClock();
    emit worldChanged();
}

void SimulationController::resetClock()
{
    m_world.updateDiagnostics();
    m_energyReference = EnergyReference::of(m_world);
    m_history.reset(m_world);
    m_previousPoses.clear();
    m_accumulator = 0.0;
    m_slow = false;
    m_sampleClock.reset();
    m_samples.clear();
    resetVariants();
    m_measurements.reset(m_world, m_watched);
    emit samplesCleared();
    pushSample();
}

void SimulationController::resetVariants()
{
    m_variantReferences.clear();
    for (physics::World& w : m_variants) {
        w.updateDiagnostics();
        m_variantReferences.push_back(EnergyReference::of(w));
    }
}

void SimulationController::watch(const std::vector<lessons::Measure>& measures)
{
    m_watched = measures;
    m_measurements.reset(m_world, m_watched);
}

double SimulationController::driftPercent() const
{
    return m_energyReference.driftPercent(m_world.diagnostics());
}

double SimulationController::dissipated() const
{
    return m_energyReference.dissipatedSince(m_world.diagnostics());
}

Pose SimulationController::drawPose(physics::BodyId id) const
{
    const physics::Body& b = m_world.body(id);
    Pose now{b.origin(), b.angle};
    const auto i = static_cast<std::size_t>(id);
    if (!m_running || i >= m_previousPoses.size())
        return now;
    const double alpha = std::clamp(m_accumulator / m_world.def().dt, 0.0, 1.0);
    const Pose& before = m_previousPoses[i];
    return {before.origin + alpha * (now.origin - before.origin),
            before.angle + alpha * (now.angle - before.angle)};
}

void SimulationController::setRunning(bool running)
{
    if (running == m_running)
        return;
    m_running = running;
    m_accumulator = 0.0;
    if (running) {
        m_wall.start();
        m_frameTimer.start();
        // The rates measure this run only, not the pause before it.
        m_rateClock.restart();
        m_stepsThisSecond = 0;
        m_simulatedThisSecond = 0.0;
        m_stepsPerSecond = 0.0;
        m_realTimeFactor.reset();
    } else {
        m_frameTimer.stop();
        m_slow = false;
    }
    emit runningChanged(running);
    emit worldChanged();
}

void SimulationController::doStep()
{
    const long long step = m_world.stepCount();
    const bool replaying = step < m_history.latest();
    std::optional<UserInput> input;
    if (m_grab) {
        // The grab spring: k = m w^2, critically damped, at the grabbed point.
        const physics::Body& b = m_world.body(m_grab->body);
        const physics::Vec2 p = b.transform().apply(m_grab->localPoint);
        const double h = m_world.def().dt;
        const double w = std::min(2.0 * std::numbers::pi * kGrabFrequency, 0.5 / h);
        const physics::Vec2 f =
            b.mass * (w * w * (m_grab->target - p) - 2.0 * w * b.pointVelocity(p));
        input = UserInput{m_grab->body, f, physics::cross(physics::Vec2(p - b.position), f)};
        if (replaying) {
            m_history.branchAt(m_world); // a new push makes a new future
            dropEditsAfterNow();
        }
    } else if (replaying) {
        if (const UserInput* logged = m_history.inputFor(step))
            input = *logged;
    }
    m_previousPoses.resize(m_world.bodies().size());
    for (std::size_t i = 0; i < m_world.bodies().size(); ++i)
        m_previousPoses[i] = {m_world.bodies()[i].origin(), m_world.bodies()[i].angle};
    if (input)
        applyInput(m_world, *input);
    m_world.step();
    for (physics::World& w : m_variants)
        w.step();
    m_history.recorded(m_world, input ? &*input : nullptr);
    m_measurements.observe(m_world);
    ++m_stepsThisSecond;
    pushSample();
}

void SimulationController::pushSample()
{
    // Taken when due as the lesson export takes them (step_sampler.h: SampleClock).
    if (!m_sampleClock.due(stepTime(m_world)))
        return;
    // Variant 0 is the main world; the others follow in order (step_sampler.h, as the
    // lesson export samples).
    m_samples.push(makeSample(m_world, m_energyReference, m_variants, m_variantReferences,
                              !m_variantLabels.isEmpty()));
}

void SimulationController::advanceFrame()
{
    QElapsedTimer physicsClock;
    physicsClock.start();
    // Nanoseconds: restart() would round to whole milliseconds and lose ~3% of the time.
    const double unclampedWall = m_wall.nsecsElapsed() * 1e-9;
    const double wall = std::min(unclampedWall, kMaxFrameSeconds);
    m_wall.start();
    const double h = m_world.def().dt;
    // A frame longer than kMaxFrameSeconds (the window was busy) loses the rest of its time:
    // the run fell behind real time, and says so.
    bool slow = unclampedWall > kMaxFrameSeconds;
    if (m_running && !m_stepsHeld) {
        m_accumulator += wall * m_timeScale;
        while (m_accumulator >= h) {
            if (physicsClock.nsecsElapsed() * 1e-6 > kPhysicsBudgetMs) {
                slow = true;
                m_accumulator = 0.0; // drop what cannot be done in time
                break;
            }
            doStep();
            m_accumulator -= h;
            m_simulatedThisSecond += h;
        }
    }
    m_physicsMs = physicsClock.nsecsElapsed() * 1e-6;
    m_frameMs = wall * 1e3;
    if (m_measureFrames > 0) {
        m_measuredFrameMs.push_back(unclampedWall * 1e3);
        m_measuredPhysicsMs.push_back(m_physicsMs);
        if (--m_measureFrames == 0)
            emit framesMeasured(m_measuredFrameMs, m_measuredPhysicsMs);
    }
    m_slow = slow;
    if (m_rateClock.elapsed() >= 1000) {
        const double seconds = static_cast<double>(m_rateClock.nsecsElapsed()) * 1e-9;
        m_rateClock.restart();
        m_stepsPerSecond = static_cast<double>(m_stepsThisSecond) / seconds;
        m_realTimeFactor = m_simulatedThisSecond / seconds;
        m_stepsThisSecond = 0;
        m_simulatedThisSecond = 0.0;
    }
    emit worldChanged();
    emit frameAdvanced();
}

void SimulationController::measureFrames(int frames)
{
    m_measureFrames = frames;
    m_measuredFrameMs.clear();
    m_measuredPhysicsMs.clear();
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
    // and replay from their start, deterministically.
    for (std::size_t i = 0; i < m_variants.size(); ++i) {
        physics::World w = m_variantStarts[i];
        w.setDt(m_world.def().dt);
        while (w.stepCount() < step)
            w.step();
        w.updateDiagnostics();
        m_variants[i] = std::move(w);
    }
    m_measurements.rewind(m_world);
    m_previousPoses.clear();
    m_sampleClock.rewound(stepTime(m_world)); // sample again from here on
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

void SimulationController::dropEditsAfterNow()
{
    const long long now = m_world.stepCount();
    std::erase_if(m_edits, [now](const SettingEdit& e) { return e.step > now; });
}

void SimulationController::logEdit(SettingEdit edit)
{
    dropEditsAfterNow();
    edit.step = m_world.stepCount();
    m_edits.push_back(edit);
}

void SimulationController::applyEdit(const SettingEdit& edit)
{
    using Kind = SettingEdit::Kind;
    switch (edit.kind) {
    case Kind::Dt:
        return setDt(edit.value);
    case Kind::Integrator:
        return setIntegrator(static_cast<physics::IntegratorKind>(edit.number));
    case Kind::Solver:
        return setSolver(static_cast<physics::SolverKind>(edit.number));
    case Kind::Iterations:
        return setIterations(edit.number);
    case Kind::Restitution:
        return setRestitution(edit.value);
    case Kind::Friction:
        return setFriction(edit.value);
    case Kind::Gravity:
        return setGravityEnabled(edit.number != 0);
    case Kind::BodyMaterial:
        return setBodyMaterial(edit.body, edit.value, edit.value2);
    case Kind::BodyMass:
        return setBodyMass(edit.body, edit.value);
    case Kind::BodyRotation:
        return rotateBody(edit.body, edit.value);
    }
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
    if (!(dt >= lessons::kMinDt && dt <= lessons::kMaxDt) || dt == m_world.def().dt)
        return;
    logEdit({0, SettingEdit::Kind::Dt, -1, dt, 0.0, 0});
    forEachWorld([dt](physics::World& w) { w.setDt(dt); });
    afterEdit(tr("dt = %1 s").arg(markNumber(dt)));
}

void SimulationController::setIntegrator(physics::IntegratorKind kind)
{
    if (kind == m_world.def().integrator)
        return;
    logEdit({0, SettingEdit::Kind::Integrator, -1, 0.0, 0.0, static_cast<int>(kind)});
    m_world.setIntegrator(kind);
    afterEdit(integratorDisplayName(kind));
}

void SimulationController::setSolver(physics::SolverKind kind)
{
    if (kind == m_world.def().solver)
        return;
    logEdit({0, SettingEdit::Kind::Solver, -1, 0.0, 0.0, static_cast<int>(kind)});
    m_world.setSolver(kind);
    afterEdit(solverDisplayName(kind));
}

void SimulationController::setIterations(int iterations)
{
    if (iterations == m_world.def().iterations || iterations < 1 ||
        iterations > lessons::kMaxIterations)
        return;
    logEdit({0, SettingEdit::Kind::Iterations, -1, 0.0, 0.0, iterations});
    m_world.setIterations(iterations);
    afterEdit(tr("%n iteration(s)", nullptr, iterations));
}

void SimulationController::setRestitution(double e)
{
    if (!lessons::limits::kRestitution.contains(e))
        return;
    logEdit({0, SettingEdit::Kind::Restitution, -1, e, 0.0, 0});
    forEachWorld([e](physics::World& w) { w.setRestitution(e); });
    afterEdit(tr("e = %1").arg(markNumber(e)));
}

void SimulationController::setFriction(double mu)
{
    if (!lessons::limits::kFriction.contains(mu))
        return;
    logEdit({0, SettingEdit::Kind::Friction, -1, mu, 0.0, 0});
    forEachWorld([mu](physics::World& w) { w.setFriction(mu); });
    afterEdit(tr("μ = %1").arg(markNumber(mu)));
}

void SimulationController::setGravityEnabled(bool on)
{
    const physics::Vec2 g = on ? m_sceneGravity : physics::Vec2::Zero();
    if (g == m_world.def().gravity)
        return;
    logEdit({0, SettingEdit::Kind::Gravity, -1, 0.0, 0.0, on ? 1 : 0});
    forEachWorld([&g](physics::World& w) { w.setGravity(g); });
    afterEdit(on ? tr("gravity on") : tr("gravity off"));
}

void SimulationController::setBodyMaterial(physics::BodyId id, double restitution, double friction)
{
    if (id < 0 || id >= static_cast<physics::BodyId>(m_world.bodies().size()))
        return;
    if (!lessons::limits::kRestitution.contains(restitution) ||
        !lessons::limits::kFriction.contains(friction))
        return;
    logEdit({0, SettingEdit::Kind::BodyMaterial, id, restitution, friction, 0});
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
    logEdit({0, SettingEdit::Kind::BodyMass, id, mass, 0.0, 0});
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
    logEdit({0, SettingEdit::Kind::BodyRotation, id, radians, 0.0, 0});
    m_world.setBodyAngle(id, angle); // about the centre of mass; wakes the body
    afterEdit(QString());
}

void SimulationController::grab(physics::BodyId id, const physics::Vec2& worldPoint)
{
    if (id < 0 || id >= static_cast<physics::BodyId>(m_world.bodies().size()) ||
        !m_world.body(id).isDynamic())
        return;
    m_grab = Grab{id, m_world.body(id).transform().applyInverse(worldPoint), worldPoint};
}

void SimulationController::dragTo(const physics::Vec2& worldPoint)
{
    if (m_grab)
        m_grab->target = worldPoint;
}

void SimulationController::release()
{
    m_grab.reset();
}

bool SimulationController::grabLine(physics::Vec2& from, physics::Vec2& to) const
{
    if (!m_grab)
        return false;
    from = m_world.body(m_grab->body).transform().apply(m_grab->localPoint);
    to = m_grab->target;
    return true;
}

} // namespace rigidlab::ui
