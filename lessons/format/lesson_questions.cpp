// SPDX-License-Identifier: GPL-3.0-or-later
// Lesson files: the parts of a step that name bodies of its scene, the SAT pair and the
// questions with what they measure (lessons/LESSON_FORMAT.md). Read for lesson_loader.cpp.

#include "format/lesson_reading.h"

#include <array>
#include <cassert>
#include <type_traits>
#include <variant>

namespace rigidlab::lessons::detail {

namespace {

constexpr int kMaxQuestions = 20;
constexpr int kMaxApex = 1000;
constexpr double kMaxMeasureTime = 3600.0; ///< [s]

struct MeasureName {
    QStringView name;
    Measure::Kind kind;
};
constexpr std::array kMeasureNames = {
    MeasureName{u"apex", Measure::Kind::Apex},
    MeasureName{u"speed", Measure::Kind::Speed},
    MeasureName{u"velocity-x", Measure::Kind::VelocityX},
    MeasureName{u"velocity-y", Measure::Kind::VelocityY},
    MeasureName{u"angular-velocity", Measure::Kind::AngularVelocity},
    MeasureName{u"position-x", Measure::Kind::PositionX},
    MeasureName{u"position-y", Measure::Kind::PositionY},
    MeasureName{u"energy-drift", Measure::Kind::EnergyDrift},
    MeasureName{u"momentum-x", Measure::Kind::MomentumX},
    MeasureName{u"momentum-y", Measure::Kind::MomentumY},
};

bool measuresBody(Measure::Kind kind)
{
    return kind != Measure::Kind::EnergyDrift && kind != Measure::Kind::MomentumX &&
           kind != Measure::Kind::MomentumY;
}

/// A body id of the step's scene, in `object[key]`.
bool readBodyId(JsonReader& in, const QJsonObject& object, QStringView key, const QString& place,
                const Scene& scene, QString& out)
{
    if (!in.string(object, key, place, out, true)) {
        return false;
    }
    if (!scene.bodyIndex(out)) {
        return in.fail(joinPlace(place, key), FileMessages::tr("no body with id \"%1\"").arg(out));
    }
    return true;
}

bool readMeasure(JsonReader& in, const QJsonValue& value, const QString& place, const Scene& scene,
                 Measure& measure)
{
    QJsonObject object;
    QString kindName;
    if (!in.asObject(value, place, object) ||
        !in.checkKeys(object, place, {u"kind", u"body", u"n", u"above", u"time"}) ||
        !in.string(object, u"kind", place, kindName, true)) {
        return false;
    }
    bool known = false;
    for (const MeasureName& m : kMeasureNames) {
        if (kindName == m.name) {
            measure.kind = m.kind;
            known = true;
        }
    }
    if (!known) {
        QStringList names;
        for (const MeasureName& m : kMeasureNames) {
            names.append(m.name.toString());
        }
        return in.fail(joinPlace(place, u"kind"), FileMessages::tr("unknown measure \"%1\" "
                                                                   "(expected %2)")
                                                      .arg(kindName, names.join(u", ")));
    }
    // Each kind then checks its own keys, so that a key that belongs to another kind is
    // reported as such.
    if (measure.kind == Measure::Kind::Apex) {
        if (!in.checkKeys(object, place, {u"kind", u"body", u"n", u"above"}) ||
            !readBodyId(in, object, u"body", place, scene, measure.body) ||
            !in.integer(object, u"n", place, measure.n, 1, kMaxApex) ||
            !in.number(object, u"above", place, measure.above, NumberRule::Finite,
                       limits::kCoordinate)) {
            return false;
        }
    } else {
        const bool body = measuresBody(measure.kind);
        if (!(body ? in.checkKeys(object, place, {u"kind", u"body", u"time"})
                   : in.checkKeys(object, place, {u"kind", u"time"})) ||
            (body && !readBodyId(in, object, u"body", place, scene, measure.body)) ||
            !in.number(object, u"time", place, measure.time, NumberRule::NonNegative, true)) {
            return false;
        }
        if (measure.time > kMaxMeasureTime) {
            return in.fail(joinPlace(place, u"time"),
                           FileMessages::tr("must be at most %1 s, got %2")
                               .arg(kMaxMeasureTime)
                               .arg(formatNumber(measure.time)));
        }
    }
    if (!measure.body.isEmpty()) {
        const auto index = scene.bodyIndex(measure.body);
        const physics::BodyType type = scene.bodies[static_cast<size_t>(*index)].type;
        if (type == physics::BodyType::Static) {
            return in.fail(
                joinPlace(place, u"body"),
                FileMessages::tr("body \"%1\" is static: it never moves").arg(measure.body));
        }
        if (measure.kind == Measure::Kind::Apex && type != physics::BodyType::Dynamic) {
            return in.fail(
                joinPlace(place, u"body"),
                FileMessages::tr("body \"%1\" is kinematic: it never bounces").arg(measure.body));
        }
    }
    return true;
}

/// One name of a question's "holdBack": what it holds back must be something the step shows.
bool checkHoldBackName(JsonReader& in, const QString& name, const QString& place,
                       const LessonStep& step)
{
    const auto listed = [](const QStringList& names) {
        return names.isEmpty() ? QStringLiteral("none") : names.join(u", ");
    };
    if (name == QStringView(kHoldBackRun)) {
        return true;
    }
    if (name.startsWith(u"panel:")) {
        const QString panel = name.mid(6);
        return step.panels.contains(panel) ||
               in.fail(place, FileMessages::tr("\"%1\": this step shows no panel \"%2\" (its "
                                               "panels: %3)")
                                  .arg(name, panel, listed(step.panels)));
    }
    if (name.startsWith(u"plot:")) {
        const QString plot = name.mid(5);
        return step.plots.contains(plot) ||
               in.fail(place, FileMessages::tr("\"%1\": this step shows no plot \"%2\" (its "
                                               "plots: %3)")
                                  .arg(name, plot, listed(step.plots)));
    }
    for (const auto& [column, panel] :
         {std::pair{QStringView(kHoldBackCollisionAfter), QStringView(u"collision")},
          std::pair{QStringView(kHoldBackBounceHeights), QStringView(u"bounces")}}) {
        if (name == column) {
            return step.panels.contains(panel.toString()) ||
                   in.fail(place, FileMessages::tr("\"%1\" is a column of the %2 panel, which this "
                                                   "step does not show")
                                      .arg(name, panel.toString()));
        }
    }
    return in.fail(place, FileMessages::tr("unknown name \"%1\" (expected run, panel:NAME, "
                                           "plot:NAME, %2, %3)")
                              .arg(name, QStringView(kHoldBackCollisionAfter).toString(),
                                   QStringView(kHoldBackBounceHeights).toString()));
}

bool readHoldBack(JsonReader& in, const QJsonObject& object, const QString& place,
                  const LessonStep& step, QStringList& out)
{
    if (!object.contains(u"holdBack")) {
        return true;
    }
    const QString at = joinPlace(place, u"holdBack");
    QJsonArray list;
    if (!in.asArray(object.value(u"holdBack"), at, list)) {
        return false;
    }
    return readDistinctNames(
        in, list, at,
        [&](const QString& name, const QString& itemAt) {
            return checkHoldBackName(in, name, itemAt, step);
        },
        out);
}

/// A choice question's options: only the list form, each option a text of its own (an object of
/// languages holding lists could give the languages different numbers of options).
bool readChoices(JsonReader& in, LocalTexts& texts, const QJsonObject& object, const QString& place,
                 ChoiceQuestion& choice)
{
    const QString at = joinPlace(place, u"choices");
    if (!object.contains(u"choices")) {
        return in.fail(at, FileMessages::tr("required with \"answer\", but missing (the options "
                                            "to choose from)"));
    }
    if (!object.value(u"choices").isArray()) {
        return in.fail(at, FileMessages::tr("must be an array of %1 to %2 options, each a text "
                                            "\"...\" or {\"en\": \"...\", \"cs\": \"...\"}, got ")
                                   .arg(kMinChoices)
                                   .arg(kMaxChoices) +
                               describeJson(object.value(u"choices")));
    }
    if (!texts.list(object, u"choices", place, kMaxChoices, FileMessages::tr("options"),
                    choice.choices)) {
        return false;
    }
    if (choice.choices.size() < kMinChoices) {
        return in.fail(at, FileMessages::tr("%1 options, fewer than the %2 a choice needs")
                               .arg(choice.choices.size())
                               .arg(kMinChoices));
    }
    return true;
}

/// The right option of a choice question, after its options.
bool readAnswer(JsonReader& in, const QJsonObject& object, const QString& place,
                ChoiceQuestion& choice)
{
    if (!object.contains(u"answer")) {
        return in.fail(joinPlace(place, u"answer"),
                       FileMessages::tr("required, but missing (the index of the right option, "
                                        "0 for the first)"));
    }
    return in.integer(object, u"answer", place, choice.answer, 0,
                      static_cast<int>(choice.choices.size()) - 1, true);
}

/// A question's "measure": what its answer is checked against.
bool readMeasureKey(JsonReader& in, const QJsonObject& object, const QString& place,
                    const Scene& scene, MeasuredQuestion& measured)
{
    if (!object.contains(u"measure")) {
        return in.fail(joinPlace(place, u"measure"),
                       FileMessages::tr("required, but missing (what the answer is checked "
                                        "against)"));
    }
    return readMeasure(in, object.value(u"measure"), joinPlace(place, u"measure"), scene,
                       measured.measure);
}

/// What reading a question's parts needs besides the JSON object.
struct QuestionReading {
    JsonReader& in;
    LocalTexts& texts;
    const QJsonObject& object;
    const QString& place;
    const LessonStep& step;
    const Question& question; ///< every question's fields, read before its kind's
};

/// A part of a question (a row of kind Part), by its key, read by its own function: one
/// overload per kind of question that has parts (format/question_kind.h).
bool readKindPart(const QuestionReading& r, std::string_view key, MeasuredQuestion& measured)
{
    if (key == schema::question_keys::kMeasure)
        return readMeasureKey(r.in, r.object, r.place, r.step.scene, measured);
    if (key == schema::question_keys::kSet)
        return readQuestionSet(r.in, r.object, r.place, r.step, r.question.holdBack, measured.set);
    return true;
}

bool readKindPart(const QuestionReading& r, std::string_view key, ChoiceQuestion& choice)
{
    if (key == schema::question_keys::kChoices)
        return readChoices(r.in, r.texts, r.object, r.place, choice);
    if (key == schema::question_keys::kAnswer)
        return readAnswer(r.in, r.object, r.place, choice);
    return true;
}

/// The kind's own rows, in the file's order: the texts and plain values as their rows say,
/// each part by its own function.
template <class K> bool readKind(const QuestionReading& r, K& kind)
{
    for (const schema::KindField<K>& row : schema::kindFields(std::type_identity<K>{})) {
        bool ok = true;
        if (row.kind != schema::LessonKind::Part)
            ok = readLessonRow(r.in, r.texts, row, r.object, r.place, kind);
        else if constexpr (requires { readKindPart(r, row.key, kind); })
            ok = readKindPart(r, row.key, kind);
        else
            assert(false && "a kind with a part has its readKindPart here");
        if (!ok)
            return false;
    }
    if (const std::optional<KindProblem> problem = kindProblem(kind))
        return r.in.fail(joinPlace(r.place, schema::jsonKey(problem->key)), problem->message);
    return true;
}

bool readQuestion(JsonReader& in, LocalTexts& texts, const QJsonValue& value, const QString& place,
                  const LessonStep& step, Question& question)
{
    QJsonObject object;
    if (!in.asObject(value, place, object) ||
        !in.checkKeys(object, place, schema::questionKeys())) {
        return false;
    }
    // The keys of another kind of question are refused rather than ignored.
    question.kind = schema::newQuestionKind(schema::questionKindIn(object));
    const QStringList own = schema::questionKindKeys(question.kind.index());
    for (std::size_t k = 0; k < std::variant_size_v<decltype(Question::kind)>; ++k) {
        for (const QString& key : schema::questionKindKeys(k)) {
            if (!own.contains(key) && object.contains(key)) {
                return in.fail(joinPlace(place, key),
                               std::visit([](const auto& kind) { return otherKindsKey(kind); },
                                          question.kind));
            }
        }
    }
    for (const schema::QuestionField& row : schema::questionFields()) {
        const bool ok = row.kind == schema::LessonKind::Part
                            ? row.key != schema::question_keys::kHoldBack ||
                                  readHoldBack(in, object, place, step, question.holdBack)
                            : readLessonRow(in, texts, row, object, place, question);
        if (!ok)
            return false;
    }
    const QuestionReading reading{in, texts, object, place, step, question};
    return std::visit([&](auto& kind) { return readKind(reading, kind); }, question.kind);
}

} // namespace

bool readSat(JsonReader& in, const QJsonObject& object, const QString& place, const Scene& scene,
             std::optional<std::pair<QString, QString>>& out)
{
    if (!object.contains(u"sat")) {
        return true;
    }
    const QString at = joinPlace(place, u"sat");
    QJsonObject pair;
    QString a;
    QString b;
    if (!in.asObject(object.value(u"sat"), at, pair) || !in.checkKeys(pair, at, {u"a", u"b"}) ||
        !readBodyId(in, pair, u"a", at, scene, a) || !readBodyId(in, pair, u"b", at, scene, b)) {
        return false;
    }
    if (a == b) {
        return in.fail(joinPlace(at, u"b"),
                       FileMessages::tr("the same body as \"a\": the test needs two bodies"));
    }
    for (const auto& [key, id] :
         {std::pair{QStringView(u"a"), a}, std::pair{QStringView(u"b"), b}}) {
        const physics::BodyDef& def = scene.bodies[static_cast<size_t>(*scene.bodyIndex(id))];
        if (!def.shape.asPolygon()) {
            return in.fail(joinPlace(at, key),
                           FileMessages::tr("body \"%1\" is a circle: the separating axis test "
                                            "steps through polygons (boxes and polygons)")
                               .arg(id));
        }
    }
    out = std::pair{a, b};
    return true;
}

bool readQuestions(JsonReader& in, LocalTexts& texts, const QJsonObject& object,
                   const QString& place, const LessonStep& step, std::vector<Question>& out)
{
    if (!object.contains(u"questions")) {
        return true;
    }
    const QString at = joinPlace(place, u"questions");
    QJsonArray list;
    if (!in.asArray(object.value(u"questions"), at, list)) {
        return false;
    }
    if (list.size() > kMaxQuestions) {
        return in.fail(at, FileMessages::tr("%1 questions, more than the limit of %2")
                               .arg(list.size())
                               .arg(kMaxQuestions));
    }
    for (qsizetype i = 0; i < list.size(); ++i) {
        Question question;
        if (!readQuestion(in, texts, list[i], indexPlace(at, i), step, question)) {
            return false;
        }
        out.push_back(std::move(question));
    }
    return true;
}

} // namespace rigidlab::lessons::detail
