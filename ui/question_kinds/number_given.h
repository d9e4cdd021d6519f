// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What a number-given question (lessons/format/question_kinds/number_given.h) shows in the
// window (question_kinds/kind_ui.h): an answer box with its unit in the player, a line to write
// on in the worksheet (the key gives the number), its number, tolerance and unit in the editor.

#include "question_kinds/kind_ui.h"

#include "format/lesson_rows.h"
#include "format/question_kinds/number_given.h"

#include <QCoreApplication>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLineEdit>
#include <QLocale>
#include <QPushButton>

#include <limits>
#include <optional>
#include <type_traits>
#include <vector>

namespace rigidlab::ui {

namespace number_given {

/// A number field that shows what it holds with no trailing zeros, and keeps every digit a
/// lesson gives (a spin box's fixed decimals would round 1e-5 away on the next edit).
class NumberField : public QDoubleSpinBox {
public:
    NumberField(double min, QWidget* parent) : QDoubleSpinBox(parent)
    {
        setDecimals(std::numeric_limits<double>::max_digits10);
        setRange(min, lessons::kMaxAnswerMagnitude);
    }
    QString textFromValue(double value) const override
    {
        QLocale shownIn = locale();
        shownIn.setNumberOptions(QLocale::OmitGroupSeparator);
        return shownIn.toString(value, 'g', 12);
    }
};

/// Its fields in the lesson editor.
class Page : public KindPage {
public:
    explicit Page(QWidget* parent) : KindPage(parent)
    {
        auto* form = new QFormLayout(this);
        form->setContentsMargins(0, 0, 0, 0);
        m_number = new NumberField(-lessons::kMaxAnswerMagnitude, this);
        m_number->setObjectName(QStringLiteral("givenNumber"));
        m_number->setAccessibleName(
            QCoreApplication::translate("NumberGivenQuestion", "The right answer"));
        m_within = new NumberField(0, this);
        m_within->setObjectName(QStringLiteral("givenWithin"));
        m_within->setAccessibleName(
            QCoreApplication::translate("NumberGivenQuestion", "How far off an answer may be"));
        m_unit = new QLineEdit(this);
        m_unit->setObjectName(QStringLiteral("givenUnit"));
        m_unit->setAccessibleName(
            QCoreApplication::translate("NumberGivenQuestion", "Unit of the answer"));
        form->addRow(QCoreApplication::translate("NumberGivenQuestion", "Right ans&wer"), m_number);
        form->addRow(QCoreApplication::translate("NumberGivenQuestion", "Right &within ±"),
                     m_within);
        form->addRow(QCoreApplication::translate("NumberGivenQuestion", "&Unit"), m_unit);
        const auto changed = [this] {
            if (edited && !m_showing)
                edited();
        };
        connect(m_number, &QDoubleSpinBox::valueChanged, this, changed);
        connect(m_within, &QDoubleSpinBox::valueChanged, this, changed);
        connect(m_unit, &QLineEdit::textEdited, this, changed);
    }
    void showQuestion(const QJsonObject& q, const QJsonObject& /*scene*/) override
    {
        namespace keys = lessons::schema::question_keys;
        using lessons::schema::jsonKey;
        m_showing = true;
        m_number->setValue(q.value(jsonKey(keys::kNumber)).toDouble());
        m_within->setValue(q.value(jsonKey(keys::kWithin)).toDouble());
        if (m_unit->text() != q.value(jsonKey(keys::kUnit)).toString())
            m_unit->setText(q.value(jsonKey(keys::kUnit)).toString());
        m_showing = false;
    }
    void applyTo(QJsonObject& q) const override
    {
        namespace keys = lessons::schema::question_keys;
        using lessons::schema::jsonKey;
        q.insert(jsonKey(keys::kNumber), m_number->value());
        q.insert(jsonKey(keys::kWithin), m_within->value());
        if (m_unit->text().trimmed().isEmpty())
            q.remove(jsonKey(keys::kUnit));
        else
            q.insert(jsonKey(keys::kUnit), m_unit->text().trimmed());
    }

private:
    NumberField* m_number;
    NumberField* m_within;
    QLineEdit* m_unit;
    bool m_showing = false; ///< the fields are being filled from the question, not edited
};

} // namespace number_given

/// The answer box: a number typed is judged against the lesson's number at once.
inline AnswerRow answerRow(const lessons::NumberGivenQuestion& q, QLabel* prompt,
                           QVBoxLayout* layout, const RowHooks& hooks)
{
    const AnswerRow row = typedNumberRow(
        prompt, layout, q.unit,
        QCoreApplication::translate("NumberGivenQuestion", "Give up and show the right answer"));
    // The try keeps the number it is judged against, as a measured one keeps the value.
    const double number = q.number;
    const auto check = [hooks, number] {
        if (const std::optional<double> typed = hooks.typedNumber()) {
            lessons::AnswerTry attempt;
            attempt.answer = typed;
            attempt.measured = number;
            hooks.judge(attempt);
        }
    };
    QObject::connect(row.check, &QPushButton::clicked, row.check, check);
    QObject::connect(row.edit, &QLineEdit::returnPressed, row.edit, check);
    QObject::connect(row.show, &QPushButton::clicked, row.show, [hooks, number] {
        lessons::AnswerTry attempt;
        attempt.measured = number;
        hooks.judge(attempt);
    });
    return row;
}

inline std::vector<SheetLine> worksheetLines(const lessons::NumberGivenQuestion& q,
                                             const SheetQuestion& at)
{
    using Is = SheetLine::Is;
    const QString right = lessons::formatGiven(q, q.number);
    switch (at.sheet) {
    case WorksheetKind::Empty:
        return {
            {Is::Text,
             QCoreApplication::translate("NumberGivenQuestion", "Your answer (%1):").arg(q.unit)},
            {Is::WritingLine, {}}};
    case WorksheetKind::Key:
        return {{Is::Text, QCoreApplication::translate("NumberGivenQuestion",
                                                       "Right answer: %1 (accepted from %2 to %3)")
                               .arg(right, lessons::formatGiven(q, q.number - q.within),
                                    lessons::formatGiven(q, q.number + q.within))}};
    case WorksheetKind::Answers:
        return {
            {Is::Tries, q.unit},
            {Is::Bold,
             QCoreApplication::translate("NumberGivenQuestion", "Right answer: %1").arg(right)}};
    }
    return {};
}

inline QString kindTitle(std::type_identity<lessons::NumberGivenQuestion>)
{
    return QCoreApplication::translate("NumberGivenQuestion", "a number the lesson gives");
}

/// A question becoming one: the number 1, right within 0.05, no unit yet.
inline QJsonObject newKindKeys(std::type_identity<lessons::NumberGivenQuestion>,
                               const QJsonObject& /*scene*/)
{
    namespace keys = lessons::schema::question_keys;
    using lessons::schema::jsonKey;
    return QJsonObject{{jsonKey(keys::kNumber), 1.0}, {jsonKey(keys::kWithin), 0.05}};
}

inline KindPage* editorPage(std::type_identity<lessons::NumberGivenQuestion>, QWidget* parent)
{
    return new number_given::Page(parent);
}

inline AnswerLine answerLine(const lessons::NumberGivenQuestion& q, const lessons::LessonStep&,
                             const lessons::Question&)
{
    return {
        QCoreApplication::translate("NumberGivenQuestion", "The right answer"),
        lessons::keepUnitsTogether(
            QCoreApplication::translate("NumberGivenQuestion",
                                        "The right answer is %1; answers from %2 to %3 are right.")
                .arg(lessons::formatGiven(q, q.number),
                     lessons::formatGiven(q, q.number - q.within),
                     lessons::formatGiven(q, q.number + q.within)))};
}

} // namespace rigidlab::ui
