// SPDX-License-Identifier: GPL-3.0-or-later
#include "panels/divergence_text.h"

#include <QCoreApplication>
#include <QLocale>

namespace rigidlab::ui {

namespace {

/// The translation context of these words.
class DivergenceWords {
    Q_DECLARE_TR_FUNCTIONS(DivergenceWords)
};

QString number(double value, int digits = 4)
{
    return QLocale().toString(value, 'g', digits);
}

QString quantity(physics::Divergence::Quantity q)
{
    using Q = physics::Divergence::Quantity;
    switch (q) {
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
    }
    return QString();
}

} // namespace

QString divergenceReason(const physics::Divergence& d, const QString& bodyLabel)
{
    const QString body = bodyLabel.isEmpty() ? QString::fromStdString(d.bodyName) : bodyLabel;
    const bool energy = d.quantity == physics::Divergence::Quantity::TotalEnergy;
    if (d.kind == physics::Divergence::Kind::NonFinite && !energy)
        return DivergenceWords::tr("the %1 of body “%2” is no longer finite")
            .arg(quantity(d.quantity), body);
    QString reason =
        d.kind == physics::Divergence::Kind::NonFinite
            ? DivergenceWords::tr("the total energy is no longer finite")
            : DivergenceWords::tr("the total energy grew from %1 J to %2 J, past the bound of %3 J")
                  .arg(number(d.start), number(d.value), number(d.bound));
    if (d.body != physics::kWorld)
        reason += DivergenceWords::tr(" (body “%1” holds the most kinetic energy)").arg(body);
    return reason;
}

QString divergenceSentence(const physics::Divergence& d, const QString& bodyLabel)
{
    const std::string_view integrator = physics::integratorName(d.integrator);
    return DivergenceWords::tr(
               "The simulation diverged at t = %1 s (step %2, dt = %3 s, %4): %5. It stopped "
               "here rather than draw garbage.")
        .arg(number(d.time, 6), QLocale().toString(d.step), number(d.dt, 6),
             QString::fromUtf8(integrator.data(), static_cast<qsizetype>(integrator.size())),
             divergenceReason(d, bodyLabel));
}

QString divergenceShort(const physics::Divergence& d)
{
    if (d.kind == physics::Divergence::Kind::EnergyGrowth)
        return DivergenceWords::tr("energy blew up");
    return DivergenceWords::tr("%1 no longer finite").arg(quantity(d.quantity));
}

QString divergenceLabel(const physics::Divergence& d, const QString& bodyLabel)
{
    return DivergenceWords::tr("stopped at t = %1 s: %2")
        .arg(number(d.time, 6), divergenceReason(d, bodyLabel));
}

} // namespace rigidlab::ui
