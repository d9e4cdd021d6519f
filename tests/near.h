// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The one near-comparison of every test: RL_VERIFY_NEAR compares within an absolute and a
// relative tolerance (qFuzzyCompare fails near zero) and, when it fails, prints both values,
// their difference and the tolerance; RL_VERIFY_AT_MOST prints the value and its bound.

#include <QByteArray>
#include <QTest>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace rigidlab::test {

/// True when |actual - expected| <= max(absTol, relTol * max(|actual|, |expected|)).
/// The absolute floor is what makes comparisons of quantities that should be zero possible.
inline bool isClose(double actual, double expected, double absTol, double relTol = 0.0)
{
    if (!std::isfinite(actual) || !std::isfinite(expected)) {
        return false;
    }
    const double scale = std::max(std::abs(actual), std::abs(expected));
    return std::abs(actual - expected) <= std::max(absTol, relTol * scale);
}

/// The failure message of RL_VERIFY_NEAR: both values, their difference and the tolerance.
inline QByteArray nearMessage(const char* what, double actual, double expected, double absTol,
                              double relTol)
{
    char buf[512];
    std::snprintf(buf, sizeof buf,
                  "%s: got %.17g, expected %.17g (difference %.3g, tolerance abs %.3g rel %.3g)",
                  what, actual, expected, actual - expected, absTol, relTol);
    return QByteArray(buf);
}

/// A message for a failed inequality: "what: got X, bound B".
inline QByteArray boundMessage(const char* what, double actual, double bound)
{
    char buf[512];
    std::snprintf(buf, sizeof buf, "%s: got %.17g, bound %.17g", what, actual, bound);
    return QByteArray(buf);
}

} // namespace rigidlab::test

/// QVERIFY that actual is within max(absTol, relTol * magnitude) of expected.
#define RL_VERIFY_NEAR(actual, expected, absTol, relTol)                                           \
    do {                                                                                           \
        const double rlActual = (actual);                                                          \
        const double rlExpected = (expected);                                                      \
        QVERIFY2(::rigidlab::test::isClose(rlActual, rlExpected, (absTol), (relTol)),              \
                 ::rigidlab::test::nearMessage(#actual, rlActual, rlExpected, (absTol), (relTol))  \
                     .constData());                                                                \
    } while (false)

/// QVERIFY that actual <= bound, printing both when it is not.
#define RL_VERIFY_AT_MOST(actual, bound)                                                           \
    do {                                                                                           \
        const double rlActual = (actual);                                                          \
        const double rlBound = (bound);                                                            \
        QVERIFY2(rlActual <= rlBound,                                                              \
                 ::rigidlab::test::boundMessage(#actual, rlActual, rlBound).constData());          \
    } while (false)
