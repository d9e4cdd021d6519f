// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The languages RigidLab's lessons ship in, and the one lessons are loaded in.
//
// Every text a student reads in a lesson may be a plain string (English) or an object
// {"en": ..., "cs": ...} (lessons/LESSON_FORMAT.md, "Languages"), which may hold one language
// only: a lesson written in Czech alone is a lesson like any other. The loader picks the
// language chosen here; a text without it is shown in English, or, without English, in the
// first language of the list it has (textLanguage). The list below is the one place that names
// the languages, for the lessons and the window alike: a new one is one more row (and its
// texts in the lessons, and translations/rigidlab_CODE.ts).

#include <QString>
#include <QStringList>
#include <QStringView>
#include <QtGlobal>

#include <array>

namespace rigidlab::lessons {

struct Language {
    QStringView code;   ///< ISO 639-1, the key in a lesson's text objects
    QStringView name;   ///< in the language itself, for a language menu
    QStringView locale; ///< the locale numbers on screen follow in it ("cs_CZ": decimal comma)
    /// Its name in English, translated by the lab's translation (languageTitle): "Czech" in an
    /// English window, "čeština" in a Czech one.
    const char* title = nullptr;
};

/// The languages the lab ships, English (the fallback) first.
inline constexpr std::array kLanguages = {
    Language{u"en", u"English", u"en_US",
             QT_TRANSLATE_NOOP("rigidlab::lessons::Language", "English")},
    Language{u"cs", u"Čeština", u"cs_CZ",
             QT_TRANSLATE_NOOP("rigidlab::lessons::Language", "Czech")},
};

/// The language a text is shown in first when the chosen one is missing.
inline constexpr QStringView kFallbackLanguage = u"en";

/// Whether `code` is one of kLanguages.
bool isShippedLanguage(QStringView code);
/// The codes of kLanguages, "en, cs", for messages.
QString shippedLanguageCodes();
/// The name of a shipped language, or an empty string.
QString languageName(QStringView code);
/// The name of a shipped language in the window's language ("Czech", "čeština"), or `code`.
QString languageTitle(QStringView code);

/// The language a text written in the languages `present` is shown in when `wanted` is asked
/// for: `wanted` when the text has it, else English when it has that, else the first language of
/// kLanguages it has. Empty when it has none. The one rule for the loaders, the writers and the
/// lesson editor.
QString textLanguage(QStringView wanted, const QStringList& present);

/// The language lessons are loaded in when the caller names none (LessonLoadOptions):
/// "en" until an app sets it from the user's choice.
QString lessonLanguage();
/// Sets lessonLanguage(); false (and nothing changed) when `code` is not shipped.
bool setLessonLanguage(const QString& code);

} // namespace rigidlab::lessons
