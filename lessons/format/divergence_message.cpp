// SPDX-License-Identifier: GPL-3.0-or-later
#include "format/divergence_message.h"
#include "format/view_text.h"

#include "rigidlab/physics/integrator.h"

namespace rigidlab::lessons {

namespace {

QString number(const QLocale& numbers, double value)
{
    return numbers.toString(value, 'g', 6);
}

} // namespace

QString quantityName(physics::Divergence::Quantity quantity)
{
    using Q = physics::Divergence::Quantity;
    switch (quantity) {
    case Q::Position:
        return DivergenceWords::tr("position");
    case Q::Angle:
        return DivergenceWords::tr("angle");
    case Q::Velocity:
        return DivergenceWords::tr("velocity");
    case Q::AngularVelocity:
        return DivergenceWords::tr("angular velocity");
    case Q::TotalEnergy:
        return DivergenceWords::tr("total energy");
    case Q::BodyPairs:
        return DivergenceWords::tr("pairs of bodies");
    }
    return QString();
}

QString divergenceReason(const physics::Divergence& d, const QString& bodyLabel,
                         const QLocale& numbers)
{
    const QString body = bodyLabel.isEmpty() ? QString::fromStdString(d.bodyName) : bodyLabel;
    if (d.kind == physics::Divergence::Kind::Crowded)
        return DivergenceWords::tr("more than %1 pairs of bodies overlap or nearly touch "
                                   "(around body \"%2\"): so crowded a scene needs memory and "
                                   "time growing with the square of the bodies; spread them out")
            .arg(numbers.toString(qlonglong(d.bound)), body);
    const bool energy = d.quantity == physics::Divergence::Quantity::TotalEnergy;
    if (d.kind == physics::Divergence::Kind::NonFinite && !energy)
        return DivergenceWords::tr("body \"%1\": %2 is no longer finite")
            .arg(body, quantityName(d.quantity));
    QString reason =
        d.kind == physics::Divergence::Kind::NonFinite
            ? DivergenceWords::tr("the total energy is no longer finite")
            : DivergenceWords::tr("the total energy grew to %1 J, past the bound of %2 J")
                  .arg(number(numbers, d.value), number(numbers, d.bound));
    if (d.body != physics::kWorld)
        reason += DivergenceWords::tr(" (body \"%1\" holds the most kinetic energy)").arg(body);
    return reason;
}

QString divergenceMessage(const physics::Divergence& d, const QString& bodyLabel,
                          const QLocale& numbers)
{
    if (d.kind == physics::Divergence::Kind::Crowded)
        return DivergenceWords::tr("stopped at t = %1 s, before step %2: %3")
            .arg(number(numbers, d.time), numbers.toString(qlonglong(d.step + 1)),
                 divergenceReason(d, bodyLabel, numbers));
    return DivergenceWords::tr("diverged at t = %1 s (step %2, dt = %3 s, %4): %5")
        .arg(number(numbers, d.time), numbers.toString(qlonglong(d.step)), number(numbers, d.dt),
             textFromView(physics::integratorName(d.integrator)),
             divergenceReason(d, bodyLabel, numbers));
}

} // namespace rigidlab::lessons
