// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A text field that Tab reaches is spoken by its label and value first.
//
// A screen reader takes the first event it hears of a newly focused field as the focus, and
// QWidget::setFocus tells assistive technology of the focus only after the field has handled
// its focus-in event, in which two things happen first:
// - On a field's first focus, its caret, never placed before, sends "caret moved". Orca takes
//   that as the new focus, silently, then finds the focus event's object already its focus and
//   says nothing ("tab", and silence). A field whose caret was placed once while it was built
//   sends no caret event when it is focused.
// - Reached by Tab (or Shift+Tab, or a line edit by its shortcut), a field selects its whole
//   text as it takes the focus, and that selection was told before the focus: Orca said
//   "0,64 selected" and only then the field's label. Such a field now takes the focus
//   without selecting, Qt tells the focus, and the text is selected just after (at once if
//   a key comes first, so that typing still replaces it). Telling the focus twice instead
//   did not help: Orca drops the first of two equal focus events as a duplicate.

namespace rigidlab::ui {

/// Places the caret of every text field (line edits and the fields of spin boxes) as it is
/// made ready to show, and lets a field reached by Tab select its text only after its focus
/// is told, for the whole application (once; later calls do nothing).
void tellFieldFocusFirst();

} // namespace rigidlab::ui
