// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The hand-over between the simulation and the plots. The controller pushes one sample per
// recorded step; each plot drains what is new on its own timer (about 30 Hz). The buffer
// is a bounded ring: memory stays the same however long the run, and a reader that fell
// more than the capacity behind just loses the oldest samples.

#include <QtGlobal>

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace rigidlab::ui {

/// What the plots show, for one moment of the run.
struct Sample {
    double t = 0;               ///< simulated time [s]
    double kinetic = 0;         ///< [J]
    double potential = 0;       ///< [J]
    double total = 0;           ///< [J]
    double px = 0, py = 0;      ///< linear momentum [kg m/s]
    double angularMomentum = 0; ///< about the origin [kg m^2/s]
    /// Energy taken since the start by contacts (bounces, friction), drag and dampers [J].
    double dissipated = 0;
    /// The numerical error: (total + dissipated - total at start) / |total at start| * 100 [%]
    double driftPercent = 0;
    // What the quantities are worth in the scene: a plot draws a variation below a billionth
    // of that as flat (plot_range.h). 0 when unknown.
    double energyScale = 0;          ///< |E0|, or K + |P| at the start [J]
    double momentumScale = 0;        ///< [kg m/s]
    double angularMomentumScale = 0; ///< [kg m^2/s]
    /// Worlds compared side by side (a lesson step): their total energy and drift, variant 0
    /// being the main world. `variants` says how many are in use.
    static constexpr int kMaxVariants = 6;
    int variants = 0;
    std::array<double, kMaxVariants> variantTotal{};        ///< [J]
    std::array<double, kMaxVariants> variantDriftPercent{}; ///< [%]
};

class SampleBuffer {
public:
    explicit SampleBuffer(std::size_t capacity = 8192) : m_ring(capacity) {}

    void push(const Sample& s)
    {
        m_ring[static_cast<std::size_t>(m_written % m_ring.size())] = s;
        ++m_written;
    }
    /// Forgets the samples so far (a new scene, a reset). Readers' cursors stay valid: the
    /// count of samples ever written only grows.
    void clear() { m_begin = m_written; }
    /// Everything written since `cursor` (at most the capacity), and moves the cursor on.
    std::vector<Sample> readSince(std::uint64_t& cursor) const
    {
        std::vector<Sample> out;
        cursor = std::clamp(cursor, m_begin, m_written);
        if (cursor + m_ring.size() < m_written)
            cursor = m_written - m_ring.size();
        out.reserve(static_cast<std::size_t>(m_written - cursor));
        for (; cursor < m_written; ++cursor)
            out.push_back(m_ring[static_cast<std::size_t>(cursor % m_ring.size())]);
        return out;
    }
    std::uint64_t written() const { return m_written; }
    std::size_t capacity() const { return m_ring.size(); }

private:
    std::vector<Sample> m_ring;
    std::uint64_t m_written = 0;
    std::uint64_t m_begin = 0; ///< samples before this were cleared
};

} // namespace rigidlab::ui
