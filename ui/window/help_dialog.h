// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Help › Controls (F1): the key table as a page that scrolls inside a window no larger than
// the screen, so that its close button is always in reach on a 1024×768 projector.

class QDialog;
class QString;
class QWidget;

namespace rigidlab::ui {

/// Opens the help `html` under `title` in a window over `parent` (not blocking; deleted when
/// closed) and returns it. Its size is its preferred one, bounded by the screen's available area.
QDialog* showControlsHelp(QWidget* parent, const QString& title, const QString& html);

} // namespace rigidlab::ui
