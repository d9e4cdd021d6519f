// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Where a few labels go on the scene, each beside its own body: inside the view (a label cut
// at the view's edge cannot be read) and never over another label (two bodies close together
// would write one name over the other).

#include <QRect>
#include <QSize>

#include <vector>

namespace rigidlab::ui {

struct LabelWish {
    QSize size; ///< the label's box [px]
    QRect body; ///< the body it names, in the view [px]
};

/// The labels' boxes, in the order of `wishes`, inside `area` [px]. Each goes centred above
/// its body if it can; where that box would meet a box in `taken` or a label placed before
/// it, the next place is tried: below the body, then a row higher above it, a row lower below
/// it, and so on. Kept inside `area` (slid along its edge), so a label over a body near the
/// edge sits a little to the side. When no place is free, the first one is used.
std::vector<QRect> placeLabels(const std::vector<LabelWish>& wishes, const QRect& area,
                               std::vector<QRect> taken = {});

} // namespace rigidlab::ui
