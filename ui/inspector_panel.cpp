#include "inspector_panel.h"

#include "simulation_controller.h"

#include "rigidlab/lessons/limits.h"

#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QSignalBlocker>

namespace rigidlab::ui {

namespace {

QString num(double v, int precision = 4)
{
    return QString::number(v, 'g', precision);
}

} // namespace

InspectorPanel::InspectorPanel(SimulationController& controller, QWidget* parent)
    : QWidget(parent), m_controller(controller), m_name(new QLabel(this)), m_mass(new QLabel(this)),
      m_inertia(new QLabel(this)), m_position(new QLabel(this)), m_angle(new QLabel(this)),
      m_velocity(new QLabel(this)), m_omega(new QLabel(this)), m_energy(new QLabel(this)),
      m_restitution(new QDoubleSpinBox(this)), m_friction(new QDoubleSpinBox(this))
{
    auto* form = new QFormLayout(this);
    form->addRow(tr("Body"), m_name);
    form->addRow(tr("Mass m"), m_mass);
    form->addRow(tr("Inertia I"), m_inertia);
    form->addRow(tr("Position"), m_position);
    form->addRow(tr("Angle θ"), m_angle);
    form->addRow(tr("Velocity v"), m_velocity);
    form->addRow(tr("Angular vel. ω"), m_omega);
    form->addRow(tr("Kinetic energy"), m_energy);
    form->addRow(tr("Restitution e"), m_restitution);
    form->addRow(tr("Friction μ"), m_friction);
    for (QLabel* l :
         {m_name, m_mass, m_inertia, m_position, m_angle, m_velocity, m_omega, m_energy})
        l->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_restitution->setRange(0.0, 1.0);
    m_restitution->setSingleStep(0.05);
    m_friction->setRange(lessons::limits::kFriction.min, lessons::limits::kFriction.max);
    m_friction->setSingleStep(0.05);
    auto edit = [this] {
        m_controller.setBodyMaterial(m_body, m_restitution->value(), m_friction->value());
    };
    connect(m_restitution, &QDoubleSpinBox::valueChanged, this, edit);
    connect(m_friction, &QDoubleSpinBox::valueChanged, this, edit);
    connect(&m_controller, &SimulationController::worldChanged, this, &InspectorPanel::refresh);
    connect(&m_controller, &SimulationController::sceneLoaded, this, [this] { setBody(-1); });
    setBody(-1);
}

void InspectorPanel::setBody(int id)
{
    const int count = static_cast<int>(m_controller.world().bodies().size());
    m_body = id >= 0 && id < count ? id : -1;
    refresh();
}

void InspectorPanel::refresh()
{
    const bool has = m_body >= 0;
    m_restitution->setEnabled(has);
    m_friction->setEnabled(has);
    if (!has) {
        m_name->setText(tr("click a body"));
        for (QLabel* l : {m_mass, m_inertia, m_position, m_angle, m_velocity, m_omega, m_energy})
            l->setText(QStringLiteral("–"));
        return;
    }
    const physics::Body& b = m_controller.world().body(m_body);
    const char* kind = b.type == physics::BodyType::Static      ? "static"
                       : b.type == physics::BodyType::Kinematic ? "kinematic"
                                                                : "dynamic";
    m_name->setText(QStringLiteral("%1 (%2)").arg(QString::fromStdString(b.name), tr(kind)));
    if (b.isDynamic()) {
        m_mass->setText(tr("%1 kg").arg(num(b.mass)));
        m_inertia->setText(tr("%1 kg·m²").arg(num(b.inertia)));
    } else {
        m_mass->setText(tr("infinite"));
        m_inertia->setText(tr("infinite"));
    }
    const physics::Vec2 o = b.origin();
    const physics::Vec2 v = m_controller.world().originVelocity(m_body);
    m_position->setText(tr("(%1, %2) m").arg(num(o.x()), num(o.y())));
    m_angle->setText(tr("%1 rad").arg(num(b.angle)));
    m_velocity->setText(tr("(%1, %2) m/s").arg(num(v.x()), num(v.y())));
    m_omega->setText(tr("%1 rad/s").arg(num(b.angularVelocity)));
    const double ke = b.isDynamic() ? 0.5 * b.mass * b.velocity.squaredNorm() +
                                          0.5 * b.inertia * b.angularVelocity * b.angularVelocity
                                    : 0.0;
    m_energy->setText(tr("%1 J").arg(num(ke)));
    const QSignalBlocker b1(m_restitution), b2(m_friction);
    if (!m_restitution->hasFocus())
        m_restitution->setValue(b.restitution);
    if (!m_friction->hasFocus())
        m_friction->setValue(b.friction);
}

QString InspectorPanel::text() const
{
    QStringList parts;
    for (QLabel* l :
         {m_name, m_mass, m_inertia, m_position, m_angle, m_velocity, m_omega, m_energy})
        parts << l->text();
    return parts.join(QLatin1Char('\n'));
}

} // namespace rigidlab::ui
