// SPDX-License-Identifier: GPL-3.0-or-later
#include "simulation/drift_words.h"

#include <QCoreApplication>

namespace rigidlab::ui {

namespace {

/// The translation context of these words.
class DriftWords {
    Q_DECLARE_TR_FUNCTIONS(DriftWords)
};

} // namespace

QString driftLabel(bool brief)
{
    return brief ? DriftWords::tr("energy drift %1 %")
                 : DriftWords::tr("energy drift (integrator, contacts, joints) %1 %");
}

QString driftExplanation()
{
    return DriftWords::tr(
        "<p>Energy drift: how far the total energy (motion, height, springs) has moved from its "
        "value at the start, as a share of it, after adding back what bounces, friction, drag "
        "and dampers took. Exact physics would keep it at 0.</p>"
        "<p>What is left is numerical error: the integrator's, step by step; that of the "
        "corrections after contacts and joints are solved (bodies that sank into each other "
        "are pushed apart, pins are pulled back together); and that of the estimate of what "
        "the contacts took, which grows steadily while bodies rest on each other. A method "
        "that follows a free fall exactly, such as velocity Verlet, still drifts where bodies "
        "touch.</p>");
}

} // namespace rigidlab::ui
