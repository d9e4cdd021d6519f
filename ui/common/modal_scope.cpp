// SPDX-License-Identifier: GPL-3.0-or-later
#include "common/modal_scope.h"

namespace rigidlab::ui {

int ModalScope::s_depth = 0;
std::vector<ModalScope::Pending> ModalScope::s_pending;

ModalScope::ModalScope()
{
    ++s_depth;
}

ModalScope::~ModalScope()
{
    if (--s_depth > 0)
        return;
    // What waited runs now, after the dialog's answer was acted upon. A callback may open a
    // scope of its own; anything it queues runs when that one ends.
    std::vector<Pending> pending;
    pending.swap(s_pending);
    for (Pending& p : pending)
        if (p.context)
            p.then();
}

bool ModalScope::active()
{
    return s_depth > 0;
}

void ModalScope::whenDone(QObject* context, std::function<void()> then)
{
    if (s_depth == 0) {
        then();
        return;
    }
    s_pending.push_back({QPointer<QObject>(context), std::move(then)});
}

} // namespace rigidlab::ui
