// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// File › Import measurement…: a measured time series read from CSV (lessons/measure), its
// columns mapped to quantities, its units and its offsets set, with a preview of what the lab
// will compare. The dialog guesses the mapping from the header, or takes the one last used
// for a file with the same header (QSettings). A file the reader refuses is named with its
// line and column; the dialog then offers nothing to import.

#include "measure/measurement.h"

#include <QDialog>
#include <QString>

#include <vector>

class QComboBox;
class QDialogButtonBox;
class QDoubleSpinBox;
class QFormLayout;
class QGridLayout;
class QLabel;
class QTableWidget;

namespace rigidlab::ui {

/// The quantity's name in the window ("position y (height) [m]").
QString quantityText(measure::Quantity q);
/// The quantity's unit in the lab: "s", "m", "m/s".
QString quantityUnit(measure::Quantity q);

/// The mapping last used for tables with this header (their column names and count), or
/// empty; remembered by rememberMapping.
std::vector<measure::Quantity> rememberedMapping(const measure::Table& table);
void rememberMapping(const measure::Table& table, const std::vector<measure::Quantity>& mapping);

class MeasurementImportDialog : public QDialog {
    Q_OBJECT
public:
    /// Reads the file at `path`; a refusal is shown in the dialog (error()).
    explicit MeasurementImportDialog(const QString& path, QWidget* parent = nullptr);

    /// Why the file or the choices cannot be imported (one line naming the place), or empty.
    QString error() const { return m_error; }
    /// The measurement with the choices made, when error() is empty.
    const measure::Measurement& measurement() const { return m_result.measurement; }
    const measure::MeasurementOptions& options() const { return m_options; }
    const QString& path() const { return m_path; }

    /// The combo box mapping column `column` (for tests and for the keyboard), or nullptr.
    QComboBox* mappingBox(int column) const;
    /// Sets what column `column` holds, as choosing it in its box does.
    void setMapping(int column, measure::Quantity q);
    void setTimeZero(double seconds);
    void setOrigin(double x, double y);
    /// Units by hand: seconds and metres per unit of the file (0: from the header).
    void setUnits(double secondsPerUnit, double metresPerUnit);
    QTableWidget* preview() const { return m_preview; }

    /// Accepting remembers the mapping for this header.
    void accept() override;

private:
    void buildColumns(QGridLayout& grid);
    void buildOffsets(QFormLayout& form);
    /// Reads the choices, converts the table and fills the preview and the message.
    void update();
    void fillPreview();

    QString m_path;
    measure::TableResult m_table;
    measure::MeasurementOptions m_options;
    measure::MeasurementResult m_result;
    QString m_error;
    std::vector<QComboBox*> m_mapping;
    QComboBox* m_timeUnit = nullptr;
    QComboBox* m_lengthUnit = nullptr;
    QDoubleSpinBox* m_timeZero = nullptr;
    QDoubleSpinBox* m_originX = nullptr;
    QDoubleSpinBox* m_originY = nullptr;
    QTableWidget* m_preview = nullptr;
    QLabel* m_message = nullptr;
    QDialogButtonBox* m_buttons = nullptr;
};

} // namespace rigidlab::ui
