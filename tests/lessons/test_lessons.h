// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Tests of the lessons library, one executable: the scene loader (test_scene_loader.cpp) and
// running scenes, validation and the SAT report (test_scene_run.cpp). Shared helpers here.

#include "build_paths.h"
#include "format/scene_loader.h"
#include "test_files.h"

#include <QByteArray>
#include <QFile>
#include <QObject>
#include <QString>
#include <QTest>

#include <cmath>

namespace rigidlab::test {

inline const QString kScenesDir = rigidlab::test::sourcePath(u"/lessons/scenes");

/// A scene with the given top-level members after the version.
inline QByteArray sceneWith(const char* members)
{
    return QByteArray(R"({"rigidlab": 1, )") + members + "}";
}

/// A scene with one body whose JSON object holds `fields` after its id.
inline QByteArray oneBody(const char* fields)
{
    return sceneWith((QByteArray(R"("bodies": [{"id": "ball", )") + fields + "}]").constData());
}

inline bool isClose(double a, double b, double tol = 1e-12)
{
    return std::abs(a - b) <= tol;
}

} // namespace rigidlab::test

class TestLessons : public QObject {
    Q_OBJECT

private slots:
    void rejectsBadScene_data();
    void rejectsBadScene();
    void missingFile();
    void fileTooLarge();
    void tooManyBodies();
    void defaults();
    void everyField();
    void sceneTexts_data();
    void sceneTexts();
    void rejectsBadSceneText_data();
    void rejectsBadSceneText();
    void sceneTextsDefaultToLessonLanguage();
    void bodyLabels_data();
    void bodyLabels();
    void rejectsBadBodyLabel_data();
    void rejectsBadBodyLabel();
    void nonConvexPolygonWarns();
    void springRestLengthDefaultsToDistance();
    void pinAnchorBDefaultsToCoincidentPoint();
    void buildWorldPlacesBodyOrigin();
    void shippedScenesLoad_data();
    void shippedScenesLoad();
    void validateRecognisesScenes();
    void summaryBooksContactsThatAddEnergy();
    void formatDocumentExampleLoads();
    void runWritesHeadersAndRows();
    void runIsDeterministic();
    void runStopsOnNonFinite();
    void runFailsOnUnwritableOutput();
    void stepsForTime_data();
    void stepsForTime();
    void welcomeDriftIsTheErrorAlone();
    void conservativeDriftIsTheEnergyChange_data();
    void conservativeDriftIsTheEnergyChange();
    void satReport();
    void satReportRejects_data();
    void satReportRejects();
    void sweptBoundsFollowTheMotion();
};
