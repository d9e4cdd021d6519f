// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Private: the stages of a step (profile.h's Stage), as free functions of the step's context
// (step_context.h). World::step() calls them in order; each reads the context and writes the
// world's parts it names. A stage's plain path is in stages/, its acceleration (where it has
// one) in fast/, chosen by StepContext::plain.

#include "step_context.h"

#include <utility>
#include <vector>

namespace rigidlab::physics {

/// What this step needs, from what the world holds (step_plan.cpp).
StepPlan planStep(const WorldDef& def, const std::vector<Body>& bodies,
                  const std::vector<SpringDef>& springs, const std::vector<PinJointDef>& joints,
                  const std::vector<std::pair<int, int>>& jointPairs, bool plain);

/// Each body's placement for the step, StepScratch::xf. Plain: every body's anew
/// (step_plan.cpp); fast: only the bodies that moved (fast/body_placement.cpp).
void placeBodies(StepContext& ctx);
void placeMovedBodies(StepContext& ctx);

/// The velocities at the start of the step, to time bounces within it (contact_response.cpp).
void rememberStartVelocities(StepContext& ctx);

/// Stage::BroadPhase and Stage::NarrowPhase: the contacts where the shapes stand now
/// (broad_phase.cpp, continuous.cpp, narrow_phase.cpp).
void findContacts(StepContext& ctx);
/// The speculative margin each fast body's motion asks for [m] (StepContext::sweep): for the
/// broad phase's boxes and the narrow phase's pairs (continuous.cpp).
void findSweeps(StepContext& ctx);

/// Stage::Islands: groups touching bodies; an island with an awake body wakes whole
/// (islands.cpp).
void wakeIslands(StepContext& ctx);

/// Stage::Forces and Stage::Integration: the integrator over the ODE state (integration.cpp),
/// or with StepPlan::direct symplectic Euler straight on the bodies
/// (fast/integrate_direct.cpp).
void integrate(StepContext& ctx);
void integrateDirect(StepContext& ctx);

/// The joints a contact of this step touches (one of its bodies is an end), and every joint
/// that shares a body with one of them, into StepScratch::touchedJoints; whether there are any
/// (contact_response.cpp). The contact solvers solve these with the contacts.
bool touchedJoints(StepContext& ctx);

/// Stage::ContactSolve: impulses on the new velocities, then position correction
/// (contact_response.cpp, contact_solver.cpp).
void solveContacts(StepContext& ctx);

/// Stage::Forces, Stage::Integration and Stage::ContactSolve together, in substeps: the soft
/// step (soft_step.cpp, soft_solver.cpp).
void softStep(StepContext& ctx);

/// How the bodies of an isolated impact fly within the step, from StepScratch::xfPosition and
/// velocityAtStart: by the soft step's constant forces (soft_step.cpp, symplectic Euler);
/// to where the integrator has already moved them (the impulse solvers, contact_response.cpp);
/// or to where the integrator ended the soft step's smooth motion (StepScratch::smoothEnd).
enum class Flown { ByForces, ToBodies, ToSmoothEnd };

/// Whether `ct` is an impact faster than `threshold` [m/s] within the step that can be solved
/// exactly: no impulse carried from the step before, the bodies touching within the step flown
/// freely. The caller checks that neither moving body has another contact (soft_impacts.cpp).
bool isolatedImpact(StepContext& ctx, const Contact& ct, double threshold, Flown flown,
                    IsolatedImpact& out);
/// The isolated impacts of this step: contacts whose moving bodies have no other contact and
/// no pin, each solved exactly at its moment of impact (soft_impacts.cpp). Fills
/// StepScratch::impacts and StepScratch::isolated; returns whether there are any.
bool findIsolatedImpacts(StepContext& ctx, double threshold, Flown flown);
/// The same search, bit for bit, with less memory traffic (fast/isolated_pairs.cpp).
bool findIsolatedImpactsFast(StepContext& ctx, double threshold, Flown flown);
/// StepScratch::contactsOf for this step's contacts and pins (a pin counts as two contacts);
/// `pairs`, when given, gets each contact's two bodies.
void countContactsOf(StepContext& ctx, std::vector<std::pair<int, int>>* pairs);

/// Distance from the body's centre of mass to its shape's farthest point [m] (continuous.cpp).
double outerRadius(const Body& b);
/// The body's smallest width: what it must not jump past in a step [m] (continuous.cpp).
double ownSize(const Body& b);
/// Each body's outerRadius() and ownSize(), at the body's index: StepScratch::extent, computed
/// for the bodies added since it was last asked for (continuous.cpp).
const std::vector<BodyExtent>& bodyExtents(StepContext& ctx);

/// Continuous collision after every solver: each body that moved more than its own size put
/// back where its motion in the step first comes within the slop of a body that does not move
/// (soft_continuous.cpp).
void sweepBackBullets(StepContext& ctx);

/// Stage::Sleep: islands that have rested long enough (islands.cpp).
void sleepIslands(StepContext& ctx);

} // namespace rigidlab::physics
