// SPDX-License-Identifier: GPL-3.0-or-later
#include "lesson_player/question_area.h"

#include "common/accessible_names.h"

#include <QDockWidget>
#include <QEvent>
#include <QLayout>
#include <QScrollBar>
#include <QTimer>

#include <algorithm>

namespace rigidlab::ui {

namespace {

/// The height `w` needs at `width` [px]: word-wrapped prompts and verdicts grow with less width.
int heightAt(const QWidget& w, int width)
{
    return w.hasHeightForWidth() ? w.heightForWidth(width) : w.sizeHint().height();
}

} // namespace

QuestionArea::QuestionArea(QWidget* questions, QWidget* parent) : QScrollArea(parent)
{
    setObjectName(QStringLiteral("lessonQuestionArea"));
    // Named with its scroll bars; the Tab key goes through the questions' fields and buttons
    // (each scrolled into sight), not to the area around them.
    nameScrollArea(*this, tr("Questions"));
    setWidgetResizable(true);
    setFrameShape(QFrame::NoFrame);
    // The prompts and verdicts wrap to the column: never a sideways scroll bar.
    setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Fixed);
    // The scroll area watches its widget (eventFilter): a verdict shown, a question added or
    // a font changed makes the questions' layout ask to be done again.
    setWidget(questions);
}

void QuestionArea::setRoom(int px)
{
    m_room = px;
    fit();
    fitSoon();
}

void QuestionArea::fitSoon()
{
    // Questions just made are shown once the events queued with them are handled; until then
    // their layout leaves them out. (Each call queues its own fit: one queued before the
    // questions were made would measure none.)
    QTimer::singleShot(0, this, &QuestionArea::fit);
}

int QuestionArea::contentWidth() const
{
    // The scroll bar's width is kept free, so that the height does not change when it comes.
    return std::max(1, width() - 2 * frameWidth() - verticalScrollBar()->sizeHint().width());
}

int QuestionArea::contentHeight() const
{
    return widget() ? heightAt(*widget(), contentWidth()) : 0;
}

int QuestionArea::firstQuestionHeight() const
{
    const QLayout* layout = widget() ? widget()->layout() : nullptr;
    if (!layout)
        return 0;
    // Inside the questions' own margins and their layout's.
    const QMargins m = widget()->contentsMargins() + layout->contentsMargins();
    for (int i = 0; i < layout->count(); ++i)
        if (const QWidget* first = layout->itemAt(i)->widget(); first && !first->isHidden())
            return heightAt(*first, contentWidth() - m.left() - m.right()) + m.top() + m.bottom();
    return 0;
}

void QuestionArea::fit()
{
    m_fittedWidth = width();
    const int content = contentHeight();
    const bool any = widget() && widget()->layout() && widget()->layout()->count() > 0;
    setVisible(any);
    if (!any)
        return;
    // The questions whole where there is room; the first whole in any case.
    const int height =
        std::min(content, std::max(firstQuestionHeight(), m_room)) + 2 * frameWidth();
    if (height == this->height() && minimumHeight() == height)
        return;
    setFixedHeight(height);
    // The column around takes the new height now, not some queued layout passes later: a
    // verdict is in sight the moment it is shown. Innermost first (each layout done tells the
    // one around it that its size changed), up to the dock.
    for (QWidget* p = parentWidget(); p && !p->isWindow() && !qobject_cast<QDockWidget*>(p);
         p = p->parentWidget())
        if (p->layout())
            p->layout()->activate();
}

void QuestionArea::resizeEvent(QResizeEvent* event)
{
    QScrollArea::resizeEvent(event);
    if (width() != m_fittedWidth)
        fit();
}

bool QuestionArea::eventFilter(QObject* watched, QEvent* event)
{
    if (watched == widget() && event->type() == QEvent::LayoutRequest)
        fit();
    if (watched == widget() &&
        (event->type() == QEvent::ChildAdded || event->type() == QEvent::ChildRemoved))
        fitSoon();
    return QScrollArea::eventFilter(watched, event);
}

} // namespace rigidlab::ui
