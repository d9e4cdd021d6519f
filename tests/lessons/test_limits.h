// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Hostile files (test_limits.cpp): every limit of the scene and lesson formats with its place
// and range, and scene paths that try to leave a lesson's folder. The class is declared here,
// apart from the JSON in raw strings, which moc does not read.

#include <QObject>

class TestLimits : public QObject {
    Q_OBJECT

private slots:
    void magnitudesAreRefused_data();
    void magnitudesAreRefused();
    void valuesAtTheLimitsLoadAndStayFinite();
    void deepNestingIsRefused();
    void messagesAreOneLine();
    void oversizedFilesAreRefused();
    void lessonBodiesAreCountedOverItsSteps();
    void lessonMagnitudesAreRefused_data();
    void lessonMagnitudesAreRefused();
    void sliverDeepInsideAPolygonHasAContact();
    void scenePathsStayInside_data();
    void scenePathsStayInside();
    void scenePathsStayInsideTheDataFolder_data();
    void scenePathsStayInsideTheDataFolder();
    void nothingInAFileIsRun();
};
