// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Short messages a screen reader speaks without the focus moving: the verdict after Check, a
// new lesson step, the body chosen in the scene, play and pause, a run that diverged.
//
// Qt 6.4 has no announcement event (QAccessibleAnnouncementEvent came with Qt 6.8), and a
// reader speaks a changed label only when it has the focus. So each window holds one object
// of the notification role, out of sight: a message becomes its name and the object is shown,
// which Orca speaks as "notification, <message>" (its default script's onShowingChanged, as
// for a desktop notification). The message is plain text: markup would be read out.

class QAccessibleInterface;
class QObject;
class QString;
class QWidget;

namespace rigidlab::ui {

/// Tells `message` to a screen reader from `widget`'s window. Rich text is told as its plain
/// text; an empty message tells nothing.
void announce(QWidget& widget, const QString& message);

/// Makes `window`'s announcer now, hidden, so that a reader knows it before the first
/// announcement (Orca was slow to speak the first one of an object it had not seen).
void prepareAnnouncer(QWidget& window);

/// The factory of the announcer's interface: a notification named by its message (installed
/// with the window's others, window/accessible_factories.h).
QAccessibleInterface* announcerInterface(const QString& className, QObject* object);

/// The widget that tells `window`'s announcements (its accessible name is the last one), or
/// nullptr before the first.
QWidget* announcer(const QWidget& window);

} // namespace rigidlab::ui
