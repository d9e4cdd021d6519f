// SPDX-License-Identifier: GPL-3.0-or-later
#include "panels/divergence_banner.h"

#include "common/divergence_text.h"
#include "common/theme.h"
#include "simulation/simulation_controller.h"

#include "format/scene_loader.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>

namespace rigidlab::ui {

DivergenceBanner::DivergenceBanner(SimulationController& controller, QWidget* parent)
    : QWidget(parent), m_controller(controller), m_text(new QLabel(this))
{
    setObjectName(QStringLiteral("divergenceBanner"));
    // An opaque background of its own, from the palette. A plain QWidget paints no
    // style-sheet background (that needs WA_StyledBackground), and autoFillBackground paints
    // the background role, which a child inherits from its parent: from the view, Base, the
    // system's white (or black). So both roles are set here, on the banner and its text.
    QPalette colours = palette();
    colours.setColor(QPalette::Window, theme::alertBackground());
    colours.setColor(QPalette::WindowText, theme::alertText());
    setPalette(colours);
    setBackgroundRole(QPalette::Window);
    setForegroundRole(QPalette::WindowText);
    setAutoFillBackground(true);
    m_text->setPalette(colours);
    m_text->setBackgroundRole(QPalette::Window);
    m_text->setForegroundRole(QPalette::WindowText);
    QFont bold = m_text->font();
    bold.setBold(true);
    m_text->setFont(bold);
    m_text->setWordWrap(true);
    auto* reset = new QPushButton(tr("Reset"), this);
    auto* halve = new QPushButton(tr("Halve dt"), this);
    reset->setToolTip(tr("Back to the start of the scene"));
    halve->setToolTip(tr("Back to the start with half the time step"));
    halve->setObjectName(QStringLiteral("halveDt"));
    auto* layout = new QHBoxLayout(this);
    layout->addWidget(m_text, 1);
    layout->addWidget(reset);
    layout->addWidget(halve);
    connect(reset, &QPushButton::clicked, &m_controller, &SimulationController::reset);
    connect(halve, &QPushButton::clicked, this, [this] {
        m_controller.setDt(0.5 * m_controller.world().def().dt);
        m_controller.reset();
    });
    connect(&m_controller, &SimulationController::worldChanged, this, &DivergenceBanner::refresh);
    setVisible(false);
}

QString DivergenceBanner::text() const
{
    return m_text->text();
}

void DivergenceBanner::refresh()
{
    const auto& d = m_controller.world().divergence();
    if (d && m_controller.isRunning())
        m_controller.setRunning(false);
    if (d)
        m_text->setText(divergenceSentence(*d, m_controller.scene().bodyLabel(d->body)));
    // dt cannot go below a scene file's smallest: there the button has nothing left to do.
    if (auto* halve = findChild<QPushButton*>(QStringLiteral("halveDt")))
        halve->setEnabled(0.5 * m_controller.world().def().dt >= lessons::kMinDt);
    setVisible(d.has_value());
}

} // namespace rigidlab::ui
