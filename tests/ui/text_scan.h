// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What test_untranslated counts as a text left in the other language: a text is cut into its
// sentences (pieces), and a piece that reads the same in both languages (invariant: numbers,
// units, keys, proper names) is no sign of a missing translation. test_text_scan checks these
// rules on their own; test_untranslated applies them to every text of the window.

#include <QRegularExpression>
#include <QSet>
#include <QString>
#include <QStringList>
#include <QTextDocumentFragment>

#include <algorithm>

namespace rigidlab::test {

/// Texts that are the same in Czech and in English, compared whole (after '&' mnemonics are
/// removed). Only proper names and symbols belong here; a method's name inside a longer
/// sentence needs no entry, because that sentence is translated around it.
inline const QSet<QString>& invariantTexts()
{
    static const QSet<QString> texts{
        QStringLiteral("RigidLab"),      // the program's name
        QStringLiteral("SAT"),           // the separating axis theorem's usual abbreviation
        QStringLiteral("Runge–Kutta"),   // people's names: integrators
        QStringLiteral("Runge–Kutta 4"), // the method's name with its order, in both languages
        QStringLiteral("Verlet"),        QStringLiteral("Euler"), QStringLiteral("Newton"),
        QStringLiteral("Box2D"),         QStringLiteral("Qt"),    QStringLiteral("Eigen"),
        QStringLiteral("QCustomPlot"),
        QStringLiteral("PNG"), // file formats
        QStringLiteral("PDF"),           QStringLiteral("SVG"),   QStringLiteral("CSV"),
        QStringLiteral("Tab"), // the key's name on a Czech keyboard too (Qt's Czech keeps it)
    };
    return texts;
}

/// Words of three letters or more that are the same in both languages wherever they stand.
inline const QStringList& sameWords()
{
    static const QStringList words{
        QStringLiteral("rad"),      // the unit radian
        QStringLiteral("drift"),    // a Czech word too: the translation says "energetický drift"
        QStringLiteral("interval"), // a Czech word too (the SAT table's projections)
    };
    return words;
}

/// The letters Czech has and English does not.
inline const QString& czechLetters()
{
    static const QString letters = QStringLiteral("ěščřžýůťďňĚŠČŘŽÝŮŤĎŇ");
    return letters;
}

/// A text without its mnemonic ampersands ("&&" is a literal one).
inline QString withoutMnemonics(QString text)
{
    text.replace(QStringLiteral("&&"), QStringLiteral("\x01"));
    text.remove(u'&');
    text.replace(u'\x01', u'&');
    return text;
}

/// A text's sentences or lines, rich text made plain: texts that are paragraphs are compared
/// sentence by sentence, so one untranslated sentence is found inside a translated paragraph.
inline QStringList pieces(const QString& text)
{
    QString plain = Qt::mightBeRichText(text) ? QTextDocumentFragment::fromHtml(text).toPlainText()
                                              : withoutMnemonics(text);
    plain.replace(QChar::ParagraphSeparator, u'\n');
    plain.replace(QChar::LineSeparator, u'\n');
    plain.replace(QChar::Nbsp, u' ');
    // Sentences end before a capital ("4. řádu" is one); a title joined to the program's name by
    // a dash, or titles joined by a dot, are split too, so that an untranslated scene title is
    // found inside a translated "%1 — RigidLab".
    static const QRegularExpression sentenceEnd(
        QStringLiteral("(?<=[.!?;])\\s+(?=\\P{Ll})|\\s+[–—·]\\s+|\\n"));
    QStringList out;
    for (const QString& piece : plain.split(sentenceEnd, Qt::SkipEmptyParts))
        if (const QString trimmed = piece.trimmed(); !trimmed.isEmpty())
            out << trimmed;
    return out;
}

/// Whether a text reads the same in every language: no word of three letters or more (numbers,
/// symbols, units such as "m/s" or "J"), a key ("Ctrl+Z"), or a name of invariantTexts().
inline bool invariant(const QString& piece)
{
    if (invariantTexts().contains(piece))
        return true;
    static const QRegularExpression keys(QStringLiteral("^(Ctrl|Shift|Alt|Meta)(\\+\\S+)+$"));
    if (keys.match(piece).hasMatch())
        return true;
    static const QRegularExpression word(QStringLiteral("\\p{L}{3,}"));
    auto it = word.globalMatch(piece);
    while (it.hasNext())
        if (!sameWords().contains(it.next().captured(), Qt::CaseInsensitive)) // "Drift" too
            return false;
    return true;
}

/// Whether a text has a letter that only Czech has.
inline bool hasCzechLetter(const QString& text)
{
    return std::any_of(text.cbegin(), text.cend(),
                       [](QChar ch) { return czechLetters().contains(ch); });
}

} // namespace rigidlab::test
