// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The rules of a scene that are more than a range (limits.h holds those), with their messages:
// shared by the loader, which reads a scene from a file, and the editor, which builds one by
// hand (lessons/edit/), so that both refuse the same things in the same words.

#include "rigidlab/physics/body.h"

#include <QString>

#include <optional>

namespace rigidlab::lessons::rules {

/// What is wrong with a body's mass, and under which key of the body it is reported.
struct MassProblem {
    QString key; ///< "shape" or "density"
    QString what;
};
/// A shape too large or too small to have a finite area and inertia, or a mass (given, or
/// density times area) outside limits::kMass.
std::optional<MassProblem> checkMass(const physics::BodyDef& def);

/// Empty, or why `id` cannot name a body (empty, too long, control characters).
QString idProblem(const QString& id);
/// "duplicate id "ID" (bodies[N] has it already)".
QString duplicateId(const QString& id, int otherIndex);
/// "a polygon needs 3 to 64 vertices, got N".
QString polygonVertexCount(qsizetype count);
/// A spring with both ends fixed in the world.
QString springBothInWorld();
/// A spring whose two ends are the same body.
QString springSameBody();
/// A pin whose two ends are the same body.
QString pinSameBody();
/// Empty, or why `text` is not a body's colour "#rrggbb" (six hexadecimal digits, either case).
QString colourProblem(const QString& text);

} // namespace rigidlab::lessons::rules
