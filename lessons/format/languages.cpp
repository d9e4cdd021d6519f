// SPDX-License-Identifier: GPL-3.0-or-later
#include "format/languages.h"

#include <QCoreApplication>
#include <QStringList>

namespace rigidlab::lessons {

namespace {

/// The process's choice: one value, set by the app's main or its language menu, read by the
/// loaders (the lesson player, the lesson catalogue, rigidlab-cli).
QString& chosenLanguage()
{
    static QString language = kFallbackLanguage.toString();
    return language;
}

} // namespace

bool isShippedLanguage(QStringView code)
{
    for (const Language& l : kLanguages) {
        if (l.code == code)
            return true;
    }
    return false;
}

QString shippedLanguageCodes()
{
    QStringList codes;
    for (const Language& l : kLanguages)
        codes.append(l.code.toString());
    return codes.join(u", ");
}

QString languageName(QStringView code)
{
    for (const Language& l : kLanguages) {
        if (l.code == code)
            return l.name.toString();
    }
    return {};
}

QString languageTitle(QStringView code)
{
    for (const Language& l : kLanguages) {
        if (l.code == code)
            return QCoreApplication::translate("rigidlab::lessons::Language", l.title);
    }
    return code.toString();
}

QString textLanguage(QStringView wanted, const QStringList& present)
{
    if (present.contains(wanted))
        return wanted.toString();
    if (present.contains(kFallbackLanguage))
        return kFallbackLanguage.toString();
    for (const Language& l : kLanguages) {
        if (present.contains(l.code))
            return l.code.toString();
    }
    return {};
}

QString lessonLanguage()
{
    return chosenLanguage();
}

bool setLessonLanguage(const QString& code)
{
    if (!isShippedLanguage(code))
        return false;
    chosenLanguage() = code;
    return true;
}

} // namespace rigidlab::lessons
