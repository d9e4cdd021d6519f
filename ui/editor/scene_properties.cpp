// SPDX-License-Identifier: GPL-3.0-or-later
#include "editor/scene_properties.h"

#include "editor/colour_field.h"
#include "editor/edit_tools.h"
#include "editor/scene_document.h"

#include "common/display_names.h"
#include "edit/scene_edits.h"
#include "format/editor_tools.h"
#include "format/limits.h"
#include "panels/number_field.h"
#include "view/body_item.h"
#include "view/world_view.h"

#include "rigidlab/physics/contact.h"
#include "rigidlab/physics/integrator.h"

#include <QComboBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QLabel>
#include <QLineEdit>
#include <QVBoxLayout>

#include <algorithm>

namespace rigidlab::ui {

namespace edit = lessons::edit;
namespace limits = lessons::limits;

namespace {

/// Merge ids of the fields' edits: one per field, well apart from the tools' drag ids.
constexpr int kFieldMergeBase = 1 << 20;

/// A field's row label with the unit the field shows, as the Controls panel writes it:
/// "Density [kg/m²]" (the ranges spell powers as ^2, ^3).
void labelWithUnit(QFormLayout* form, NumberField* f, const QString& label)
{
    if (f->unit().isEmpty())
        return;
    QString unit = f->unit();
    unit.replace(QLatin1String("^2"), QStringLiteral("²"))
        .replace(QLatin1String("^3"), QStringLiteral("³"));
    if (auto* l = qobject_cast<QLabel*>(form->labelForField(f)))
        l->setText(QStringLiteral("%1 [%2]").arg(label, unit));
}

/// A field's label as it reads inside a sentence of the History: "friction μ" for "Friction μ".
QString inSentence(const QString& label)
{
    return label.isEmpty() ? label : label.front().toLower() + label.mid(1);
}

/// The name a lesson's "editor" key gives the property a field edits (format/editor_tools.h):
/// the field's objectName, but one name for both components of a vector.
QString propertyOf(const QWidget* field)
{
    const QString name = field->objectName();
    // The colour row's swatch, text and Default button: one property.
    if (name.startsWith(QLatin1String("colour")))
        return QStringLiteral("colour");
    for (const char* vector : {"velocity", "gravity"}) {
        const QString v = QLatin1String(vector);
        if (name == v + u'X' || name == v + u'Y')
            return v;
    }
    return name;
}

/// Whether `name` is one of the properties a lesson step may lock.
bool isEditorProperty(const QString& name)
{
    return std::any_of(lessons::kEditorPropertyNames.begin(), lessons::kEditorPropertyNames.end(),
                       [&name](std::string_view p) {
                           return name == QLatin1String(p.data(), qsizetype(p.size()));
                       });
}

/// The field's row label as shown, without its unit: "Mass", "Velocity vx".
QString rowLabel(const QWidget* field)
{
    // A part of a compound row (the colour's swatch, text and button) takes its row's label.
    for (const QWidget* w = field; w && w->parentWidget(); w = w->parentWidget()) {
        const auto* form = qobject_cast<QFormLayout*>(w->parentWidget()->layout());
        const auto* label =
            form ? qobject_cast<QLabel*>(form->labelForField(const_cast<QWidget*>(w))) : nullptr;
        if (label)
            return label->text().section(QStringLiteral(" ["), 0, 0);
    }
    return field->objectName();
}

} // namespace

SceneProperties::SceneProperties(EditTools& tools, SceneDocument& document, QWidget* parent)
    : QWidget(parent), m_tools(tools), m_document(document)
{
    auto* layout = new QVBoxLayout(this);
    // At least as tall as its rows, so that a scroll area scrolls rather than squeezes them.
    layout->setSizeConstraint(QLayout::SetMinimumSize);

    m_bodyBox = new QGroupBox(tr("Body"), this);
    auto* body = new QFormLayout(m_bodyBox);
    body->setRowWrapPolicy(QFormLayout::WrapAllRows); // labels above: fields as wide as the dock
    m_id = new QLineEdit(m_bodyBox);
    m_id->setObjectName(QStringLiteral("id"));
    body->addRow(tr("Id"), m_id);
    m_type = new QComboBox(m_bodyBox);
    m_type->setObjectName(QStringLiteral("type"));
    m_type->addItem(tr("dynamic"), int(physics::BodyType::Dynamic));
    m_type->addItem(tr("static"), int(physics::BodyType::Static));
    m_type->addItem(tr("kinematic"), int(physics::BodyType::Kinematic));
    body->addRow(tr("Type"), m_type);
    struct BodyRow {
        const char* name;
        QString label;
        edit::BodyNumber what;
        limits::Range range;
    };
    const BodyRow bodyRows[] = {
        {"density", tr("Density"), edit::BodyNumber::Density, limits::kDensity},
        {"mass", tr("Mass"), edit::BodyNumber::Mass, limits::kMass},
        {"restitution", tr("Restitution e"), edit::BodyNumber::Restitution, limits::kRestitution},
        {"friction", tr("Friction μ"), edit::BodyNumber::Friction, limits::kFriction},
        {"velocityX", tr("Velocity vx"), edit::BodyNumber::VelocityX, limits::kVelocity},
        {"velocityY", tr("Velocity vy"), edit::BodyNumber::VelocityY, limits::kVelocity},
        {"angularVelocity", tr("Angular vel. ω"), edit::BodyNumber::AngularVelocity,
         limits::kAngularVelocity},
    };
    int merge = kFieldMergeBase;
    for (const BodyRow& row : bodyRows) {
        NumberField* f = addNumber(body, QLatin1String(row.name), row.label);
        f->setRange(row.range, row.label);
        labelWithUnit(body, f, row.label);
        const int mergeId = merge++;
        const auto what = row.what;
        const QString label = row.label;
        connect(f, &NumberField::valueEdited, this, [this, f, what, label, mergeId](double v) {
            if (refuseLocked(f))
                return;
            const int selected = m_tools.selectedBody();
            apply(tr("Set %1 of %2")
                      .arg(inSentence(label), EditTools::bodyName(m_document.scene(), selected)),
                  edit::setBodyNumber(m_document.scene(), selected, what, v),
                  mergeId + 64 * selected);
        });
    }
    connect(m_id, &QLineEdit::editingFinished, this, [this] {
        if (refuseLocked(m_id))
            return;
        const int selected = m_tools.selectedBody();
        if (selected < 0 || m_id->text() == QString::fromStdString(
                                                m_document.scene().bodies[size_t(selected)].name)) {
            return;
        }
        apply(tr("Rename %1 to %2")
                  .arg(QString::fromStdString(m_document.scene().bodies[size_t(selected)].name),
                       m_id->text()),
              edit::setBodyId(m_document.scene(), selected, m_id->text()), -1);
    });
    connect(m_type, &QComboBox::activated, this, [this] {
        if (refuseLocked(m_type))
            return;
        apply(tr("Set type of %1")
                  .arg(EditTools::bodyName(m_document.scene(), m_tools.selectedBody())),
              edit::setBodyType(m_document.scene(), m_tools.selectedBody(),
                                physics::BodyType(m_type->currentData().toInt())),
              -1);
    });
    addColourRow(body);
    layout->addWidget(m_bodyBox);

    m_springBox = new QGroupBox(tr("Spring"), this);
    auto* spring = new QFormLayout(m_springBox);
    spring->setRowWrapPolicy(QFormLayout::WrapAllRows); // labels above: fields as wide as the dock
    struct SpringRow {
        const char* name;
        QString label;
        edit::SpringNumber what;
        limits::Range range;
    };
    const SpringRow springRows[] = {
        {"stiffness", tr("Stiffness k"), edit::SpringNumber::Stiffness, limits::kStiffness},
        {"damping", tr("Damping c"), edit::SpringNumber::Damping, limits::kDamping},
        {"restLength", tr("Rest length"), edit::SpringNumber::RestLength, limits::kRestLength},
    };
    for (const SpringRow& row : springRows) {
        NumberField* f = addNumber(spring, QLatin1String(row.name), row.label);
        f->setRange(row.range, row.label);
        labelWithUnit(spring, f, row.label);
        const int mergeId = merge++;
        const auto what = row.what;
        const QString label = row.label;
        connect(f, &NumberField::valueEdited, this, [this, f, what, label, mergeId](double v) {
            if (refuseLocked(f))
                return;
            const int selected = m_tools.selectedSpring();
            apply(tr("Set %1 of spring %2").arg(inSentence(label)).arg(selected + 1),
                  edit::setSpringNumber(m_document.scene(), selected, what, v),
                  mergeId + 64 * selected);
        });
    }
    layout->addWidget(m_springBox);

    auto* worldBox = new QGroupBox(tr("World"), this);
    auto* world = new QFormLayout(worldBox);
    world->setRowWrapPolicy(QFormLayout::WrapAllRows); // labels above: fields as wide as the dock
    struct WorldRow {
        const char* name;
        QString label;
        edit::WorldNumber what;
        limits::Range range;
        double scale; ///< shown in a unit this many times the stored one (dt in ms)
        QString unit;
    };
    const WorldRow worldRows[] = {
        {"gravityX", tr("Gravity gx"), edit::WorldNumber::GravityX, limits::kGravity, 1.0, {}},
        {"gravityY", tr("Gravity gy"), edit::WorldNumber::GravityY, limits::kGravity, 1.0, {}},
        {"dt", tr("Time step dt"), edit::WorldNumber::Dt, limits::kDt, 1e3, tr("ms")},
        {"iterations",
         tr("Iterations"),
         edit::WorldNumber::Iterations,
         limits::kIterations,
         1.0,
         {}},
    };
    for (const WorldRow& row : worldRows) {
        NumberField* f = addNumber(world, QLatin1String(row.name), row.label);
        f->setRange(NumberField::scaled(row.range, row.scale), row.label, row.unit);
        labelWithUnit(world, f, row.label);
        f->setInteger(row.what == edit::WorldNumber::Iterations);
        const int mergeId = merge++;
        const auto what = row.what;
        const double scale = row.scale;
        const QString label = row.label;
        connect(f, &NumberField::valueEdited, this,
                [this, f, what, label, mergeId, scale](double v) {
                    if (refuseLocked(f))
                        return;
                    apply(tr("Set %1").arg(inSentence(label)),
                          edit::setWorldNumber(m_document.scene(), what, v / scale), mergeId);
                });
    }
    m_integrator = new QComboBox(worldBox);
    m_integrator->setObjectName(QStringLiteral("integrator"));
    for (const physics::IntegratorKind kind : physics::kAllIntegrators) {
        m_integrator->addItem(integratorDisplayName(kind), int(kind));
    }
    world->addRow(tr("Integrator"), m_integrator);
    connect(m_integrator, &QComboBox::activated, this, [this] {
        if (refuseLocked(m_integrator))
            return;
        apply(tr("Set integrator"),
              edit::setIntegrator(m_document.scene(),
                                  physics::IntegratorKind(m_integrator->currentData().toInt())),
              -1);
    });
    m_solver = new QComboBox(worldBox);
    m_solver->setObjectName(QStringLiteral("solver"));
    for (const physics::SolverKind kind :
         {physics::SolverKind::SeedImpulse, physics::SolverKind::SequentialImpulse}) {
        m_solver->addItem(solverDisplayName(kind), int(kind));
    }
    world->addRow(tr("Solver"), m_solver);
    connect(m_solver, &QComboBox::activated, this, [this] {
        if (refuseLocked(m_solver))
            return;
        apply(tr("Set solver"),
              edit::setSolver(m_document.scene(),
                              physics::SolverKind(m_solver->currentData().toInt())),
              -1);
    });
    layout->addWidget(worldBox);
    layout->addStretch(1);

    for (NumberField* f : findChildren<NumberField*>()) {
        connect(f, &NumberField::refused, this, &SceneProperties::refused);
    }
    connect(&m_document, &SceneDocument::sceneChanged, this, &SceneProperties::refresh);
    connect(&m_tools, &EditTools::selectionChanged, this, &SceneProperties::refresh);
    connect(&m_tools, &EditTools::propertyLocksChanged, this, &SceneProperties::applyLocks);
    refresh();
    applyLocks();
}

void SceneProperties::applyLocks()
{
    for (QWidget* w : findChildren<QWidget*>()) {
        const QString property = propertyOf(w);
        if (!isEditorProperty(property))
            continue;
        // The field's own tooltip (its range) comes back when the lock goes.
        if (!w->property("unlockedToolTip").isValid())
            w->setProperty("unlockedToolTip", w->toolTip());
        const bool locked = m_tools.propertyLocked(property);
        w->setEnabled(!locked);
        w->setToolTip(locked ? EditTools::propertyLockedMessage(rowLabel(w))
                             : w->property("unlockedToolTip").toString());
    }
}

bool SceneProperties::refuseLocked(const QWidget* field)
{
    if (!m_tools.propertyLocked(propertyOf(field)))
        return false;
    emit refused(EditTools::propertyLockedMessage(rowLabel(field)));
    refresh(); // the value in force comes back
    return true;
}

NumberField* SceneProperties::addNumber(QFormLayout* form, const QString& name,
                                        const QString& label)
{
    auto* f = new NumberField(this);
    f->setObjectName(name);
    form->addRow(label, f);
    return f;
}

void SceneProperties::addColourRow(QFormLayout* form)
{
    m_colour = new ColourField(m_bodyBox);
    form->addRow(tr("Colour"), m_colour);
    connect(m_colour, &ColourField::colourChosen, this, [this](const QString& colour) {
        apply(colour.isEmpty() ? tr("Default colour") : tr("Set colour"),
              edit::setBodyColour(m_document.scene(), m_tools.selectedBody(), colour), -1);
    });
}

NumberField* SceneProperties::field(const QString& name) const
{
    return findChild<NumberField*>(name);
}

void SceneProperties::apply(const QString& what, const edit::EditResult& result, int mergeId)
{
    if (!result.ok) {
        emit refused(result.error);
        refresh(); // the value in force comes back
        return;
    }
    m_document.apply(what, result.scene, mergeId);
}

void SceneProperties::refresh()
{
    const lessons::Scene& scene = m_document.scene();
    const int selected = m_tools.selectedBody();
    const bool hasBody = selected >= 0 && size_t(selected) < scene.bodies.size();
    m_bodyBox->setVisible(hasBody);
    if (hasBody) {
        const physics::BodyDef& def = scene.bodies[size_t(selected)];
        if (!m_id->hasFocus()) {
            m_id->setText(QString::fromStdString(def.name));
        }
        m_type->setCurrentIndex(m_type->findData(int(def.type)));
        // The one of density and mass the scene gives is shown as given; the other, computed
        // from it and the area, to four digits, without the rounding noise of the product.
        constexpr int kComputedDigits = 4;
        const double area = physics::computeMass(def.shape, 1.0).area;
        const bool massGiven = def.mass > 0;
        field(QStringLiteral("density"))
            ->setValue(massGiven ? def.mass / area : def.density,
                       massGiven ? kComputedDigits : NumberField::kFullDigits);
        field(QStringLiteral("mass"))
            ->setValue(massGiven ? def.mass : def.density * area,
                       massGiven ? NumberField::kFullDigits : kComputedDigits);
        // A static body has no mass and never moves; a kinematic one moves at its velocity
        // whatever its mass: only the rows that change something are shown.
        if (auto* form = qobject_cast<QFormLayout*>(m_bodyBox->layout())) {
            const bool dynamic = def.type == physics::BodyType::Dynamic;
            const bool moves = def.type != physics::BodyType::Static;
            for (const char* name : {"density", "mass"})
                form->setRowVisible(field(QLatin1String(name)), dynamic);
            for (const char* name : {"velocityX", "velocityY", "angularVelocity"})
                form->setRowVisible(field(QLatin1String(name)), moves);
        }
        // A body without its own restitution or friction takes the world's: shown as such.
        field(QStringLiteral("restitution"))
            ->setValue(def.restitution >= 0 ? def.restitution : scene.world.restitution);
        field(QStringLiteral("friction"))
            ->setValue(def.friction >= 0 ? def.friction : scene.world.friction);
        field(QStringLiteral("velocityX"))->setValue(def.velocity.x());
        field(QStringLiteral("velocityY"))->setValue(def.velocity.y());
        field(QStringLiteral("angularVelocity"))->setValue(def.angularVelocity);
        m_colour->setColour(scene.colourOf(size_t(selected)));
        if (const BodyItem* item = m_tools.view().itemFor(selected)) {
            m_colour->setShownColour(item->fill());
        }
    }
    const int spring = m_tools.selectedSpring();
    const bool hasSpring = spring >= 0 && size_t(spring) < scene.springs.size();
    m_springBox->setVisible(hasSpring);
    if (hasSpring) {
        const physics::SpringDef& s = scene.springs[size_t(spring)];
        field(QStringLiteral("stiffness"))->setValue(s.stiffness);
        field(QStringLiteral("damping"))->setValue(s.damping);
        field(QStringLiteral("restLength"))->setValue(s.restLength);
    }
    field(QStringLiteral("gravityX"))->setValue(scene.world.gravity.x());
    field(QStringLiteral("gravityY"))->setValue(scene.world.gravity.y());
    field(QStringLiteral("dt"))->setValue(scene.world.dt * 1e3);
    field(QStringLiteral("iterations"))->setValue(scene.world.iterations);
    m_integrator->setCurrentIndex(m_integrator->findData(int(scene.world.integrator)));
    m_solver->setCurrentIndex(m_solver->findData(int(scene.world.solver)));
}

} // namespace rigidlab::ui
