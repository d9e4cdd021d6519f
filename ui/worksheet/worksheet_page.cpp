// SPDX-License-Identifier: GPL-3.0-or-later
#include "worksheet/worksheet_page.h"

#include "common/drawable_text.h"
#include "plots/plot_export.h"
#include "plots/plot_widget.h"

#include <QBuffer>
#include <QCoreApplication>
#include <QFontMetrics>
#include <QPageLayout>
#include <QPageSize>
#include <QPdfWriter>

namespace rigidlab::ui {

namespace {

struct WorksheetText {
    Q_DECLARE_TR_FUNCTIONS(WorksheetText)
};

/// Device pixels per inch: fonts in points and the plots' logical pixels come out at the size
/// they have on a plain screen and in the plot export (1/96 in).
constexpr int kDpi = 96;
/// The plot's layout size, as the plot export lays it out [logical pixels].
constexpr QSize kPlotSize{800, 500};
/// Page margins [mm]: room for a school printer's unprintable edge and a hole punch.
constexpr double kMarginMm = 15.0;
/// Distance between ruled writing lines [device pixels]: about 8 mm.
constexpr int kWritingLine = 30;

} // namespace

std::optional<QByteArray> drawPdf(const QString& title,
                                  const std::function<bool(QPdfWriter&)>& draw)
{
    QByteArray bytes;
    {
        QBuffer out(&bytes);
        out.open(QIODevice::WriteOnly);
        QPdfWriter pdf(&out);
        pdf.setCreator(QStringLiteral("RigidLab"));
        pdf.setTitle(title);
        if (!draw(pdf))
            return std::nullopt;
    } // the writer finishes the file as it goes, before its buffer closes
    return bytes;
}

WorksheetPages::WorksheetPages(QPdfWriter& pdf, const QString& header)
    : m_pdf(pdf), m_header(header)
{
    m_pdf.setResolution(kDpi);
    m_pdf.setPageLayout(QPageLayout(QPageSize(QPageSize::A4), QPageLayout::Portrait,
                                    QMarginsF(kMarginMm, kMarginMm, kMarginMm, kMarginMm),
                                    QPageLayout::Millimeter));
    m_began = m_painter.begin(&m_pdf);
    if (!m_began)
        return;
    // Curves as vectors with their true widths: the figures stay sharp when printed or zoomed.
    m_painter.setMode(QCPPainter::pmVectorized);
    m_painter.setMode(QCPPainter::pmNonCosmetic);
    m_base = QFont(m_painter.font().family());
    m_base.setPointSizeF(10.5);
    m_pages = 1;
    drawHeader();
}

void WorksheetPages::end()
{
    if (m_began)
        m_painter.end();
    m_began = false;
}

void WorksheetPages::drawHeader()
{
    // The painter's origin is the corner of the page inside its margins.
    const QRect page(QPoint(0, 0), m_pdf.pageLayout().paintRectPixels(kDpi).size());
    QFont small = m_base;
    small.setPointSizeF(8.5);
    m_painter.setFont(small);
    m_painter.setPen(Qt::black);
    const QFontMetrics fm(small, &m_pdf);
    const QString number = WorksheetText::tr("page %1").arg(m_pages);
    const int numberWidth = fm.horizontalAdvance(number) + 8;
    const QString header = fm.elidedText(drawableText(m_header, small), Qt::ElideRight,
                                         page.width() - numberWidth - 8);
    m_painter.drawText(QRect(0, 0, page.width() - numberWidth, fm.height()),
                       Qt::AlignLeft | Qt::AlignVCenter, header);
    m_painter.drawText(QRect(page.width() - numberWidth, 0, numberWidth, fm.height()),
                       Qt::AlignRight | Qt::AlignVCenter, number);
    const int rule = fm.height() + 3;
    m_painter.setPen(QPen(Qt::gray, 0.75));
    m_painter.drawLine(QLineF(0, rule, page.width(), rule));
    m_area = QRect(0, rule + 12, page.width(), page.height() - rule - 12);
    m_y = m_area.top();
}

void WorksheetPages::newPage()
{
    m_pdf.newPage();
    ++m_pages;
    drawHeader();
}

void WorksheetPages::keepRoom(int pixels)
{
    if (m_y > m_area.top() && m_y + pixels > m_area.bottom())
        newPage();
}

int WorksheetPages::heightOf(const QString& text, const QFont& font, int indent)
{
    m_painter.setFont(font);
    const QRect box(m_area.left() + indent, 0, m_area.width() - indent, 100000);
    return m_painter.boundingRect(box, Qt::TextWordWrap, drawableText(text, font)).height();
}

void WorksheetPages::text(const QString& text, const QFont& font, int indent)
{
    if (!m_began)
        return;
    const int height = heightOf(text, font, indent);
    keepRoom(height);
    m_painter.setFont(font);
    m_painter.setPen(Qt::black);
    // A character no font has would print as nothing: its placeholder instead.
    m_painter.drawText(QRect(m_area.left() + indent, m_y, m_area.width() - indent, height),
                       Qt::TextWordWrap, drawableText(text, font));
    m_y += height;
}

void WorksheetPages::writingLines(int count, int indent)
{
    if (!m_began)
        return;
    keepRoom(count * kWritingLine);
    m_painter.setPen(QPen(Qt::gray, 0.75, Qt::DotLine));
    for (int i = 0; i < count; ++i) {
        m_y += kWritingLine;
        m_painter.drawLine(QLineF(m_area.left() + indent, m_y, m_area.right(), m_y));
    }
    m_y += 6;
}

void WorksheetPages::gap(int pixels)
{
    m_y += pixels;
}

int WorksheetPages::figureHeight() const
{
    return qRound(kPlotSize.height() * static_cast<double>(m_area.width()) / kPlotSize.width()) + 8;
}

void WorksheetPages::figure(PlotWidget& plot)
{
    if (!m_began)
        return;
    const double scale = static_cast<double>(m_area.width()) / kPlotSize.width();
    const int height = figureHeight() - 8;
    keepRoom(height);
    {
        // Laid out as the plot export lays it out, two points per column of a fine print.
        const ExportLayout layout(plot, kPlotSize, 2 * kPlotSize.width());
        m_painter.save();
        m_painter.translate(m_area.left(), m_y);
        m_painter.scale(scale, scale);
        plot.plot()->toPainter(&m_painter, kPlotSize.width(), kPlotSize.height());
        m_painter.restore();
    }
    m_y += height + 8;
    ++m_figures;
}

} // namespace rigidlab::ui
