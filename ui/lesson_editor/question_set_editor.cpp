// SPDX-License-Identifier: GPL-3.0-or-later
#include "lesson_editor/question_set_editor.h"

#include "common/display_names.h"
#include "panels/number_field.h"

#include "format/scene_schema.h"

#include <QComboBox>
#include <QCoreApplication>
#include <QHBoxLayout>
#include <QStackedWidget>

namespace rigidlab::ui {

namespace {

namespace schema = lessons::schema;

QString fromView(std::string_view s)
{
    return QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size()));
}

/// The settings a question may ask for: the world's (the window's slow motion changes nothing
/// measured; the loader refuses it).
std::vector<const schema::Field*> askable()
{
    std::vector<const schema::Field*> out;
    for (const schema::Field& f : schema::settings())
        if (f.apply)
            out.push_back(&f);
    return out;
}

const schema::Field* fieldOf(const QString& key)
{
    for (const schema::Field* f : askable())
        if (fromView(f->key) == key)
            return f;
    return nullptr;
}

/// A value the setting starts from when the teacher picks it.
QJsonValue firstValue(const schema::Field& f)
{
    switch (f.kind) {
    case schema::Kind::Choice:
        return f.options ? QJsonValue(f.options().value(0)) : QJsonValue();
    case schema::Kind::Bool:
        return false;
    case schema::Kind::Integer:
        return static_cast<int>(f.range.min);
    default:
        return f.range.min;
    }
}

} // namespace

QuestionSetEditor::QuestionSetEditor(QWidget* parent) : QWidget(parent)
{
    auto* row = new QHBoxLayout(this);
    row->setContentsMargins(0, 0, 0, 0);
    m_key = new QComboBox(this);
    m_key->setObjectName(QStringLiteral("questionSetKey"));
    m_key->setAccessibleName(tr("Setting the student sets first"));
    m_key->addItem(tr("nothing (the step's settings)"), QString());
    for (const schema::Field* f : askable())
        m_key->addItem(QCoreApplication::translate(schema::kContext, f->label), fromView(f->key));
    m_pages = new QStackedWidget(this);
    m_number = new NumberField(this);
    m_number->setObjectName(QStringLiteral("questionSetNumber"));
    m_number->setAccessibleName(tr("Value the student sets"));
    m_choice = new QComboBox(this);
    m_choice->setObjectName(QStringLiteral("questionSetChoice"));
    m_choice->setAccessibleName(tr("Value the student sets"));
    m_pages->addWidget(m_number);
    m_pages->addWidget(m_choice);
    row->addWidget(m_key, 1);
    row->addWidget(m_pages, 1);
    connect(m_key, &QComboBox::activated, this, &QuestionSetEditor::choose);
    connect(m_number, &NumberField::valueEdited, this, &QuestionSetEditor::valueChosen);
    connect(m_choice, &QComboBox::activated, this, &QuestionSetEditor::valueChosen);
    show(QJsonObject());
}

void QuestionSetEditor::show(const QJsonObject& set)
{
    m_showing = true;
    m_set = set;
    // The first setting the question asks for, in the order of the settings' rows.
    const schema::Field* shown = nullptr;
    for (const schema::Field* f : askable())
        if (!shown && set.contains(fromView(f->key)))
            shown = f;
    m_key->setCurrentIndex(shown ? m_key->findData(fromView(shown->key)) : 0);
    m_pages->setEnabled(shown != nullptr);
    if (shown) {
        const QJsonValue v = set.value(fromView(shown->key));
        const bool list = shown->kind == schema::Kind::Choice || shown->kind == schema::Kind::Bool;
        m_pages->setCurrentWidget(list ? static_cast<QWidget*>(m_choice) : m_number);
        m_choice->clear();
        if (shown->kind == schema::Kind::Choice) {
            for (const QString& option : shown->options())
                m_choice->addItem(methodDisplayName(option), option);
            m_choice->setCurrentIndex(m_choice->findData(v.toString()));
        } else if (shown->kind == schema::Kind::Bool) {
            m_choice->addItem(tr("on"), true);
            m_choice->addItem(tr("off"), false);
            m_choice->setCurrentIndex(v.toBool() ? 0 : 1);
        } else {
            m_number->setRange(shown->range,
                               QCoreApplication::translate(schema::kContext, shown->label));
            m_number->setInteger(shown->kind == schema::Kind::Integer);
            m_number->setValue(v.toDouble());
        }
    }
    m_showing = false;
}

void QuestionSetEditor::choose()
{
    if (m_showing)
        return;
    const QString key = m_key->currentData().toString();
    // One setting at a time here: the one shown is replaced, others the file gives stay.
    for (const schema::Field* f : askable())
        if (m_set.contains(fromView(f->key))) {
            m_set.remove(fromView(f->key));
            break;
        }
    if (const schema::Field* f = fieldOf(key))
        m_set.insert(key, firstValue(*f));
    show(m_set);
    emit edited();
}

void QuestionSetEditor::valueChosen()
{
    if (m_showing)
        return;
    const QString key = m_key->currentData().toString();
    const schema::Field* f = fieldOf(key);
    if (f == nullptr)
        return;
    if (f->kind == schema::Kind::Choice || f->kind == schema::Kind::Bool)
        m_set.insert(key, m_choice->currentData().toJsonValue());
    else if (f->kind == schema::Kind::Integer)
        m_set.insert(key, static_cast<int>(m_number->value()));
    else
        m_set.insert(key, m_number->value());
    emit edited();
}

} // namespace rigidlab::ui
