// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The languages RigidLab's lessons ship in, and the one lessons are loaded in.
//
// Every text a student reads in a lesson may be a plain string (English) or an object
// {"en": ..., "cs": ...} (lessons/LESSON_FORMAT.md, "Languages"); the loader picks the
// language chosen here and falls back to English. The list below is the one place that names
// the languages, for the lessons and the window alike: a new one is one more row (and its
// texts in the lessons, and translations/rigidlab_CODE.ts).

#include <QString>
#include <QStringView>

#include <array>

namespace rigidlab::lessons {

struct Language {
    QStringView code;   ///< ISO 639-1, the key in a lesson's text objects
    QStringView name;   ///< in the language itself, for a language menu
    QStringView locale; ///< the locale numbers on screen follow in it ("cs_CZ": decimal comma)
};

/// The languages the lab ships, English (the fallback) first.
inline constexpr std::array kLanguages = {
    Language{u"en", u"English", u"en_US"},
    Language{u"cs", u"Čeština", u"cs_CZ"},
};

/// The language every lesson text has, shown when the chosen one is missing.
inline constexpr QStringView kFallbackLanguage = u"en";

/// Whether `code` is one of kLanguages.
bool isShippedLanguage(QStringView code);
/// The codes of kLanguages, "en, cs", for messages.
QString shippedLanguageCodes();
/// The name of a shipped language, or an empty string.
QString languageName(QStringView code);

/// The language lessons are loaded in when the caller names none (LessonLoadOptions):
/// "en" until an app sets it from the user's choice.
QString lessonLanguage();
/// Sets lessonLanguage(); false (and nothing changed) when `code` is not shipped.
bool setLessonLanguage(const QString& code);

} // namespace rigidlab::lessons
