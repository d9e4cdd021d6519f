// SPDX-License-Identifier: GPL-3.0-or-later
#include "editor/scene_properties.h"

#include "editor/colour_field.h"
#include "editor/edit_tools.h"
#include "editor/scene_document.h"

#include "common/display_names.h"
#include "edit/scene_edits.h"
#include "panels/number_field.h"
#include "view/body_item.h"
#include "view/world_view.h"

#include "rigidlab/physics/contact.h"
#include "rigidlab/physics/integrator.h"
#include "rigidlab/physics/shape.h"

#include <QComboBox>
#include <QCoreApplication>
#include <QFormLayout>
#include <QGroupBox>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QVBoxLayout>

namespace rigidlab::ui {

namespace edit = lessons::edit;
namespace schema = lessons::schema;
using schema::Kind;
using schema::Object;

namespace {

/// Merge ids of the fields' edits: one per field, well apart from the tools' drag ids.
constexpr int kFieldMergeBase = 1 << 20;

QString keyOf(const schema::Field& f)
{
    return QString::fromLatin1(f.key.data(), qsizetype(f.key.size()));
}

/// A field's label as it reads inside a sentence of the History: "friction μ" for "Friction μ".
QString inSentence(const QString& label)
{
    return label.isEmpty() ? label : label.front().toLower() + label.mid(1);
}

/// "Density [kg/m²]": the row's label with the unit its field shows (the ranges spell powers
/// as ^2, ^3), as the Controls panel writes it.
QString withUnit(const QString& label, QString unit)
{
    if (unit.isEmpty())
        return label;
    unit.replace(QLatin1String("^2"), QStringLiteral("²"))
        .replace(QLatin1String("^3"), QStringLiteral("³"));
    return QStringLiteral("%1 [%2]").arg(label, unit);
}

/// A choice's item data: the enum the code name stands for, as the lists have always held it
/// (tests and the lists' users find items by it).
int choiceData(const schema::Field& f, const QString& name)
{
    if (f.key == "type")
        return int(schema::bodyTypeFromName(name).value_or(physics::BodyType::Dynamic));
    if (f.key == "integrator")
        return int(physics::integratorFromName(name.toStdString()).value());
    return int(physics::solverFromName(name.toStdString()).value());
}

QString choiceText(const schema::Field& f, const QString& name)
{
    if (f.key == "type")
        return schema::bodyTypeLabel(*schema::bodyTypeFromName(name));
    return methodDisplayName(name);
}

} // namespace

SceneProperties::SceneProperties(EditTools& tools, SceneDocument& document, QWidget* parent)
    : QWidget(parent), m_tools(tools), m_document(document)
{
    auto* layout = new QVBoxLayout(this);
    // At least as tall as its rows, so that a scroll area scrolls rather than squeezes them.
    layout->setSizeConstraint(QLayout::SetMinimumSize);
    auto* sceneBox = new QGroupBox(tr("Scene"), this);
    m_bodyBox = new QGroupBox(tr("Body"), this);
    m_springBox = new QGroupBox(tr("Spring"), this);
    auto* worldBox = new QGroupBox(tr("World"), this);
    const std::pair<QGroupBox*, Object> groups[] = {{m_bodyBox, Object::Body},
                                                    {m_springBox, Object::Spring},
                                                    {worldBox, Object::World},
                                                    {sceneBox, Object::Scene}};
    for (const auto& [box, object] : groups) {
        addRows(object, addGroup(box));
        layout->addWidget(box);
    }
    layout->addStretch(1);

    for (NumberField* f : findChildren<NumberField*>())
        connect(f, &NumberField::refused, this, &SceneProperties::refused);
    connect(&m_document, &SceneDocument::sceneChanged, this, &SceneProperties::refresh);
    connect(&m_tools, &EditTools::selectionChanged, this, &SceneProperties::refresh);
    connect(&m_tools, &EditTools::propertyLocksChanged, this, &SceneProperties::applyLocks);
    refresh();
    applyLocks();
}

QFormLayout* SceneProperties::addGroup(QGroupBox* box)
{
    auto* form = new QFormLayout(box);
    form->setRowWrapPolicy(QFormLayout::WrapAllRows); // labels above: fields as wide as the dock
    return form;
}

void SceneProperties::addRows(Object object, QFormLayout* form)
{
    for (const schema::Field& f : schema::fields(object)) {
        if (!f.inEditor)
            continue;
        m_rows.push_back(Row{object, &f, {}, form});
        Row& row = m_rows.back();
        switch (f.kind) {
        case Kind::Number:
        case Kind::Integer:
        case Kind::Size:
        case Kind::Vec2:
            addNumbers(row, kFieldMergeBase + int(m_rows.size()));
            break;
        case Kind::Choice:
            addChoice(row);
            break;
        case Kind::Colour:
            addColour(row);
            break;
        default:
            addText(row);
            break;
        }
        for (QWidget* w : row.widgets) {
            w->setProperty("schemaKey", keyOf(f));
            w->installEventFilter(this);
        }
    }
}

void SceneProperties::addNumbers(Row& row, int mergeId)
{
    const schema::Field& f = *row.field;
    const std::size_t rowIndex = m_rows.size() - 1;
    const int components = f.kind == Kind::Vec2 ? 2 : 1;
    for (int c = 0; c < components; ++c) {
        auto* field = new NumberField(row.form->parentWidget());
        field->setObjectName(components == 2 ? keyOf(f) + (c == 0 ? u'X' : u'Y') : keyOf(f));
        const QString label = schema::label(f, c);
        const QString unit =
            f.shownUnit ? QCoreApplication::translate(schema::kContext, f.shownUnit) : QString();
        field->setRange(NumberField::scaled(f.range, f.shownScale), label, unit);
        field->setInteger(f.kind == Kind::Integer);
        row.form->addRow(withUnit(label, field->unit()), field);
        row.widgets.push_back(field);
        connect(field, &NumberField::valueEdited, this, [this, rowIndex, c, mergeId](double v) {
            const Row& r = m_rows[rowIndex];
            if (refuseLocked(r, c))
                return;
            const int component = r.field->kind == Kind::Vec2 ? c : -1;
            edit(r, v / r.field->shownScale, component,
                 mergeId + 64 * std::max(0, indexOf(r.object)) + (c << 18));
        });
    }
}

void SceneProperties::addChoice(Row& row)
{
    const std::size_t rowIndex = m_rows.size() - 1;
    auto* box = new QComboBox(row.form->parentWidget());
    box->setObjectName(keyOf(*row.field));
    for (const QString& name : row.field->options())
        box->addItem(choiceText(*row.field, name), choiceData(*row.field, name));
    row.form->addRow(schema::label(*row.field), box);
    row.widgets.push_back(box);
    connect(box, &QComboBox::activated, this, [this, rowIndex, box](int item) {
        const Row& r = m_rows[rowIndex];
        if (refuseLocked(r))
            return;
        const QStringList names = r.field->options();
        if (item >= 0 && item < names.size())
            edit(r, names[item], -1, -1);
    });
}

void SceneProperties::addText(Row& row)
{
    const std::size_t rowIndex = m_rows.size() - 1;
    auto* line = new QLineEdit(row.form->parentWidget());
    line->setObjectName(keyOf(*row.field));
    row.form->addRow(schema::label(*row.field), line);
    row.widgets.push_back(line);
    connect(line, &QLineEdit::editingFinished, this, [this, rowIndex, line] {
        const Row& r = m_rows[rowIndex];
        if (refuseLocked(r))
            return;
        const int index = indexOf(r.object);
        if (index < 0)
            return;
        const schema::Value now = r.field->get(m_document.scene(), std::size_t(index));
        const QString* text = std::get_if<QString>(&now);
        if (line->text() == (text ? *text : QString()))
            return;
        edit(r, line->text().isEmpty() && r.field->optional ? schema::Value() : line->text(), -1,
             -1);
    });
}

void SceneProperties::addColour(Row& row)
{
    const std::size_t rowIndex = m_rows.size() - 1;
    m_colour = new ColourField(row.form->parentWidget());
    row.form->addRow(schema::label(*row.field), m_colour);
    row.widgets.push_back(m_colour);
    connect(m_colour, &ColourField::colourChosen, this, [this, rowIndex](const QString& colour) {
        const Row& r = m_rows[rowIndex];
        if (refuseLocked(r))
            return;
        const QString what = colour.isEmpty() ? tr("Default colour") : tr("Set colour");
        const auto result = edit::setField(
            m_document.scene(), r.object, std::size_t(indexOf(r.object)), r.field->key,
            colour.isEmpty() ? schema::Value() : schema::Value(colour));
        if (!result.ok) {
            emit refused(result.error);
            refresh();
            return;
        }
        m_document.apply(what, result.scene, -1);
    });
}

int SceneProperties::indexOf(Object object) const
{
    const lessons::Scene& scene = m_document.scene();
    const int selected = object == Object::Body     ? m_tools.selectedBody()
                         : object == Object::Spring ? m_tools.selectedSpring()
                                                    : 0;
    return selected >= 0 && std::size_t(selected) < schema::count(scene, object) ? selected : -1;
}

QString SceneProperties::editName(const Row& row, int component) const
{
    const QString label = inSentence(schema::label(*row.field, std::max(component, 0)));
    const int index = indexOf(row.object);
    if (row.object == Object::Body) {
        const QString body = EditTools::bodyName(m_document.scene(), index);
        if (row.field->key == "id") // the id itself, which the label (if any) does not show
            return tr("Rename %1 to %2")
                .arg(QString::fromStdString(
                         m_document.scene().bodies[static_cast<std::size_t>(index)].name),
                     idField()->text());
        if (row.field->key == "type")
            return tr("Set type of %1").arg(body);
        return tr("Set %1 of %2").arg(label, body);
    }
    if (row.object == Object::Spring)
        return tr("Set %1 of spring %2").arg(label).arg(index + 1);
    return tr("Set %1").arg(label);
}

void SceneProperties::edit(const Row& row, const schema::Value& value, int component, int mergeId)
{
    const int index = indexOf(row.object);
    const edit::EditResult result =
        edit::setField(m_document.scene(), row.object, std::size_t(std::max(index, 0)),
                       row.field->key, value, component);
    if (!result.ok) {
        emit refused(result.error);
        refresh(); // the value in force comes back
        return;
    }
    m_document.apply(editName(row, component), result.scene, mergeId);
}

void SceneProperties::applyLocks()
{
    for (const Row& row : m_rows) {
        const bool locked = m_tools.propertyLocked(keyOf(*row.field));
        // The colour row's swatch, text and Default button: each says it is locked.
        std::vector<QWidget*> widgets = row.widgets;
        if (row.field->kind == Kind::Colour)
            for (QWidget* part : m_colour->findChildren<QWidget*>())
                if (part->objectName().startsWith(QLatin1String("colour")))
                    widgets.push_back(part);
        for (std::size_t c = 0; c < widgets.size(); ++c) {
            QWidget* w = widgets[c];
            // The field's own tooltip (its range) comes back when the lock goes.
            if (!w->property("unlockedToolTip").isValid())
                w->setProperty("unlockedToolTip", w->toolTip());
            w->setEnabled(!locked);
            w->setToolTip(
                locked ? EditTools::propertyLockedMessage(schema::label(*row.field, c == 1 ? 1 : 0))
                       : w->property("unlockedToolTip").toString());
        }
    }
}

bool SceneProperties::refuseLocked(const Row& row, int component)
{
    if (!m_tools.propertyLocked(keyOf(*row.field)))
        return false;
    emit refused(EditTools::propertyLockedMessage(schema::label(*row.field, component)));
    refresh(); // the value in force comes back
    return true;
}

bool SceneProperties::eventFilter(QObject* watched, QEvent* event)
{
    if (event->type() != QEvent::KeyPress)
        return QWidget::eventFilter(watched, event);
    const int key = static_cast<QKeyEvent*>(event)->key();
    if (key != Qt::Key_Return && key != Qt::Key_Enter)
        return QWidget::eventFilter(watched, event);
    // Return takes the value and hands the keyboard back to the scene, so that a tool's key or
    // Ctrl+Z after it acts on the scene, not in the field. A refused value keeps the focus
    // where it can be corrected.
    if (auto* number = qobject_cast<NumberField*>(watched)) {
        if (!number->commit())
            return true;
    } else if (auto* line = qobject_cast<QLineEdit*>(watched)) {
        emit line->editingFinished();
    } else {
        return QWidget::eventFilter(watched, event);
    }
    // Only the focus moves: the view is the tools' own.
    const_cast<WorldView&>(m_tools.view()).setFocus(Qt::OtherFocusReason);
    return true;
}

NumberField* SceneProperties::field(const QString& name) const
{
    return findChild<NumberField*>(name);
}

QLineEdit* SceneProperties::textField(const QString& key) const
{
    for (QLineEdit* line : findChildren<QLineEdit*>(key))
        if (!qobject_cast<NumberField*>(line))
            return line;
    return nullptr;
}

QComboBox* SceneProperties::typeBox() const
{
    return findChild<QComboBox*>(QStringLiteral("type"));
}

void SceneProperties::showRow(const Row& row, int index)
{
    const lessons::Scene& scene = m_document.scene();
    const std::size_t i = std::size_t(index);
    const schema::Field& f = *row.field;
    // Only rows that can go away are touched: showing a row lays the form out again.
    if (f.applies) {
        const bool applies = f.applies(scene, i);
        for (QWidget* w : row.widgets)
            row.form->setRowVisible(w, applies);
        if (!applies)
            return;
    }
    const schema::Value value = schema::effective(scene, f, i);
    if (f.key == "density" || f.key == "mass") {
        // The one of density and mass the scene gives is shown as given; the other, computed
        // from it and the area, to four digits, without the rounding noise of the product.
        constexpr int kComputedDigits = 4;
        const physics::BodyDef& def = scene.bodies[i];
        const double area = physics::computeMass(def.shape, 1.0).area;
        const bool massGiven = def.mass > 0;
        const bool given = massGiven == (f.key == "mass");
        const double shown = f.key == "mass" ? (massGiven ? def.mass : def.density * area)
                                             : (massGiven ? def.mass / area : def.density);
        static_cast<NumberField*>(row.widgets[0])
            ->setValue(shown, given ? NumberField::kShownDigits : kComputedDigits);
        return;
    }
    if (const auto* v = std::get_if<physics::Vec2>(&value)) {
        for (int c = 0; c < 2; ++c)
            static_cast<NumberField*>(row.widgets[std::size_t(c)])->setValue((*v)[c]);
    } else if (const auto* d = std::get_if<double>(&value)) {
        static_cast<NumberField*>(row.widgets[0])->setValue(*d * f.shownScale);
    } else if (const auto* n = std::get_if<int>(&value)) {
        static_cast<NumberField*>(row.widgets[0])->setValue(*n);
    } else if (auto* box = qobject_cast<QComboBox*>(row.widgets[0])) {
        box->setCurrentIndex(box->findData(choiceData(f, std::get<QString>(value))));
    } else if (row.widgets[0] == m_colour) {
        const QString* colour = std::get_if<QString>(&value);
        m_colour->setColour(colour ? *colour : QString());
        if (const BodyItem* item = m_tools.view().itemFor(index))
            m_colour->setShownColour(item->fill());
    } else if (auto* line = qobject_cast<QLineEdit*>(row.widgets[0]); line && !line->hasFocus()) {
        const QString* text = std::get_if<QString>(&value);
        line->setText(text ? *text : QString());
    }
}

void SceneProperties::refresh()
{
    m_bodyBox->setVisible(indexOf(Object::Body) >= 0);
    m_springBox->setVisible(indexOf(Object::Spring) >= 0);
    for (const Row& row : m_rows)
        if (const int index = indexOf(row.object); index >= 0)
            showRow(row, index);
}

} // namespace rigidlab::ui
