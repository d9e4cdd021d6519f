// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The state of the separating-axis walk-through, read by both of its faces: the SAT panel's
// table (ui/panels) and the overlay drawn in the world view (ui/view). The panel changes it
// (a new pair, the next axis); the overlay only reads it, so the view needs no widget.

#include "rigidlab/physics/sat.h"

#include <array>
#include <vector>

namespace rigidlab::ui {

class RunView;

class SatViewModel {
public:
    explicit SatViewModel(const RunView& run) : m_run(run) {}

    /// The two bodies to test (ids), or -1 for none; anything but two polygons is none.
    /// Starts again at the first axis.
    void setBodies(int a, int b);
    void nextAxis();
    void previousAxis();
    /// Every axis, up to the verdict (and again after each refresh, until a step back).
    void showAll();
    /// Whether the pair, a pose or a shape of it differs from the world's since the last
    /// refresh (the test then would give another result).
    bool outOfDate() const { return m_tested != testedNow(); }
    /// Tests the pair again in the world as it is now, where outOfDate() (the separating-axis
    /// test is not made again for a pair that did not move). Returns whether it was out of
    /// date.
    bool refresh();

    bool active() const { return m_a >= 0 && m_b >= 0; }
    int bodyA() const { return m_a; }
    int bodyB() const { return m_b; }
    /// How many of the tested axes are shown (the step the student is at).
    int shown() const { return m_shown; }
    /// Whether the last axis has been reached (the verdict is shown).
    bool complete() const { return m_shown == static_cast<int>(m_result.axes.size()); }
    const physics::SatResult& result() const { return m_result; }
    const RunView& run() const { return m_run; }

private:
    /// `m_shown` within the axes tested (all of them after showAll()).
    void settle();

    /// What a test was made of: the pair, its poses (x, y [m], angle [rad], A then B) and its
    /// outlines; an inactive pair has none.
    struct Tested {
        int a = -1, b = -1;
        std::array<double, 6> poses{};
        std::vector<physics::Vec2> outlineA, outlineB;
        bool operator==(const Tested&) const = default;
    };
    /// The pair in the world as it is now; inactive when either is not a polygon (any more).
    Tested testedNow() const;

    const RunView& m_run;
    int m_a = -1, m_b = -1;
    int m_shown = 0; ///< none before a pair is set
    bool m_all = false;
    physics::SatResult m_result;
    Tested m_tested; ///< at the last refresh
};

} // namespace rigidlab::ui
