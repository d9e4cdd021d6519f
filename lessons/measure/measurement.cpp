// SPDX-License-Identifier: GPL-3.0-or-later
// toMeasurement: columns to quantities, units, time zero and origin.
#include "measure/measurement.h"

#include <QCoreApplication>

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

namespace rigidlab::measure {

namespace {

struct QuantityName {
    Quantity quantity;
    const char* name;
};
constexpr std::array kQuantityNames{
    QuantityName{Quantity::Time, "t"},
    QuantityName{Quantity::X, "x"},
    QuantityName{Quantity::Y, "y"},
    QuantityName{Quantity::Vx, "vx"},
    QuantityName{Quantity::Vy, "vy"},
    QuantityName{Quantity::Speed, "v"},
    QuantityName{Quantity::BounceTime, "bounce"},
};

/// Header names (lower case, unit removed) and what they hold: Tracker's short names,
/// phyphox's English names, and Czech ones.
struct HeaderName {
    const char16_t* name;
    Quantity quantity;
};
constexpr std::array kHeaderNames{
    HeaderName{u"t", Quantity::Time},
    HeaderName{u"time", Quantity::Time},
    HeaderName{u"čas", Quantity::Time},
    HeaderName{u"x", Quantity::X},
    HeaderName{u"position x", Quantity::X},
    HeaderName{u"x position", Quantity::X},
    HeaderName{u"poloha x", Quantity::X},
    HeaderName{u"y", Quantity::Y},
    HeaderName{u"position y", Quantity::Y},
    HeaderName{u"y position", Quantity::Y},
    HeaderName{u"poloha y", Quantity::Y},
    HeaderName{u"height", Quantity::Y},
    HeaderName{u"h", Quantity::Y},
    HeaderName{u"výška", Quantity::Y},
    HeaderName{u"vx", Quantity::Vx},
    HeaderName{u"v_x", Quantity::Vx},
    HeaderName{u"velocity x", Quantity::Vx},
    HeaderName{u"vy", Quantity::Vy},
    HeaderName{u"v_y", Quantity::Vy},
    HeaderName{u"velocity y", Quantity::Vy},
    HeaderName{u"v", Quantity::Speed},
    HeaderName{u"speed", Quantity::Speed},
    HeaderName{u"velocity", Quantity::Speed},
    HeaderName{u"rychlost", Quantity::Speed},
    HeaderName{u"bounce", Quantity::BounceTime},
    HeaderName{u"bounces", Quantity::BounceTime},
    HeaderName{u"bounce time", Quantity::BounceTime},
    HeaderName{u"impact", Quantity::BounceTime},
    HeaderName{u"odraz", Quantity::BounceTime},
    HeaderName{u"náraz", Quantity::BounceTime},
};

/// Units and how many of the lab's unit (s, m, m/s) each is.
struct Unit {
    const char16_t* name;
    double scale;
};
constexpr std::array kTimeUnits{Unit{u"s", 1.0}, Unit{u"ms", 1e-3}, Unit{u"min", 60.0}};
constexpr std::array kLengthUnits{Unit{u"m", 1.0}, Unit{u"cm", 1e-2}, Unit{u"mm", 1e-3}};
constexpr std::array kSpeedUnits{Unit{u"m/s", 1.0}, Unit{u"cm/s", 1e-2}, Unit{u"mm/s", 1e-3},
                                 Unit{u"km/h", 1.0 / 3.6}};

bool isTime(Quantity q)
{
    return q == Quantity::Time || q == Quantity::BounceTime;
}
bool isSpeed(Quantity q)
{
    return q == Quantity::Vx || q == Quantity::Vy || q == Quantity::Speed;
}

QString columnPlace(const Table& table, std::size_t c)
{
    const QString& name = table.columns[c].name;
    const int col = static_cast<int>(c) + 1;
    if (name.isEmpty())
        return QCoreApplication::translate("rigidlab::measure", "column %1").arg(col);
    return QCoreApplication::translate("rigidlab::measure", "column %1 (\"%2\")")
        .arg(col)
        .arg(name);
}

QString cellPlace(const Table& table, int row, std::size_t c)
{
    return QCoreApplication::translate("rigidlab::measure", "line %1, %2")
        .arg(table.lines[static_cast<std::size_t>(row)])
        .arg(columnPlace(table, c));
}

/// The scale of column c to the lab's units, or nullopt with `error` set.
std::optional<double> columnScale(const Table& table, std::size_t c, Quantity q,
                                  const MeasurementOptions& options, QString& error)
{
    if (isTime(q) && options.timeScale)
        return *options.timeScale;
    if (!isTime(q) && options.lengthScale)
        return *options.lengthScale;
    const QString& unit = table.columns[c].unit;
    if (unit.isEmpty())
        return 1.0;
    const auto find = [&](const auto& units) -> std::optional<double> {
        for (const Unit& u : units) {
            if (unit == QStringView(u.name))
                return u.scale;
        }
        return std::nullopt;
    };
    const auto scale = isTime(q)    ? find(kTimeUnits)
                       : isSpeed(q) ? find(kSpeedUnits)
                                    : find(kLengthUnits);
    if (!scale) {
        const QString expected = isTime(q)    ? QStringLiteral("s, ms, min")
                                 : isSpeed(q) ? QStringLiteral("m/s, cm/s, mm/s, km/h")
                                              : QStringLiteral("m, cm, mm");
        error = QCoreApplication::translate("rigidlab::measure",
                                            "%1: unknown unit \"%2\" for %3 (expected %4, or "
                                            "set the unit)")
                    .arg(columnPlace(table, c), unit, quantityName(q), expected);
    }
    return scale;
}

/// The values of column c as lab numbers: scaled, shifted; NaN stays NaN (an empty cell).
/// Time (rising) must be there in every row; bounce times may be missing.
bool convertColumn(const Table& table, std::size_t c, Quantity q, double scale, double shift,
                   std::vector<double>& out, QString& error)
{
    const std::vector<double>& in = table.columns[c].values;
    out.resize(in.size());
    double last = -INFINITY;
    int lastRow = -1;
    for (std::size_t r = 0; r < in.size(); ++r) {
        const int row = static_cast<int>(r);
        if (std::isnan(in[r])) {
            if (q == Quantity::Time) {
                error = QCoreApplication::translate("rigidlab::measure", "%1: the time is missing")
                            .arg(cellPlace(table, row, c));
                return false;
            }
            out[r] = in[r];
            continue;
        }
        out[r] = in[r] * scale - shift;
        if (!std::isfinite(out[r])) {
            error = QCoreApplication::translate("rigidlab::measure",
                                                "%1: %2 is too large in the lab's units")
                        .arg(cellPlace(table, row, c))
                        .arg(in[r]);
            return false;
        }
        if (isTime(q) && lastRow >= 0 && !(out[r] > last) &&
            in[r] > in[static_cast<std::size_t>(lastRow)]) {
            // Rising in the file, not once time zero is taken off: rounded away.
            error = QCoreApplication::translate("rigidlab::measure",
                                                "%1: time zero (%2 s) is so far from the "
                                                "file's times that they cannot be told apart")
                        .arg(cellPlace(table, row, c))
                        .arg(shift);
            return false;
        }
        if (isTime(q) && lastRow >= 0 && !(out[r] > last)) {
            error = QCoreApplication::translate("rigidlab::measure",
                                                "%1: the time %2 is not after %3 on line %4 "
                                                "(time must rise from row to row)")
                        .arg(cellPlace(table, row, c))
                        .arg(in[r])
                        .arg(table.columns[c].values[static_cast<std::size_t>(lastRow)])
                        .arg(table.lines[static_cast<std::size_t>(lastRow)]);
            return false;
        }
        last = out[r];
        lastRow = row;
    }
    return true;
}

/// Checks the mapping against the table: its size, one column per quantity, a time column.
bool checkMapping(const Table& table, const std::vector<Quantity>& mapping,
                  const MeasurementOptions& options, QString& error)
{
    if (mapping.size() != table.columns.size()) {
        error = QCoreApplication::translate("rigidlab::measure",
                                            "the mapping names %1 columns, the file has %2")
                    .arg(mapping.size())
                    .arg(table.columns.size());
        return false;
    }
    for (std::size_t a = 0; a < mapping.size(); ++a) {
        for (std::size_t b = a + 1; b < mapping.size(); ++b) {
            if (mapping[a] != Quantity::Ignored && mapping[a] == mapping[b]) {
                error = QCoreApplication::translate("rigidlab::measure",
                                                    "%1 and %2 both hold %3: map one of them")
                            .arg(columnPlace(table, a), columnPlace(table, b),
                                 quantityName(mapping[a]));
                return false;
            }
        }
    }
    const bool hasTime = std::find(mapping.begin(), mapping.end(), Quantity::Time) != mapping.end();
    const bool hasBounces =
        std::find(mapping.begin(), mapping.end(), Quantity::BounceTime) != mapping.end();
    if (!hasTime && !(options.bounceTimesOnly && hasBounces)) {
        error = QCoreApplication::translate("rigidlab::measure",
                                            "no column holds the time (name it t or Time (s), "
                                            "or map a column to it)");
        return false;
    }
    if (table.columns.size() == 1 && !options.bounceTimesOnly) {
        error = QCoreApplication::translate("rigidlab::measure",
                                            "line %1: only one column; a time series needs the "
                                            "time and a measured value (or read it as bounce "
                                            "times)")
                    .arg(table.lines.front());
        return false;
    }
    return true;
}

MeasurementResult failed(const QString& sourceName, const QString& what)
{
    MeasurementResult r;
    r.error = sourceName + QStringLiteral(": ") + what;
    return r;
}

/// The bounce times from column c, empty cells left out.
void collectBounces(const std::vector<double>& values, std::vector<double>& bounces)
{
    for (double t : values) {
        if (!std::isnan(t))
            bounces.push_back(t);
    }
}

} // namespace

QString quantityName(Quantity q)
{
    for (const QuantityName& n : kQuantityNames) {
        if (n.quantity == q)
            return QLatin1StringView(n.name);
    }
    return QStringLiteral("-");
}

std::optional<Quantity> quantityFromName(const QString& name)
{
    for (const QuantityName& n : kQuantityNames) {
        if (name == QLatin1StringView(n.name))
            return n.quantity;
    }
    return std::nullopt;
}

const Series* Measurement::find(Quantity q) const
{
    for (const Series& s : series) {
        if (s.quantity == q)
            return &s;
    }
    return nullptr;
}

std::vector<Quantity> guessMapping(const Table& table, Quantity plainValue)
{
    const std::size_t n = table.columns.size();
    std::vector<Quantity> mapping(n, Quantity::Ignored);
    bool named = false;
    for (const Column& c : table.columns)
        named = named || !c.name.isEmpty();
    if (!named) {
        const std::array<Quantity, 3> plain{Quantity::Time, n == 2 ? plainValue : Quantity::X,
                                            Quantity::Y};
        for (std::size_t c = 0; c < n && c < plain.size(); ++c)
            mapping[c] = plain[c];
        return mapping;
    }
    for (std::size_t c = 0; c < n; ++c) {
        const QString name = table.columns[c].name.toLower().simplified();
        // Two columns with names of one quantity (t, y, height) both get it: which one is
        // meant is the user's choice, and toMeasurement refuses the pair until it is made.
        for (const HeaderName& h : kHeaderNames) {
            if (name == QStringView(h.name)) {
                mapping[c] = h.quantity;
                break;
            }
        }
    }
    return mapping;
}

MeasurementResult toMeasurement(const Table& table, const QString& sourceName,
                                const MeasurementOptions& options)
{
    const std::vector<Quantity> mapping =
        options.mapping.empty() ? guessMapping(table, options.plainValue) : options.mapping;
    QString error;
    if (!checkMapping(table, mapping, options, error))
        return failed(sourceName, error);
    MeasurementResult result;
    Measurement& m = result.measurement;
    m.layout = table.layout;
    m.mapping = mapping;
    std::vector<std::vector<double>> lab(mapping.size());
    std::vector<double> time;
    for (std::size_t c = 0; c < mapping.size(); ++c) {
        const Quantity q = mapping[c];
        if (q == Quantity::Ignored)
            continue;
        const auto scale = columnScale(table, c, q, options, error);
        if (!scale)
            return failed(sourceName, error);
        const double shift = isTime(q)          ? options.timeZero
                             : q == Quantity::X ? options.originX
                             : q == Quantity::Y ? options.originY
                                                : 0.0;
        if (!convertColumn(table, c, q, *scale, shift, lab[c], error))
            return failed(sourceName, error);
        if (q == Quantity::Time)
            time = lab[c];
        else if (q == Quantity::BounceTime)
            collectBounces(lab[c], m.bounces);
    }
    if (options.bounceTimesOnly) {
        // A time column is read as bounce times only when it is all the file holds: beside
        // positions or speeds it holds the time of every frame.
        const auto values = std::count_if(mapping.begin(), mapping.end(), [](Quantity q) {
            return q != Quantity::Ignored && !isTime(q);
        });
        if (m.bounces.empty() && values > 0)
            return failed(sourceName, QCoreApplication::translate(
                                          "rigidlab::measure",
                                          "the time column holds the time of every frame, not "
                                          "bounce times (name the column of bounce times "
                                          "\"bounce\", or fit the positions with --quantity)"));
        if (m.bounces.empty())
            collectBounces(time, m.bounces);
        result.ok = true;
        return result;
    }
    for (std::size_t c = 0; c < mapping.size(); ++c) {
        if (isTime(mapping[c]) || mapping[c] == Quantity::Ignored)
            continue;
        Series s;
        s.quantity = mapping[c];
        for (std::size_t r = 0; r < time.size(); ++r) {
            if (time[r] >= 0 && !std::isnan(lab[c][r])) {
                s.t.push_back(time[r]);
                s.value.push_back(lab[c][r]);
                s.lines.push_back(table.lines[r]);
            }
        }
        if (s.t.empty())
            return failed(sourceName, QCoreApplication::translate(
                                          "rigidlab::measure", "%1: no numbers from time zero on")
                                          .arg(columnPlace(table, c)));
        m.series.push_back(std::move(s));
    }
    m.rowsBeforeStart =
        static_cast<int>(std::count_if(time.begin(), time.end(), [](double t) { return t < 0; }));
    if (m.series.empty())
        return failed(sourceName, QCoreApplication::translate(
                                      "rigidlab::measure",
                                      "no column holds a measured value (x, y, vx, vy or v)"));
    result.ok = true;
    return result;
}

MeasurementResult readMeasurementFile(const QString& path, const MeasurementOptions& options)
{
    const TableResult table = readTableFile(path);
    if (!table.ok) {
        MeasurementResult r;
        r.error = table.error;
        return r;
    }
    return toMeasurement(table.table, path, options);
}

} // namespace rigidlab::measure
