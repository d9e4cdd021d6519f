// SPDX-License-Identifier: GPL-3.0-or-later
// The step's work budget (work_budget.h): the broad phase counts its pairs as it finds them
// and stops past pairBudget(); the world then stops with a diagnosis, before the contacts,
// the solver and the integrator would work on pairs in the square of the bodies. The world
// is left as it was at the start of the step, so what the user sees is the crowded start.

#include "rigidlab/physics/work_budget.h"
#include "rigidlab/physics/touching.h"
#include "rigidlab/physics/world.h"

#include "step_context.h"

namespace rigidlab::physics {

bool World::stopWhenCrowded()
{
    const std::optional<Crowding>& crowding = m_scratch->broadPhase.crowding();
    if (!crowding)
        return false;
    Divergence d;
    d.kind = Divergence::Kind::Crowded;
    d.quantity = Divergence::Quantity::BodyPairs;
    d.body = static_cast<BodyId>(crowding->body);
    d.bodyName = m_bodies[static_cast<size_t>(crowding->body)].name;
    d.value = static_cast<double>(crowding->pairs);
    d.bound = static_cast<double>(crowding->fat ? kFatPairsPerPair * pairBudget(m_bodies.size())
                                                : pairBudget(m_bodies.size()));
    d.time = m_time;
    d.step = m_steps;
    d.dt = m_def.dt;
    d.integrator = m_def.integrator;
    d.start = m_diagnostics.total;
    // The diagnostics stay the start's, its touching points too: counted (diagnostics()) from
    // the contacts the step started with, before they go.
    if (!m_touchingCounted) {
        m_diagnostics.contacts = touchingPoints(m_scratch->previous);
        m_touchingCounted = true;
    }
    m_contacts.clear();
    m_contactAnchors.clear();
    m_profile.pairs = 0;
    m_divergence = d;
    return true;
}

} // namespace rigidlab::physics
