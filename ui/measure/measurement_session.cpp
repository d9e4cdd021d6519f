// SPDX-License-Identifier: GPL-3.0-or-later
#include "measure/measurement_session.h"

#include "common/modal_scope.h"
#include "common/shortcuts.h"
#include "editor/scene_document.h"
#include "measure/import_dialog.h"
#include "measure/measured_trail.h"
#include "measure/measurement_panel.h"
#include "view/world_view.h"

#include "format/data_dirs.h"

#include <QAction>
#include <QDir>
#include <QDockWidget>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QGraphicsScene>
#include <QMainWindow>
#include <QMimeData>
#include <QTimer>

#include <algorithm>
#include <cmath>
#include <map>

namespace rigidlab::ui {

using measure::Quantity;

namespace {

/// The Measurement dock's width when it opens: its own share of the window, at least enough
/// for the plots' tick labels and the fitted values [px].
constexpr int kDockWidthPx = 360;
constexpr double kDockShare = 0.36;
/// Points of the simulated line: smooth on any plot a dock can be, cheap to run again.
constexpr int kLinePoints = 600;

/// A file dropped that could be a measurement (the reader says whether it is one).
QString droppedMeasurement(const QMimeData* mime)
{
    if (!mime || !mime->hasUrls())
        return {};
    for (const QUrl& url : mime->urls()) {
        const QString suffix = QFileInfo(url.toLocalFile()).suffix().toLower();
        if (url.isLocalFile() && (suffix == QLatin1String("csv") ||
                                  suffix == QLatin1String("txt") || suffix == QLatin1String("tsv")))
            return url.toLocalFile();
    }
    return {};
}

/// The samples folder shipped with the lab (lessons/measure/samples in the source tree).
QString samplesFolder()
{
    const QString dir = lessons::shippedDataDir();
    return dir.isEmpty() ? QString() : dir + QStringLiteral("/measure/samples");
}

} // namespace

MeasurementSession::MeasurementSession(QWidget& window, WorldView& view, SceneDocument& document)
    : QObject(&window), m_window(window), m_view(view), m_document(document)
{
    m_import = new QAction(tr("&Import measurement…"), this);
    m_import->setObjectName(QStringLiteral("importMeasurement"));
    m_import->setShortcuts(controlKeys("importMeasurement"));
    m_import->setToolTip(tr("Read a measured time series (Tracker, phyphox or plain CSV) to "
                            "compare the scene with and fit it to"));
    connect(m_import, &QAction::triggered, this, &MeasurementSession::importInteractively);
    m_panel = new MeasurementPanel(&window);
    m_trail = new MeasuredTrailItem;
    view.scene()->addItem(m_trail);
    window.setAcceptDrops(true);
    window.installEventFilter(this);
    view.viewport()->installEventFilter(this);
    m_fitting = new MeasurementFit(
        *m_panel, document, [this] { return fitSubject(); }, this);
    connect(m_panel, &MeasurementPanel::choiceChanged, this, [this] {
        m_fitting->dataChanged(MeasurementFit::Change::Compared);
        compare();
    });
    connect(m_fitting, &MeasurementFit::message, this, &MeasurementSession::message);
    connect(&document, &SceneDocument::sceneReset, this, &MeasurementSession::sceneReset);
    connect(&document, &SceneDocument::sceneChanged, this, [this] {
        m_fitting->dataChanged(MeasurementFit::Change::Edited);
        updateChoices();
        compare();
    });
}

MeasurementSession::~MeasurementSession() = default; // the view's scene owns the trail

void MeasurementSession::importInteractively()
{
    QString folder = m_lastFolder.isEmpty() ? samplesFolder() : m_lastFolder;
    QString path;
    {
        ModalScope scope;
        path = QFileDialog::getOpenFileName(&m_window, tr("Import measurement"), folder,
                                            tr("Measurements (*.csv *.txt *.tsv);;All files (*)"));
    }
    if (path.isEmpty())
        return;
    m_lastFolder = QFileInfo(path).absolutePath();
    if (const QString error = importFile(path); !error.isEmpty())
        emit message(error, 10000);
}

QString MeasurementSession::importFile(const QString& path)
{
    std::optional<measure::MeasurementOptions> options;
    QString error;
    if (m_asker) {
        options = m_asker(path, error);
    } else {
        ModalScope scope;
        MeasurementImportDialog dialog(path, &m_window);
        if (dialog.exec() == QDialog::Accepted)
            options = dialog.options();
        else
            error = dialog.error();
    }
    if (!options)
        return error;
    return load(path, *options);
}

QString MeasurementSession::load(const QString& path, const measure::MeasurementOptions& options)
{
    measure::MeasurementResult read = measure::readMeasurementFile(path, options);
    if (!read.ok) {
        emit message(read.error, 10000);
        return read.error;
    }
    // A second file adds to the first (measurement_files.h).
    if (!m_measurement || m_measurementLesson != m_lesson)
        forget();
    m_imports.push_back({QFileInfo(path).fileName(), std::move(read.measurement)});
    merge();
    m_measurementLesson = m_lesson;
    m_fitting->dataChanged(MeasurementFit::Change::Imported);
    m_panel->setSource(sourceText());
    updateChoices();
    m_fitting->fitBounceTimes(m_measurement->bounces, m_bouncesFile);
    compare();
    showDock();
    emit imported(path);
    return {};
}

void MeasurementSession::setLesson(const QString& lessonPath)
{
    m_lesson = lessonPath;
    if (m_measurement && m_measurementLesson != m_lesson)
        forget();
}

void MeasurementSession::sceneReset()
{
    // The window may say which lesson is open before or after the step's scene starts over:
    // either way, a measurement of another lesson or of a scene goes.
    if (m_measurement && (m_lesson.isEmpty() || m_measurementLesson != m_lesson))
        forget();
}

void MeasurementSession::merge()
{
    MergedMeasurement merged = mergeMeasurementFiles(m_imports);
    m_measurement = std::move(merged.measurement);
    m_seriesFile = std::move(merged.seriesFile);
    m_bouncesFile = std::move(merged.bouncesFile);
}

QString MeasurementSession::sourceText() const
{
    // One line per file, naming what the comparison takes from it.
    QStringList lines;
    for (const MeasurementFile& in : m_imports) {
        QStringList what;
        int points = 0;
        for (const measure::Series& s : m_measurement->series)
            if (m_seriesFile.at(s.quantity) == in.file) {
                what << quantityText(s.quantity);
                points = std::max(points, static_cast<int>(s.t.size()));
            }
        if (m_bouncesFile == in.file && !m_measurement->bounces.empty()) {
            what << quantityText(Quantity::BounceTime);
            if (points == 0)
                points = static_cast<int>(m_measurement->bounces.size());
        }
        if (!what.isEmpty())
            lines << tr("%1: %n point(s) of %2", nullptr, points)
                         .arg(in.file, what.join(QStringLiteral(", ")));
    }
    lines.removeDuplicates();
    return lines.join(QLatin1Char('\n'));
}

void MeasurementSession::forget()
{
    m_fitting->forget();
    m_measurement.reset();
    m_imports.clear();
    m_seriesFile.clear();
    m_bouncesFile.clear();
    m_measurementLesson.clear();
    m_simulated.clear();
    m_residuals.clear();
    m_panel->clear();
    updateTrail();
}

void MeasurementSession::showDock()
{
    if (!m_dock)
        return;
    auto* window = qobject_cast<QMainWindow*>(&m_window);
    if (window && m_dock->isHidden()) {
        // In the place of the tallest dock beside it (the plots), in front, in a column wide
        // enough for two plots' tick labels and the fit's numbers.
        QDockWidget* tallest = nullptr;
        for (QDockWidget* d : window->findChildren<QDockWidget*>())
            if (d != m_dock && !d->isHidden() && !d->isFloating() &&
                window->dockWidgetArea(d) == window->dockWidgetArea(m_dock) &&
                (!tallest || d->height() > tallest->height()))
                tallest = d;
        if (tallest)
            window->tabifyDockWidget(tallest, m_dock);
        // Never narrower than the plots' tick labels need, on a projector's 1024 px too (the
        // side column's own share of the window is less).
        m_dock->setMinimumWidth(
            std::min(kDockWidthPx, static_cast<int>(kDockShare * window->width())));
    }
    m_dock->show();
    m_dock->raise();
}

std::optional<physics::BodyId> MeasurementSession::body() const
{
    const lessons::Scene& scene = m_document.scene();
    int index = m_panel->body();
    for (std::size_t i = 0; i < scene.bodies.size(); ++i)
        if (scene.bodies[i].type != physics::BodyType::Static && index-- == 0)
            return static_cast<physics::BodyId>(i);
    return std::nullopt;
}

std::optional<measure::Target> MeasurementSession::target() const
{
    const auto b = body();
    const Quantity q = m_panel->quantity();
    if (!b || q == Quantity::Ignored)
        return std::nullopt;
    return measure::Target{q, *b,
                           measure::quantityName(q) + QLatin1Char(':') +
                               QString::fromStdString(m_document.scene().bodies[*b].name)};
}

MeasurementFit::Subject MeasurementSession::fitSubject() const
{
    MeasurementFit::Subject subject{body(), target(), nullptr, {}};
    if (m_measurement && subject.target) {
        subject.series = m_measurement->find(subject.target->quantity);
        if (const auto file = m_seriesFile.find(subject.target->quantity);
            file != m_seriesFile.end())
            subject.file = file->second;
    }
    return subject;
}

void MeasurementSession::updateChoices()
{
    if (!m_measurement)
        return;
    const lessons::Scene& scene = m_document.scene();
    std::vector<MeasurementPanel::BodyChoice> bodies;
    for (std::size_t i = 0; i < scene.bodies.size(); ++i)
        if (scene.bodies[i].type != physics::BodyType::Static)
            bodies.push_back({QString::fromStdString(scene.bodies[i].name),
                              scene.bodyLabel(static_cast<physics::BodyId>(i))});
    std::vector<Quantity> quantities;
    for (const measure::Series& s : m_measurement->series)
        quantities.push_back(s.quantity);
    m_panel->setChoices(bodies, quantities);
}

void MeasurementSession::compare()
{
    m_simulated.clear();
    m_residuals.clear();
    const auto t = target();
    const measure::Series* series = m_measurement && t ? m_measurement->find(t->quantity) : nullptr;
    if (!series) {
        m_panel->clearPlots();
        updateTrail();
        return;
    }
    const lessons::Scene& scene = m_document.scene();
    measure::Simulated at = measure::simulateAt(scene, *t, series->t);
    std::vector<double> lineT;
    const double end = series->t.back();
    const double step = std::max(scene.world.dt, end / kLinePoints);
    for (double time = 0; time <= end + 0.5 * step; time += step)
        lineT.push_back(std::min(time, end));
    measure::Simulated line = at.ok ? measure::simulateAt(scene, *t, lineT) : at;
    if (at.ok && line.ok) {
        m_simulated = at.values;
        for (std::size_t i = 0; i < series->value.size(); ++i)
            m_residuals.push_back(series->value[i] - m_simulated[i]);
    }
    m_panel->showComparison(*series, lineT, line.values, m_residuals,
                            at.ok && line.ok ? QString() : (at.ok ? line.error : at.error));
    // The same quantity from the other files, beside it.
    const QString& file = m_seriesFile.at(t->quantity);
    m_panel->showOtherFiles(file, otherFileSeries(m_imports, t->quantity, file));
    updateTrail();
}

void MeasurementSession::updateTrail()
{
    std::vector<QPointF> points;
    const auto t = target();
    if (m_measurement && t) {
        const physics::Vec2 start = m_document.scene().bodies[t->body].position;
        const measure::Series* xs = m_measurement->find(Quantity::X);
        const measure::Series* ys = m_measurement->find(Quantity::Y);
        std::map<int, QPointF> byLine; // the file's line: a point seen in both columns
        if (xs)
            for (std::size_t i = 0; i < xs->t.size(); ++i)
                byLine[xs->lines[i]] = QPointF(xs->value[i], ys ? NAN : start.y());
        if (ys)
            for (std::size_t i = 0; i < ys->t.size(); ++i) {
                auto [it, added] =
                    byLine.try_emplace(ys->lines[i], QPointF(xs ? NAN : start.x(), ys->value[i]));
                if (!added)
                    it->second.setY(ys->value[i]);
            }
        for (const auto& [line, p] : byLine)
            if (std::isfinite(p.x()) && std::isfinite(p.y()))
                points.push_back(p);
    }
    m_trail->setPoints(std::move(points));
}

bool MeasurementSession::eventFilter(QObject* watched, QEvent* event)
{
    switch (event->type()) {
    case QEvent::DragEnter:
    case QEvent::DragMove: {
        auto* drag = static_cast<QDragMoveEvent*>(event);
        if (droppedMeasurement(drag->mimeData()).isEmpty())
            break;
        drag->acceptProposedAction();
        return true;
    }
    case QEvent::Drop: {
        auto* drop = static_cast<QDropEvent*>(event);
        const QString path = droppedMeasurement(drop->mimeData());
        if (path.isEmpty())
            break;
        drop->acceptProposedAction();
        // The dialog opens after the drop is done: the application the file came from is not
        // kept waiting for it.
        QTimer::singleShot(0, this, [this, path] {
            if (const QString error = importFile(path); !error.isEmpty())
                emit message(error, 10000);
        });
        return true;
    }
    default:
        break;
    }
    return QObject::eventFilter(watched, event);
}

} // namespace rigidlab::ui
