// SPDX-License-Identifier: GPL-3.0-or-later
#include "common/language.h"

#include <QCoreApplication>
#include <QLibraryInfo>
#include <QPointer>
#include <QSettings>
#include <QTranslator>

namespace rigidlab::ui {

namespace {

const QString kSettingKey = QStringLiteral("language");

/// The translators in effect, owned by the application; null before the first language.
struct Installed {
    QPointer<QTranslator> lab;
    QPointer<QTranslator> qt;
    QString code = lessons::kFallbackLanguage.toString();
};

Installed& installed()
{
    static Installed s;
    return s;
}

void remove(QPointer<QTranslator>& translator)
{
    if (!translator)
        return;
    QCoreApplication::removeTranslator(translator);
    delete translator;
}

} // namespace

const lessons::Language* findLanguage(const QString& code)
{
    for (const lessons::Language& l : lessons::kLanguages)
        if (code == l.code)
            return &l;
    return nullptr;
}

QString languageForLocale(const QLocale& system)
{
    // The shipped language the system speaks, by the language of each one's locale.
    for (const lessons::Language& l : lessons::kLanguages)
        if (QLocale(l.locale.toString()).language() == system.language())
            return l.code.toString();
    return lessons::kFallbackLanguage.toString();
}

QString chooseLanguage(const QString& commandLine, const QString& saved, const QLocale& system)
{
    if (findLanguage(commandLine))
        return commandLine;
    if (findLanguage(saved))
        return saved;
    return languageForLocale(system);
}

QString savedLanguage()
{
    const QString code = QSettings().value(kSettingKey).toString();
    return findLanguage(code) ? code : QString();
}

bool saveLanguage(const QString& code)
{
    if (!findLanguage(code))
        return false;
    QSettings s;
    s.setValue(kSettingKey, code);
    s.sync();
    return s.status() == QSettings::NoError;
}

bool applyLanguage(const QString& code)
{
    const lessons::Language* language = findLanguage(code);
    if (!language)
        return false;
    Installed& now = installed();
    remove(now.lab);
    remove(now.qt);

    const QLocale locale(language->locale.toString());
    QLocale::setDefault(locale);
    QCoreApplication* app = QCoreApplication::instance();
    // English is the sources' language: its .qm holds only the plural forms ("1 step").
    auto* lab = new QTranslator(app);
    if (lab->load(QStringLiteral(":/i18n/rigidlab_") + code) &&
        QCoreApplication::installTranslator(lab))
        now.lab = lab;
    else
        delete lab;
    auto* qt = new QTranslator(app);
    if (qt->load(locale, QStringLiteral("qtbase"), QStringLiteral("_"),
                 QLibraryInfo::path(QLibraryInfo::TranslationsPath)) &&
        QCoreApplication::installTranslator(qt))
        now.qt = qt;
    else
        delete qt;
    now.code = code;
    lessons::setLessonLanguage(code); // lessons open in the window's language
    return true;
}

QString currentLanguage()
{
    return installed().code;
}

} // namespace rigidlab::ui
