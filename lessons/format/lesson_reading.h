// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Reading a lesson file, below the document level of lesson_loader.cpp: a step
// (lesson_step.cpp), its settings and comparison (lesson_settings.cpp), its SAT pair and
// questions (lesson_questions.cpp).

#include "format/json_reader.h"

#include "format/field_reading.h"
#include "format/lesson.h"
#include "format/lesson_schema.h"
#include "format/local_text.h"

#include <optional>
#include <utility>
#include <vector>

#include <functional>
#include <map>

namespace rigidlab::lessons::detail {

/// What reading a step needs from the lesson around it.
struct StepContext {
    QString folder;              ///< the lesson's folder, absolute; scene paths start here
    qint64 bodies = 0;           ///< bodies in the scenes of the steps read so far
    LocalTexts* texts = nullptr; ///< the lesson's texts, in its language
    /// The scenes the lesson file carries (LessonLoadOptions::embeddedScenes), or null.
    const std::map<QString, Scene>* embedded = nullptr;
};

/// One step of "steps", at `place`; adds its bodies to `context.bodies`.
bool readStep(JsonReader& in, const QJsonValue& value, const QString& place, StepContext& context,
              LessonStep& step);

/// The names in `list` (at `at`): each a string, none twice, each one `accept` takes (it fails
/// `in` with its own message at the item's place when it does not). `out` gets them in order.
bool readDistinctNames(
    JsonReader& in, const QJsonArray& list, const QString& at,
    const std::function<bool(const QString& name, const QString& itemAt)>& accept,
    QStringList& out);

/// The step's "settings", on top of its scene's.
bool readSettings(JsonReader& in, const QJsonObject& object, const QString& place,
                  StepSettings& settings);

/// A question's "set": the settings the student is asked to set before the run it measures.
/// Fails on what cannot be meant; warns when the step does not let the student set them.
bool readQuestionSet(JsonReader& in, const QJsonObject& question, const QString& place,
                     const LessonStep& step, const QStringList& holdBack, StepSettings& set);

/// The step's "compare", after its settings (a compared setting may not be set as well).
bool readCompare(JsonReader& in, const QJsonObject& object, const QString& place, LessonStep& step);

/// The step's "sat": {"a": ID, "b": ID}, two different polygons of `scene`; `out` is left
/// empty when the step has none.
bool readSat(JsonReader& in, const QJsonObject& step, const QString& place, const Scene& scene,
             std::optional<std::pair<QString, QString>>& out);

/// A lesson row of kind Line, Paragraphs, Unit or Plain (lesson_schema.h) from `object` at
/// `place` into `target`: a text in the lesson's languages (a line not empty in any of them),
/// or a number or flag as its value row says. A Part row is its caller's (true).
template <class Target>
bool readLessonRow(JsonReader& in, LocalTexts& texts, const schema::LessonFieldOf<Target>& row,
                   const QJsonObject& object, const QString& place, Target& target)
{
    using schema::LessonKind;
    const QString key = QString::fromUtf8(row.key.data(), qsizetype(row.key.size()));
    switch (row.kind) {
    case LessonKind::Line:
        if (!texts.line(object, key, place, target.*row.text, row.required))
            return false;
        for (const LocalTexts::Variant& v : texts.variants()) {
            if (v.text.trimmed().isEmpty())
                return in.fail(v.place, row.required
                                            ? FileMessages::tr("must not be empty")
                                            : FileMessages::tr("must not be empty (leave the key "
                                                               "out instead)"));
        }
        return true;
    case LessonKind::Paragraphs:
        return texts.paragraphs(object, key, place, target.*row.text);
    case LessonKind::Unit:
        return texts.unit(object, key, place, target.*row.text);
    case LessonKind::Plain:
        return readPlainField(in, row.value, object, place, target, 0);
    case LessonKind::Part:
        return true;
    }
    return true;
}

/// The step's "questions", their measures naming bodies of its scene and what they hold
/// back naming panels and plots it shows.
bool readQuestions(JsonReader& in, LocalTexts& texts, const QJsonObject& object,
                   const QString& place, const LessonStep& step, std::vector<Question>& out);

} // namespace rigidlab::lessons::detail
