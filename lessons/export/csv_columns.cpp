// SPDX-License-Identifier: GPL-3.0-or-later
#include "export/csv_columns.h"

#include <QCoreApplication>

namespace rigidlab::lessons {

namespace {

struct CsvColumns {
    Q_DECLARE_TR_FUNCTIONS(CsvColumns)
};

} // namespace

QString csvColumnHead(CsvColumn column)
{
    switch (column) {
    case CsvColumn::Step:
        return CsvColumns::tr("step");
    case CsvColumn::Time:
        return QStringLiteral("t [s]");
    case CsvColumn::Body:
        return CsvColumns::tr("body");
    case CsvColumn::X:
        return QStringLiteral("x [m]");
    case CsvColumn::Y:
        return QStringLiteral("y [m]");
    case CsvColumn::Angle:
        return CsvColumns::tr("angle [rad]");
    case CsvColumn::Vx:
        return QStringLiteral("v_x [m/s]");
    case CsvColumn::Vy:
        return QStringLiteral("v_y [m/s]");
    case CsvColumn::Omega:
        return QStringLiteral("ω [rad/s]");
    case CsvColumn::Kinetic:
        return QStringLiteral("E_k [J]");
    case CsvColumn::Potential:
        return QStringLiteral("E_p [J]");
    case CsvColumn::Total:
        return QStringLiteral("E [J]");
    case CsvColumn::Dissipated:
        return QStringLiteral("E_diss [J]");
    case CsvColumn::TotalDissipated:
        return QStringLiteral("E + E_diss [J]");
    case CsvColumn::Px:
        return QStringLiteral("p_x [kg m/s]");
    case CsvColumn::Py:
        return QStringLiteral("p_y [kg m/s]");
    case CsvColumn::AngularMomentum:
        return QStringLiteral("L [kg m²/s]");
    case CsvColumn::Contacts:
        return CsvColumns::tr("contacts");
    case CsvColumn::Drift:
        return CsvColumns::tr("drift [1]");
    case CsvColumn::DriftPercent:
        return CsvColumns::tr("drift [%]");
    }
    return {};
}

} // namespace rigidlab::lessons
