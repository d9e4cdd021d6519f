// SPDX-License-Identifier: GPL-3.0-or-later
#include "view/sat_view_model.h"

#include "simulation/run_view.h"

#include <algorithm>

namespace rigidlab::ui {

void SatViewModel::setBodies(int a, int b)
{
    const int n = static_cast<int>(m_run.world().bodies().size());
    auto polygon = [&](int id) {
        return id >= 0 && id < n && m_run.world().body(id).shape.asPolygon();
    };
    m_a = polygon(a) && polygon(b) ? a : -1;
    m_b = m_a >= 0 ? b : -1;
    m_shown = 1;
    m_all = false;
    refresh();
    settle();
}

void SatViewModel::nextAxis()
{
    m_all = false;
    m_shown = std::min<int>(m_shown + 1, static_cast<int>(m_result.axes.size()));
    settle();
}

void SatViewModel::previousAxis()
{
    m_all = false;
    m_shown = std::max(1, m_shown - 1);
    settle();
}

void SatViewModel::showAll()
{
    m_all = true;
    settle();
}

void SatViewModel::settle()
{
    const int total = static_cast<int>(m_result.axes.size());
    if (m_all)
        m_shown = total;
    m_shown = std::clamp(m_shown, std::min(1, total), total);
}

SatViewModel::Tested SatViewModel::testedNow() const
{
    // The pair was checked to be two polygons when it was set; a world replaced since is
    // checked again rather than trusted.
    const auto& world = m_run.world();
    const int n = static_cast<int>(world.bodies().size());
    const bool inWorld = active() && m_a < n && m_b < n;
    const physics::Polygon* pa = inWorld ? world.body(m_a).shape.asPolygon() : nullptr;
    const physics::Polygon* pb = inWorld ? world.body(m_b).shape.asPolygon() : nullptr;
    if (!pa || !pb)
        return {};
    const physics::Body& a = world.body(m_a);
    const physics::Body& b = world.body(m_b);
    return {m_a,
            m_b,
            {a.position.x(), a.position.y(), a.angle, b.position.x(), b.position.y(), b.angle},
            pa->vertices,
            pb->vertices};
}

bool SatViewModel::refresh()
{
    Tested now = testedNow();
    if (now == m_tested)
        return false;
    m_tested = std::move(now);
    if (m_tested.a < 0) {
        m_result = physics::SatResult{};
    } else {
        const auto& world = m_run.world();
        const physics::Body& a = world.body(m_a);
        const physics::Body& b = world.body(m_b);
        m_result = physics::satPolygons(*a.shape.asPolygon(), a.transform(), *b.shape.asPolygon(),
                                        b.transform());
    }
    settle();
    return true;
}

} // namespace rigidlab::ui
