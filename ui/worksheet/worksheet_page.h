// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The worksheet's pages: A4 portrait, text flowed top to bottom and wrapped to the margins,
// a new page when a block does not fit, a running header (lesson, student, date) and the page
// number on each, and plots drawn as vectors.

#include <qcustomplot.h>

#include <QByteArray>
#include <QFont>
#include <QString>

#include <functional>
#include <optional>

class QPdfWriter;

namespace rigidlab::ui {

/// A PDF drawn into memory, to be written whole (lessons/format/atomic_file.h): `draw` gets a
/// writer with the lab as its creator and `title` as its title, and returns false when it
/// could not draw; nothing is returned then.
std::optional<QByteArray> drawPdf(const QString& title,
                                  const std::function<bool(QPdfWriter&)>& draw);

class PlotWidget;

class WorksheetPages {
public:
    /// Draws on `pdf` (A4, set up here); `header` heads every page. Check began() after.
    WorksheetPages(QPdfWriter& pdf, const QString& header);
    bool began() const { return m_began; }
    /// Finishes the last page.
    void end();

    /// Text wrapped to the width, `indent` device pixels in from the left margin.
    void text(const QString& text, const QFont& font, int indent = 0);
    /// Empty lines to write on by hand, ruled.
    void writingLines(int count, int indent = 0);
    /// Vertical space [device pixels].
    void gap(int pixels);
    /// Starts a new page unless `pixels` still fit on this one.
    void keepRoom(int pixels);
    /// The plot as vectors, scaled to the text's width with its export proportions.
    void figure(PlotWidget& plot);

    /// Height a figure takes on the page [device pixels].
    int figureHeight() const;

    int pages() const { return m_pages; }
    int figures() const { return m_figures; }
    /// Height of `text` wrapped to the width from `indent` [device pixels].
    int heightOf(const QString& text, const QFont& font, int indent = 0);
    QFont baseFont() const { return m_base; }

private:
    void newPage();
    void drawHeader();

    QPdfWriter& m_pdf;
    QCPPainter m_painter;
    QString m_header;
    QFont m_base;
    QRect m_area; ///< the page inside its margins, below the header [device pixels]
    int m_y = 0;  ///< where the next block starts
    int m_pages = 0;
    int m_figures = 0;
    bool m_began = false;
};

} // namespace rigidlab::ui
