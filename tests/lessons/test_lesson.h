// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Tests of lessons, one executable: the lesson loader and its checks
// (test_lesson_loader.cpp), and what the lessons measure, judge and claim about the physics
// (test_lesson_physics.cpp). Shared helpers here.

#include "build_paths.h"
#include "format/lesson.h"
#include "run/measurements.h"
#include "test_files.h"

#include "question_kinds.h"
#include <QDir>
#include <QFile>
#include <QObject>
#include <QString>
#include <QTest>

namespace rigidlab::test {

inline const QString kLessonsDir = rigidlab::test::sourcePath(u"/lessons/lessons");
/// The one folder of shipped scenes, the lessons' included.
inline const QString kScenesDir = rigidlab::test::sourcePath(u"/lessons/scenes");
/// Hand-made lessons written in one language only.
inline const QString kOneLanguageDir =
    rigidlab::test::sourcePath(u"/tests/lessons/data/one_language");

inline QString lessonPath(const char* name)
{
    return QDir(kLessonsDir).filePath(QLatin1StringView(name) + QStringLiteral(".json"));
}

/// A shipped lesson, loaded; the test fails (and returns an empty lesson) if it does not load.
inline lessons::Lesson shippedLesson(const char* name)
{
    const lessons::LessonLoadResult loaded = lessons::loadLessonFile(lessonPath(name));
    if (!loaded.ok)
        qWarning("%s", qPrintable(loaded.error));
    return loaded.lesson;
}

/// A step's worlds run side by side for `seconds`, each observed by its Measurements (the
/// questions' measures watched), as the window runs them.
struct StepRun {
    std::vector<physics::World> worlds;
    std::vector<lessons::Measurements> measurements;

    explicit StepRun(const lessons::LessonStep& step) : worlds(lessons::buildStepWorlds(step))
    {
        std::vector<lessons::Measure> watched;
        for (const lessons::Question& q : step.questions)
            if (!isChoice(q))
                watched.push_back(measuredOf(q).measure);
        measurements.resize(worlds.size());
        for (std::size_t i = 0; i < worlds.size(); ++i) {
            worlds[i].updateDiagnostics();
            measurements[i].reset(worlds[i], watched);
        }
    }
    /// Runs every world `seconds` further; `each(i)` is called after every step of world i.
    template <typename Each> void run(double seconds, Each&& each)
    {
        const auto steps = static_cast<long long>(std::llround(seconds / worlds[0].def().dt));
        for (long long n = 0; n < steps; ++n) {
            for (std::size_t i = 0; i < worlds.size(); ++i) {
                worlds[i].step();
                measurements[i].observe(worlds[i]);
                each(i);
            }
        }
    }
    void run(double seconds)
    {
        run(seconds, [](std::size_t) {});
    }
};

} // namespace rigidlab::test

class TestLesson : public QObject {
    Q_OBJECT

private slots:
    // test_lesson_loader.cpp
    void shippedScenesUseTheSoftStep();
    void shippedLessonsLoad_data();
    void shippedLessonsLoad();
    void shippedLessonsLabelEveryBody_data();
    void shippedLessonsLabelEveryBody();
    void sceneTextsInLessonLanguage();
    void validateRecognisesLessons();
    void shippedLessonsInTeachingOrder();
    void lessonsWithoutOrderComeLast();
    void userLessonsListedAfterShipped();
    void rejectsBadLesson_data();
    void rejectsBadLesson();
    void choiceQuestionRead();
    void choiceMissingLanguageWarns();
    void rejectsBadChoice_data();
    void rejectsBadChoice();
    void judgeChoiceTries();
    void choiceTriesInAnswersFile();
    void numberGivenRead();
    void rejectsBadNumberGiven_data();
    void rejectsBadNumberGiven();
    void judgeNumberGivenTries();
    void rejectsSymbolicLinkOutOfFolder();
    void sceneFileErrorsCarryBothPlaces();
    void inlineSceneErrorsContinueThePlace();
    void everyField();
    void editorListsDefaultToAll();
    void formatDocumentExampleLoads();
    void textsInBothForms();
    void textsFallBackToEnglish();
    void missingLanguageWarns();
    void oneLanguageLessons_data();
    void oneLanguageLessons();
    void badLanguageObjectRefused_data();
    void badLanguageObjectRefused();
    void originalVerticesOfNonConvexPolygon();
    void buildStepWorldsMakesOneWorldPerVariant();
    void applySettingsOverridesScene();
    void questionSetAsksForItsOwnRun();

    // test_lesson_physics.cpp
    void judgeApexRightAndWrong();
    void verdictsOfARunNotYetShownSayWhatItWillMeasure();
    void judgeTimedValue();
    void judgeWaitsInWholeSentences();
    void judgeMessages_data();
    void judgeMessages();
    void judgeAttemptGivesHintThenValue();
    void rewindForgetsLaterEvents();
    void measurementsKeepTheFirstEvents();
    void measurementsFindEveryNewTouch();
    void collisionPredictionsOfOffCentreHit();
    void shippedQuestionsHaveTheirTextbookAnswers_data();
    void shippedQuestionsHaveTheirTextbookAnswers();
    void restitutionBounceRatiosAreESquared();
    void bounceHeightsAreExactMechanics();
    void restitutionDriftStaysAtZero();
    void energyDriftClaims();
    void pendulumEulerGoesOverTheTop();
    void smallerStepShrinksDrift();
    void sequentialImpulseStackMovesLess();
    void softStepPyramidStands();
    void billiardsBreakConservesMomentum();
    void billiardsCushionsWhereTheTextSays();
    void editorStepIsAnsweredByEditing();
    void stiffSpringsDivergeWhereTheoryPredicts();
    void worldsStopWhereTheTextSays_data();
    void worldsStopWhereTheTextSays();
    void stiffSpringsEulerTenfoldWhereTheorySays();
    void divergenceMessageWords();

    // test_lesson_physics_texts.cpp
    void unitsStayWithTheirNumbers();
};
