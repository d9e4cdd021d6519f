// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The world: owns the bodies, the force elements and the contacts, and steps them.

#include "rigidlab/physics/body.h"
#include "rigidlab/physics/contact.h"
#include "rigidlab/physics/diagnostics.h"
#include "rigidlab/physics/divergence.h"
#include "rigidlab/physics/forces.h"
#include "rigidlab/physics/integrator.h"
#include "rigidlab/physics/profile.h"
#include "rigidlab/physics/settings.h"
#include "rigidlab/physics/value_ptr.h"

#include <memory>
#include <optional>
#include <utility>
#include <vector>

namespace rigidlab::physics {

// Private (physics/src/stages/step_context.h): the buffers a step reuses, and its context.
struct StepScratch;
struct StepContext;
// Private (physics/src/stages/narrow_phase.h): what the soft step keeps of a contact's manifold
// to recycle it.
struct ContactAnchors;

class World {
public:
    explicit World(const WorldDef& def = {});
    // All defaulted (in world.cpp, where StepScratch is complete). A copy steps on bit for bit
    // as the original: it carries the integrator's state (ClonePtr) and starts with empty
    // buffers (FreshOnCopy), which hold no state.
    ~World();
    World(const World& other);
    World& operator=(const World& other);
    World(World&& other) noexcept;
    World& operator=(World&& other) noexcept;

    /// Adds a body; mass, centre of mass and inertia come from the shape and density
    /// (or the given mass). Returns its id, its index in bodies().
    BodyId addBody(const BodyDef& def);
    void addSpring(const SpringDef& spring);
    void addPinJoint(const PinJointDef& joint);

    /// Advances the world by one fixed step dt, through the stages in the order of
    /// physics::Stage (profile.h), which says what each does and in which file.
    void step();

    // Settings, changeable between steps. Each setter asserts its argument is inside its
    // range of limits.h (the caller checks it first, and tells the user).
    const WorldDef& def() const { return m_def; }
    void setDt(double dt);
    void setIntegrator(IntegratorKind kind);
    void setSolver(SolverKind kind) { m_def.solver = kind; }
    void setIterations(int n);
    // A change of gravity, restitution or friction wakes every body.
    void setGravity(const Vec2& g);
    void setTolerances(const Tolerances& tolerances);
    /// Sets the default coefficient of restitution and gives it to every body.
    void setRestitution(double e);
    /// Sets the default friction coefficient and gives it to every body.
    void setFriction(double mu);
    ContactSettings& contactSettings() { return m_contactSettings; }
    const ContactSettings& contactSettings() const { return m_contactSettings; }
    DivergenceSettings& divergenceSettings() { return m_divergenceSettings; }
    /// How the engine computes (the plain paths or the fast ones): the same bits either way.
    EngineSettings& engineSettings() { return m_engineSettings; }
    const EngineSettings& engineSettings() const { return m_engineSettings; }
    /// The integrator in use (its error estimate, its substeps).
    const Integrator& integrator() const { return *m_integrator; }

    /// Set when a step diverged (divergence.cpp), or its bodies crowded past the step's work
    /// budget (work_budget.h): step() then does nothing more.
    const std::optional<Divergence>& divergence() const { return m_divergence; }

    // State.
    const std::vector<Body>& bodies() const { return m_bodies; }
    const Body& body(BodyId id) const { return m_bodies[static_cast<size_t>(id)]; }
    /// A body to change field by field: for the engine's own stages and for tests that set up
    /// a state no setter reaches (an infinite force). The window and the lessons change bodies
    /// only through the setters below, which check their values and wake the body.
    Body& mutableBody(BodyId id) { return m_bodies[static_cast<size_t>(id)]; }
    const std::vector<SpringDef>& springs() const { return m_springs; }
    const std::vector<PinJointDef>& joints() const { return m_joints; }
    const std::vector<Contact>& contacts() const { return m_contacts; }
    /// Sets a body's pose from its origin (as a scene gives it).
    void setBodyOrigin(BodyId id, const Vec2& origin, double angle);
    /// Sets the velocity of a body's origin point [m/s] and its angular velocity [rad/s].
    void setBodyVelocity(BodyId id, const Vec2& originVelocity, double angularVelocity);
    /// Velocity of the body origin [m/s].
    Vec2 originVelocity(BodyId id) const;
    /// Gives a dynamic body the mass `mass` [kg] (> 0, finite). Its shape keeps its density
    /// distribution, so the inertia about the centre of mass scales by the same factor; the
    /// velocities stay (momentum and energy change with the mass). Wakes the body. Returns
    /// false, changing nothing, for another kind of body or an invalid mass.
    bool setBodyMass(BodyId id, double mass);
    /// Gives a body the restitution and friction coefficients (limits.h). Wakes it.
    void setBodyMaterial(BodyId id, double restitution, double friction);
    /// Turns a moving body to `angle` [rad] about its centre of mass. Wakes it.
    void setBodyAngle(BodyId id, double angle);
    /// Adds to a body's force and torque accumulators for the next step (the paper's
    /// accumulators: cleared after every step), e.g. the user's pull. Wakes it.
    void applyForce(BodyId id, const Vec2& force, double torque);

    double time() const { return m_time; }
    long long stepCount() const { return m_steps; }
    /// Force evaluations so far (integrator stages).
    long long evaluations() const { return m_evaluations; }
    /// The energies, momenta and losses of the current state, and its touching contact points
    /// (Diagnostics::contacts, counted when first asked for after a step: the step itself
    /// reads only the energies, and a pile of 5,050 boxes took 2.6 % of its step to count them).
    const Diagnostics& diagnostics() const;
    /// Recomputes the diagnostics for the current state (done by step() already).
    void updateDiagnostics();

    /// What the last step cost, stage by stage, and which stages it left out (profile.h).
    const StepProfile& profile() const { return m_profile; }

    // Sleeping (islands.cpp): resting islands of bodies are left out of integration and the
    // contact solver until something wakes them.
    /// Whether resting bodies go to sleep now: WorldDef::sleep, or unset, the scene's size.
    bool sleepEnabled() const;
    void setSleep(std::optional<bool> on);
    /// Wakes a body (and, at the next step, its island): the window calls it when the user
    /// grabs a body. Setting a body's pose or velocity wakes it too.
    void wakeBody(BodyId id);

    // The equations of motion alone, for integrating outside step() (reference solutions,
    // another ODE library): the state as the integrators see it, q = (x, y, angle) of the
    // centre of mass of every moving body in id order and v = (vx, vy, omega), and
    // a(t, q, v) from the applied forces and the exact joint forces, without contacts
    // (world_ode.cpp). The equations refer to this world: they live as long as it does.
    void getState(Eigen::VectorXd& q, Eigen::VectorXd& v) const;
    void setState(const Eigen::VectorXd& q, const Eigen::VectorXd& v);
    std::unique_ptr<OdeSystem> equations() const;

private:
    /// The step's context: its numbers, its plan and the world's parts (stages/step_context.h).
    StepContext context();
    void wakeAll();
    void rememberStartEnergy();
    void checkDivergence();
    /// Whether this step's broad phase stopped at the work budget (work_budget.h); then the
    /// world is stopped with that diagnosis (work_budget.cpp).
    bool stopWhenCrowded();

    WorldDef m_def;
    ContactSettings m_contactSettings;
    EngineSettings m_engineSettings;
    std::vector<Body> m_bodies;
    std::vector<SpringDef> m_springs;
    std::vector<PinJointDef> m_joints;
    std::vector<Contact> m_contacts;
    /// Beside each contact, at the same index: its manifold's anchors on the bodies, for
    /// recycling it (state: a copy steps on with them as the original does).
    std::vector<ContactAnchors> m_contactAnchors;
    ClonePtr<Integrator> m_integrator;
    std::vector<BodyId> m_moving; ///< bodies in the integrated state, in id order
    std::vector<int> m_slot;      ///< each body's index in m_moving, -1 for static bodies
    std::vector<std::pair<int, int>> m_jointPairs; ///< body pairs joined by a pin, sorted
    FreshOnCopy<StepScratch> m_scratch; ///< buffers reused from step to step (step_context.h)
    double m_time = 0;
    long long m_steps = 0;
    long long m_evaluations = 0;
    double m_collisionLoss = 0; ///< see Diagnostics [J]
    double m_dragLoss = 0;      ///< see Diagnostics [J]
    double m_dampingLoss = 0;   ///< see Diagnostics [J]
    /// The last diagnostics; their count of touching points is filled in by diagnostics() when
    /// m_touchingCounted is false (a cache of a function of m_contacts, hence mutable: a copy
    /// counts the same contacts).
    mutable Diagnostics m_diagnostics;
    mutable bool m_touchingCounted = false;
    DivergenceSettings m_divergenceSettings;
    std::optional<Divergence> m_divergence;
    std::optional<double> m_energyStart; ///< total energy before the first step [J]
    double m_energyScale = 0;            ///< see DivergenceSettings::energyGrowth [J]
    std::vector<double> m_sweep;         ///< per body: extra contact margin this step [m]
    StepProfile m_profile;               ///< the last step's
};

} // namespace rigidlab::physics
