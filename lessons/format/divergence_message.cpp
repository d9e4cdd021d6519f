// SPDX-License-Identifier: GPL-3.0-or-later
#include "format/divergence_message.h"
#include "format/view_text.h"

namespace rigidlab::lessons {

namespace {

QString number(double value)
{
    return QString::number(value, 'g', 6);
}

} // namespace

QString quantityName(physics::Divergence::Quantity quantity)
{
    using Q = physics::Divergence::Quantity;
    switch (quantity) {
    case Q::Position:
        return QStringLiteral("position");
    case Q::Angle:
        return QStringLiteral("angle");
    case Q::Velocity:
        return QStringLiteral("velocity");
    case Q::AngularVelocity:
        return QStringLiteral("angular velocity");
    case Q::TotalEnergy:
        return QStringLiteral("total energy");
    }
    return QString();
}

QString divergenceMessage(const physics::Divergence& d)
{
    const std::string_view integrator = physics::integratorName(d.integrator);
    const QString where =
        QStringLiteral("diverged at t = %1 s (step %2, dt = %3 s, %4): ")
            .arg(number(d.time), QString::number(d.step), number(d.dt), textFromView(integrator));
    const QString body = QString::fromStdString(d.bodyName);
    const bool energy = d.quantity == physics::Divergence::Quantity::TotalEnergy;
    QString line;
    if (d.kind == physics::Divergence::Kind::NonFinite && !energy)
        return where + QStringLiteral("body \"%1\": %2 is no longer finite")
                           .arg(body, quantityName(d.quantity));
    if (d.kind == physics::Divergence::Kind::NonFinite)
        line = where + QStringLiteral("the total energy is no longer finite");
    else
        line = where + QStringLiteral("the total energy grew to %1 J, past the bound of %2 J")
                           .arg(number(d.value), number(d.bound));
    if (d.body != physics::kWorld)
        line += QStringLiteral(" (body \"%1\" holds the most kinetic energy)").arg(body);
    return line;
}

} // namespace rigidlab::lessons
