// SPDX-License-Identifier: GPL-3.0-or-later
#include "common/theme.h"

#include <algorithm>
#include <cmath>

namespace rigidlab::ui::theme {

namespace {
bool g_presentation = false; // one window per process; set from the GUI thread only
} // namespace

void setPresentation(bool on)
{
    g_presentation = on;
}

bool presentation()
{
    return g_presentation;
}

double lineWidth(double widthPx)
{
    return g_presentation ? std::max(widthPx * 1.5, kPresentationMinLinePx) : widthPx;
}

QColor worldBackground()
{
    return g_presentation ? QColor(Qt::white) : QColor(0xfb, 0xfb, 0xf8);
}

QColor worldGrid()
{
    return g_presentation ? QColor(0xc8, 0xc8, 0xc0) : QColor(0xe2, 0xe2, 0xdc);
}

QColor worldText()
{
    return g_presentation ? QColor(Qt::black) : QColor(0x1e, 0x1e, 0x1e); // 16:1 or 21:1
}

QColor worldAlertText()
{
    return QColor(0xa3, 0x1f, 0x14); // 7:1 on the background
}

QColor worldLabelBox()
{
    return worldBackground();
}

QColor satProjectionA()
{
    return QColor(0x2f, 0x6d, 0xb5); // blue
}

QColor satProjectionB()
{
    return QColor(0xd9, 0x6c, 0x1e); // orange
}

QColor satAxis()
{
    return QColor(0x5a, 0x5a, 0x5a);
}

QColor satGap()
{
    return QColor(0x1b, 0x7a, 0x3a); // dark green, 5.2:1 on the background
}

QColor satOverlap()
{
    return QColor(0x8e, 0x24, 0xaa); // purple, 6.8:1 on the background
}

QColor focusRing()
{
    return g_presentation ? QColor(Qt::black) : QColor(0x0b, 0x3d, 0x91); // 10:1 on #efefef
}

QColor focusHalo()
{
    return QColor(Qt::white);
}

QColor placeholderText()
{
    return QColor(0x5f, 0x5f, 0x5f); // 6.4:1 on white
}

QColor plotBackground()
{
    return QColor(Qt::white);
}

QColor alertBackground()
{
    return QColor(0xa3, 0x1f, 0x14); // a darker red than #c0392b, which gives white only 5.4:1
}

QColor alertText()
{
    return QColor(Qt::white); // 7:1 on the banner
}

double relativeLuminance(const QColor& c)
{
    // sRGB to linear light (IEC 61966-2-1), then the Rec. 709 weights.
    auto linear = [](double v) {
        return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
    };
    const QColor rgb = c.toRgb();
    return 0.2126 * linear(rgb.redF()) + 0.7152 * linear(rgb.greenF()) +
           0.0722 * linear(rgb.blueF());
}

double contrastRatio(const QColor& a, const QColor& b)
{
    const double la = relativeLuminance(a), lb = relativeLuminance(b);
    return (std::max(la, lb) + 0.05) / (std::min(la, lb) + 0.05);
}

} // namespace rigidlab::ui::theme
