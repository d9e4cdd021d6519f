// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The fit of an imported measurement in the window: the parameters ticked in the Measurement
// dock fitted to the series compared (lessons/measure/fit.h's fitScene) in a worker of its own
// (fit_worker.h), its runs so far and Cancel in the panel meanwhile, its values with their
// intervals shown when it ends and put into the scene, on Apply, as one edit of its document
// that Undo takes back; and e from the bounce times alike (fitBounceTimes). What is compared,
// and from which file, is the session's (measurement_session.h): the fit asks it each time.

#include "measure/fit.h"
#include "measure/fit_worker.h"
#include "measure/measurement.h"

#include <QObject>
#include <QString>

#include <functional>
#include <optional>
#include <vector>

class QTimer;

namespace rigidlab::ui {

class MeasurementPanel;
class SceneDocument;

class MeasurementFit : public QObject {
    Q_OBJECT
public:
    /// What the panel compares now, as the session knows it.
    struct Subject {
        std::optional<physics::BodyId> body;     ///< the panel's body, if the scene has one
        std::optional<measure::Target> target;   ///< that body's quantity chosen, if measured
        const measure::Series* series = nullptr; ///< the target's measured series, or null
        QString file;                            ///< the file the series comes from, or empty
    };
    using SubjectOf = std::function<Subject()>;

    /// Fits what `subject` says the panel compares, in `document`'s scene; the panel's Fit,
    /// Cancel and Apply buttons drive it.
    MeasurementFit(MeasurementPanel& panel, SceneDocument& document, SubjectOf subject,
                   QObject* parent);

    /// Fits the parameters ticked in the panel, here and now (the screenshots); the result
    /// stays for apply().
    const measure::FitResult& fit();
    /// The same fit in a thread of its own (the panel's Fit button): the panel shows it
    /// running with a Cancel button; fitFinished() when it ends, lastFit() then holds it.
    void startFit();
    void cancelFit();
    bool fitRunning() const;
    const measure::FitResult& lastFit() const { return m_fit; }
    /// Puts the fitted values into the scene, one undoable edit; returns the refusal or empty.
    QString apply();

    /// e from `bounces` (the times of a measurement's bounces, read from `file`), shown in the
    /// panel; none when there are no bounce times.
    void fitBounceTimes(const std::vector<double>& bounces, const QString& file);
    const measure::BounceFit& bounceFit() const { return m_bounceFit; }
    QString applyBounceFit();

    /// What changes what a fit is of: the series compared and the scene it is fitted in.
    enum class Change {
        Imported, ///< another file imported: the series may be another's
        Compared, ///< another body or quantity chosen in the panel
        Edited,   ///< the scene edited, undone or started over
    };
    /// `change` happened: a fit still running is of the data before it, so its result is
    /// dropped and the panel says why (it would otherwise show, and Apply, values fitted to
    /// data no longer shown). A new file imported takes the last fit's result from the panel
    /// too; the other changes leave a result that ended (Apply puts in what it fitted).
    void dataChanged(Change change);
    /// The measurement forgotten: a fit running is dropped, and every result goes.
    void forget();

signals:
    /// A fit started by startFit() ended (cancelled too): lastFit() holds it.
    void fitFinished();
    /// Why Apply was refused, for the status bar.
    void message(const QString& text, int timeoutMs);

private:
    /// What the panel asks to fit, into m_fitted; nothing (m_fit says why) when it cannot be.
    std::optional<FitWorker::Job> fitJob();
    /// m_fit in the panel.
    void showFitResult();
    /// A fit started whose result is still wanted: from startFit() until it is shown or
    /// dropped (its progress is shown meanwhile). The worker may run on a moment after a drop,
    /// to its next run.
    bool fitAwaited() const;
    QString applyValues(const std::vector<measure::Parameter>& parameters,
                        const std::vector<double>& values, const QString& what);

    MeasurementPanel& m_panel;
    SceneDocument& m_document;
    SubjectOf m_subject;
    FitWorker* m_fitWorker = nullptr;
    QTimer* m_fitTimer = nullptr; ///< while a fit runs: its runs so far into the panel
    measure::FitResult m_fit;
    std::vector<measure::Parameter> m_fitted;
    measure::BounceFit m_bounceFit;
};

/// "0,720 ± 0,012": a value to the digits its uncertainty leaves meaningful (two of the
/// uncertainty), in the locale's numbers.
QString valueWithUncertainty(double value, double uncertainty);

} // namespace rigidlab::ui
