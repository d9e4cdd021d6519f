// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A list's current item is where the arrow keys go, and Qt's accessible list cells report the
// current item "focused" whether or not the list has the focus: a screen reader walking the
// window met the History list's "Scene as opened" as focused while the keys were in the scene.
// So a view given to keepCurrentOnlyWhileFocused has a current item only while it has the
// focus: out of it the current index is cleared (the selection, what the list shows chosen,
// stays), and the focus coming in makes the selected item current again before the view would
// pick its first row. QUndoView's model follows the current index to the stack's index and
// ignores an invalid one, so clearing it undoes nothing.

class QAbstractItemView;

namespace rigidlab::ui {

void keepCurrentOnlyWhileFocused(QAbstractItemView& view);

} // namespace rigidlab::ui
