// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The window's words for a divergence: the lab's one message (lessons/format/
// divergence_message.h), translated, with numbers in the user's locale, framed for the banner,
// a legend and a label beside a stopped world.

#include "rigidlab/physics/divergence.h"

#include <QString>

namespace rigidlab::ui {

/// What went wrong, as a clause (lessons::divergenceReason in the user's locale). `bodyLabel`
/// names the body as the scene labels it (lessons::Scene::bodyLabel); empty, by its id.
QString divergenceReason(const physics::Divergence& d, const QString& bodyLabel = {});

/// The banner's sentence: the message (when, what went wrong), and that the run stopped there.
QString divergenceSentence(const physics::Divergence& d, const QString& bodyLabel = {});

/// Why, in a few words for a legend read from the back of a room: "energy blew up".
QString divergenceShort(const physics::Divergence& d);

/// Short, for a label beside a stopped world: "stopped at t = 0.045 s: the total energy ...".
QString divergenceLabel(const physics::Divergence& d, const QString& bodyLabel = {});

} // namespace rigidlab::ui
