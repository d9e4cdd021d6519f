// SPDX-License-Identifier: GPL-3.0-or-later
#include "plots/plot_turns.h"

#include "plots/plot_widget.h"

#include <algorithm>

namespace rigidlab::ui {

namespace {

/// A frame may come this much before the refresh interval has passed and still count as
/// having passed it [ms]: at 60 frames a second the second frame after a drain comes 33 ms
/// later, give or take the timer's jitter, and must find the plot due.
constexpr int kFrameSlackMs = 8;

} // namespace

PlotTurns::PlotTurns(QObject* parent) : QObject(parent)
{
    m_clock.start();
}

void PlotTurns::add(PlotWidget* plot)
{
    // While no frames come (a paused run) each plot's own timer drains it: staggered too.
    plot->staggerRefresh(static_cast<int>(m_turns.size()));
    m_turns.push_back({plot});
}

int PlotTurns::count() const
{
    return static_cast<int>(std::count_if(m_turns.begin(), m_turns.end(),
                                          [](const Turn& t) { return !t.plot.isNull(); }));
}

void PlotTurns::frameAdvanced()
{
    frame(m_clock.elapsed());
}

std::vector<PlotWidget*> PlotTurns::frame(qint64 nowMs)
{
    std::erase_if(m_turns, [](const Turn& t) { return t.plot.isNull(); });
    std::vector<Turn*> due;
    for (Turn& t : m_turns) {
        t.plot->frameCame();
        if (!t.drained || nowMs - t.lastMs >= PlotWidget::kRefreshIntervalMs - kFrameSlackMs)
            due.push_back(&t);
    }
    // Those that waited longest first: never drained, then by the time, then by the order of
    // their drains (plots drained in one frame take the next ones in the same order).
    std::stable_sort(due.begin(), due.end(), [](const Turn* a, const Turn* b) {
        if (a->drained != b->drained)
            return !a->drained;
        return a->lastMs != b->lastMs ? a->lastMs < b->lastMs : a->order < b->order;
    });
    const std::size_t room = (m_turns.size() + 1) / 2;
    std::vector<PlotWidget*> drained;
    for (std::size_t i = 0; i < due.size() && i < room; ++i) {
        Turn& t = *due[i];
        t.lastMs = nowMs;
        t.drained = true;
        t.order = ++m_drains;
        drained.push_back(t.plot);
        t.plot->drain();
    }
    return drained;
}

} // namespace rigidlab::ui
