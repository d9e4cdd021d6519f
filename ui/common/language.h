// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The window's languages (the list is lessons::kLanguages): which one to start in, and
// putting one in effect (RigidLab's translation, Qt's own for its standard dialogs, and the locale
// that numbers on screen follow). Files always use the decimal point, whatever the language.

#include "format/languages.h"

#include <QLocale>
#include <QString>

namespace rigidlab::ui {

/// The language with this code, or nullptr.
const lessons::Language* findLanguage(const QString& code);

/// The language for a system locale: Czech for a Czech one, English otherwise.
QString languageForLocale(const QLocale& system);

/// The language to start in: `commandLine` (rigidlab --lang) when it names one, else `saved`
/// (the setting) when it names one, else the system locale's.
QString chooseLanguage(const QString& commandLine, const QString& saved, const QLocale& system);

/// The language saved by View › Language (QSettings "language"), empty when none is.
QString savedLanguage();
/// Saves the choice for the next start; false if the settings could not be written.
bool saveLanguage(const QString& code);

/// Puts a language in effect: RigidLab's translation from :/i18n, Qt's own (qtbase) from
/// Qt's translations folder, and QLocale::setDefault to its locale. Translators of an earlier
/// language are removed first. An unknown code changes nothing and returns false; a missing
/// Qt translation is no error (its dialogs stay English).
bool applyLanguage(const QString& code);

/// The code of the language last put in effect ("en" before any).
QString currentLanguage();

} // namespace rigidlab::ui
