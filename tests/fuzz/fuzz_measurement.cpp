// SPDX-License-Identifier: GPL-3.0-or-later
// Fuzz target: the measurement reader (readTable, toMeasurement) on any bytes, and e from the
// bounce times it reads.
//
// Whatever the bytes, the reader returns: a table or one error line naming the source. A table
// it accepts is within the limits (measure/measurement.h), every column has a value (or NaN for
// an empty cell) per row, and the rows' lines rise. A measurement made from it has rising,
// finite times and finite values, no two columns of one quantity, and bounce times read from a
// time column only when nothing else is measured; a fit of e to its bounce times is finite,
// from at most kMaxBounces flights that shrink (its interval below 1), or refused.

#include "fuzz_check.h"

#include "measure/fit.h"
#include "measure/measurement.h"

#include <QByteArray>
#include <QString>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>

using namespace rigidlab;

namespace {

void checkError(const QString& error, const QString& source)
{
    FUZZ_CHECK(error.startsWith(source + QStringLiteral(": ")));
    FUZZ_CHECK(!error.contains(u'\n'));
}

void checkMeasurement(const measure::MeasurementResult& r, const QString& source)
{
    if (!r.ok) {
        checkError(r.error, source);
        return;
    }
    for (const measure::Series& s : r.measurement.series) {
        FUZZ_CHECK(s.t.size() == s.value.size() && s.t.size() == s.lines.size());
        for (std::size_t i = 0; i < s.t.size(); ++i) {
            FUZZ_CHECK(std::isfinite(s.t[i]) && s.t[i] >= 0 && std::isfinite(s.value[i]));
            FUZZ_CHECK(i == 0 || s.t[i] > s.t[i - 1]);
        }
    }
    const std::vector<double>& b = r.measurement.bounces;
    for (std::size_t i = 0; i < b.size(); ++i)
        FUZZ_CHECK(std::isfinite(b[i]) && (i == 0 || b[i] > b[i - 1]));
    const std::vector<measure::Quantity>& mapping = r.measurement.mapping;
    for (std::size_t c = 0; c < mapping.size(); ++c)
        for (std::size_t d = c + 1; d < mapping.size(); ++d)
            FUZZ_CHECK(mapping[c] == measure::Quantity::Ignored || mapping[c] != mapping[d]);
    const measure::BounceFit fit = measure::fitBounceTimes(b);
    FUZZ_CHECK(!fit.ok || (std::isfinite(fit.e.value) && std::isfinite(fit.e.halfWidth95) &&
                           fit.e.value + fit.e.halfWidth95 < 1 &&
                           b.size() <= static_cast<std::size_t>(measure::kMaxBounces)));
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const QString source = QStringLiteral("fuzz.csv");
    const QByteArray bytes(reinterpret_cast<const char*>(data), static_cast<qsizetype>(size));
    const measure::TableResult r = measure::readTable(bytes, source);
    if (!r.ok) {
        checkError(r.error, source);
        return 0;
    }
    const measure::Table& table = r.table;
    FUZZ_CHECK(!table.columns.empty() && table.columns.size() <= measure::kMaxColumns);
    FUZZ_CHECK(table.rows() >= 1 && table.rows() <= measure::kMaxRows);
    for (const measure::Column& c : table.columns) {
        FUZZ_CHECK(c.values.size() == table.lines.size());
        for (double v : c.values)
            FUZZ_CHECK(std::isnan(v) || std::isfinite(v));
    }
    for (std::size_t i = 1; i < table.lines.size(); ++i)
        FUZZ_CHECK(table.lines[i] > table.lines[i - 1]);
    checkMeasurement(measure::toMeasurement(table, source), source);
    measure::MeasurementOptions bounces;
    bounces.bounceTimesOnly = true;
    const measure::MeasurementResult read = measure::toMeasurement(table, source, bounces);
    checkMeasurement(read, source);
    // Bounce times from the time column only when it is all the file measures.
    const auto has = [&](measure::Quantity q) {
        return std::find(read.measurement.mapping.begin(), read.measurement.mapping.end(), q) !=
               read.measurement.mapping.end();
    };
    if (read.ok && !has(measure::Quantity::BounceTime))
        for (const measure::Quantity q : read.measurement.mapping)
            FUZZ_CHECK(q == measure::Quantity::Ignored || q == measure::Quantity::Time);
    return 0;
}
