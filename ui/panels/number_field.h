// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A field for one number that a teacher types while the simulation runs.
//
// The value is taken on Enter or when the field loses focus, never per keystroke, so a
// running world that redraws the panels cannot reformat a number half typed. Escape brings
// back the value in force. A value that is not a number, or lies outside the field's range,
// is refused out loud: the field turns red, its tooltip says why (naming the range and its
// unit, and the value that stays), a screen reader is told the same (common/announcer.h),
// refused() carries the same words for the status bar, and the old value stays. Both
// the decimal point and the decimal comma are read in every locale; numbers are shown in
// QLocale(), the application's locale, without group separators.
//
// Keys without Ctrl or Alt belong to the field while it has focus: the window's one-key
// shortcuts (Space plays, S steps, arrows, Backspace...) do not fire from inside it.

#include "format/limits.h"

#include <QLineEdit>
#include <QString>

#include <optional>

namespace rigidlab::ui {

/// Reads a number typed by a person: an optional sign, digits with at most one decimal
/// separator, '.' or ',' whatever the locale, and an optional exponent ("6,4", "6.4", "-2e-3").
/// Surrounding spaces are ignored. Also takes what QLocale() writes (its own digits, minus
/// sign and exponent), never with group separators. Refuses anything else: "1,2,3", "1.2.3",
/// "0x10", "nan", "inf", and numbers a double cannot hold ("1e999", "1e-400").
std::optional<double> parseNumber(const QString& text);

/// `v` as QLocale() writes it, with up to `significant` digits and no group separators.
QString formatNumber(double v, int significant = 12);

class NumberField : public QLineEdit {
    Q_OBJECT
public:
    explicit NumberField(QWidget* parent = nullptr);

    /// What the field accepts, in the unit it shows. `name` starts the refusal message
    /// ("dt must be from 0.0001 ms to 1000 ms"); `unit` overrides the range's own unit.
    void setRange(const lessons::limits::Range& range, const QString& name,
                  const QString& unit = QString());
    /// The unit the field shows its value in ("ms", "kg/m^2"); empty for a pure number.
    const QString& unit() const { return m_unit; }
    /// The range scaled into the unit shown, e.g. limits::kDt in ms: scaled(kDt, 1e3).
    static lessons::limits::Range scaled(const lessons::limits::Range& range, double factor);
    /// Accepts whole numbers only.
    void setInteger(bool on) { m_integer = on; }
    /// The unit is shown beside the field, not in its label ("Mass m", the field, "kg"): a
    /// screen reader is told it first in the field's description ("in kg. The body's mass…"),
    /// which otherwise is the tooltip (a refusal's message while the value is refused).
    void setUnitBeside(bool on);

    double value() const { return m_value; }
    /// Shows `v` as the value in force, to `significant` digits (fewer for a value computed
    /// from others, such as a mass from density and area, where the last digits are rounding
    /// noise). A text that already says `v` stays: the rounded one, or a value as it was
    /// typed (to kFullDigits), so that what a teacher typed is what the field goes on showing.
    /// An edit in progress is left alone: the value it would restore on Escape becomes `v`.
    void setValue(double v, int significant = kShownDigits);
    /// The digits a value from a file or from the program is shown with: 1/60 s reads
    /// "16.6667" ms, not "16.6666666667".
    static constexpr int kShownDigits = 6;
    /// The digits a typed value is shown with once taken: every digit a person types.
    static constexpr int kFullDigits = 12;

    /// Takes what was typed, as Enter does; false when it was refused. A refusal is told to a
    /// screen reader; `retell` false: only if its message differs from the one told before
    /// (leaving the field after Enter was refused tells nothing new).
    bool commit(bool retell = true);
    /// Drops what was typed, as Escape does.
    void revert();
    /// The last refusal, empty when the value shown is accepted.
    QString error() const { return m_error; }
    /// The refusal message for `v`, or empty when `v` is in range.
    QString rangeMessage(double v) const;

signals:
    /// The user changed the value (after Enter or on leaving the field).
    void valueEdited(double value);
    /// What was typed was refused; `message` says why. The value stays as it was.
    void refused(const QString& message);

protected:
    bool event(QEvent* e) override;
    void keyPressEvent(QKeyEvent* e) override;
    void focusOutEvent(QFocusEvent* e) override;

private:
    /// Shows `v` to `digits` significant digits, as the value in force.
    void display(double v, int digits);
    int m_digits = kShownDigits; ///< see setValue
    /// The value in force was typed here: it is shown with every digit typed (kFullDigits).
    bool m_typed = false;
    /// The digits the value in force is shown with.
    int shownDigits() const { return m_typed ? kFullDigits : m_digits; }
    /// "dt must be from 0.0001 ms to 1000 ms".
    QString rangeSentence() const;
    /// `number` followed by the field's unit, if it has one.
    QString withUnit(const QString& number) const;
    void setError(const QString& message);
    /// The accessible description: the unit beside the field, then the tooltip.
    void describe();
    bool m_unitBeside = false;

    lessons::limits::Range m_range{-1e300, 1e300, ""};
    QString m_name;
    QString m_unit;
    QString m_toolTip; ///< the tooltip when nothing is wrong
    bool m_integer = false;
    double m_value = 0.0;
    QString m_error;
    bool m_reverted = false; ///< the text went back to the value on leaving a refused edit
};

} // namespace rigidlab::ui
