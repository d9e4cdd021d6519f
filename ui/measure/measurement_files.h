// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The files of a measurement imported into one scene or lesson, in the order imported, and
// what the comparison takes from them: each quantity from the last file that has it, the
// bounce times likewise (a video's heights, then a phone's bounce times). A later file of a
// quantity an earlier one has too (a second video) gives the quantity compared and fitted
// from then on; the earlier file's series is still shown beside it, named by its file.

#include "measure/measurement.h"

#include <QString>

#include <map>
#include <vector>

namespace rigidlab::ui {

/// A file imported: its name and what it held.
struct MeasurementFile {
    QString file;
    measure::Measurement measurement;
};

/// A measured series and the name of the file it comes from.
struct FileSeries {
    QString file;
    measure::Series series;
};

/// What the comparison takes from the files: each quantity from the last file that has it.
struct MergedMeasurement {
    measure::Measurement measurement;
    std::map<measure::Quantity, QString> seriesFile; ///< the file each series comes from
    QString bouncesFile;                             ///< the file the bounce times come from
};

MergedMeasurement mergeMeasurementFiles(const std::vector<MeasurementFile>& files);

/// The series of `quantity` in the files not named `compared`, in the order imported, one per
/// file name (the last one imported under that name).
std::vector<FileSeries> otherFileSeries(const std::vector<MeasurementFile>& files,
                                        measure::Quantity quantity, const QString& compared);

} // namespace rigidlab::ui
