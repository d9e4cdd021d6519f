// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// rigidlab-cli results: a class's answers files in one table. Argument handling only; the
// work is in rigidlab_results (reading, judging, text and CSV) and rigidlab_plots (the PDF).

#include <QStringList>

namespace rigidlab::cli {

/// `results FOLDER [--lesson FILE] [--all-lessons] [-o OUT.csv|OUT.pdf] [--lang CODE]
/// [--csv-dialect D]`. Writes a PDF with Qt's text layout, so it needs a QApplication.
int commandResults(const QStringList& words);

} // namespace rigidlab::cli
