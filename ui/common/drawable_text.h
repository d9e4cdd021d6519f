// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Text the lab's fonts cannot draw, made visible. A character that no installed font has (an
// emoji in a student's name or a lesson's title, on a school PC with only text fonts) would be
// drawn as nothing at all in a PDF, or as an empty box on the screen: lost without a word.
// drawableText puts a placeholder naming its code point in its place ("Anna [U+1F980]"), so a
// teacher reading the worksheet sees that something was there and what it was. Characters
// some font has, through Qt's fallback fonts too, stay as they are.

#include <QFont>
#include <QString>

namespace rigidlab::ui {

/// `text` with each character that neither `font` nor any fallback font can draw replaced by
/// "[U+XXXX]". Format characters that draw nothing by design (joiners, variation selectors,
/// bidirectional marks and isolates, line breaks) stay.
QString drawableText(const QString& text, const QFont& font);

/// Whether `font` or a fallback font of it has a glyph for the code point `ucs4`.
bool canDraw(char32_t ucs4, const QFont& font);

} // namespace rigidlab::ui
