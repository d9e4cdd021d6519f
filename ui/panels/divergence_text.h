// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The window's words for a divergence (physics::Divergence is data only): translated with
// tr(), numbers in the user's locale. The command line has its own English line
// (lessons/divergence_message.h).

#include "rigidlab/physics/divergence.h"

#include <QString>

namespace rigidlab::ui {

/// What went wrong, as a clause: "the total energy grew from 0.5 J to 1e+06 J, past the bound
/// of 1e+06 J (body “puck” holds the most kinetic energy)". `bodyLabel` names the body as the
/// scene labels it (lessons::Scene::bodyLabel); empty, the body's id is named.
QString divergenceReason(const physics::Divergence& d, const QString& bodyLabel = {});

/// The banner's sentence: when (time, step, dt, integrator), what went wrong, and that the
/// run stopped there.
QString divergenceSentence(const physics::Divergence& d, const QString& bodyLabel = {});

/// Why, in a few words for a legend read from the back of a room: "energy blew up".
QString divergenceShort(const physics::Divergence& d);

/// Short, for a label beside a stopped world: "stopped at t = 0.045 s: the total energy ...".
QString divergenceLabel(const physics::Divergence& d, const QString& bodyLabel = {});

} // namespace rigidlab::ui
