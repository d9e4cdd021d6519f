// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Tests of measurements and fits (rigidlab_measure), one executable: reading every layout and
// refusing damaged files (test_measure_read.cpp), the minimisers and the fits on synthetic
// measurements made by the lab itself (test_measure_fit.cpp), and `rigidlab-cli fit` as a
// process (test_measure_cli.cpp).

#include "build_paths.h"

#include <QObject>
#include <QString>

namespace rigidlab::test {

inline const QString kMeasureSamples = rigidlab::test::sourcePath(u"/lessons/measure/samples");
inline const QString kMeasureDamaged = rigidlab::test::sourcePath(u"/tests/lessons/data/measure");

} // namespace rigidlab::test

class TestMeasure : public QObject {
    Q_OBJECT

private slots:
    // test_measure_read.cpp
    void readsLayouts_data();
    void readsLayouts();
    void refusesDamaged_data();
    void refusesDamaged();
    void refusesMillionRows();
    void refusesTooLarge();
    void unitsAndOffsets();
    void explicitMapping();
    void bounceTimesOnly();

    // test_measure_fit.cpp
    void brentFindsMinimum();
    void nelderMeadFindsMinimum();
    void gridFindsDeeperDip();
    void parsesParametersAndTargets_data();
    void parsesParametersAndTargets();
    void simulatedSamplesInterpolate();
    void exactFlightsAreTheLabsLimit();
    void fitsFriction();
    void fitsTwoParameters();
    void bounceTimesGiveRestitution();
    void bounceTimesFromTheLab();
    void refusesUnfittable();

    // test_measure_cli.cpp
    void cliHelp();
    void cliFitsSamples_data();
    void cliFitsSamples();
    void cliRefuses_data();
    void cliRefuses();
};
