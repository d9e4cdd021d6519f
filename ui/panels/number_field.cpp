// SPDX-License-Identifier: GPL-3.0-or-later
#include "panels/number_field.h"

#include "common/announcer.h"
#include "common/number_format.h"

#include <QKeyEvent>
#include <QLocale>
#include <QRegularExpression>
#include <QToolTip>

#include <charconv>
#include <cmath>

namespace rigidlab::ui {

namespace {

/// The field's look when what was typed is refused: dark text on light red, so the number
/// stays readable.
const char* const kRefusedStyle =
    "QLineEdit { border: 2px solid #b3261e; background: #fde7e5; color: #1b1b1b; }";

/// What QLocale() writes, in ASCII: its digits, signs, decimal separator and exponent
/// (Arabic-Indic digits, U+2212 minus, "×10^" in Swedish), without the bidi marks some
/// locales put before a sign. Anything else stays, for the form check to refuse.
QString toAscii(const QString& text)
{
    const QLocale locale;
    QString s = text;
    for (const QString& exponent : {locale.exponential(), QStringLiteral("×10^")})
        if (exponent.compare(QLatin1String("e"), Qt::CaseInsensitive) != 0)
            s.replace(exponent, QStringLiteral("e"));
    QString out;
    out.reserve(s.size());
    for (const QChar c : s) {
        if (c.unicode() < 0x80)
            out += c;
        else if (c.category() == QChar::Other_Format)
            continue; // U+200E, U+061C...: direction marks, not part of the number
        else if (c.isDigit() && c.digitValue() >= 0)
            out += QChar(u'0' + c.digitValue());
        else if (c == QChar(0x2212) || QString(c) == locale.negativeSign())
            out += u'-';
        else if (QString(c) == locale.positiveSign())
            out += u'+';
        else if (c == QChar(0x066B) || QString(c) == locale.decimalPoint())
            out += u'.';
        else
            out += c;
    }
    return out;
}

/// Whether `s` (in ASCII, trimmed) is written as a number: one decimal separator at most,
/// point or comma ("6,4" and "6.4" are the same number in every locale, and "1,2,3", a list or
/// thousands, is no number).
bool hasNumberForm(const QString& s)
{
    static const QRegularExpression kForm(
        QStringLiteral("^[+-]?([0-9]+([.,][0-9]*)?|[.,][0-9]+)([eE][+-]?[0-9]+)?$"));
    return kForm.match(s).hasMatch();
}

} // namespace

std::optional<double> parseNumber(const QString& text)
{
    const QString s = toAscii(text).trimmed();
    if (!hasNumberForm(s))
        return std::nullopt;
    QByteArray bytes = s.toLatin1();
    bytes.replace(',', '.');
    if (bytes.startsWith('+'))
        bytes.remove(0, 1);
    // from_chars reads the C locale whatever the process's, and reports both overflow
    // ("1e999") and underflow ("1e-400") instead of rounding them to inf or 0.
    double v = 0.0;
    const char* end = bytes.constData() + bytes.size();
    const auto [ptr, ec] = std::from_chars(bytes.constData(), end, v);
    if (ec != std::errc() || ptr != end)
        return std::nullopt;
    if (!std::isfinite(v))
        return std::nullopt;
    return v == 0.0 ? 0.0 : v; // "-0" is 0
}

QString formatNumber(double v, int significant)
{
    QLocale locale;
    locale.setNumberOptions(QLocale::OmitGroupSeparator);
    return locale.toString(v == 0.0 ? 0.0 : v, 'g', significant);
}

NumberField::NumberField(QWidget* parent) : QLineEdit(parent)
{
    display(m_value, m_digits);
}

void NumberField::setRange(const lessons::limits::Range& range, const QString& name,
                           const QString& unit)
{
    m_range = range;
    m_name = name;
    m_unit = unit.isEmpty()
                 ? QString::fromUtf8(range.unit.data(), static_cast<qsizetype>(range.unit.size()))
                 : unit;
    describe();
}

void NumberField::setUnitBeside(bool on)
{
    if (!on && m_unitBeside)
        setAccessibleDescription(QString()); // Qt then gives the tooltip
    m_unitBeside = on;
    describe();
}

void NumberField::describe()
{
    // A description the field's owner gave stays, unless the unit is to be told.
    if (!m_unitBeside || m_unit.isEmpty())
        return;
    const QString unit = tr("in %1", "the unit a number field holds its value in").arg(m_unit);
    setAccessibleDescription(toolTip().isEmpty()
                                 ? unit
                                 : tr("%1. %2", "the unit, then the tooltip").arg(unit, toolTip()));
}

lessons::limits::Range NumberField::scaled(const lessons::limits::Range& range, double factor)
{
    return {range.min * factor, range.max * factor, range.unit};
}

void NumberField::setValue(double v, int significant)
{
    if (!std::isfinite(v))
        return;
    m_value = v;
    m_digits = significant;
    // An edit in progress keeps its text; otherwise the text changes only when it must, so
    // that a redraw of the panel leaves the cursor where it is. A typed value that came back
    // through a unit (2.5 ms, held as 0.0025 s) may differ in its last bits: to kFullDigits it
    // reads the same, and the field keeps showing it as typed.
    if (isModified() || text() == formatNumber(v, m_digits) ||
        text() == formatNumber(v, kFullDigits))
        return;
    m_typed = false;
    display(v, m_digits);
}

QString NumberField::withUnit(const QString& number) const
{
    return m_unit.isEmpty() ? number : tr("%1 %2").arg(number, m_unit);
}

namespace {

/// A number in a message, as formatNumber writes it but never with an exponent ("1E-09"): a
/// message is read, not typed back, so a power of ten as the window writes it elsewhere.
QString formatSaid(double v, int significant = 12)
{
    const QString plain = formatNumber(v, significant);
    return plain.contains(QLatin1Char('E'), Qt::CaseInsensitive) ? formatPowerOfTen(v, significant)
                                                                 : plain;
}

} // namespace

QString NumberField::rangeSentence() const
{
    const auto withUnit = [this](double x) { return this->withUnit(formatSaid(x)); };
    return m_integer ? tr("%1 must be a whole number from %2 to %3")
                           .arg(m_name, withUnit(m_range.min), withUnit(m_range.max))
                     : tr("%1 must be from %2 to %3")
                           .arg(m_name, withUnit(m_range.min), withUnit(m_range.max));
}

QString NumberField::rangeMessage(double v) const
{
    if (!m_range.contains(v) || (m_integer && std::floor(v) != v))
        return rangeSentence();
    return QString();
}

bool NumberField::commit(bool retell)
{
    // Nothing typed: the text is the value in force, rounded for display; reading it back
    // would change a value such as 1/240 s by its last digits.
    if (!isModified() && m_error.isEmpty())
        return true;
    const std::optional<double> v = parseNumber(text());
    const QString typed = text().trimmed();
    QString why;
    if (!v) {
        // Nothing, or a number written right that no double holds ("1e999"): the range says
        // what is wanted. Anything else is named as typed.
        why = typed.isEmpty() || hasNumberForm(toAscii(typed))
                  ? rangeSentence()
                  : tr("“%1” is not a number: %2").arg(typed, rangeSentence());
    } else {
        why = rangeMessage(*v);
    }
    if (!why.isEmpty()) {
        // And what happens instead: the value in force stays (the field shows it again when
        // it is left), never a value made up from what was typed.
        why = tr("%1. It stays %2.", "a refusal, then the value that stays in force")
                  .arg(why, withUnit(formatSaid(m_value, shownDigits())));
        const bool told = why == m_error;
        setError(why);
        // Shown at once below the field, not only on hovering it, and told to a reader, who
        // hears neither the tooltip nor the status bar.
        if (isVisible()) {
            QToolTip::showText(mapToGlobal(QPoint(0, height())), why, this);
            if (retell || !told)
                announce(*this, why);
        }
        emit refused(why);
        return false;
    }
    m_reverted = false;
    setError(QString());
    setModified(false);
    const bool changed = *v != m_value;
    m_value = *v;
    // Every digit typed stays in sight: the value taken is the value shown.
    m_typed = true;
    display(m_value, kFullDigits);
    if (changed)
        emit valueEdited(m_value);
    return true;
}

void NumberField::revert()
{
    m_reverted = false;
    setError(QString());
    setModified(false);
    display(m_value, shownDigits());
}

void NumberField::display(double v, int digits)
{
    setText(formatNumber(v, digits));
    setModified(false);
}

void NumberField::setError(const QString& message)
{
    if (message == m_error)
        return;
    if (m_error.isEmpty())
        m_toolTip = toolTip();
    m_error = message;
    setProperty("refused", !message.isEmpty());
    setStyleSheet(message.isEmpty() ? QString() : QString::fromLatin1(kRefusedStyle));
    setToolTip(message.isEmpty() ? m_toolTip : message);
}

bool NumberField::event(QEvent* e)
{
    if (e->type() == QEvent::ToolTipChange && m_unitBeside)
        describe();
    if (e->type() == QEvent::ShortcutOverride) {
        // Keys without Ctrl, Alt or Meta are the field's: the window's one-key shortcuts
        // (Space, letters, arrows, Backspace) must not fire while a number is typed. Escape
        // is the field's while there is an edit to drop.
        auto* key = static_cast<QKeyEvent*>(e);
        const Qt::KeyboardModifiers mods =
            key->modifiers() & ~(Qt::ShiftModifier | Qt::KeypadModifier);
        const bool escape = key->key() == Qt::Key_Escape;
        if (mods == Qt::NoModifier && (!escape || isModified() || !m_error.isEmpty())) {
            e->accept();
            return true;
        }
    }
    return QLineEdit::event(e);
}

void NumberField::keyPressEvent(QKeyEvent* e)
{
    switch (e->key()) {
    case Qt::Key_Return:
    case Qt::Key_Enter:
        commit();
        e->accept();
        return;
    case Qt::Key_Escape:
        revert();
        e->accept();
        return;
    case Qt::Key_Space:
        e->accept(); // no number holds a space; it neither types nor plays
        return;
    default:
        break;
    }
    QLineEdit::keyPressEvent(e);
    if (m_reverted && isModified()) {
        // Typing again after a refusal shown on leaving: the mark has said its piece.
        m_reverted = false;
        setError(QString());
    }
}

void NumberField::focusOutEvent(QFocusEvent* e)
{
    // A context menu takes focus for a moment, and another window (or this one closing) takes
    // it from the whole window: the edit goes on when the focus comes back. Only leaving the
    // field for another part of the window takes the value.
    const bool away =
        e->reason() == Qt::PopupFocusReason || e->reason() == Qt::ActiveWindowFocusReason;
    if (!away && isModified() && !commit(false)) {
        // Leaving with a refused value: the value in force comes back, the mark and its
        // message stay until the next edit, so that the refusal is not missed.
        display(m_value, shownDigits());
        m_reverted = true;
    }
    QLineEdit::focusOutEvent(e);
}

} // namespace rigidlab::ui
