// SPDX-License-Identifier: GPL-3.0-or-later
// Lesson files, format v1 (lessons/LESSON_FORMAT.md): reading and checking. As with scenes,
// the first problem found is the one reported, as `FILE: PLACE: what is wrong`, and the checks
// follow the file's order so that it is the first one a reader of the file would meet.
//
// Nothing in a lesson is ever executed: texts are shown, names are looked up in fixed lists,
// and scene files are read only from the lesson's own folder.

#include "format/lesson.h"
#include "format/scene_loader.h"

#include "format/json_reader.h"
#include "format/lesson_reading.h"

#include <QDir>
#include <QFileInfo>

#include <array>
#include <cmath>

namespace rigidlab::lessons {

using detail::FileMessages;

using detail::indexPlace;
using detail::joinPlace;
using detail::JsonReader;
using detail::NumberRule;

namespace {

constexpr int kMaxSteps = 100;
constexpr int kMaxGoals = 20;
constexpr int kMaxMinutes = 1000;
/// The largest teaching-order number a lesson may have.
constexpr int kMaxOrder = 999;
/// The longest one-line description, in characters: it shares a menu line with the title.
constexpr int kMaxDescription = 100;
constexpr double kMaxExportTime = 600.0; ///< [s]
constexpr double kMaxExportSteps = 1e7;  ///< exportTime / dt at most
constexpr double kMinTimeScale = 0.1;
constexpr double kMaxTimeScale = 4.0;

constexpr std::array kPlotNames = {u"energy", u"momentum", u"drift", u"compare-energy",
                                   u"compare-drift"};
constexpr std::array kOverlayNames = {u"velocities", u"contacts", u"boxes",
                                      u"centres",    u"trails",   u"springs"};
constexpr std::array kPanelNames = {u"controls", u"inspector", u"sat", u"bounces", u"collision"};
constexpr std::array kControlNames = {u"integrator",  u"dt",       u"solver",  u"iterations",
                                      u"restitution", u"friction", u"gravity", u"timeScale"};

// The names messages list; any name physics::integratorFromName knows is accepted.
constexpr std::array kIntegrators = {
    physics::IntegratorKind::Euler,
    physics::IntegratorKind::SymplecticEuler,
    physics::IntegratorKind::Verlet,
    physics::IntegratorKind::RK4,
};
constexpr std::array kSolvers = {
    physics::SolverKind::SeedImpulse,
    physics::SolverKind::SequentialImpulse,
};

QString fromView(std::string_view s)
{
    return QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size()));
}

template <typename Names> QString joinNames(const Names& names)
{
    QStringList list;
    for (QStringView n : names) {
        list.append(n.toString());
    }
    return list.join(u", ");
}

/// A scene loader's message `SOURCE: PLACE: what` as a place under the lesson's `at` and the
/// rest: (`at.PLACE`, `what`), which JsonReader joins back into `SOURCE: at.PLACE: what`.
std::pair<QString, QString> rebase(const QString& message, const QString& source, const QString& at)
{
    const QString prefix = source + QStringLiteral(": ");
    const QString rest = message.startsWith(prefix) ? message.mid(prefix.size()) : message;
    const qsizetype colon = rest.indexOf(QStringLiteral(": "));
    if (colon < 0) {
        return {at, rest};
    }
    return {at + u'.' + rest.left(colon), rest.mid(colon + 2)};
}

class LessonReader {
public:
    LessonReader(const QString& sourceName, const QString& absolutePath)
        : m_in(sourceName), m_folder(QFileInfo(absolutePath).absolutePath())
    {
        m_lesson.path = absolutePath;
    }

    LessonLoadResult read(const QJsonObject& root);

private:
    bool readGoals(const QJsonObject& root);
    bool readSteps(const QJsonObject& root);
    bool readStep(const QJsonValue& value, const QString& place, LessonStep& step);
    bool readText(const QJsonObject& object, const QString& place, QString& out);
    bool readScene(const QJsonObject& object, const QString& place, LessonStep& step);
    /// The one-line description: one line, short enough for a menu.
    bool readDescription(const QJsonObject& root);
    bool readSceneFile(const QString& relative, const QString& place, LessonStep& step);
    bool readSettings(const QJsonObject& object, const QString& place, StepSettings& settings);
    bool readCompare(const QJsonObject& object, const QString& place, LessonStep& step);
    /// A list of distinct names, each one of `known`.
    template <typename Known>
    bool readNames(const QJsonObject& object, QStringView key, const QString& place,
                   const Known& known, QStringView what, QStringList& out);

    JsonReader m_in;
    QString m_folder; ///< the lesson's folder, absolute
    Lesson m_lesson;
    qint64 m_bodies = 0; ///< over the steps read so far
};

bool LessonReader::readDescription(const QJsonObject& root)
{
    if (!m_in.string(root, u"description", {}, m_lesson.description))
        return false;
    const QString& d = m_lesson.description;
    if (d.contains(QLatin1Char('\n')) || d.contains(QLatin1Char('\r')))
        return m_in.fail(QStringLiteral("description"),
                         FileMessages::tr("must be one line (it is shown in the lesson menu); put "
                                          "longer text in \"summary\""));
    if (d.size() > kMaxDescription)
        return m_in.fail(QStringLiteral("description"),
                         FileMessages::tr("is %1 characters long; at most %2 fit a menu line (put "
                                          "longer text in \"summary\")")
                             .arg(d.size())
                             .arg(kMaxDescription));
    if (root.contains(QStringLiteral("description")) && d.trimmed().isEmpty())
        return m_in.fail(QStringLiteral("description"),
                         FileMessages::tr("must not be empty (leave the key out instead)"));
    return true;
}

LessonLoadResult LessonReader::read(const QJsonObject& root)
{
    const bool ok = m_in.formatVersion(root, QStringLiteral("rigidlab-lesson"),
                                       FileMessages::tr("a lesson file"), kLessonFormatVersion) &&
                    m_in.checkKeys(root, {},
                                   {u"rigidlab-lesson", u"title", u"summary", u"level", u"minutes",
                                    u"order", u"description", u"goals", u"steps"}) &&
                    m_in.string(root, u"title", {}, m_lesson.title, true) &&
                    (!m_lesson.title.trimmed().isEmpty() ||
                     m_in.fail(QStringLiteral("title"), FileMessages::tr("must not be empty"))) &&
                    m_in.string(root, u"summary", {}, m_lesson.summary) &&
                    m_in.string(root, u"level", {}, m_lesson.level) &&
                    m_in.integer(root, u"minutes", {}, m_lesson.minutes, 0, kMaxMinutes) &&
                    m_in.integer(root, u"order", {}, m_lesson.order, 1, kMaxOrder) &&
                    readDescription(root) && readGoals(root) && readSteps(root);
    LessonLoadResult result;
    result.warnings = m_in.warnings();
    if (!ok) {
        result.error = m_in.error();
        return result;
    }
    result.ok = true;
    result.lesson = std::move(m_lesson);
    return result;
}

bool LessonReader::readGoals(const QJsonObject& root)
{
    if (!root.contains(u"goals")) {
        return true;
    }
    const QString place = QStringLiteral("goals");
    QJsonArray goals;
    if (!m_in.asArray(root.value(u"goals"), place, goals)) {
        return false;
    }
    if (goals.size() > kMaxGoals) {
        return m_in.fail(place, FileMessages::tr("%1 goals, more than the limit of %2")
                                    .arg(goals.size())
                                    .arg(kMaxGoals));
    }
    for (qsizetype i = 0; i < goals.size(); ++i) {
        if (!goals[i].isString() || goals[i].toString().trimmed().isEmpty()) {
            return m_in.fail(indexPlace(place, i),
                             FileMessages::tr("must be a non-empty string \"...\", got ") +
                                 detail::describeJson(goals[i]));
        }
        m_lesson.goals.append(goals[i].toString());
    }
    return true;
}

bool LessonReader::readSteps(const QJsonObject& root)
{
    const QString place = QStringLiteral("steps");
    if (!root.contains(u"steps")) {
        return m_in.fail(place, FileMessages::tr("required, but missing"));
    }
    QJsonArray steps;
    if (!m_in.asArray(root.value(u"steps"), place, steps)) {
        return false;
    }
    if (steps.isEmpty() || steps.size() > kMaxSteps) {
        return m_in.fail(place, FileMessages::tr("a lesson needs 1 to %1 steps, got %2")
                                    .arg(kMaxSteps)
                                    .arg(steps.size()));
    }
    for (qsizetype i = 0; i < steps.size(); ++i) {
        LessonStep step;
        if (!readStep(steps[i], indexPlace(place, i), step)) {
            return false;
        }
        m_lesson.steps.push_back(std::move(step));
    }
    return true;
}

bool LessonReader::readStep(const QJsonValue& value, const QString& place, LessonStep& step)
{
    QJsonObject object;
    if (!m_in.asObject(value, place, object) ||
        !m_in.checkKeys(object, place,
                        {u"title", u"text", u"scene", u"settings", u"compare", u"plots",
                         u"overlays", u"panels", u"allow", u"sat", u"questions", u"exportTime",
                         u"autoplay"}) ||
        !m_in.string(object, u"title", place, step.title, true)) {
        return false;
    }
    if (step.title.trimmed().isEmpty()) {
        return m_in.fail(joinPlace(place, u"title"), FileMessages::tr("must not be empty"));
    }
    if (!readText(object, place, step.text) || !readScene(object, place, step) ||
        !readSettings(object, place, step.settings) || !readCompare(object, place, step) ||
        !readNames(object, u"plots", place, kPlotNames, u"plot", step.plots) ||
        !readNames(object, u"overlays", place, kOverlayNames, u"overlay", step.overlays) ||
        !readNames(object, u"panels", place, kPanelNames, u"panel", step.panels)) {
        return false;
    }
    // Every step keeps its scene: many steps reading one large scene file add up.
    m_bodies += static_cast<qint64>(step.scene.bodies.size());
    if (m_bodies > limits::kMaxLessonBodies) {
        return m_in.fail(joinPlace(place, u"scene"),
                         FileMessages::tr("the steps up to this one hold %1 bodies in all, more "
                                          "than the limit of %2 for a lesson")
                             .arg(m_bodies)
                             .arg(limits::kMaxLessonBodies));
    }
    for (qsizetype i = 0; i < step.plots.size(); ++i) {
        if (step.plots[i].startsWith(u"compare-") && !step.compare) {
            return m_in.fail(indexPlace(joinPlace(place, u"plots"), i),
                             FileMessages::tr("\"%1\" plots the worlds of \"compare\", and this "
                                              "step has none")
                                 .arg(step.plots[i]));
        }
    }
    if (object.contains(u"allow")) {
        QStringList allow;
        if (!readNames(object, u"allow", place, kControlNames, u"control", allow)) {
            return false;
        }
        step.allow = allow;
    }
    if (!detail::readSat(m_in, object, place, step.scene, step.sat) ||
        !detail::readQuestions(m_in, object, place, step, step.questions) ||
        !m_in.number(object, u"exportTime", place, step.exportTime, NumberRule::Positive) ||
        !m_in.boolean(object, u"autoplay", place, step.autoplay)) {
        return false;
    }
    const QString exportPlace = joinPlace(place, u"exportTime");
    if (step.exportTime > kMaxExportTime) {
        return m_in.fail(exportPlace, FileMessages::tr("must be at most %1 s, got %2")
                                          .arg(kMaxExportTime)
                                          .arg(detail::formatNumber(step.exportTime)));
    }
    const double dt = step.settings.dt.value_or(step.scene.world.dt);
    if (step.exportTime / dt > kMaxExportSteps) {
        return m_in.fail(exportPlace,
                         FileMessages::tr("%1 s at a step of %2 s is more than %3 steps")
                             .arg(detail::formatNumber(step.exportTime), detail::formatNumber(dt),
                                  QString::number(static_cast<qint64>(kMaxExportSteps))));
    }
    const int panelSat = static_cast<int>(step.panels.indexOf(u"sat"));
    if (panelSat >= 0 && !step.sat) {
        return m_in.fail(indexPlace(joinPlace(place, u"panels"), panelSat),
                         FileMessages::tr("the \"sat\" panel needs the pair it looks at: add "
                                          "\"sat\": {\"a\": ID, \"b\": ID} to the step"));
    }
    return true;
}

bool LessonReader::readText(const QJsonObject& object, const QString& place, QString& out)
{
    // A string, or an array of strings (one per line or paragraph), which is easier to write
    // and to read in a JSON file; the lines are joined with line breaks.
    const auto it = object.constFind(u"text");
    if (it == object.constEnd()) {
        return true;
    }
    const QString at = joinPlace(place, u"text");
    if (it.value().isString()) {
        out = it.value().toString();
        return true;
    }
    if (!it.value().isArray()) {
        return m_in.fail(at, FileMessages::tr("must be a string or an array of strings, got ") +
                                 detail::describeJson(it.value()));
    }
    const QJsonArray lines = it.value().toArray();
    QStringList parts;
    for (qsizetype i = 0; i < lines.size(); ++i) {
        if (!lines[i].isString()) {
            return m_in.fail(indexPlace(at, i), FileMessages::tr("must be a string \"...\", got ") +
                                                    detail::describeJson(lines[i]));
        }
        parts.append(lines[i].toString());
    }
    out = parts.join(u'\n');
    return true;
}

bool LessonReader::readScene(const QJsonObject& object, const QString& place, LessonStep& step)
{
    const QString at = joinPlace(place, u"scene");
    const auto it = object.constFind(u"scene");
    if (it == object.constEnd()) {
        return m_in.fail(at, FileMessages::tr("required, but missing (a scene object, or the path "
                                              "of a scene file)"));
    }
    if (it.value().isString()) {
        return readSceneFile(it.value().toString(), at, step);
    }
    if (!it.value().isObject()) {
        return m_in.fail(at, FileMessages::tr("must be a scene object {...} or the path of a scene "
                                              "file, got ") +
                                 detail::describeJson(it.value()));
    }
    const SceneLoadResult loaded = loadSceneObject(it.value().toObject(), m_in.sourceName());
    for (const QString& w : loaded.warnings) {
        const auto [wherePlace, what] = rebase(w, m_in.sourceName(), at);
        m_in.warn(wherePlace, what);
    }
    if (!loaded.ok) {
        const auto [wherePlace, what] = rebase(loaded.error, m_in.sourceName(), at);
        return m_in.fail(wherePlace, what);
    }
    step.scene = loaded.scene;
    return true;
}

bool LessonReader::readSceneFile(const QString& relative, const QString& place, LessonStep& step)
{
    // The path is relative to the lesson and stays inside its folder: a lesson someone sends
    // must not make the lab read files elsewhere on the machine.
    if (relative.isEmpty()) {
        return m_in.fail(place, FileMessages::tr("must name a scene file, got an empty path"));
    }
    if (relative.contains(u'\\')) {
        return m_in.fail(place,
                         FileMessages::tr("use '/' between folders, got \"%1\"").arg(relative));
    }
    if (QDir::isAbsolutePath(relative) || relative.startsWith(u'/') ||
        (relative.size() >= 2 && relative[1] == u':')) {
        return m_in.fail(place, FileMessages::tr("must be a path relative to the lesson's folder, "
                                                 "got \"%1\"")
                                    .arg(relative));
    }
    if (relative.split(u'/').contains(QStringLiteral(".."))) {
        return m_in.fail(place, FileMessages::tr("must not leave the lesson's folder (no \"..\"), "
                                                 "got \"%1\"")
                                    .arg(relative));
    }
    for (const QChar c : relative) {
        if (c.unicode() < 0x20 || c.unicode() == 0x7f) {
            return m_in.fail(place, FileMessages::tr("must not hold control characters"));
        }
    }
    const QString path = QDir::cleanPath(QDir(m_folder).filePath(relative));
    // A symbolic link inside the folder could still point out of it. What is read is the
    // resolved path itself, checked to be a plain file below the folder: a link swapped after
    // the check cannot redirect the read, and a named pipe or a device cannot block or feed it.
    const QString canonicalFolder = QFileInfo(m_folder).canonicalFilePath();
    const QString canonical = QFileInfo(path).canonicalFilePath();
    QString readPath = path;
    if (!canonical.isEmpty()) {
        const QString inside =
            canonicalFolder.endsWith(u'/') ? canonicalFolder : canonicalFolder + u'/';
        if (canonicalFolder.isEmpty() || !canonical.startsWith(inside)) {
            return m_in.fail(place, FileMessages::tr("\"%1\" leads out of the lesson's folder "
                                                     "(through a symbolic link)")
                                        .arg(relative));
        }
        if (!QFileInfo(canonical).isFile()) {
            return m_in.fail(place, FileMessages::tr("\"%1\" is not a plain file").arg(relative));
        }
        readPath = canonical;
    }
    const detail::FileBytes file = detail::readFileBytes(readPath, kMaxSceneFileBytes);
    if (!file.ok) {
        return m_in.fail(place, file.error);
    }
    // Messages name the scene file as the lesson's own name leads to it.
    const QString shown =
        QDir::cleanPath(QDir(QFileInfo(m_in.sourceName()).path()).filePath(relative));
    const SceneLoadResult loaded = loadSceneJson(file.bytes, shown);
    for (const QString& w : loaded.warnings) {
        m_in.warn(place, w);
    }
    if (!loaded.ok) {
        return m_in.fail(place, loaded.error);
    }
    step.scene = loaded.scene;
    step.scenePath = QFileInfo(path).absoluteFilePath();
    return true;
}

bool LessonReader::readSettings(const QJsonObject& object, const QString& place,
                                StepSettings& settings)
{
    if (!object.contains(u"settings")) {
        return true;
    }
    const QString at = joinPlace(place, u"settings");
    QJsonObject s;
    if (!m_in.asObject(object.value(u"settings"), at, s) ||
        !m_in.checkKeys(s, at,
                        {u"integrator", u"dt", u"solver", u"iterations", u"restitution",
                         u"friction", u"gravity", u"timeScale"})) {
        return false;
    }
    QString name;
    if (s.contains(u"integrator")) {
        if (!m_in.string(s, u"integrator", at, name)) {
            return false;
        }
        settings.integrator = physics::integratorFromName(name.toStdString());
        if (!settings.integrator) {
            QStringList names;
            for (auto k : kIntegrators) {
                names.append(fromView(physics::integratorName(k)));
            }
            return m_in.fail(joinPlace(at, u"integrator"),
                             FileMessages::tr("unknown integrator \"%1\" (expected %2)")
                                 .arg(name, names.join(u", ")));
        }
    }
    if (s.contains(u"dt")) {
        double dt = 0;
        if (!m_in.number(s, u"dt", at, dt, NumberRule::Positive)) {
            return false;
        }
        if (dt < kMinDt || dt > kMaxDt) {
            return m_in.fail(joinPlace(at, u"dt"),
                             FileMessages::tr("must be from %1 to %2 s, got %3")
                                 .arg(detail::formatNumber(kMinDt), detail::formatNumber(kMaxDt),
                                      detail::formatNumber(dt)));
        }
        settings.dt = dt;
    }
    if (s.contains(u"solver")) {
        if (!m_in.string(s, u"solver", at, name)) {
            return false;
        }
        settings.solver = physics::solverFromName(name.toStdString());
        if (!settings.solver) {
            QStringList names;
            for (auto k : kSolvers) {
                names.append(fromView(physics::solverName(k)));
            }
            return m_in.fail(joinPlace(at, u"solver"),
                             FileMessages::tr("unknown solver \"%1\" (expected %2)")
                                 .arg(name, names.join(u", ")));
        }
    }
    if (s.contains(u"iterations")) {
        int n = 0;
        if (!m_in.integer(s, u"iterations", at, n, 1, kMaxIterations)) {
            return false;
        }
        settings.iterations = n;
    }
    double value = 0;
    if (s.contains(u"restitution")) {
        if (!m_in.number(s, u"restitution", at, value, NumberRule::UnitInterval,
                         limits::kRestitution)) {
            return false;
        }
        settings.restitution = value;
    }
    if (s.contains(u"friction")) {
        if (!m_in.number(s, u"friction", at, value, NumberRule::NonNegative, limits::kFriction)) {
            return false;
        }
        settings.friction = value;
    }
    if (s.contains(u"gravity")) {
        bool on = true;
        if (!m_in.boolean(s, u"gravity", at, on)) {
            return false;
        }
        settings.gravity = on;
    }
    if (s.contains(u"timeScale")) {
        if (!m_in.number(s, u"timeScale", at, value, NumberRule::Positive)) {
            return false;
        }
        if (value < kMinTimeScale || value > kMaxTimeScale) {
            return m_in.fail(joinPlace(at, u"timeScale"),
                             FileMessages::tr("must be from %1 to %2, got %3")
                                 .arg(detail::formatNumber(kMinTimeScale),
                                      detail::formatNumber(kMaxTimeScale),
                                      detail::formatNumber(value)));
        }
        settings.timeScale = value;
    }
    return true;
}

bool LessonReader::readCompare(const QJsonObject& object, const QString& place, LessonStep& step)
{
    if (!object.contains(u"compare")) {
        return true;
    }
    const QString at = joinPlace(place, u"compare");
    QJsonObject c;
    if (!m_in.asObject(object.value(u"compare"), at, c) ||
        !m_in.checkKeys(c, at, {u"integrators", u"solvers", u"offset"})) {
        return false;
    }
    const bool byIntegrator = c.contains(u"integrators");
    if (byIntegrator && c.contains(u"solvers")) {
        return m_in.fail(joinPlace(at, u"solvers"),
                         FileMessages::tr("compare \"integrators\" or \"solvers\", not both"));
    }
    if (!byIntegrator && !c.contains(u"solvers")) {
        return m_in.fail(at, FileMessages::tr("needs \"integrators\" or \"solvers\": the worlds to "
                                              "run side by side"));
    }
    const QStringView key = byIntegrator ? QStringView(u"integrators") : QStringView(u"solvers");
    const QString listAt = joinPlace(at, key);
    if (byIntegrator ? step.settings.integrator.has_value() : step.settings.solver.has_value()) {
        return m_in.fail(listAt,
                         FileMessages::tr("settings.%1 is given too: the main world runs the first "
                                          "of this list, so leave settings.%1 out")
                             .arg(byIntegrator ? u"integrator" : u"solver"));
    }
    QJsonArray list;
    if (!m_in.asArray(c.value(key), listAt, list)) {
        return false;
    }
    if (list.size() < 2 || list.size() > kMaxVariants) {
        return m_in.fail(
            listAt,
            FileMessages::tr("compares 2 to %1 worlds, got %2").arg(kMaxVariants).arg(list.size()));
    }
    Comparison comparison;
    QStringList seen;
    for (qsizetype i = 0; i < list.size(); ++i) {
        const QString itemAt = indexPlace(listAt, i);
        if (!list[i].isString()) {
            return m_in.fail(itemAt, FileMessages::tr("must be a name \"...\", got ") +
                                         detail::describeJson(list[i]));
        }
        const QString name = list[i].toString();
        if (seen.contains(name)) {
            return m_in.fail(itemAt, FileMessages::tr("\"%1\" is listed twice").arg(name));
        }
        seen.append(name);
        if (byIntegrator) {
            const auto kind = physics::integratorFromName(name.toStdString());
            if (!kind) {
                QStringList names;
                for (auto k : kIntegrators) {
                    names.append(fromView(physics::integratorName(k)));
                }
                return m_in.fail(itemAt, FileMessages::tr("unknown integrator \"%1\" (expected %2)")
                                             .arg(name, names.join(u", ")));
            }
            comparison.integrators.push_back(*kind);
        } else {
            const auto kind = physics::solverFromName(name.toStdString());
            if (!kind) {
                QStringList names;
                for (auto k : kSolvers) {
                    names.append(fromView(physics::solverName(k)));
                }
                return m_in.fail(itemAt, FileMessages::tr("unknown solver \"%1\" (expected %2)")
                                             .arg(name, names.join(u", ")));
            }
            comparison.solvers.push_back(*kind);
        }
    }
    if (!m_in.vec2(c, u"offset", at, comparison.offset, limits::kCoordinate)) {
        return false;
    }
    step.compare = comparison;
    return true;
}

template <typename Known>
bool LessonReader::readNames(const QJsonObject& object, QStringView key, const QString& place,
                             const Known& known, QStringView what, QStringList& out)
{
    if (!object.contains(key)) {
        return true;
    }
    const QString at = joinPlace(place, key);
    QJsonArray list;
    if (!m_in.asArray(object.value(key), at, list)) {
        return false;
    }
    for (qsizetype i = 0; i < list.size(); ++i) {
        const QString itemAt = indexPlace(at, i);
        if (!list[i].isString()) {
            return m_in.fail(itemAt, FileMessages::tr("must be a name \"...\", got ") +
                                         detail::describeJson(list[i]));
        }
        const QString name = list[i].toString();
        bool isKnown = false;
        for (QStringView k : known) {
            isKnown = isKnown || name == k;
        }
        if (!isKnown) {
            return m_in.fail(itemAt, FileMessages::tr("unknown %1 \"%2\" (expected %3)")
                                         .arg(what.toString(), name, joinNames(known)));
        }
        if (out.contains(name)) {
            return m_in.fail(itemAt, FileMessages::tr("\"%1\" is listed twice").arg(name));
        }
        out.append(name);
    }
    return true;
}

} // namespace

LessonLoadResult loadLessonObject(const QJsonObject& root, const QString& path)
{
    return LessonReader(path, QFileInfo(path).absoluteFilePath()).read(root);
}

LessonLoadResult loadLessonJson(const QByteArray& bytes, const QString& path)
{
    const detail::ParsedJson parsed = detail::parseJson(bytes, path, kMaxLessonFileBytes);
    if (!parsed.ok) {
        LessonLoadResult result;
        result.error = parsed.error;
        return result;
    }
    if (!parsed.document.isObject()) {
        LessonLoadResult result;
        result.error =
            path + FileMessages::tr(": the top level must be an object {...}, got an array");
        return result;
    }
    return loadLessonObject(parsed.document.object(), path);
}

LessonLoadResult loadLessonFile(const QString& path)
{
    const detail::FileBytes file = detail::readFileBytes(path, kMaxLessonFileBytes);
    if (!file.ok) {
        LessonLoadResult result;
        result.error = file.error;
        return result;
    }
    return loadLessonJson(file.bytes, path);
}

} // namespace rigidlab::lessons
