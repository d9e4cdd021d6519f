// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Docks under short titles on a narrow projector column: a tab reads "Drift", not "E…". The
// dock's full title (its "fullTitle" property) shows as the tooltip of its tab and title bar.

class QDockWidget;
class QMainWindow;
class QString;

namespace rigidlab::ui {

/// Gives `dock` its full title, shown as a tooltip where its short title is.
void setFullTitle(QDockWidget& dock, const QString& fullTitle);
/// The full title setFullTitle gave, or else the dock's title.
QString fullTitle(const QDockWidget& dock);

/// Keeps the tabs of `window`'s tabbed docks whole: a tab is never elided nor scrolled away
/// (the column is as wide as its tabs), and its tooltip is the dock's full title.
void keepDockTabsWhole(QMainWindow& window);

/// Keeps the keyboard out of `dock` while it lies behind another dock's tab: Qt moves such a
/// dock out of sight rather than hiding it, so Tab would walk into fields nobody can see. Its
/// content is hidden while it is behind, shown when its tab is chosen.
void keepFocusInSight(QDockWidget& dock);
/// The same, now (after docks were moved or a dock got new content).
void showContentIfInSight(QDockWidget& dock);

/// Puts the focus in `dock` when it is shown by its action (its key or the View menu), once
/// the window has made room for it: a student who asked for a panel works in it next.
void focusWhenAsked(QDockWidget& dock);

} // namespace rigidlab::ui
