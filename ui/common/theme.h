// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The colours of everything the lab draws over the world, in one place, with the contrast
// they are chosen for. The world's background is the lab's own (it does not follow the
// system palette), so text drawn over it is dark in every palette; the banner paints its own
// opaque background. A presentation palette can replace these later, here only.
//
// Contrast follows WCAG 2.x: relative luminance of sRGB colours, ratio (L1 + 0.05)/(L2 + 0.05)
// of the lighter to the darker; 4.5:1 is the least for normal text (success criterion 1.4.3).

#include <QColor>

namespace rigidlab::ui::theme {

/// Text needs at least this contrast against what lies behind it (WCAG 1.4.3, level AA).
inline constexpr double kMinTextContrast = 4.5;

/// The world's background and its grid lines.
QColor worldBackground();
QColor worldGrid();
/// Text and the scale bar drawn over the world (legend, scale, labels at ghosts).
QColor worldText();
/// A stopped world's diagnosis over the world: dark red, readable on the background.
QColor worldAlertText();
/// The label box behind a diagnosis drawn at a ghost: the world's background, opaque, so the
/// text stays readable over bodies and grid lines.
QColor worldLabelBox();

/// The separating-axis overlay: each polygon's projection interval (and its axis edge), the
/// axis line, and the gap or the overlap between the intervals, each a colour of its own. The
/// gap and overlap colours also write their labels (on a worldLabelBox()), so they keep
/// kMinTextContrast against the world's background.
QColor satProjectionA();
QColor satProjectionB();
QColor satAxis();
QColor satGap();
QColor satOverlap();

/// Lines and overlays need at least this contrast against what lies behind them (WCAG 1.4.11,
/// non-text contrast): plot curves, arrows, the focus ring.
inline constexpr double kMinOverlayContrast = 3.0;

/// The keyboard focus ring (common/focus_ring.h): dark, at least kMinOverlayContrast against
/// the window's light backgrounds, with a light halo that gives it the same against anything
/// dark beneath.
QColor focusRing();
QColor focusHalo();
/// The hint in an empty field ("your answer"): Qt's is the text at half opacity, 4:1 on
/// white; this grey keeps kMinTextContrast.
QColor placeholderText();
/// The background the plots are drawn on (window, presentation and exports alike).
QColor plotBackground();

/// The divergence banner: its opaque background and its text.
QColor alertBackground();
QColor alertText();

/// Presentation mode (a projector at the back of a bright room): the world's background turns
/// pure white, its grid and text darker, and every line at least kPresentationMinLinePx wide.
void setPresentation(bool on);
bool presentation();
/// The least width of a line in presentation mode [px]: visible from the back of a room.
inline constexpr double kPresentationMinLinePx = 3.0;
/// How much larger text is in presentation mode.
inline constexpr double kPresentationFontScale = 1.5;
/// How much larger than the system's text the texts a class reads are (the lesson's text, the
/// status bar), in every mode: a projector at 1024×768 is read from the back of the room.
inline constexpr double kReadingFontScale = 1.25;
/// A line drawn `widthPx` wide in the window, as wide as it is drawn now [px].
double lineWidth(double widthPx);

/// WCAG relative luminance of an sRGB colour, 0 (black) to 1 (white); alpha is ignored.
double relativeLuminance(const QColor& c);
/// WCAG contrast ratio of two colours, from 1 (the same) to 21 (black on white).
double contrastRatio(const QColor& a, const QColor& b);

} // namespace rigidlab::ui::theme
