// SPDX-License-Identifier: GPL-3.0-or-later
#include "common/focus_ring.h"

#include "common/theme.h"

#include <QApplication>
#include <QEvent>
#include <QPainter>

namespace rigidlab::ui {

FocusRing& FocusRing::install()
{
    static QPointer<FocusRing> ring;
    if (!ring) {
        ring = new FocusRing;
        connect(qApp, &QApplication::focusChanged, ring,
                [](QWidget*, QWidget* now) { ring->follow(now); });
    }
    return *ring;
}

FocusRing::FocusRing()
{
    setAttribute(Qt::WA_TransparentForMouseEvents);
    setAttribute(Qt::WA_NoSystemBackground);
    setFocusPolicy(Qt::NoFocus);
    setObjectName(QStringLiteral("focusRing"));
    hide();
}

int FocusRing::ringWidth()
{
    return theme::presentation() ? 4 : 3;
}

void FocusRing::follow(QWidget* focus)
{
    if (m_target)
        m_target->removeEventFilter(this);
    // Menus and popups draw their own highlight; a window of its own has nothing to ring.
    if (!focus || focus->isWindow() || (focus->window()->windowFlags() & Qt::Popup)) {
        m_target = nullptr;
        hide();
        return;
    }
    m_target = focus;
    m_target->installEventFilter(this);
    if (parentWidget() != focus->window()) {
        setParent(focus->window());
        setAttribute(Qt::WA_TransparentForMouseEvents);
    }
    place();
}

void FocusRing::place()
{
    if (!m_target || !m_target->isVisible()) {
        hide();
        return;
    }
    const int margin = ringWidth() + 1; // the ring and its halo, outside the control
    const QPoint topLeft = m_target->mapTo(parentWidget(), QPoint(0, 0));
    setGeometry(QRect(topLeft, m_target->size()).adjusted(-margin, -margin, margin, margin));
    show();
    raise();
    update();
}

bool FocusRing::eventFilter(QObject* watched, QEvent* event)
{
    if (watched == m_target) {
        switch (event->type()) {
        case QEvent::Move:
        case QEvent::Resize:
        case QEvent::Show:
        case QEvent::Hide:
            place();
            break;
        default:
            break;
        }
    }
    return QWidget::eventFilter(watched, event);
}

void FocusRing::paintEvent(QPaintEvent*)
{
    QPainter p(this);
    const int w = ringWidth();
    const QRectF outer = QRectF(rect()).adjusted(0.5, 0.5, -0.5, -0.5);
    p.setPen(QPen(theme::focusHalo(), 1));
    p.drawRect(outer);
    p.setPen(QPen(theme::focusRing(), w, Qt::SolidLine, Qt::SquareCap, Qt::MiterJoin));
    p.drawRect(outer.adjusted(1 + w / 2.0, 1 + w / 2.0, -1 - w / 2.0, -1 - w / 2.0));
}

} // namespace rigidlab::ui
