// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A measured time series read from CSV: Tracker's export, phyphox's exports and plain files
// (lessons/measure/MEASUREMENT_FORMAT.md). Reading is two stages:
//   readTable        the text: separator, decimal mark, header, numbers, one row per line;
//   toMeasurement    which column is which quantity, units, time zero and origin.
// The first problem found comes back as one line `FILE: line L, column C ("NAME"): what`;
// nothing in a file can crash the reader or make it take unbounded memory or time.

#include <QByteArray>
#include <QString>
#include <QStringList>

#include <optional>
#include <vector>

namespace rigidlab::measure {

/// Limits that keep a mistyped or hostile file from taking the machine down. A video tracked
/// at 240 frames a second for 5 minutes has 72 000 rows; a phone's sensor at 500 Hz for
/// 3 minutes 90 000.
inline constexpr int kMaxRows = 100'000;
inline constexpr qint64 kMaxFileBytes = 16 * 1024 * 1024;
inline constexpr int kMaxColumns = 64;
/// Lines before the first row of numbers (title, header, comments).
inline constexpr int kMaxHeaderLines = 50;

/// What a column holds.
enum class Quantity {
    Ignored,
    Time,       ///< [s]
    X,          ///< position [m]
    Y,          ///< position (height) [m]
    Vx,         ///< velocity component [m/s]
    Vy,         ///< [m/s]
    Speed,      ///< |v| [m/s]
    BounceTime, ///< the times of bounces, heard or seen [s]
};

/// "t", "x", "y", "vx", "vy", "v", "bounce" (the names of the command line and of files).
QString quantityName(Quantity q);
/// The quantity of a name above, or nullopt.
std::optional<Quantity> quantityFromName(const QString& name);

enum class Layout {
    Plain,   ///< numbers only, or one header line of names
    Tracker, ///< a title line (the track's name), then a header of short names (t, x, y)
    Phyphox, ///< a header of names with units: "Time (s)", "Height (m)"
};

struct Column {
    QString name; ///< as the header gives it, unit removed; empty without a header
    QString unit; ///< from "(s)" or "[cm]" in the header; empty when none
    /// Per row; NaN for an empty cell (Tracker leaves frames without a mark empty).
    std::vector<double> values;
};

struct Table {
    Layout layout = Layout::Plain;
    QChar separator;           ///< ',', ';', '\t' or ' ' (spaces)
    bool decimalComma = false; ///< numbers were written 0,25
    QStringList titleLines;    ///< lines before the header (Tracker: the track's name)
    std::vector<Column> columns;
    std::vector<int> lines; ///< the file's line (1-based) of each row
    int rows() const { return static_cast<int>(lines.size()); }
};

struct TableResult {
    bool ok = false;
    QString error; ///< one line when !ok
    Table table;
};

/// Reads the text of a measurement; `sourceName` names it in messages.
TableResult readTable(const QByteArray& bytes, const QString& sourceName);
/// Reads a file (at most kMaxFileBytes); the path as given names it in messages.
TableResult readTableFile(const QString& path);

/// How columns become quantities, and the lab's units and frame.
struct MeasurementOptions {
    /// One quantity per column; empty: guessed from the header (guessMapping).
    std::vector<Quantity> mapping;
    /// The quantity a second column without a header holds (a plain two-column file).
    Quantity plainValue = Quantity::Y;
    /// Seconds per unit of the time columns; unset: from the header's unit, else 1.
    std::optional<double> timeScale;
    /// Metres per unit of the lengths (velocities: metres per unit per second); unset: from
    /// the header's unit, else 1.
    std::optional<double> lengthScale;
    /// The time in the file (in seconds) at which the simulation starts: lab time = file time
    /// - timeZero. Rows before it are left out.
    double timeZero = 0;
    /// Where the lab's origin is in the file's frame, in metres: lab x = file x - originX.
    double originX = 0, originY = 0;
    /// Reading bounce times only: a file of one column is enough.
    bool bounceTimesOnly = false;
};

/// One measured quantity against lab time, rows with an empty cell left out.
struct Series {
    Quantity quantity = Quantity::Ignored;
    std::vector<double> t;     ///< [s], increasing
    std::vector<double> value; ///< [m], [m/s]
    std::vector<int> lines;    ///< the file's line of each point
};

struct Measurement {
    Layout layout = Layout::Plain;
    std::vector<Quantity> mapping; ///< per column of the table
    std::vector<Series> series;    ///< one per mapped quantity other than time and bounces
    std::vector<double> bounces;   ///< bounce times [s], increasing; empty when none
    int rowsBeforeStart = 0;       ///< rows before timeZero, left out
    /// The series of quantity q, or nullptr.
    const Series* find(Quantity q) const;
};

struct MeasurementResult {
    bool ok = false;
    QString error; ///< one line when !ok
    Measurement measurement;
};

/// The quantity of each column, from its header name (Ignored where unknown; two names of one
/// quantity both get it, which toMeasurement refuses). Without a header: time, then plainValue
/// for two columns, x and y for three.
std::vector<Quantity> guessMapping(const Table& table, Quantity plainValue = Quantity::Y);

/// Applies the mapping, units and offsets, and checks the result: a time column that rises
/// from row to row, finite numbers, at least two points (three bounce times).
MeasurementResult toMeasurement(const Table& table, const QString& sourceName,
                                const MeasurementOptions& options = {});

/// readTableFile and toMeasurement.
MeasurementResult readMeasurementFile(const QString& path, const MeasurementOptions& options = {});

} // namespace rigidlab::measure
