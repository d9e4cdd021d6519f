// SPDX-License-Identifier: GPL-3.0-or-later
#include "window/status_line.h"

#include "common/announcer.h"
#include "common/calm_text.h"
#include "common/display_names.h"
#include "common/status_text.h"
#include "common/theme.h"
#include "panels/divergence_banner.h"
#include "simulation/drift_words.h"
#include "simulation/simulation_controller.h"
#include "view/world_view.h"
#include "window/settings_sync.h"
#include "window/status_solver.h"
#include "window/window_layout.h"

#include <QAction>
#include <QLabel>
#include <QLocale>
#include <QMainWindow>
#include <QSettings>
#include <QSignalBlocker>
#include <QSlider>
#include <QStatusBar>
#include <QTextDocumentFragment>
#include <QTimer>
#include <QToolBar>

#include <cmath>
#include <optional>

namespace rigidlab::ui {

namespace {

/// The timeline's "step … of … · t = … s" is at least this wide [px].
constexpr int kTimelineLabelWidth = 180;

} // namespace

StatusLine::StatusLine(QMainWindow& window, SimulationController& controller, WorldView& view)
    : QObject(&window), m_window(window), m_controller(controller), m_view(view)
{
    QStatusBar* bar = window.statusBar();
    // Readable from the back of a classroom, not only from the teacher's chair.
    QFont font = bar->font();
    font.setPointSizeF(font.pointSizeF() * theme::kReadingFontScale);
    bar->setFont(font);
    bar->setProperty(kReadingSizeProperty, true);
    m_time = new QLabel(&window);
    m_rate = new QLabel(&window);
    m_drift = new QLabel(&window);
    m_solver = new QLabel(&window);
    m_solver->setObjectName(QStringLiteral("statusSolver"));
    m_details = new QLabel(&window);
    m_slow = new QLabel(tr("slower than real time"), &window);
    m_slow->setStyleSheet(QStringLiteral("color: white; background: #c0392b; padding: 1px 6px;"));
    m_slow->setVisible(false);
    m_slow->setToolTip(tr("A frame's physics takes longer than the frame has: the clock leaves "
                          "out the time it cannot catch up with, so the run goes slower than "
                          "real time instead of falling further behind."));
    // A dot between the items: the style's own separators are faint or none (presentation
    // mode's palette), and "t = 2,000 s paused energy drift" reads as one phrase.
    const auto separator = [&window](const QString& name) {
        auto* dot = new QLabel(QStringLiteral("·"), &window);
        dot->setObjectName(name);
        return dot;
    };
    bar->addWidget(m_time);
    bar->addWidget(separator(QStringLiteral("statusSeparator")));
    bar->addWidget(m_rate);
    bar->addWidget(separator(QStringLiteral("statusSeparator")));
    bar->addWidget(m_drift);
    bar->addWidget(separator(QStringLiteral("statusSeparator")));
    bar->addWidget(m_solver);
    bar->addWidget(separator(QStringLiteral("statusDetailsSeparator")));
    bar->addWidget(m_details);
    bar->addPermanentWidget(m_slow);
    // A message (the editor's hint, a refusal) takes the line's place while it lasts. The
    // status bar hides its widgets only if they are visible at that moment, so a label shown
    // again later, or one not yet on screen, would be drawn over the message.
    connect(bar, &QStatusBar::messageChanged, this, [this](const QString& message) {
        m_messageShown = !message.isEmpty();
        for (QLabel* label : {m_time, m_rate, m_drift, m_solver})
            label->setVisible(!m_messageShown);
        for (auto* dot : m_window.findChildren<QLabel*>(QStringLiteral("statusSeparator")))
            dot->setVisible(!m_messageShown);
        setDetailsShown(!m_presentation);
    });

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
        syncSettings(s, m_window);
        update();
    });
    buildTimeline();
    // Made now, so that a screen reader knows it before the first announcement.
    prepareAnnouncer(window);
    connect(&controller, &SimulationController::worldChanged, this, &StatusLine::updateTimeline);
    m_timelineLater.setSingleShot(true);
    connect(&m_timelineLater, &QTimer::timeout, this, &StatusLine::updateTimeline);
    connect(&controller, &SimulationController::runningChanged, this, &StatusLine::updateTimeline);

    auto* statusTimer = new QTimer(this);
    connect(statusTimer, &QTimer::timeout, this, &StatusLine::update);
    statusTimer->start(250);
}

void StatusLine::buildTimeline()
{
    // The timeline: drag to any earlier moment of the run.
    auto* timebar = new QToolBar(tr("Timeline"), &m_window);
    timebar->setObjectName(QStringLiteral("timelineToolbar"));
    m_window.addToolBar(Qt::BottomToolBarArea, timebar);
    m_timeline = new QSlider(Qt::Horizontal, timebar);
    m_timeline->setToolTip(tr("Time travel: drag to go back to any moment, then play to go on "
                              "(or change a setting to branch)"));
    m_timeline->setObjectName(QStringLiteral("timeline"));
    m_timeline->setAccessibleName(tr("Timeline"));
    m_timeLabel = new QLabel(timebar);
    m_timeLabel->setObjectName(QStringLiteral("timelineLabel"));
    m_timeLabel->setMinimumWidth(kTimelineLabelWidth);
    timebar->addWidget(new QLabel(tr(" Timeline "), timebar));
    timebar->addWidget(m_timeline);
    timebar->addWidget(m_timeLabel);
    connect(m_timeline, &QSlider::valueChanged, this, [this](int value) {
        if (m_timeline->isSliderDown() || value != m_controller.world().stepCount())
            m_controller.seek(value);
    });
}

void StatusLine::update()
{
    const QLocale locale;
    const bool running = m_controller.isRunning();
    setSteadyText(*m_time, tr("t = %1 s").arg(locale.toString(m_controller.time(), 'f', 3)),
                  running);
    // Simulated seconds per wall second; while paused there is no rate to show.
    if (!running)
        setCalmText(*m_rate, tr("paused"));
    else if (const std::optional<double> factor = m_controller.timing().realTimeFactor())
        setCalmText(*m_rate, tr("%1 × real time").arg(locale.toString(*factor, 'f', 2)));
    else
        setCalmText(*m_rate, tr("running"));
    // The short wording of presentation mode where the full one would be cut (a 1024-pixel
    // window at the classroom text size); the full one in the tooltip.
    // The solver that runs, not only the one asked for (status_solver.h).
    setCalmText(*m_solver, solverStatusText(m_controller.world()));
    m_solver->setToolTip(solverStatusTip(m_controller.world()));
    const QString full = driftText(m_presentation);
    int others = 0;
    for (const QLabel* label : m_window.statusBar()->findChildren<QLabel*>())
        if (label != m_drift && !label->isHidden())
            others += label->sizeHint().width() + 8;
    const bool fits =
        m_drift->fontMetrics().horizontalAdvance(full) + others < m_window.statusBar()->width();
    setCalmText(*m_drift, fits ? full : driftText(true));
    m_drift->setToolTip(driftText(false) + QStringLiteral("\n\n") + driftExplanation());
    // A reader gets the tooltip's explanation as plain words (the tooltip is rich text, which
    // it would read tag by tag), once: it does not change as the run goes on.
    if (m_drift->accessibleDescription().isEmpty())
        m_drift->setAccessibleDescription(
            QTextDocumentFragment::fromHtml(driftExplanation()).toPlainText());
    if (m_detailsAction->isChecked())
        setCalmText(*m_details, detailsText(running));
    else
        m_details->clear();
    // Over the world, a banner when it diverged.
    if (auto* banner = m_window.findChild<DivergenceBanner*>()) {
        banner->refresh();
        banner->setGeometry(0, 0, m_view.width(), banner->sizeHint().height());
        banner->raise();
    }
    m_slow->setVisible(running && m_controller.slowerThanRealTime());
}

QString StatusLine::driftText(bool brief) const
{
    const QLocale locale;
    const physics::World& w = m_controller.world();
    // Drift is the numerical error alone: what contacts, friction, drag and dampers took is
    // physics, said apart. The label says whose error (drift_words.h).
    // In short (`brief`) on a projector: the line must fit 1024 pixels at the larger size.
    QString drift = driftLabel(brief).arg(
        driftPercentText(m_controller.recorder().driftPercent(m_controller.world()), locale));
    const double lost = m_controller.recorder().dissipated(m_controller.world());
    if (std::abs(lost) > 1e-9)
        drift += (brief ? tr(" · dissipated %1 J")
                        : tr(" · dissipated by contacts, friction, drag and dampers %1 J"))
                     .arg(dissipatedText(lost, m_controller.recorder().energyScale(), locale));
    // The adaptive integrator's own estimate of its local error, live (a developer's detail,
    // not shown on a projector).
    if (const auto estimate = w.integrator().errorEstimate(); estimate && !brief)
        drift += tr(" · %1 error estimate %2 (%Ln substep(s))", nullptr, w.integrator().substeps())
                     .arg(integratorDisplayName(w.def().integrator))
                     .arg(estimateText(*estimate, 2, locale));
    return drift;
}

QString StatusLine::detailsText(bool running) const
{
    const QLocale locale;
    // The last step's stages that ran, with their times (physics/profile.h).
    QStringList stages;
    const physics::StepProfile& profile = m_controller.world().profile();
    for (int k = 0; k < physics::kStageCount; ++k)
        if (profile.ran[k])
            stages << tr("%1 %2").arg(stageDisplayName(static_cast<physics::Stage>(k)),
                                      locale.toString(profile.ms[k], 'f', 2));
    const QString step =
        tr("last step %1 ms: %2")
            .arg(locale.toString(profile.total, 'f', 2), stages.join(QStringLiteral(", ")));
    // Rates only while the clock runs: a paused world has none, and an old one is stale.
    if (!running)
        return step;
    return tr("%1 steps/s · frame %2 ms (physics %3 ms) · %4")
        .arg(locale.toString(m_controller.timing().stepsPerSecond(), 'f', 0),
             locale.toString(m_controller.timing().frameMilliseconds(), 'f', 1),
             locale.toString(m_controller.timing().physicsMilliseconds(), 'f', 1), step);
}

QString StatusLine::text() const
{
    QStringList parts;
    for (const QLabel* label : {m_time, m_rate, m_drift, m_solver, m_details, m_slow})
        if (!label->isHidden() && !label->text().isEmpty())
            parts << label->text();
    return parts.join(QStringLiteral(" | "));
}

void StatusLine::updateTimeline()
{
    // The label follows the drag too; the slider itself is left to the hand that holds it.
    const long long lo = m_controller.history().earliest(), hi = m_controller.history().latest();
    // One clock: the status bar's time moves with the timeline's, in the same frame.
    const QString t = QLocale().toString(m_controller.time(), 'f', 3);
    // Both change every frame while the clock runs: they keep their size then (calm_text.h).
    const bool running = m_controller.isRunning();
    setSteadyText(*m_time, tr("t = %1 s").arg(t), running);
    // Step counts grouped as the locale does ("10 000" in Czech), as on the plots' axes.
    setSteadyText(
        *m_timeLabel,
        tr(" step %1 of %2 · t = %3 s")
            .arg(QLocale().toString(m_controller.world().stepCount()), QLocale().toString(hi), t),
        running, kTimelineLabelWidth);
    if (m_timeline->isSliderDown())
        return;
    // A slider tells assistive technology of every value it takes. While the clock runs the
    // timeline follows it once a second (its handle stays at the end of a run that grows);
    // a step, a seek or a pause moves it at once.
    if (m_controller.isRunning() && m_timelineMoved.isValid() &&
        m_timelineMoved.elapsed() < kCalmIntervalMs) {
        if (!m_timelineLater.isActive())
            m_timelineLater.start(kCalmIntervalMs - static_cast<int>(m_timelineMoved.elapsed()));
        return;
    }
    m_timelineLater.stop();
    m_timelineMoved.restart();
    const QSignalBlocker block(m_timeline);
    m_timeline->setRange(static_cast<int>(lo), static_cast<int>(hi));
    m_timeline->setValue(static_cast<int>(m_controller.world().stepCount()));
}

void StatusLine::setPresentation(bool on)
{
    m_presentation = on;
    // No developer details on a projector.
    setDetailsShown(!on);
    update(); // the short status line of presentation mode, or the full one
}

void StatusLine::setDetailsShown(bool shown)
{
    // Presentation mode hides them whatever View › Status details says.
    m_details->setVisible(shown && m_detailsAction->isChecked() && !m_presentation &&
                          !m_messageShown);
    if (auto* dot = m_window.findChild<QLabel*>(QStringLiteral("statusDetailsSeparator")))
        dot->setVisible(!m_details->isHidden());
}

} // namespace rigidlab::ui
