// SPDX-License-Identifier: GPL-3.0-or-later
#include "simulation/run_view.h"

#include "simulation/step_sampler.h"

namespace rigidlab::ui {

double RunView::time() const
{
    return stepTime(world());
}

} // namespace rigidlab::ui
