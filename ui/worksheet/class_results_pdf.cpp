// SPDX-License-Identifier: GPL-3.0-or-later
#include "worksheet/class_results_pdf.h"

#include "worksheet/worksheet_page.h"

#include "format/atomic_file.h"

#include <QCoreApplication>
#include <QDir>
#include <QPageLayout>
#include <QPageSize>
#include <QPdfWriter>
#include <QTextDocument>

#include <functional>

namespace rigidlab::ui {

namespace {

struct ClassResultsText {
    Q_DECLARE_TR_FUNCTIONS(ClassResultsText)
};

/// Device pixels per inch, as the worksheet's: fonts in points come out at their size.
constexpr int kDpi = 96;
/// Page margins [mm], as the worksheet's.
constexpr double kMarginMm = 15.0;

QString escaped(const QString& text)
{
    return text.toHtmlEscaped();
}

/// A row of cells, `tag` td or th; the student's own columns one cell each, a question's
/// group in one cell, a line per column of the group.
QString tableRow(const std::vector<lessons::ClassColumn>& columns,
                 const std::function<lessons::ClassCell(const lessons::ClassColumn&)>& cellOf,
                 const char* tag)
{
    const auto cell = [tag](const QString& html) {
        return QStringLiteral("<%1>%2</%1>").arg(QLatin1StringView(tag), html);
    };
    QString row = QStringLiteral("<tr>");
    QStringList lines;
    int group = -1; // the question whose lines are gathered; -1: none
    const auto flush = [&] {
        if (group >= 0)
            row += cell(lines.join(QStringLiteral("<br>")));
        lines.clear();
        group = -1;
    };
    for (const lessons::ClassColumn& c : columns) {
        const QString text = escaped(cellOf(c).text);
        if (c.question < 0) {
            flush();
            row += cell(text);
            continue;
        }
        if (c.question != group) {
            flush();
            group = c.question;
        }
        if (!text.isEmpty())
            lines.append(text);
    }
    flush();
    return row + QStringLiteral("</tr>");
}

QString tableHtml(const lessons::ClassTable& table)
{
    const std::vector<lessons::ClassColumn> columns = lessons::classColumns(table);
    QString html = QStringLiteral("<h2>%1</h2><p>%2</p>")
                       .arg(escaped(table.lessonTitle),
                            ClassResultsText::tr("Students: %1. Each question's cell: the first "
                                                 "answer, its verdict, the tries, hint or Show "
                                                 "me used.")
                                .arg(table.rows.size()));
    html +=
        QStringLiteral("<table border=\"1\" cellspacing=\"0\" cellpadding=\"3\" width=\"100%\">");
    // The heads of a question's group name it once: the first head of the group.
    html += tableRow(
        columns,
        [&](const lessons::ClassColumn& c) -> lessons::ClassCell {
            if (c.question >= 0 && c.kind != lessons::ClassColumnKind::FirstAnswer)
                return {};
            return {lessons::classColumnHead(table, c), std::nullopt};
        },
        "th");
    for (std::size_t r = 0; r < table.rows.size(); ++r)
        html += tableRow(
            columns, [&](const lessons::ClassColumn& c) { return lessons::classCell(table, r, c); },
            "td");
    html += tableRow(
        columns, [&](const lessons::ClassColumn& c) { return lessons::classSummaryCell(table, c); },
        "th");
    return html + QStringLiteral("</table>");
}

} // namespace

QString classResultsHtml(const std::vector<lessons::ClassTable>& tables, const QStringList& skipped)
{
    QString html = QStringLiteral("<html><body>");
    for (const lessons::ClassTable& table : tables)
        html += tableHtml(table);
    if (!skipped.isEmpty()) {
        html += QStringLiteral("<h3>%1</h3><ul>").arg(ClassResultsText::tr("Files left out"));
        for (const QString& line : skipped)
            html += QStringLiteral("<li>%1</li>").arg(escaped(line));
        html += QStringLiteral("</ul>");
    }
    return html + QStringLiteral("</body></html>");
}

ClassResultsPdf writeClassResultsPdf(const std::vector<lessons::ClassTable>& tables,
                                     const QStringList& skipped, const QString& path)
{
    ClassResultsPdf result;
    const QString title =
        tables.empty() ? ClassResultsText::tr("Class results")
                       : ClassResultsText::tr("Class results: %1").arg(tables.front().lessonTitle);
    const std::optional<QByteArray> bytes = drawPdf(title, [&](QPdfWriter& pdf) {
        pdf.setResolution(kDpi);
        // Landscape: a column per question, side by side.
        pdf.setPageLayout(QPageLayout(QPageSize(QPageSize::A4), QPageLayout::Landscape,
                                      QMarginsF(kMarginMm, kMarginMm, kMarginMm, kMarginMm),
                                      QPageLayout::Millimeter));
        QTextDocument document;
        QFont font = document.defaultFont();
        font.setPointSizeF(9.5);
        document.setDefaultFont(font);
        document.setHtml(classResultsHtml(tables, skipped));
        document.setPageSize(pdf.pageLayout().paintRectPixels(kDpi).size());
        result.pages = document.pageCount();
        document.print(&pdf);
        return true;
    });
    if (!bytes || bytes->isEmpty()) {
        result.error = ClassResultsText::tr("cannot write %1: could not start drawing the PDF")
                           .arg(QDir::toNativeSeparators(path));
        return result;
    }
    if (const QString error = lessons::writeFileAtomically(path, *bytes); !error.isEmpty()) {
        result.error = error;
        return result;
    }
    result.ok = true;
    return result;
}

} // namespace rigidlab::ui
