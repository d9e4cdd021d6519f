// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A measurement in the window: File › Import measurement… (or a CSV dropped on the window)
// reads it through the import dialog; the Measurement dock compares it with the scene as
// edited, run headless from t = 0 (lessons/measure/fit.h's simulateAt, the same run the fit
// uses), and the scene view shows the measured positions as a faint trail. The fit of what is
// compared is measurement_fit.h's; the session tells it what the panel compares.
//
// A second import adds to the first rather than replacing it (a video's heights, then a
// phone's bounce times): each quantity is compared and fitted from the file imported last
// that has it, the dock names the file of each, and the plot shows the same quantity from
// the earlier files beside it, each named by its file (measurement_files.h).
//
// A measurement belongs to the scene it was imported into, or to the lesson: when another
// scene opens (a file, a new scene, another lesson), it is forgotten, trail and plots too, so
// that no unrelated crosses stay in the scene. The steps of one lesson keep it (a lesson
// imports in one step and fits in the next).

#include "measure/fit.h"
#include "measure/measurement.h"
#include "measure/measurement_files.h"
#include "measure/measurement_fit.h"

#include <QObject>
#include <QString>

#include <functional>
#include <map>
#include <optional>
#include <vector>

class QAction;
class QDockWidget;
class QWidget;

namespace rigidlab::ui {

class MeasuredTrailItem;
class MeasurementPanel;
class SceneDocument;
class WorldView;

class MeasurementSession : public QObject {
    Q_OBJECT
public:
    /// `window` gets the import action's drops; the view gets the trail.
    MeasurementSession(QWidget& window, WorldView& view, SceneDocument& document);
    ~MeasurementSession() override;

    /// File › Import measurement… (its keys from the key table).
    QAction* importAction() const { return m_import; }
    MeasurementPanel* panel() const { return m_panel; }
    /// The dock the panel is in; shown when a measurement is imported.
    void setDock(QDockWidget* dock) { m_dock = dock; }
    const MeasuredTrailItem* trail() const { return m_trail; }

    /// Asks for a file, then runs the import dialog on it.
    void importInteractively();
    /// Runs the import dialog on `path` and loads what it accepts; returns the refusal, empty
    /// when imported or cancelled.
    QString importFile(const QString& path);
    /// Loads `path` with `options` without a dialog; on an error nothing changes and the
    /// error (naming the file, line and column) is returned.
    QString load(const QString& path, const measure::MeasurementOptions& options = {});

    /// What the import dialog answers: the measurement's options, or nullopt when cancelled.
    /// Unset: the dialog, modal. (Tests answer without a dialog.)
    using ImportAsker = std::function<std::optional<measure::MeasurementOptions>(
        const QString& path, QString& error)>;
    void setImportAsker(ImportAsker asker) { m_asker = std::move(asker); }

    bool hasMeasurement() const { return m_measurement.has_value(); }
    const measure::Measurement& measurement() const { return *m_measurement; }
    /// The simulated values at the measured times and the residuals, of the last comparison.
    const std::vector<double>& simulated() const { return m_simulated; }
    const std::vector<double>& residuals() const { return m_residuals; }
    /// The body chosen in the panel, or nullopt (a scene without a dynamic body).
    std::optional<physics::BodyId> body() const;
    /// The target compared: the panel's body and quantity, or nullopt.
    std::optional<measure::Target> target() const;

    /// The fit of what the panel compares, and e from the bounce times.
    MeasurementFit& fitting() const { return *m_fitting; }

    /// Compares the measurement with the scene as it is now.
    void compare();

    /// The lesson open (its file), or empty: the window says so when a lesson's step starts
    /// and when the lesson closes. A measurement imported in another lesson, or outside one,
    /// is forgotten.
    void setLesson(const QString& lessonPath);
    /// Forgets the measurement: the trail, the plots and the fit go.
    void forget();

signals:
    /// A measurement was imported (the path).
    void imported(const QString& path);
    /// Why an import (or an Apply of the fit) failed, for the status bar.
    void message(const QString& text, int timeoutMs);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    /// Shows the dock in front, the first time in the place of the plots beside the view.
    void showDock();
    void updateChoices();
    void updateTrail();
    /// Another scene opened (SceneDocument::sceneReset).
    void sceneReset();
    /// What the panel compares now, for the fit.
    MeasurementFit::Subject fitSubject() const;
    /// m_measurement from the files imported, each quantity from the last file that has it.
    void merge();
    /// The files imported, one line each with what is taken from it.
    QString sourceText() const;

    QWidget& m_window;
    WorldView& m_view;
    SceneDocument& m_document;
    QAction* m_import = nullptr;
    MeasurementPanel* m_panel = nullptr;
    QDockWidget* m_dock = nullptr;
    MeasuredTrailItem* m_trail = nullptr; ///< owned by the view's scene
    ImportAsker m_asker;
    std::vector<MeasurementFile> m_imports;            ///< in the order imported
    std::map<measure::Quantity, QString> m_seriesFile; ///< the file each series comes from
    QString m_bouncesFile;                             ///< the file the bounce times come from
    QString m_lastFolder;
    QString m_lesson;            ///< the lesson open, or empty
    QString m_measurementLesson; ///< the lesson open when the measurement was imported
    std::optional<measure::Measurement> m_measurement;
    std::vector<double> m_simulated;
    std::vector<double> m_residuals;
    MeasurementFit* m_fitting = nullptr;
};

} // namespace rigidlab::ui
