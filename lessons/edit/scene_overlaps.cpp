// SPDX-License-Identifier: GPL-3.0-or-later
// Bodies that overlap as the editor placed them: the scene runs, but the contacts push them
// apart at once, which a teacher should know before the class sees it.

#include "format/scene_overlaps.h"
#include "edit/edit_support.h"

#include <QStringList>

#include <algorithm>

namespace rigidlab::lessons::edit {

using namespace support;
using physics::BodyId;

std::vector<std::pair<BodyId, BodyId>> overlappingPairs(const Scene& scene)
{
    // Bounded (format/scene_overlaps.h): a heap of duplicates lists its first pairs.
    auto pairs = surveyOverlaps(scene, kMaxListedOverlaps).pairs;
    std::sort(pairs.begin(), pairs.end());
    return pairs;
}

QString overlapMessage(const Scene& scene)
{
    const auto pairs = overlappingPairs(scene);
    if (pairs.empty()) {
        return {};
    }
    QStringList names;
    for (const auto& [a, b] : pairs) {
        names << EditMessages::tr("%1 overlaps %2")
                     .arg(bodyId(scene.bodies[static_cast<size_t>(a)]),
                          bodyId(scene.bodies[static_cast<size_t>(b)]));
    }
    return EditMessages::tr("%1; overlapping bodies are pushed apart when the scene runs")
        .arg(names.join(QStringLiteral(", ")));
}

} // namespace rigidlab::lessons::edit
