// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The texts a student reads, in the language a lesson or scene is loaded in
// (lessons/LESSON_FORMAT.md, "Languages"; lessons/SCENE_FORMAT.md, "title" and "description").
// Each is a plain string, meaning English, or an object that maps language codes (languages.h)
// to the same kind of value:
//
//     "title": "Bounces"
//     "title": {"en": "Bounces", "cs": "Odrazy"}
//     "text": {"en": ["...", "..."], "cs": ["...", "..."]}
//
// One language is enough. A text without the chosen language is shown in English, or without
// English in the language it has (textLanguage, languages.h). A code the lab does not ship, an
// object with no language, or a value of the wrong kind, is an error with its place, like every
// other.

#include "format/json_reader.h"

#include <utility>
#include <vector>

namespace rigidlab::lessons::detail {

class LocalTexts {
public:
    /// `whole` is the warning of a language no text has, "no %1 text (\"%2\") in the whole
    /// lesson: it will show in %3" (the language, its code, the one shown instead).
    LocalTexts(JsonReader& in, QString language, QString whole)
        : m_in(in), m_language(std::move(language)), m_whole(std::move(whole))
    {
    }

    /// The language the texts are kept in.
    const QString& language() const { return m_language; }

    /// A text at `object[key]`: "..." or {"en": "...", ...}. Absent: `out` is left as it
    /// was, which is fine unless `required`.
    bool line(const QJsonObject& object, QStringView key, const QString& place, QString& out,
              bool required = false);
    /// A unit at `object[key]`, read as line(): a plain string is a symbol ("m", "J·s"), the
    /// same in every language, so it lacks none; a worded unit may be an object of languages.
    bool unit(const QJsonObject& object, QStringView key, const QString& place, QString& out);
    /// Paragraphs at `object[key]`: "...", ["...", ...] (joined with line breaks), or an
    /// object of languages holding either.
    bool paragraphs(const QJsonObject& object, QStringView key, const QString& place, QString& out);
    /// A list of non-empty texts at `object[key]`, at most `maxItems` (`noun` names them in the
    /// message): [text, ...], each a string or an object of languages, or
    /// {"en": ["...", ...], ...}.
    bool list(const QJsonObject& object, QStringView key, const QString& place, qsizetype maxItems,
              QStringView noun, QStringList& out);

    /// Each language's version of the text line() last read, with its place (the text's own
    /// for a plain string, `PLACE.cs` in an object), for the checks a text has in every
    /// language.
    struct Variant {
        QString place;
        QString text;
    };
    const std::vector<Variant>& variants() const { return m_variants; }

    /// Warns of each text that lacks a shipped language, saying where, which and the language
    /// it shows in instead; a language no text has is one warning. Called once the whole lesson
    /// or scene is read: one with no text in the object form is in English only, and warns of
    /// nothing.
    void warnMissing();

private:
    /// Reads one language's version of a text at `place`.
    using ReadOne = bool (LocalTexts::*)(const QJsonValue& value, const QString& place,
                                         QString& out);
    bool oneLine(const QJsonValue& value, const QString& place, QString& out);
    bool oneParagraphs(const QJsonValue& value, const QString& place, QString& out);
    /// A plain value or an object of languages; `plainKinds` says what a plain value may be,
    /// for the message.
    bool readText(const QJsonValue& value, const QString& place, ReadOne one,
                  QStringView plainKinds, QString& out);
    /// The object of languages at `place`: every key a shipped code, at least one.
    bool checkLanguages(const QJsonObject& object, const QString& place);
    /// Notes the shipped languages `present` lacks, for warnMissing().
    void noteMissing(const QString& place, const QStringList& present);

    struct Missing {
        QString place;
        QString code;    ///< the language the text lacks
        QString shownIn; ///< the language it shows in instead
    };

    JsonReader& m_in;
    QString m_language;
    QString m_whole;
    bool m_translated = false; ///< some text is in the object form
    int m_texts = 0;           ///< the texts read that a language could be missing from
    std::vector<Missing> m_missing;
    std::vector<Variant> m_variants;
};

} // namespace rigidlab::lessons::detail
