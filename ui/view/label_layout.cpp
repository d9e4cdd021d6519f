// SPDX-License-Identifier: GPL-3.0-or-later
#include "view/label_layout.h"

#include <algorithm>

namespace rigidlab::ui {

namespace {

/// The gap between a label and its body, and between two labels stacked [px].
constexpr int kGapPx = 4;
/// How many rows above and below its body a label may move to make room.
constexpr int kMostRows = 4;

/// `box` moved the least to lie inside `area` (its top-left corner when it is too big).
QRect inside(QRect box, const QRect& area)
{
    box.moveLeft(
        std::clamp(box.left(), area.left(), std::max(area.left(), area.right() - box.width() + 1)));
    box.moveTop(
        std::clamp(box.top(), area.top(), std::max(area.top(), area.bottom() - box.height() + 1)));
    return box;
}

/// The places tried for a label, best first: above, below, then rows further out.
std::vector<QRect> candidates(const LabelWish& wish, const QRect& area)
{
    std::vector<QRect> places;
    const int row = wish.size.height() + kGapPx;
    for (int k = 0; k < kMostRows; ++k) {
        QRect above(QPoint(0, 0), wish.size);
        above.moveCenter(QPoint(wish.body.center().x(), 0));
        QRect below = above;
        above.moveBottom(wish.body.top() - kGapPx - k * row);
        below.moveTop(wish.body.bottom() + kGapPx + k * row);
        places.push_back(inside(above, area));
        places.push_back(inside(below, area));
    }
    return places;
}

} // namespace

std::vector<QRect> placeLabels(const std::vector<LabelWish>& wishes, const QRect& area,
                               std::vector<QRect> taken)
{
    std::vector<QRect> placed;
    placed.reserve(wishes.size());
    for (const LabelWish& wish : wishes) {
        const std::vector<QRect> places = candidates(wish, area);
        const auto free = std::find_if(places.begin(), places.end(), [&](const QRect& box) {
            return std::none_of(taken.begin(), taken.end(),
                                [&](const QRect& t) { return t.intersects(box); });
        });
        const QRect box = free != places.end() ? *free : places.front();
        placed.push_back(box);
        taken.push_back(box);
    }
    return placed;
}

} // namespace rigidlab::ui
