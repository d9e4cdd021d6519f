// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The state of the separating-axis walk-through, read by both of its faces: the SAT panel's
// table (ui/panels) and the overlay drawn in the world view (ui/view). The panel changes it
// (a new pair, the next axis); the overlay only reads it, so the view needs no widget.

#include "rigidlab/physics/sat.h"

#include <array>

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
    /// Tests the pair again in the world as it is now. Returns whether either body moved or
    /// turned since the last refresh.
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

    const RunView& m_run;
    int m_a = -1, m_b = -1;
    int m_shown = 1;
    bool m_all = false;
    physics::SatResult m_result;
    /// The pair's poses at the last refresh: x, y [m], angle [rad], for A then B.
    std::array<double, 6> m_poses{};
};

} // namespace rigidlab::ui
