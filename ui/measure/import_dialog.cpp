// SPDX-License-Identifier: GPL-3.0-or-later
#include "measure/import_dialog.h"

#include "common/number_format.h"

#include <QComboBox>
#include <QCryptographicHash>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFileInfo>
#include <QFormLayout>
#include <QGridLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QScrollArea>
#include <QSettings>
#include <QTableWidget>
#include <QVBoxLayout>

#include <map>

namespace rigidlab::ui {

using measure::Quantity;

namespace {

constexpr Quantity kQuantities[] = {Quantity::Ignored, Quantity::Time,      Quantity::X,
                                    Quantity::Y,       Quantity::Vx,        Quantity::Vy,
                                    Quantity::Speed,   Quantity::BounceTime};
/// Rows of the preview: enough to check the units, few enough to fit a small screen.
constexpr int kPreviewRows = 8;
/// Height of the list of columns before it scrolls [px].
constexpr int kColumnsMaxHeightPx = 180;
/// Offsets a file may need [s], [m]: a video's time zero, an origin anywhere on a table.
constexpr double kOffsetLimit = 1e5;

QString settingsKey(const measure::Table& table)
{
    QStringList names;
    for (const measure::Column& c : table.columns)
        names << c.name + QLatin1Char('|') + c.unit;
    const QByteArray hash =
        QCryptographicHash::hash(names.join(QLatin1Char('\t')).toUtf8(), QCryptographicHash::Sha1);
    return QStringLiteral("measurementMapping/") + QString::fromLatin1(hash.toHex().left(16));
}

QDoubleSpinBox* offsetBox(QWidget* parent, const QString& suffix, const QString& name)
{
    auto* box = new QDoubleSpinBox(parent);
    box->setRange(-kOffsetLimit, kOffsetLimit);
    box->setDecimals(4);
    box->setSingleStep(0.01);
    box->setSuffix(QChar(0x00A0) + suffix);
    box->setAccessibleName(name);
    return box;
}

} // namespace

QString quantityText(Quantity q)
{
    switch (q) {
    case Quantity::Ignored:
        return MeasurementImportDialog::tr("not used");
    case Quantity::Time:
        return MeasurementImportDialog::tr("time t [s]");
    case Quantity::X:
        return MeasurementImportDialog::tr("position x [m]");
    case Quantity::Y:
        return MeasurementImportDialog::tr("position y (height) [m]");
    case Quantity::Vx:
        return MeasurementImportDialog::tr("velocity vx [m/s]");
    case Quantity::Vy:
        return MeasurementImportDialog::tr("velocity vy [m/s]");
    case Quantity::Speed:
        return MeasurementImportDialog::tr("speed v [m/s]");
    case Quantity::BounceTime:
        return MeasurementImportDialog::tr("bounce times [s]");
    }
    return {};
}

QString quantityUnit(Quantity q)
{
    switch (q) {
    case Quantity::Time:
    case Quantity::BounceTime:
        return QStringLiteral("s");
    case Quantity::X:
    case Quantity::Y:
        return QStringLiteral("m");
    case Quantity::Vx:
    case Quantity::Vy:
    case Quantity::Speed:
        return QStringLiteral("m/s");
    case Quantity::Ignored:
        break;
    }
    return {};
}

std::vector<Quantity> rememberedMapping(const measure::Table& table)
{
    const QStringList names = QSettings().value(settingsKey(table)).toStringList();
    std::vector<Quantity> mapping;
    for (const QString& name : names) {
        const auto q = measure::quantityFromName(name);
        if (!q)
            return {};
        mapping.push_back(*q);
    }
    if (mapping.size() != table.columns.size())
        return {};
    return mapping;
}

void rememberMapping(const measure::Table& table, const std::vector<Quantity>& mapping)
{
    QStringList names;
    for (const Quantity q : mapping)
        names << measure::quantityName(q);
    QSettings().setValue(settingsKey(table), names);
}

MeasurementImportDialog::MeasurementImportDialog(const QString& path, QWidget* parent)
    : QDialog(parent), m_path(path), m_table(measure::readTableFile(path))
{
    setWindowTitle(tr("Import measurement"));
    setAccessibleName(windowTitle());
    auto* layout = new QVBoxLayout(this);
    auto* file = new QLabel(QFileInfo(path).fileName(), this);
    file->setAccessibleName(tr("File"));
    layout->addWidget(file);
    m_message = new QLabel(this);
    m_message->setWordWrap(true);
    m_message->setTextInteractionFlags(Qt::TextSelectableByMouse | Qt::TextSelectableByKeyboard);
    m_message->setAccessibleName(tr("What the file holds, or what is wrong with it"));
    if (m_table.ok) {
        // The columns scroll: a file may have dozens (a phone's every sensor), the dialog
        // must still fit a projector's 768 px.
        auto* columns = new QWidget;
        auto* grid = new QGridLayout(columns);
        buildColumns(*grid);
        auto* scroll = new QScrollArea(this);
        scroll->setWidgetResizable(true);
        scroll->setFrameShape(QFrame::NoFrame);
        scroll->setWidget(columns);
        scroll->setMaximumHeight(kColumnsMaxHeightPx);
        scroll->setMinimumHeight(std::min(kColumnsMaxHeightPx, columns->sizeHint().height()));
        layout->addWidget(scroll);
        auto* form = new QFormLayout;
        buildOffsets(*form);
        layout->addLayout(form);
        m_preview = new QTableWidget(this);
        m_preview->setAccessibleName(tr("Preview: the first points in the lab's units"));
        m_preview->setEditTriggers(QAbstractItemView::NoEditTriggers);
        m_preview->verticalHeader()->hide();
        m_preview->setMinimumHeight(120);
        layout->addWidget(m_preview, 1);
    }
    layout->addWidget(m_message);
    m_buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    m_buttons->button(QDialogButtonBox::Ok)->setText(tr("Import"));
    connect(m_buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(m_buttons);
    if (!m_table.ok) {
        m_error = m_table.error;
        m_message->setText(m_error);
        m_buttons->button(QDialogButtonBox::Ok)->setEnabled(false);
        return;
    }
    update();
}

void MeasurementImportDialog::buildColumns(QGridLayout& grid)
{
    const measure::Table& table = m_table.table;
    std::vector<Quantity> mapping = rememberedMapping(table);
    if (mapping.empty())
        mapping = measure::guessMapping(table);
    grid.addWidget(new QLabel(tr("Column"), this), 0, 0);
    grid.addWidget(new QLabel(tr("holds"), this), 0, 1);
    for (std::size_t i = 0; i < table.columns.size(); ++i) {
        const measure::Column& c = table.columns[i];
        QString name = c.name.isEmpty() ? tr("column %1").arg(i + 1) : c.name;
        if (!c.unit.isEmpty())
            name += QStringLiteral(" (%1)").arg(c.unit);
        auto* label = new QLabel(name, this);
        auto* box = new QComboBox(this);
        for (const Quantity q : kQuantities)
            box->addItem(quantityText(q), static_cast<int>(q));
        box->setCurrentIndex(box->findData(static_cast<int>(mapping[i])));
        box->setAccessibleName(tr("What column %1 holds").arg(name));
        label->setBuddy(box);
        connect(box, &QComboBox::currentIndexChanged, this, &MeasurementImportDialog::update);
        grid.addWidget(label, static_cast<int>(i) + 1, 0);
        grid.addWidget(box, static_cast<int>(i) + 1, 1);
        m_mapping.push_back(box);
    }
}

void MeasurementImportDialog::buildOffsets(QFormLayout& form)
{
    m_timeUnit = new QComboBox(this);
    m_timeUnit->addItem(tr("as the header says (else s)"), 0.0);
    m_timeUnit->addItem(QStringLiteral("s"), 1.0);
    m_timeUnit->addItem(QStringLiteral("ms"), 1e-3);
    m_timeUnit->addItem(QStringLiteral("min"), 60.0);
    m_timeUnit->setAccessibleName(tr("Unit of the times in the file"));
    m_lengthUnit = new QComboBox(this);
    m_lengthUnit->addItem(tr("as the header says (else m)"), 0.0);
    m_lengthUnit->addItem(QStringLiteral("m"), 1.0);
    m_lengthUnit->addItem(QStringLiteral("cm"), 1e-2);
    m_lengthUnit->addItem(QStringLiteral("mm"), 1e-3);
    m_lengthUnit->setAccessibleName(tr("Unit of the lengths in the file"));
    m_timeZero = offsetBox(this, QStringLiteral("s"),
                           tr("Time zero: the file's time at which "
                              "the scene starts"));
    m_originX = offsetBox(this, QStringLiteral("m"),
                          tr("Origin x: where the scene's origin is "
                             "in the file"));
    m_originY = offsetBox(this, QStringLiteral("m"),
                          tr("Origin y: where the scene's origin is "
                             "in the file"));
    form.addRow(tr("Time &unit:"), m_timeUnit);
    form.addRow(tr("&Length unit:"), m_lengthUnit);
    form.addRow(tr("Time &zero (file time at the scene's start):"), m_timeZero);
    form.addRow(tr("Scene origin in the file, &x:"), m_originX);
    form.addRow(tr("Scene origin in the file, &y:"), m_originY);
    for (QComboBox* box : {m_timeUnit, m_lengthUnit})
        connect(box, &QComboBox::currentIndexChanged, this, &MeasurementImportDialog::update);
    for (QDoubleSpinBox* box : {m_timeZero, m_originX, m_originY})
        connect(box, &QDoubleSpinBox::valueChanged, this, &MeasurementImportDialog::update);
}

QComboBox* MeasurementImportDialog::mappingBox(int column) const
{
    return column >= 0 && column < static_cast<int>(m_mapping.size())
               ? m_mapping[static_cast<std::size_t>(column)]
               : nullptr;
}

void MeasurementImportDialog::setMapping(int column, Quantity q)
{
    if (QComboBox* box = mappingBox(column))
        box->setCurrentIndex(box->findData(static_cast<int>(q)));
}

void MeasurementImportDialog::setTimeZero(double seconds)
{
    if (m_timeZero)
        m_timeZero->setValue(seconds);
}

void MeasurementImportDialog::setOrigin(double x, double y)
{
    if (m_originX) {
        m_originX->setValue(x);
        m_originY->setValue(y);
    }
}

void MeasurementImportDialog::setUnits(double secondsPerUnit, double metresPerUnit)
{
    if (!m_timeUnit)
        return;
    m_timeUnit->setCurrentIndex(std::max(0, m_timeUnit->findData(secondsPerUnit)));
    m_lengthUnit->setCurrentIndex(std::max(0, m_lengthUnit->findData(metresPerUnit)));
}

void MeasurementImportDialog::update()
{
    m_options = {};
    for (QComboBox* box : m_mapping)
        m_options.mapping.push_back(static_cast<Quantity>(box->currentData().toInt()));
    if (const double s = m_timeUnit->currentData().toDouble(); s > 0)
        m_options.timeScale = s;
    if (const double m = m_lengthUnit->currentData().toDouble(); m > 0)
        m_options.lengthScale = m;
    m_options.timeZero = m_timeZero->value();
    m_options.originX = m_originX->value();
    m_options.originY = m_originY->value();
    bool timeMapped = false, bouncesMapped = false;
    for (const Quantity q : m_options.mapping) {
        timeMapped |= q == Quantity::Time;
        bouncesMapped |= q == Quantity::BounceTime;
    }
    m_options.bounceTimesOnly = bouncesMapped && !timeMapped;
    m_result = measure::toMeasurement(m_table.table, QFileInfo(m_path).fileName(), m_options);
    m_error = m_result.ok ? QString() : m_result.error;
    if (m_result.ok) {
        const measure::Measurement& m = m_result.measurement;
        QString text =
            m.series.empty()
                ? tr("%n bounce time(s)", nullptr, static_cast<int>(m.bounces.size()))
                : tr("%n point(s)", nullptr, static_cast<int>(m.series.front().t.size()));
        if (m.rowsBeforeStart > 0)
            text += QStringLiteral("; ") +
                    tr("%n row(s) before time zero left out", nullptr, m.rowsBeforeStart);
        m_message->setText(text);
    } else {
        m_message->setText(m_error);
    }
    m_buttons->button(QDialogButtonBox::Ok)->setEnabled(m_result.ok);
    fillPreview();
}

void MeasurementImportDialog::fillPreview()
{
    m_preview->clear();
    const measure::Measurement& m = m_result.measurement;
    if (!m_result.ok) {
        m_preview->setRowCount(0);
        m_preview->setColumnCount(0);
        return;
    }
    // Rows by the file's line, so that a point another column leaves empty shows as a gap.
    QStringList headers{quantityText(m.series.empty() ? Quantity::BounceTime : Quantity::Time)};
    std::vector<std::map<int, double>> byLine;
    std::vector<std::pair<int, double>> rows; // line, t
    if (m.series.empty()) {
        for (std::size_t i = 0; i < m.bounces.size() && rows.size() < kPreviewRows; ++i)
            rows.emplace_back(static_cast<int>(i), m.bounces[i]);
    }
    for (const measure::Series& s : m.series) {
        headers << quantityText(s.quantity);
        byLine.emplace_back();
        for (std::size_t i = 0; i < s.t.size(); ++i)
            byLine.back()[s.lines[i]] = s.value[i];
        for (std::size_t i = 0;
             i < s.t.size() && &s == &m.series.front() && rows.size() < kPreviewRows; ++i)
            rows.emplace_back(s.lines[i], s.t[i]);
    }
    m_preview->setColumnCount(static_cast<int>(headers.size()));
    m_preview->setHorizontalHeaderLabels(headers);
    m_preview->setRowCount(static_cast<int>(rows.size()));
    for (int r = 0; r < static_cast<int>(rows.size()); ++r) {
        const auto [line, t] = rows[static_cast<std::size_t>(r)];
        m_preview->setItem(r, 0, new QTableWidgetItem(formatReadable(t, 6)));
        for (std::size_t c = 0; c < byLine.size(); ++c) {
            const auto it = byLine[c].find(line);
            m_preview->setItem(r, static_cast<int>(c) + 1,
                               new QTableWidgetItem(it == byLine[c].end()
                                                        ? QStringLiteral("–")
                                                        : formatReadable(it->second, 6)));
        }
    }
    m_preview->resizeColumnsToContents();
}

void MeasurementImportDialog::accept()
{
    if (!m_error.isEmpty())
        return;
    rememberMapping(m_table.table, m_options.mapping);
    QDialog::accept();
}

} // namespace rigidlab::ui
