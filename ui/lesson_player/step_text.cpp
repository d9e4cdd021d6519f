// SPDX-License-Identifier: GPL-3.0-or-later
#include "lesson_player/step_text.h"

#include "common/spoken_numbers.h"

#include <QAbstractTextDocumentLayout>
#include <QEvent>
#include <QResizeEvent>
#include <QScrollBar>
#include <QTextCursor>
#include <QTextDocument>
#include <QTextFrame>
#include <QTextTable>

#include <array>
#include <cmath>
#include <memory>

namespace rigidlab::ui {

namespace {

/// The tables of `doc`, outermost first.
QList<QTextTable*> tablesOf(QTextDocument& doc)
{
    QList<QTextTable*> tables;
    QList<QTextFrame*> frames{doc.rootFrame()};
    while (!frames.isEmpty()) {
        QTextFrame* frame = frames.takeFirst();
        if (auto* table = qobject_cast<QTextTable*>(frame))
            tables << table;
        frames << frame->childFrames();
    }
    return tables;
}

} // namespace

StepText::StepText(QWidget* parent) : QTextBrowser(parent)
{
    setOpenExternalLinks(false);
    // No vertical scroll bar of its own: the lesson around it scrolls. A table wider than the
    // column at its smallest text scrolls sideways (fit()).
    setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    horizontalScrollBar()->setAccessibleName(tr("Scroll the step's text sideways"));
    setLineWrapMode(QTextEdit::WidgetWidth);
    // How lines break: fit().
    QSizePolicy policy(QSizePolicy::Preferred, QSizePolicy::Preferred);
    policy.setHeightForWidth(true);
    setSizePolicy(policy);
}

void StepText::showMarkdown(const QString& markdown)
{
    m_markdown = markdown;
    m_fittedWidth = -1;
    fit();
    tellName();
}

void StepText::setNameWhenEmpty(const QString& name)
{
    m_nameWhenEmpty = name;
    tellName();
}

void StepText::tellName()
{
    // A reader speaks a focused text of this kind (a label) by its name alone, so its name is
    // what it shows, as a label's is: the step puts the focus here to have it read.
    const QString spoken = spokenSigns(toPlainText().simplified());
    setAccessibleName(spoken.isEmpty() ? m_nameWhenEmpty : spoken);
}

void StepText::fit()
{
    const int width = viewport()->width();
    m_fittedWidth = width;
    setMarkdown(m_markdown);
    m_overflows = false;
    const QList<QTextTable*> tables = tablesOf(*document());
    // With a table, lines break between words only: a table's word broken in the middle
    // ("integrá/tor") reads as two, and a table too wide scrolls sideways instead (below).
    // Without one, a word wider than the column (a file's name) breaks rather than being cut.
    QTextOption option = document()->defaultTextOption();
    option.setWrapMode(tables.isEmpty() ? QTextOption::WrapAtWordBoundaryOrAnywhere
                                        : QTextOption::WordWrap);
    document()->setDefaultTextOption(option);
    for (QTextTable* table : tables) {
        // As wide as the column at most, with thin cells.
        QTextTableFormat format = table->format();
        format.setWidth(QTextLength(QTextLength::PercentageLength, 100));
        format.setCellPadding(2);
        format.setCellSpacing(0);
        format.setBorderCollapse(true);
        format.setColumnWidthConstraints({});
        table->setFormat(format);
    }
    if (tables.isEmpty() || width <= 0) {
        setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
        return updateGeometry();
    }
    // The tables' text smaller, in steps, until the widest fits; below 70 % it would be
    // unreadable, and the text scrolls sideways instead: its words stay whole.
    const double base = font().pointSizeF();
    document()->setTextWidth(width);
    for (const double scale : std::array{1.0, 0.9, 0.8, 0.7}) {
        if (scale < 1.0) {
            for (QTextTable* table : tables) {
                QTextCursor cursor = table->firstCursorPosition();
                cursor.setPosition(table->lastCursorPosition().position(), QTextCursor::KeepAnchor);
                QTextCharFormat smaller;
                smaller.setFontPointSize(base * scale);
                cursor.mergeCharFormat(smaller);
            }
        }
        // The widest a word makes the text, at this scale.
        const std::unique_ptr<QTextDocument> probe(document()->clone());
        probe->setTextWidth(width);
        m_overflows = std::ceil(probe->size().width()) > width;
        if (!m_overflows)
            break;
    }
    setHorizontalScrollBarPolicy(m_overflows ? Qt::ScrollBarAlwaysOn : Qt::ScrollBarAlwaysOff);
    updateGeometry();
}

int StepText::heightForWidth(int width) const
{
    const int frame = 2 * frameWidth();
    const std::unique_ptr<QTextDocument> probe(document()->clone());
    const int textWidth = std::max(1, width - frame);
    probe->setTextWidth(textWidth);
    // A table too wide for the column scrolls sideways, its scroll bar below the text.
    const int bar = std::ceil(probe->size().width()) > textWidth
                        ? horizontalScrollBar()->sizeHint().height()
                        : 0;
    return static_cast<int>(std::ceil(probe->size().height())) + frame + bar;
}

QSize StepText::sizeHint() const
{
    const int width = QTextBrowser::sizeHint().width();
    return {width, heightForWidth(this->width() > 0 ? this->width() : width)};
}

QSize StepText::minimumSizeHint() const
{
    return {fontMetrics().averageCharWidth() * 12, fontMetrics().lineSpacing() + 2 * frameWidth()};
}

void StepText::resizeEvent(QResizeEvent* event)
{
    QTextBrowser::resizeEvent(event);
    if (viewport()->width() != m_fittedWidth)
        fit();
}

void StepText::changeEvent(QEvent* event)
{
    QTextBrowser::changeEvent(event);
    if (event->type() == QEvent::FontChange)
        fit();
}

} // namespace rigidlab::ui
