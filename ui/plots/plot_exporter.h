// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A live plot's export as the user asks for it: the file name proposed from what the plot is
// of, the save dialog (PNG, PDF, SVG, or CSV in a dialect it offers), and the data shown put
// on the clipboard. The files themselves are written by exportPlot (plot_export.h).

#include "plots/plot_export.h"

#include <QObject>
#include <QString>

namespace rigidlab::ui {

class PlotWidget;

class PlotExporter : public QObject {
    Q_OBJECT

public:
    /// The export of `plot`, a child of it.
    explicit PlotExporter(PlotWidget& plot);

    /// What the plot's data is of, for the names its exports propose: the scene's title, or
    /// the lesson's and its step ("Energy drift, step 2").
    void setContext(const QString& context) { m_context = context; }
    /// The file name an export dialog proposes: the context, the plot's title and the
    /// language, safe on a Windows share and a USB stick ("welcome_energy_en.csv").
    QString proposedFileName(ExportFormat format) const;

public slots:
    /// Asks for a file name, then exports; a failure is shown in a message box. Returns the
    /// file written, or an empty string. The dialog opens in the folder last exported into
    /// (else Documents) with the proposed name; a CSV's dialect is one of its filters, the
    /// window's by default, and a change is remembered.
    QString exportInteractively(rigidlab::ui::ExportFormat format);
    /// Puts the data shown (the series over the time axis' range) on the clipboard as
    /// tab-separated text in the language's number format (Ctrl+C).
    void copyData();

signals:
    void exported(const QString& path);

private:
    PlotWidget& m_plot;
    QString m_context;
};

} // namespace rigidlab::ui
