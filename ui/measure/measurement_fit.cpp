// SPDX-License-Identifier: GPL-3.0-or-later
#include "measure/measurement_fit.h"

#include "common/number_format.h"
#include "editor/scene_document.h"
#include "measure/import_dialog.h"
#include "measure/measurement_panel.h"

#include "edit/scene_edits.h"

#include <QApplication>
#include <QLocale>
#include <QTimer>

#include <algorithm>
#include <cmath>

namespace rigidlab::ui {

using measure::ParameterKind;

namespace {

/// How often a running fit's count of runs is shown [ms].
constexpr int kFitProgressMs = 200;
constexpr ParameterKind kPanelKinds[MeasurementPanel::kFitParameters] = {
    ParameterKind::Restitution, ParameterKind::Friction, ParameterKind::VelocityX,
    ParameterKind::VelocityY};

lessons::edit::BodyNumber bodyNumberOf(ParameterKind kind)
{
    switch (kind) {
    case ParameterKind::Restitution:
        return lessons::edit::BodyNumber::Restitution;
    case ParameterKind::Friction:
        return lessons::edit::BodyNumber::Friction;
    case ParameterKind::VelocityX:
        return lessons::edit::BodyNumber::VelocityX;
    case ParameterKind::VelocityY:
        return lessons::edit::BodyNumber::VelocityY;
    }
    return lessons::edit::BodyNumber::Restitution;
}

QString parameterSymbol(ParameterKind kind)
{
    switch (kind) {
    case ParameterKind::Restitution:
        return QStringLiteral("e");
    case ParameterKind::Friction:
        return QStringLiteral("μ");
    case ParameterKind::VelocityX:
        return QStringLiteral("vx");
    case ParameterKind::VelocityY:
        return QStringLiteral("vy");
    }
    return {};
}

QString parameterUnit(ParameterKind kind)
{
    return kind == ParameterKind::VelocityX || kind == ParameterKind::VelocityY
               ? QStringLiteral("\u00A0m/s")
               : QString();
}

} // namespace

QString valueWithUncertainty(double value, double uncertainty)
{
    const QLocale locale;
    if (!(uncertainty > 0) || !std::isfinite(uncertainty) || !std::isfinite(value))
        return formatReadable(value, 4);
    const int decimals =
        std::clamp(1 - static_cast<int>(std::floor(std::log10(uncertainty))), 0, kMostDecimals);
    return locale.toString(value, 'f', decimals) + QStringLiteral("\u00A0±\u00A0") +
           locale.toString(uncertainty, 'f', decimals);
}

MeasurementFit::MeasurementFit(MeasurementPanel& panel, SceneDocument& document, SubjectOf subject,
                               QObject* parent)
    : QObject(parent), m_panel(panel), m_document(document), m_subject(std::move(subject))
{
    connect(&m_panel, &MeasurementPanel::fitRequested, this, &MeasurementFit::startFit);
    connect(&m_panel, &MeasurementPanel::cancelFitRequested, this, &MeasurementFit::cancelFit);
    m_fitWorker = new FitWorker(this);
    m_fitTimer = new QTimer(this);
    m_fitTimer->setInterval(kFitProgressMs);
    connect(m_fitTimer, &QTimer::timeout, this,
            [this] { m_panel.showFitRunning(m_fitWorker->runs()); });
    connect(m_fitWorker, &FitWorker::finished, this, [this](const measure::FitResult& result) {
        m_fitTimer->stop();
        m_fit = result;
        showFitResult();
        emit fitFinished();
    });
    connect(&m_panel, &MeasurementPanel::applyRequested, this, [this] {
        if (const QString error = apply(); !error.isEmpty())
            emit message(error, 8000);
    });
    connect(&m_panel, &MeasurementPanel::applyBounceRequested, this, [this] {
        if (const QString error = applyBounceFit(); !error.isEmpty())
            emit message(error, 8000);
    });
}

void MeasurementFit::dataChanged(Change change)
{
    if (!fitAwaited()) {
        if (change == Change::Imported) {
            m_fit = {};
            m_fitted.clear();
            m_panel.showFit(QString(), false);
        }
        return;
    }
    m_fitWorker->discard();
    m_fitTimer->stop();
    m_fit = {};
    m_fitted.clear();
    QString why;
    switch (change) {
    case Change::Imported:
        why = tr("Fit stopped: another measurement was imported. Fit again to fit the data "
                 "compared now.");
        break;
    case Change::Compared:
        why = tr("Fit stopped: another body or quantity is compared. Fit again to fit the data "
                 "compared now.");
        break;
    case Change::Edited:
        why = tr("Fit stopped: the scene changed. Fit again to fit the scene as it is now.");
        break;
    }
    m_fit.error = why;
    m_panel.showFit(why, false);
}

bool MeasurementFit::fitAwaited() const
{
    return m_fitTimer->isActive();
}

void MeasurementFit::forget()
{
    m_fitWorker->discard(); // its result would be of a measurement that is gone
    m_fitTimer->stop();
    m_fit = {};
    m_fitted.clear();
    m_bounceFit = {};
}

std::optional<FitWorker::Job> MeasurementFit::fitJob()
{
    m_fit = {};
    m_fitted.clear();
    const Subject subject = m_subject();
    if (!subject.series) {
        m_fit.error = tr("Import a measurement of a position or velocity first.");
        return std::nullopt;
    }
    const measure::Target& t = *subject.target;
    for (const int i : m_panel.fitChoices())
        m_fitted.push_back(
            measure::Parameter{kPanelKinds[i], {t.body}, parameterSymbol(kPanelKinds[i])});
    if (m_fitted.empty()) {
        m_fit.error = tr("Tick a parameter to fit.");
        return std::nullopt;
    }
    return FitWorker::Job{m_document.scene(), m_fitted, t, *subject.series};
}

const measure::FitResult& MeasurementFit::fit()
{
    m_fitWorker->discard(); // this fit replaces it
    m_fitTimer->stop();
    if (const auto job = fitJob()) {
        QApplication::setOverrideCursor(Qt::WaitCursor);
        m_fit = measure::fitScene(job->scene, job->parameters, job->target, job->series);
        QApplication::restoreOverrideCursor();
    }
    showFitResult();
    return m_fit;
}

void MeasurementFit::startFit()
{
    std::optional<FitWorker::Job> job = fitJob();
    if (!job) {
        m_fitWorker->discard();
        m_fitTimer->stop();
        showFitResult();
        emit fitFinished();
        return;
    }
    m_fitWorker->start(std::move(*job));
    m_panel.showFitRunning(0);
    m_fitTimer->start();
}

void MeasurementFit::cancelFit()
{
    m_fitWorker->cancel();
}

bool MeasurementFit::fitRunning() const
{
    return m_fitWorker->isRunning();
}

void MeasurementFit::showFitResult()
{
    if (!m_fit.ok) {
        m_panel.showFit(m_fit.error, false);
        return;
    }
    const Subject subject = m_subject();
    QStringList lines;
    for (std::size_t i = 0; i < m_fitted.size(); ++i)
        lines << tr("%1 = %2%3 (95 %)")
                     .arg(m_fitted[i].name,
                          valueWithUncertainty(m_fit.values[i].value, m_fit.values[i].halfWidth95),
                          parameterUnit(m_fitted[i].kind));
    lines << measure::describeModel(m_fit, m_fitted);
    if (const auto& t = subject.target) {
        lines << tr("Residual RMS: %1 over %n point(s)", nullptr, m_fit.points)
                     .arg(formatQuantity(m_fit.rms, quantityUnit(t->quantity), 2));
        if (!subject.file.isEmpty())
            lines << tr("Fitted to the measurement in %1.").arg(subject.file);
    }
    m_panel.showFit(lines.join(QLatin1Char('\n')), true);
}

QString MeasurementFit::apply()
{
    if (!m_fit.ok)
        return tr("Fit first: there are no fitted values to apply.");
    std::vector<double> values;
    for (const measure::FittedValue& v : m_fit.values)
        values.push_back(v.value);
    return applyValues(m_fitted, values, tr("Apply fitted values"));
}

QString MeasurementFit::applyBounceFit()
{
    const auto b = m_subject().body;
    if (!m_bounceFit.ok || !b)
        return tr("There is no e from bounce times to apply.");
    return applyValues({measure::Parameter{ParameterKind::Restitution, {*b}, {}}},
                       {m_bounceFit.e.value}, tr("Apply e from the bounce times"));
}

QString MeasurementFit::applyValues(const std::vector<measure::Parameter>& parameters,
                                    const std::vector<double>& values, const QString& what)
{
    lessons::Scene scene = m_document.scene();
    for (std::size_t i = 0; i < parameters.size(); ++i)
        for (const physics::BodyId body : parameters[i].bodies) {
            lessons::edit::EditResult r = lessons::edit::setBodyNumber(
                scene, body, bodyNumberOf(parameters[i].kind), values[i]);
            if (!r.ok)
                return r.error;
            scene = std::move(r.scene);
        }
    m_document.apply(what, scene);
    return {};
}

void MeasurementFit::fitBounceTimes(const std::vector<double>& bounces, const QString& file)
{
    m_bounceFit = {};
    if (bounces.empty()) {
        m_panel.showBounceFit(QString(), false);
        return;
    }
    m_bounceFit = measure::fitBounceTimes(bounces);
    if (!m_bounceFit.ok) {
        m_panel.showBounceFit(m_bounceFit.error, false);
        return;
    }
    QStringList flights;
    for (const double f : m_bounceFit.flightTimes)
        flights << formatQuantity(f, QStringLiteral("s"), 3);
    m_panel.showBounceFit(
        tr("From the bounce times alone (%3): e = %1 (95 %). Each flight between bounces lasts "
           "e times the one before: %2.")
            .arg(valueWithUncertainty(m_bounceFit.e.value, m_bounceFit.e.halfWidth95),
                 flights.join(QStringLiteral(", ")), file),
        true);
}

} // namespace rigidlab::ui
