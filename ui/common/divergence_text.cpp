// SPDX-License-Identifier: GPL-3.0-or-later
#include "common/divergence_text.h"

#include "common/number_format.h"
#include "format/divergence_message.h"

#include <QLocale>

namespace rigidlab::ui {

using lessons::DivergenceWords;

QString divergenceReason(const physics::Divergence& d, const QString& bodyLabel)
{
    return lessons::divergenceReason(d, bodyLabel, QLocale());
}

QString divergenceSentence(const physics::Divergence& d, const QString& bodyLabel)
{
    if (d.kind == physics::Divergence::Kind::Crowded)
        return DivergenceWords::tr("The simulation %1. It stopped here rather than freeze the "
                                   "computer.")
            .arg(lessons::divergenceMessage(d, bodyLabel, QLocale()));
    return DivergenceWords::tr("The simulation %1. It stopped here rather than draw garbage.")
        .arg(lessons::divergenceMessage(d, bodyLabel, QLocale()));
}

QString divergenceShort(const physics::Divergence& d)
{
    if (d.kind == physics::Divergence::Kind::EnergyGrowth)
        return DivergenceWords::tr("energy blew up");
    if (d.kind == physics::Divergence::Kind::Crowded)
        return DivergenceWords::tr("too crowded to run");
    return DivergenceWords::tr("%1 no longer finite").arg(lessons::quantityName(d.quantity));
}

QString divergenceLabel(const physics::Divergence& d, const QString& bodyLabel)
{
    return DivergenceWords::tr("stopped at t = %1 s: %2")
        .arg(formatReadable(d.time, 6), divergenceReason(d, bodyLabel));
}

} // namespace rigidlab::ui
