// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The measured kind of question (format/question_kind.h): a number the student types, right
// within the tolerances of the value the run measures. Its parts (the measure, the settings
// asked for) are read in format/lesson_questions.cpp, its verdict needs the run
// (lessons/run/judge.cpp).

#include "format/limits.h"
#include "format/question_kind.h"
#include "format/step_settings.h"

#include <QString>

#include <cassert>

namespace rigidlab::lessons {

/// What a question reads from the running simulation.
struct Measure {
    enum class Kind {
        Apex,            ///< height of the body's n-th apex after a bounce, above `above` [m]
        Speed,           ///< |v| of the body at `time` [m/s]
        VelocityX,       ///< vx of the body at `time` [m/s]
        VelocityY,       ///< vy of the body at `time` [m/s]
        AngularVelocity, ///< omega of the body at `time` [rad/s]
        PositionX,       ///< x of the body origin at `time` [m]
        PositionY,       ///< y of the body origin at `time` [m]
        EnergyDrift,     ///< (E + dissipated - E0) / |E0| at `time` [%]
        MomentumX,       ///< total px at `time` [kg m/s]
        MomentumY,       ///< total py at `time` [kg m/s]
    };
    Kind kind = Kind::Apex;
    QString body;     ///< body id (not for EnergyDrift, MomentumX, MomentumY)
    int n = 1;        ///< Apex: 1 = the apex after the first bounce
    double above = 0; ///< Apex: heights are measured above this y [m]
    double time = 0;  ///< the others: when the value is read [s]
};

/// A question answered by a number measured from the run: the answer typed is right within
/// the tolerances of the value `measure` reads.
struct MeasuredQuestion {
    Measure measure;                ///< what the answer is checked against
    QString unit;                   ///< shown after the answer box, e.g. "m"
    double tolerance = 0.05;        ///< relative to the measured value
    double absoluteTolerance = 0.0; ///< added to it, for values near zero
    /// The settings the student is asked to set (with the step's controls) before the run
    /// this question measures: keys of "settings" but timeScale. The answer is measured with
    /// them, and a run without them is not judged. All unset: the step's own settings.
    StepSettings set;
};

namespace schema {

namespace question_keys {
inline constexpr std::string_view kMeasure = "measure";
inline constexpr std::string_view kTolerance = "tolerance";
inline constexpr std::string_view kAbsoluteTolerance = "absoluteTolerance";
inline constexpr std::string_view kSet = "set";
} // namespace question_keys

inline std::span<const KindField<MeasuredQuestion>> kindFields(std::type_identity<MeasuredQuestion>)
{
    static const KindField<MeasuredQuestion> rows[] = {
        {.key = question_keys::kMeasure},
        {.key = question_keys::kUnit, .kind = LessonKind::Unit, .text = &MeasuredQuestion::unit},
        plainRow<MeasuredQuestion>(
            {.key = question_keys::kTolerance,
             .label = QT_TRANSLATE_NOOP("SceneSchema", "Tolerance"),
             .kind = Kind::Number,
             .range = {0.0, 1.0, ""},
             .rule = detail::NumberRule::UnitInterval,
             .get = numberGet<MeasuredQuestion, &MeasuredQuestion::tolerance>,
             .set = numberSet<MeasuredQuestion, &MeasuredQuestion::tolerance>}),
        plainRow<MeasuredQuestion>(
            {.key = question_keys::kAbsoluteTolerance,
             .label = QT_TRANSLATE_NOOP("SceneSchema", "Absolute tolerance"),
             .kind = Kind::Number,
             .range = limits::kAbsoluteTolerance,
             .rule = detail::NumberRule::NonNegative,
             .get = numberGet<MeasuredQuestion, &MeasuredQuestion::absoluteTolerance>,
             .set = numberSet<MeasuredQuestion, &MeasuredQuestion::absoluteTolerance>}),
        {.key = question_keys::kSet},
    };
    return rows;
}

} // namespace schema

/// A measured question is one that holds no other kind's key (schema::questionKindIn), so it
/// never meets one.
inline QString otherKindsKey(const MeasuredQuestion&)
{
    assert(false && "a question with another kind's key is of that kind");
    return {};
}

inline std::optional<KindProblem> kindProblem(const MeasuredQuestion& measured)
{
    if (measured.tolerance == 0 && measured.absoluteTolerance == 0)
        return KindProblem{
            schema::question_keys::kTolerance,
            detail::FileMessages::tr("0, and so is absoluteTolerance: no typed answer "
                                     "would ever be right")};
    return std::nullopt;
}

inline AnswerForm answerForm(const MeasuredQuestion& measured)
{
    return {measured.unit, false};
}

} // namespace rigidlab::lessons
