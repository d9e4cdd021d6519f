// SPDX-License-Identifier: GPL-3.0-or-later
#include "common/drawable_text.h"

#include <QCoreApplication>
#include <QGlyphRun>
#include <QHash>
#include <QTextLayout>

namespace rigidlab::ui {

namespace {

struct DrawableWords {
    Q_DECLARE_TR_FUNCTIONS(DrawableWords)
};

/// Code points that draw nothing by design: controls, the soft hyphen, joiners and marks,
/// bidirectional marks and isolates, variation selectors, the byte order mark, tags.
bool drawsNothing(char32_t c)
{
    return c < 0x20 || (c >= 0x7F && c < 0xA0) || c == 0xAD || (c >= 0x200B && c <= 0x200F) ||
           (c >= 0x2028 && c <= 0x202E) || (c >= 0x2060 && c <= 0x206F) ||
           (c >= 0xFE00 && c <= 0xFE0F) || c == 0xFEFF || (c >= 0xE0000 && c <= 0xE0FFF);
}

} // namespace

bool canDraw(char32_t ucs4, const QFont& font)
{
    if (ucs4 < 0x80 || drawsNothing(ucs4))
        return true;
    // Fonts do not change while the lab runs: one layout per font and character.
    static QHash<QString, bool> known;
    const QString key = font.key() + QLatin1Char('/') + QString::number(ucs4, 16);
    if (const auto it = known.constFind(key); it != known.constEnd())
        return *it;
    // Laid out, the character is given a glyph of the font or of a fallback font; glyph 0 is
    // the "missing glyph" of a font that does not have it.
    QTextLayout layout(QString::fromUcs4(&ucs4, 1), font);
    layout.beginLayout();
    layout.createLine();
    layout.endLayout();
    bool drawn = false;
    for (const QGlyphRun& run : layout.glyphRuns()) {
        const QList<quint32> glyphs = run.glyphIndexes();
        drawn = !glyphs.isEmpty();
        for (const quint32 glyph : glyphs)
            drawn = drawn && glyph != 0;
        if (!drawn)
            break;
    }
    known.insert(key, drawn);
    return drawn;
}

QString drawableText(const QString& text, const QFont& font)
{
    QString out;
    bool changed = false;
    for (const char32_t c : text.toUcs4()) {
        if (canDraw(c, font)) {
            out += QString::fromUcs4(&c, 1);
            continue;
        }
        changed = true;
        out += DrawableWords::tr("[U+%1]").arg(QString::number(c, 16).toUpper());
    }
    return changed ? out : text;
}

} // namespace rigidlab::ui
