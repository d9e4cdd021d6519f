// SPDX-License-Identifier: GPL-3.0-or-later
#include "measure/measurement_files.h"

#include <algorithm>

namespace rigidlab::ui {

MergedMeasurement mergeMeasurementFiles(const std::vector<MeasurementFile>& files)
{
    MergedMeasurement merged;
    measure::Measurement& m = merged.measurement;
    for (const MeasurementFile& in : files) {
        m.layout = in.measurement.layout;
        m.mapping = in.measurement.mapping;
        m.rowsBeforeStart = in.measurement.rowsBeforeStart;
        for (const measure::Series& s : in.measurement.series) {
            auto same =
                std::find_if(m.series.begin(), m.series.end(),
                             [&](const measure::Series& x) { return x.quantity == s.quantity; });
            if (same != m.series.end())
                *same = s;
            else
                m.series.push_back(s);
            merged.seriesFile[s.quantity] = in.file;
        }
        if (!in.measurement.bounces.empty()) {
            m.bounces = in.measurement.bounces;
            merged.bouncesFile = in.file;
        }
    }
    return merged;
}

std::vector<FileSeries> otherFileSeries(const std::vector<MeasurementFile>& files,
                                        measure::Quantity quantity, const QString& compared)
{
    std::vector<FileSeries> others;
    for (const MeasurementFile& in : files) {
        if (in.file == compared)
            continue;
        const measure::Series* series = in.measurement.find(quantity);
        if (!series)
            continue;
        // The same file imported again: its last import.
        auto same = std::find_if(others.begin(), others.end(),
                                 [&](const FileSeries& o) { return o.file == in.file; });
        if (same != others.end())
            same->series = *series;
        else
            others.push_back({in.file, *series});
    }
    return others;
}

} // namespace rigidlab::ui
