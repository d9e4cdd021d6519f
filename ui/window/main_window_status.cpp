// SPDX-License-Identifier: GPL-3.0-or-later
// MainWindow's status bar (time, real-time rate, energy drift, stage timings) and timeline.
#include "window/main_window.h"

#include "common/display_names.h"
#include "common/status_text.h"
#include "panels/divergence_banner.h"
#include "simulation/drift_words.h"
#include "simulation/simulation_controller.h"
#include "view/world_view.h"
#include "window/settings_sync.h"

#include <QAction>
#include <QLabel>
#include <QLocale>
#include <QMenu>
#include <QSettings>
#include <QSignalBlocker>
#include <QSlider>
#include <QStatusBar>
#include <QTimer>

#include <cmath>
#include <optional>

namespace rigidlab::ui {

void MainWindow::buildStatusBar()
{
    m_statusTime = new QLabel(this);
    m_statusRate = new QLabel(this);
    m_statusDrift = new QLabel(this);
    m_statusDetails = new QLabel(this);
    m_statusSlow = new QLabel(tr("slower than real time"), this);
    m_statusSlow->setStyleSheet(
        QStringLiteral("color: white; background: #c0392b; padding: 1px 6px;"));
    m_statusSlow->setVisible(false);
    // A dot between the items: the style's own separators are faint or none (presentation
    // mode's palette), and "t = 2,000 s paused energy drift" reads as one phrase.
    const auto separator = [this](const QString& name) {
        auto* dot = new QLabel(QStringLiteral("·"), this);
        dot->setObjectName(name);
        return dot;
    };
    statusBar()->addWidget(m_statusTime);
    statusBar()->addWidget(separator(QStringLiteral("statusSeparator")));
    statusBar()->addWidget(m_statusRate);
    statusBar()->addWidget(separator(QStringLiteral("statusSeparator")));
    statusBar()->addWidget(m_statusDrift);
    statusBar()->addWidget(separator(QStringLiteral("statusDetailsSeparator")));
    statusBar()->addWidget(m_statusDetails);
    statusBar()->addPermanentWidget(m_statusSlow);

    // The timings are for whoever tunes the engine, not for the class: off unless asked for.
    const QString key = QStringLiteral("status/details");
    m_detailsAction = new QAction(tr("Status &details (steps/s, stage timings)"), this);
    m_detailsAction->setObjectName(QStringLiteral("statusDetails"));
    m_detailsAction->setCheckable(true);
    m_detailsAction->setChecked(QSettings().value(key, false).toBool());
    setDetailsShown(true);
    connect(m_detailsAction, &QAction::toggled, this, [this, key](bool on) {
        setDetailsShown(on);
        QSettings s;
        s.setValue(key, on);
        syncSettings(s, *this);
        updateStatus();
    });
    m_viewMenu->addSeparator();
    m_viewMenu->addAction(m_detailsAction);

    auto* statusTimer = new QTimer(this);
    connect(statusTimer, &QTimer::timeout, this, &MainWindow::updateStatus);
    statusTimer->start(250);
}

void MainWindow::updateStatus()
{
    const QLocale locale;
    const physics::World& w = m_controller->world();
    const bool running = m_controller->isRunning();
    m_statusTime->setText(tr("t = %1 s").arg(locale.toString(m_controller->time(), 'f', 3)));
    // Simulated seconds per wall second; while paused there is no rate to show.
    if (!running)
        m_statusRate->setText(tr("paused"));
    else if (const std::optional<double> factor = m_controller->realTimeFactor())
        m_statusRate->setText(tr("%1 × real time").arg(locale.toString(*factor, 'f', 2)));
    else
        m_statusRate->setText(tr("running"));
    // Drift is the numerical error alone: what contacts, friction, drag and dampers took is
    // physics, said apart. The label says whose error; the tooltip explains it.
    // On a projector, in short: the line must fit 1024 pixels at one and a half times the size.
    QString drift =
        driftLabel(m_presentation).arg(driftPercentText(m_controller->driftPercent(), locale));
    m_statusDrift->setToolTip(driftExplanation());
    const double lost = m_controller->dissipated();
    if (std::abs(lost) > 1e-9)
        drift += (m_presentation ? tr(" · dissipated %1 J")
                                 : tr(" · dissipated by contacts, friction, drag and dampers %1 J"))
                     .arg(locale.toString(lost, 'g', 3));
    // The adaptive integrator's own estimate of its local error, live (a developer's detail,
    // not shown on a projector).
    if (const auto estimate = w.integrator().errorEstimate(); estimate && !m_presentation)
        drift += tr(" · %1 error estimate %2 (%Ln substep(s))", nullptr, w.integrator().substeps())
                     .arg(integratorDisplayName(w.def().integrator))
                     .arg(locale.toString(*estimate, 'g', 2));
    m_statusDrift->setText(drift);
    if (m_detailsAction->isChecked()) {
        // The last step's stages that ran, with their times (physics/profile.h).
        QStringList stages;
        const physics::StepProfile& profile = w.profile();
        for (int k = 0; k < physics::kStageCount; ++k)
            if (profile.ran[k])
                stages << tr("%1 %2").arg(stageDisplayName(static_cast<physics::Stage>(k)),
                                          locale.toString(profile.ms[k], 'f', 2));
        const QString step =
            tr("last step %1 ms: %2")
                .arg(locale.toString(profile.total, 'f', 2), stages.join(QStringLiteral(", ")));
        // Rates only while the clock runs: a paused world has none, and an old one is stale.
        m_statusDetails->setText(
            running ? tr("%1 steps/s · frame %2 ms (physics %3 ms) · %4")
                          .arg(locale.toString(m_controller->stepsPerSecond(), 'f', 0),
                               locale.toString(m_controller->frameMilliseconds(), 'f', 1),
                               locale.toString(m_controller->physicsMilliseconds(), 'f', 1), step)
                    : step);
    } else {
        m_statusDetails->clear();
    }
    // Over the world, a banner when it diverged.
    if (auto* banner = findChild<DivergenceBanner*>()) {
        banner->refresh();
        banner->setGeometry(0, 0, m_view->width(), banner->sizeHint().height());
        banner->raise();
    }
    m_statusSlow->setVisible(running && m_controller->slowerThanRealTime());
}

QString MainWindow::statusText() const
{
    QStringList parts;
    for (const QLabel* label :
         {m_statusTime, m_statusRate, m_statusDrift, m_statusDetails, m_statusSlow})
        if (!label->isHidden() && !label->text().isEmpty())
            parts << label->text();
    return parts.join(QStringLiteral(" | "));
}

void MainWindow::updateTimeline()
{
    // The label follows the drag too; the slider itself is left to the hand that holds it.
    const long long lo = m_controller->earliestStep(), hi = m_controller->latestStep();
    // One clock: the status bar's time moves with the timeline's, in the same frame.
    const QString t = QLocale().toString(m_controller->time(), 'f', 3);
    m_statusTime->setText(tr("t = %1 s").arg(t));
    // Step counts grouped as the locale does ("10 000" in Czech), as on the plots' axes.
    m_timeLabel->setText(
        tr(" step %1 of %2 · t = %3 s")
            .arg(QLocale().toString(m_controller->currentStep()), QLocale().toString(hi), t));
    if (m_timeline->isSliderDown())
        return;
    const QSignalBlocker block(m_timeline);
    m_timeline->setRange(static_cast<int>(lo), static_cast<int>(hi));
    m_timeline->setValue(static_cast<int>(m_controller->currentStep()));
}

void MainWindow::setDetailsShown(bool shown)
{
    // Presentation mode hides them whatever View › Status details says.
    m_statusDetails->setVisible(shown && m_detailsAction->isChecked() && !m_presentation);
    if (auto* dot = findChild<QLabel*>(QStringLiteral("statusDetailsSeparator")))
        dot->setVisible(!m_statusDetails->isHidden());
}

} // namespace rigidlab::ui
