// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Names that change with the clock ("t = 2.350 s", the energy drift, "step 140 of 140", an
// inspector's "Velocity v: (0.5, minus 1.2) m/s"), told to a screen reader at a pace a person
// can follow. A widget tells assistive technology of every new name (a QLabel of every new
// text), which for one redrawn each frame is 30 to 60 events a second that nobody can listen
// to and that bury the ones that matter. A calm name changes at most once every
// kCalmIntervalMs, and always ends on the last one asked for.

class QLabel;
class QString;
class QWidget;

namespace rigidlab::ui {

/// The least time between two changes of a calm accessible name [ms].
constexpr int kCalmIntervalMs = 1000;

/// Gives `widget` the accessible name `name` at the calm rate: at once when its last change
/// is kCalmIntervalMs old, else when it is (with the newest name asked for by then). With
/// `now` (a change the student made, not the clock), at once in any case.
void setCalmAccessibleName(QWidget& widget, const QString& name, bool now = false);
/// The same for its accessible description.
void setCalmAccessibleDescription(QWidget& widget, const QString& description, bool now = false);

/// Shows `text` in `label` now; its accessible name, the text with a negative number's sign
/// said as "minus" (spoken_numbers.h), follows at the calm rate. (While a label has an
/// accessible name of its own, QLabel::setText tells assistive technology nothing.)
void setCalmText(QLabel& label, const QString& text);

/// setCalmText for a label whose text changes every frame while the run goes (the clock),
/// with `hold` then: the label keeps its size, grown only when the text needs more, and no
/// less than `minimumWidth` [px]. A label that takes the size of each new text asks its bar,
/// and through it the whole window with its docks, to be laid out again: 60 times a second,
/// a few per cent of the base-100 pyramid's frame. Without `hold` (paused) it takes
/// the size of its text again.
void setSteadyText(QLabel& label, const QString& text, bool hold, int minimumWidth = 0);

} // namespace rigidlab::ui
