// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A class's results as a PDF to print or file (A4 landscape, fonts embedded, text
// searchable): per lesson its title and a table, a row per student and the summary row last,
// each question one column whose cell holds that question's group of the one column list
// (lessons/results/class_table.h): first answer, verdict, tries, hint or Show me. The files
// left out follow, one line each. Written like the worksheet: drawn into memory, then
// through the lab's OutputFile (lessons/format/atomic_file.h), whole or not at all.

#include "results/class_table.h"

#include <QString>
#include <QStringList>

#include <vector>

namespace rigidlab::ui {

struct ClassResultsPdf {
    bool ok = false;
    QString error; ///< what went wrong, naming the file
    int pages = 0;
};

ClassResultsPdf writeClassResultsPdf(const std::vector<lessons::ClassTable>& tables,
                                     const QStringList& skipped, const QString& path);

/// The same as HTML (what the PDF is typeset from), for a test or a preview.
QString classResultsHtml(const std::vector<lessons::ClassTable>& tables,
                         const QStringList& skipped);

} // namespace rigidlab::ui
