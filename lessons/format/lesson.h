// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A lesson: an ordered list of steps, each with its text, a prepared scene and settings, and
// only the plots, overlays and panels the step needs. Format: lessons/LESSON_FORMAT.md.

#include "format/languages.h"
#include "format/question_kinds.h"
#include "format/scene.h"
#include "format/schema_value.h"
#include "format/step_settings.h"
#include "rigidlab/physics/contact.h"
#include "rigidlab/physics/integrator.h"

#include <QByteArray>
#include <QJsonObject>
#include <QString>
#include <QStringList>

#include <algorithm>
#include <array>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

namespace rigidlab::lessons {

/// The names a lesson step may list (lessons/LESSON_FORMAT.md), in one place: the loader checks
/// steps against them and the plots' table (ui/plots/plot_table.h) takes its row names
/// from them, in the same order.
inline constexpr std::array<std::string_view, 5> kStepPlotNames{"energy", "momentum", "drift",
                                                                "compare-energy", "compare-drift"};
inline constexpr std::array<std::string_view, 6> kStepOverlayNames{
    "velocities", "contacts", "boxes", "centres", "trails", "springs"};
inline constexpr std::array<std::string_view, 6> kStepPanelNames{
    "controls", "inspector", "sat", "bounces", "collision", "measurement"};

/// The version this loader reads (the value of the top-level key "rigidlab-lesson").
inline constexpr int kLessonFormatVersion = 1;
/// The most worlds a step may compare side by side (the main one included).
inline constexpr int kMaxVariants = 6;
/// The largest lesson file read [bytes].
inline constexpr qint64 kMaxLessonFileBytes = 8 * 1024 * 1024;

/// A question: what every kind has (its prompt, hint and what it holds back) and its kind, a
/// type of its own. Where the kinds differ the code visits `kind` (physics/overloaded.h), so
/// that a new kind does not compile until every such place handles it.
struct Question {
    QString prompt; ///< plain text, shown above the answer box (or the options)
    /// Read after a wrong first try, instead of the measured value (lesson data, so that it
    /// is translated with the lesson); empty: none.
    QString hint;
    /// What would give the answer away, kept from the student until this question is
    /// answered right, twice wrong or shown: "run", "panel:NAME", "plot:NAME",
    /// "column:collision.after", "column:bounces.heights" (LESSON_FORMAT.md).
    QStringList holdBack;
    QuestionKind kind;

    /// The kind's own part when the question is of kind K, else null: for a place that reads
    /// one kind only (the others have nothing of the sort); where each kind does something
    /// of its own, visit `kind` instead.
    template <class K> const K* as() const { return std::get_if<K>(&kind); }
    template <class K> K* as() { return std::get_if<K>(&kind); }
};

/// The names a question may hold back, besides "panel:" and "plot:" with a panel or plot the
/// step shows.
inline constexpr const char16_t* kHoldBackRun = u"run";
inline constexpr const char16_t* kHoldBackCollisionAfter = u"column:collision.after";
inline constexpr const char16_t* kHoldBackBounceHeights = u"column:bounces.heights";

/// Worlds run side by side with the main one, differing in one setting. Variant 0 is the
/// main world; variant i > 0 is drawn as a ghost, shifted by i * offset.
struct Comparison {
    std::vector<physics::IntegratorKind> integrators; ///< one world each, or empty
    std::vector<physics::SolverKind> solvers;         ///< one world each, or empty
    physics::Vec2 offset = physics::Vec2::Zero();     ///< drawing shift per variant [m]
    int count() const { return static_cast<int>(std::max(integrators.size(), solvers.size())); }
    QString label(int i) const; ///< "euler", "seed-impulse", ...
};

/// A step that opens the scene editor (its "editor" key): what the student may use.
struct EditorLock {
    QStringList tools;      ///< of lessons::kEditorToolNames (editor_tools.h), enabled
    QStringList properties; ///< of schema::editorPropertyNames(), editable; the rest locked
};

/// The longest time a step's plots may be exported at [s].
inline constexpr double kMaxExportTime = 600.0;
/// The latest time a step's run may be told to stop at [s] (as late as a question may measure).
inline constexpr double kMaxEndTime = 3600.0;

struct LessonStep {
    QString title;
    QString text;      ///< Markdown
    Scene scene;       ///< inline in the lesson, or loaded from scenePath
    QString scenePath; ///< absolute path of the scene file, if any
    StepSettings settings;
    std::optional<Comparison> compare;
    QStringList plots;    ///< of: energy, momentum, drift, compare-energy, compare-drift
    QStringList overlays; ///< of: velocities, contacts, boxes, centres, trails, springs
    QStringList panels;   ///< of: controls, inspector, sat, bounces, collision, measurement
    /// Controls the student may change (integrator, dt, solver, iterations, restitution,
    /// friction, gravity, timeScale); nullopt: all of them.
    std::optional<QStringList> allow;
    std::optional<std::pair<QString, QString>> sat; ///< body ids the SAT panel looks at
    /// The step opens the scene editor with these tools and properties; nullopt: it does not.
    std::optional<EditorLock> editor;
    std::vector<Question> questions;
    double exportTime = 10.0; ///< simulated seconds run for a headless plot export [s]
    /// The run stops (pauses) when the simulated time reaches it [s]; nullopt: it runs on.
    std::optional<double> endTime;
    bool autoplay = true; ///< start running when the step opens

    /// What the questions not yet answered (answered[i] false) hold back, in order, each once.
    QStringList heldBack(const std::vector<bool>& answered) const;
};

struct Lesson {
    QString path; ///< absolute
    QString title;
    QString summary;
    QString level;   ///< "secondary school", "first year", ...
    int minutes = 0; ///< estimated time [min]; 0: not given
    /// Place in the teaching order of the shipped lessons (1 first); 0: not given, listed
    /// after the numbered ones.
    int order = 0;
    QString description; ///< one line for the lesson menu; may be empty
    QStringList goals;
    std::vector<LessonStep> steps;
};

/// How a lesson is read.
struct LessonLoadOptions {
    /// The language its texts are kept in (languages.h); a text without it is English.
    QString language = lessonLanguage();
    /// The scenes a lesson file carries inside it (a .rlesson, lesson_pack.h), by the path its
    /// steps name them with, already read in `language`. When set, a step's scene path is looked
    /// up here and never on disk; a path not here is an error.
    const std::map<QString, Scene>* embeddedScenes = nullptr;
};

struct LessonLoadResult {
    bool ok = false;
    QString error;        ///< one line `FILE: PLACE: what is wrong`, like the scene loader's
    QStringList warnings; ///< same form
    Lesson lesson;
};

/// Reads and checks a lesson, keeping its texts in `options.language`; scene paths are
/// relative to the lesson's folder and stay where format/scene_path.h allows. Every text is
/// checked in every language it has, whichever is kept; a translated lesson warns of each text
/// that lacks a shipped language. A path ending in .rlesson is read as a lesson in one file,
/// its scenes inside it (format/lesson_pack.h).
LessonLoadResult loadLessonFile(const QString& path, const LessonLoadOptions& options = {});
/// The same for a lesson held in memory; `path` names it in messages, and scene paths are
/// relative to its folder.
LessonLoadResult loadLessonJson(const QByteArray& bytes, const QString& path,
                                const LessonLoadOptions& options = {});
/// The same for a document already parsed (one whose top level holds "rigidlab-lesson").
LessonLoadResult loadLessonObject(const QJsonObject& root, const QString& path,
                                  const LessonLoadOptions& options = {});

/// The step as a question asks it: its settings with the question's "set" on top.
LessonStep askedStep(const LessonStep& step, const Question& question);
/// Whether the question asks the student to set anything.
bool asksSettings(const Question& question);

/// The question counts of the lesson's steps, in order: what an answers file is checked
/// against (answersMismatch, answers_file.h).
std::vector<int> questionCounts(const Lesson& lesson);

/// Applies a step's settings to a world built from its scene.
void applySettings(const StepSettings& settings, physics::World& world);

/// How long a step runs without a window (its exported plots, the worksheet's figures): its
/// exportTime, cut short at its endTime, where the window's run stops too [s].
double exportRunTime(const LessonStep& step);

/// The step's worlds: [0] the main world, then one per compared variant (count() - 1 more,
/// the first variant being the main world itself).
std::vector<physics::World> buildStepWorlds(const LessonStep& step);

} // namespace rigidlab::lessons
