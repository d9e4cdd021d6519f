// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A text field that Tab reaches is spoken on its first focus too.
//
// On a field's first focus by Tab, QLineEdit selects its text (none yet) and its caret, never
// placed before, sends "caret moved" to assistive technology; QWidget::setFocus tells the
// focus only after that. Orca takes the caret event of the newly focused field as the new
// focus, silently, and then finds the focus event's object already its focus: it says
// nothing ("tab", and silence). A field whose caret was placed once while it was built sends
// no caret event when it is focused, so the focus event comes first and is spoken.

namespace rigidlab::ui {

/// Places the caret of every text field (line edits and the fields of spin boxes) as it is
/// made ready to show, for the whole application (once; later calls do nothing).
void placeCaretsBeforeFocus();

} // namespace rigidlab::ui
