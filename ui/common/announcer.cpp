// SPDX-License-Identifier: GPL-3.0-or-later
#include "common/announcer.h"

#include <QAccessible>
#include <QAccessibleWidget>
#include <QTextDocumentFragment>
#include <QWidget>

namespace rigidlab::ui {

namespace {

const char* const kAnnouncerName = "rigidlabAnnouncer";

QWidget* makeAnnouncer(QWidget& window)
{
    auto* widget = new QWidget(&window);
    widget->setObjectName(QLatin1String(kAnnouncerName));
    // One transparent pixel in the corner: shown, so that a reader hears it, but not seen,
    // not clicked and never a Tab stop.
    widget->setGeometry(0, 0, 1, 1);
    widget->setAttribute(Qt::WA_TransparentForMouseEvents);
    widget->setFocusPolicy(Qt::NoFocus);
    widget->hide();
    return widget;
}

} // namespace

QAccessibleInterface* announcerInterface(const QString& className, QObject* object)
{
    // It has no class of its own for a factory's key: asked for every plain widget, this
    // knows it by its name.
    auto* widget = qobject_cast<QWidget*>(object);
    if (className != QLatin1String("QWidget") || !widget ||
        widget->objectName() != QLatin1String(kAnnouncerName))
        return nullptr;
    return new QAccessibleWidget(widget, QAccessible::Notification);
}

void prepareAnnouncer(QWidget& window)
{
    if (!announcer(window))
        makeAnnouncer(window);
}

QWidget* announcer(const QWidget& window)
{
    return window.findChild<QWidget*>(QLatin1String(kAnnouncerName), Qt::FindDirectChildrenOnly);
}

void announce(QWidget& widget, const QString& message)
{
    const QString text = Qt::mightBeRichText(message)
                             ? QTextDocumentFragment::fromHtml(message).toPlainText()
                             : message;
    if (text.trimmed().isEmpty())
        return;
    QWidget& window = *widget.window();
    QWidget* told = announcer(window);
    if (!told)
        told = makeAnnouncer(window);
    // Hidden, then shown with the message: each message is news to the reader, the same
    // one again too.
    told->hide();
    told->setAccessibleName(text.simplified());
    told->show();
    told->raise();
}

} // namespace rigidlab::ui
