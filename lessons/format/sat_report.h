// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The separating axis test as data: reads polygon pairs from JSON, runs physics::satPolygons
// on each and reports every axis it tested (for `rigidlab-cli sat` and the SAT lesson).
//
// Input: a pair {"a": POLY, "b": POLY}, or an array of pairs, where
//   POLY = {"vertices": [[x, y], ...], "position": [x, y], "angle": a}
// (vertices body-local [m]; position [m] and angle [rad] default to 0).
//
// Output, per pair (an array of them, in order, for an array input):
//   {"intersects": bool,
//    "axes": [{"owner": "a"|"b", "edge": i, "axis": [x, y], "a": [min, max], "b": [min, max],
//              "overlap": o}, ...],             // in the order tested; stops at a separating one
//    "separatingAxis": index | null,            // into axes
//    "leastAxis": index | null,                 // axis of least penetration, when intersecting
//    "normal": [x, y] | null, "depth": d | null, // from a to b, when intersecting
//    "contacts": [[x, y], ...]}                 // manifold points, when intersecting

#include "rigidlab/physics/sat.h"

#include <QByteArray>
#include <QJsonObject>
#include <QString>
#include <QStringList>

namespace rigidlab::lessons {

inline constexpr int kMaxSatPairs = 10000;

struct SatReport {
    bool ok = false;
    QString error;        ///< one line when !ok: `FILE: PLACE: what is wrong`
    QStringList warnings; ///< for example a non-convex polygon replaced by its hull
    QByteArray json;      ///< the report, indented JSON, when ok
};

SatReport satReportFile(const QString& path);
SatReport satReportJson(const QByteArray& bytes, const QString& sourceName);

/// One SAT result in the output form above.
QJsonObject satResultToJson(const physics::SatResult& result);

} // namespace rigidlab::lessons
