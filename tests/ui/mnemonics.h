// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Underlined letters ("&File") that two entries of one menu, or two controls of one window,
// share: Alt and that letter then only moves between them instead of choosing one.

#include <QAbstractButton>
#include <QGroupBox>
#include <QLabel>
#include <QMap>
#include <QStringList>
#include <QTabBar>
#include <QWidget>

namespace rigidlab::test {

/// The letter after a text's mnemonic '&' (lower case), or a null char when it has none.
inline QChar mnemonicOf(const QString& text)
{
    for (qsizetype i = 0; i + 1 < text.size(); ++i) {
        if (text[i] != u'&')
            continue;
        if (text[i + 1] == u'&') {
            ++i; // "&&" is a literal ampersand
            continue;
        }
        return text[i + 1].toLower();
    }
    return {};
}

/// The texts of `letters` that share a letter, one line each: "k: Nová le&kce, &Klíč…".
inline QStringList sharedLetters(const QMap<QChar, QStringList>& letters)
{
    QStringList out;
    for (auto it = letters.cbegin(); it != letters.cend(); ++it)
        if (it.value().size() > 1)
            out << QStringLiteral("%1: %2").arg(it.key()).arg(
                it.value().join(QStringLiteral(", ")));
    return out;
}

/// The underlined letters of the controls of `window` shown now (not those of other windows
/// inside it), each with its texts: labels that name a control, buttons, group boxes, tabs.
inline QMap<QChar, QStringList> windowMnemonics(QWidget& window)
{
    QMap<QChar, QStringList> letters;
    const auto add = [&letters](const QString& text) {
        if (const QChar c = mnemonicOf(text); !c.isNull())
            letters[c] << text;
    };
    for (QWidget* w : window.findChildren<QWidget*>()) {
        if (w->window() != &window || !w->isVisibleTo(&window))
            continue;
        if (auto* label = qobject_cast<QLabel*>(w); label && label->buddy())
            add(label->text());
        else if (auto* button = qobject_cast<QAbstractButton*>(w))
            add(button->text());
        else if (auto* box = qobject_cast<QGroupBox*>(w))
            add(box->title());
        else if (auto* tabs = qobject_cast<QTabBar*>(w))
            for (int i = 0; i < tabs->count(); ++i)
                add(tabs->tabText(i));
    }
    return letters;
}

/// The controls of `window` shown now that share their underlined letter.
inline QStringList windowMnemonicClashes(QWidget& window)
{
    return sharedLetters(windowMnemonics(window));
}

} // namespace rigidlab::test
