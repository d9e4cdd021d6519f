// SPDX-License-Identifier: GPL-3.0-or-later
#include "format/local_text.h"

#include "format/languages.h"

namespace rigidlab::lessons::detail {

bool LocalTexts::oneLine(const QJsonValue& value, const QString& place, QString& out)
{
    if (!value.isString()) {
        return m_in.fail(place,
                         FileMessages::tr("must be a string \"...\", got ") + describeJson(value));
    }
    out = value.toString();
    return true;
}

bool LocalTexts::oneParagraphs(const QJsonValue& value, const QString& place, QString& out)
{
    // A string, or an array of strings (one per line or paragraph), which is easier to write
    // and to read in a JSON file; the lines are joined with line breaks.
    if (value.isString()) {
        out = value.toString();
        return true;
    }
    if (!value.isArray()) {
        return m_in.fail(place, FileMessages::tr("must be a string or an array of strings, got ") +
                                    describeJson(value));
    }
    const QJsonArray lines = value.toArray();
    QStringList parts;
    for (qsizetype i = 0; i < lines.size(); ++i) {
        if (!lines[i].isString()) {
            return m_in.fail(indexPlace(place, i),
                             FileMessages::tr("must be a string \"...\", got ") +
                                 describeJson(lines[i]));
        }
        parts.append(lines[i].toString());
    }
    out = parts.join(u'\n');
    return true;
}

bool LocalTexts::checkLanguages(const QJsonObject& object, const QString& place)
{
    for (auto it = object.constBegin(); it != object.constEnd(); ++it) {
        if (!isShippedLanguage(it.key())) {
            return m_in.fail(joinPlace(place, it.key()),
                             FileMessages::tr("unknown language \"%1\" (expected %2)")
                                 .arg(it.key(), shippedLanguageCodes()));
        }
    }
    // One language is enough: a text written only in Czech is shown in Czech everywhere.
    if (object.isEmpty()) {
        return m_in.fail(place, FileMessages::tr("needs a text in at least one language (%1)")
                                    .arg(shippedLanguageCodes()));
    }
    m_translated = true;
    return true;
}

void LocalTexts::noteMissing(const QString& place, const QStringList& present)
{
    ++m_texts;
    for (const Language& l : kLanguages) {
        if (!present.contains(l.code.toString()))
            m_missing.push_back({place, l.code.toString(), textLanguage(l.code, present)});
    }
}

bool LocalTexts::readText(const QJsonValue& value, const QString& place, ReadOne one,
                          QStringView plainKinds, QString& out)
{
    m_variants.clear();
    if (m_in.failed()) {
        return false;
    }
    if (!value.isObject()) {
        if (!value.isString() && !value.isArray()) {
            return m_in.fail(place, FileMessages::tr("must be %1, or an object of languages "
                                                     "{\"en\": ..., \"cs\": ...}, got ")
                                            .arg(plainKinds.toString()) +
                                        describeJson(value));
        }
        QString text;
        if (!(this->*one)(value, place, text)) {
            return false;
        }
        m_variants.push_back({place, text});
        noteMissing(place, {kFallbackLanguage.toString()});
        out = text;
        return true;
    }
    const QJsonObject object = value.toObject();
    if (!checkLanguages(object, place)) {
        return false;
    }
    const QString shown = textLanguage(m_language, object.keys());
    for (const Language& l : kLanguages) {
        const auto it = object.constFind(l.code);
        if (it == object.constEnd()) {
            continue;
        }
        QString text;
        const QString at = joinPlace(place, l.code);
        if (!(this->*one)(it.value(), at, text)) {
            return false;
        }
        m_variants.push_back({at, text});
        if (l.code == shown)
            out = text;
    }
    noteMissing(place, object.keys());
    return true;
}

bool LocalTexts::line(const QJsonObject& object, QStringView key, const QString& place,
                      QString& out, bool required)
{
    m_variants.clear();
    if (m_in.failed()) {
        return false;
    }
    const QString at = joinPlace(place, key);
    const auto it = object.constFind(key);
    if (it == object.constEnd()) {
        return !required || m_in.fail(at, FileMessages::tr("required, but missing"));
    }
    if (it.value().isArray()) {
        return m_in.fail(at, FileMessages::tr("must be a string \"...\", or an object of languages "
                                              "{\"en\": \"...\", \"cs\": \"...\"}, got ") +
                                 describeJson(it.value()));
    }
    return readText(it.value(), at, &LocalTexts::oneLine, u"a string \"...\"", out);
}

bool LocalTexts::unit(const QJsonObject& object, QStringView key, const QString& place,
                      QString& out)
{
    const std::size_t missingBefore = m_missing.size();
    const int textsBefore = m_texts;
    const bool ok = line(object, key, place, out);
    if (ok && object.value(key).isString()) {
        m_missing.resize(missingBefore);
        m_texts = textsBefore; // a symbol is no text of any language
    }
    return ok;
}

bool LocalTexts::paragraphs(const QJsonObject& object, QStringView key, const QString& place,
                            QString& out)
{
    m_variants.clear();
    const auto it = object.constFind(key);
    if (it == object.constEnd()) {
        return !m_in.failed();
    }
    return readText(it.value(), joinPlace(place, key), &LocalTexts::oneParagraphs,
                    u"a string or an array of strings", out);
}

bool LocalTexts::list(const QJsonObject& object, QStringView key, const QString& place,
                      qsizetype maxItems, QStringView noun, QStringList& out)
{
    m_variants.clear();
    const auto found = object.constFind(key);
    if (m_in.failed() || found == object.constEnd()) {
        return !m_in.failed();
    }
    const QString at = joinPlace(place, key);
    // One language's list: its size, and each item a non-empty string.
    const auto readItems = [&](const QJsonArray& items, const QString& itemsAt,
                               bool itemsMayBeObjects, QStringList& texts) {
        if (items.size() > maxItems) {
            return m_in.fail(itemsAt, FileMessages::tr("%1 %2, more than the limit of %3")
                                          .arg(items.size())
                                          .arg(noun.toString())
                                          .arg(maxItems));
        }
        for (qsizetype i = 0; i < items.size(); ++i) {
            const QString itemAt = indexPlace(itemsAt, i);
            QString text;
            if (itemsMayBeObjects && items[i].isObject()) {
                if (!readText(items[i], itemAt, &LocalTexts::oneLine, u"a string \"...\"", text))
                    return false;
                for (const Variant& v : m_variants) {
                    if (v.text.trimmed().isEmpty())
                        return m_in.fail(v.place, FileMessages::tr("must not be empty"));
                }
            } else {
                if (!items[i].isString() || items[i].toString().trimmed().isEmpty()) {
                    return m_in.fail(itemAt,
                                     FileMessages::tr("must be a non-empty string \"...\", got ") +
                                         describeJson(items[i]));
                }
                text = items[i].toString();
                if (itemsMayBeObjects)
                    noteMissing(itemAt, {kFallbackLanguage.toString()});
            }
            texts.append(text);
        }
        return true;
    };
    if (found.value().isArray()) {
        return readItems(found.value().toArray(), at, true, out);
    }
    if (!found.value().isObject()) {
        return m_in.fail(at, FileMessages::tr("must be an array [...], or an object of languages "
                                              "{\"en\": [...], \"cs\": [...]}, got ") +
                                 describeJson(found.value()));
    }
    const QJsonObject languages = found.value().toObject();
    if (!checkLanguages(languages, at)) {
        return false;
    }
    const QString shown = textLanguage(m_language, languages.keys());
    for (const Language& l : kLanguages) {
        const auto it = languages.constFind(l.code);
        if (it == languages.constEnd()) {
            continue;
        }
        const QString languageAt = joinPlace(at, l.code);
        if (!it.value().isArray()) {
            return m_in.fail(languageAt, FileMessages::tr("must be an array [...], got ") +
                                             describeJson(it.value()));
        }
        QStringList texts;
        if (!readItems(it.value().toArray(), languageAt, false, texts)) {
            return false;
        }
        if (l.code == shown)
            out = texts;
    }
    noteMissing(at, languages.keys());
    return true;
}

void LocalTexts::warnMissing()
{
    if (!m_translated) {
        return;
    }
    // A language no text has is said once, for the whole lesson or scene; a language some texts
    // lack is said of each of them.
    for (const Language& l : kLanguages) {
        std::vector<const Missing*> lacking;
        for (const Missing& m : m_missing) {
            if (m.code == l.code)
                lacking.push_back(&m);
        }
        if (lacking.empty())
            continue;
        const Missing& first = *lacking.front();
        if (static_cast<int>(lacking.size()) == m_texts && m_texts > 1) {
            m_in.warn(first.place, m_whole.arg(languageTitle(first.code), first.code,
                                               languageTitle(first.shownIn)));
            continue;
        }
        for (const Missing* m : lacking) {
            m_in.warn(m->place,
                      FileMessages::tr("no %1 text (\"%2\"): it will show in %3")
                          .arg(languageTitle(m->code), m->code, languageTitle(m->shownIn)));
        }
    }
}

} // namespace rigidlab::lessons::detail
