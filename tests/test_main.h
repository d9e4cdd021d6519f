// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The main() of every test executable: QTEST_MAIN, run in a world of its own.
//
// A test must not depend on what another test executable does at the same time (ctest -j2),
// on what an earlier run left behind, or on the machine's own settings. So before anything
// reads a path, each run gets a fresh home folder of its own, removed when it ends: settings
// (QSettings in QStandardPaths' test mode), the documents folder that exports default to, and
// the last export folder all live there. Its organisation and application names are the
// executable's. A window test once failed on a fresh machine when it ran beside others.

#include <QFileInfo>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

namespace rigidlab::test {

/// Owns the run's home folder; construct it before the application object.
class IsolatedRun {
public:
    IsolatedRun()
    {
        if (!m_home.isValid())
            qFatal("cannot create a temporary home folder: %s", qPrintable(m_home.errorString()));
        // QDir::homePath() and every QStandardPaths location in test mode follow $HOME.
        qputenv("HOME", QFile::encodeName(m_home.path()));
        qunsetenv("XDG_CONFIG_HOME");
        qunsetenv("XDG_DATA_HOME");
        qunsetenv("XDG_CACHE_HOME");
        QStandardPaths::setTestModeEnabled(true);
    }

    /// Names the application after the test executable (after the application exists).
    void nameApplication() const
    {
        QCoreApplication::setOrganizationName(QStringLiteral("RigidLabTest"));
        QCoreApplication::setApplicationName(
            QFileInfo(QCoreApplication::applicationFilePath()).baseName());
    }

    QString home() const { return m_home.path(); }

private:
    QTemporaryDir m_home{QDir::tempPath() + QStringLiteral("/rigidlab-test-home-XXXXXX")};
};

} // namespace rigidlab::test

#define RIGIDLAB_TEST_MAIN_IMPL(TestObject, Application)                                           \
    int main(int argc, char** argv)                                                                \
    {                                                                                              \
        rigidlab::test::IsolatedRun isolatedRun;                                                   \
        QTest::Internal::callInitMain<TestObject>();                                               \
        Application app(argc, argv);                                                               \
        isolatedRun.nameApplication();                                                             \
        TestObject tc;                                                                             \
        QTEST_SET_MAIN_SOURCE_PATH                                                                 \
        return QTest::qExec(&tc, argc, argv);                                                      \
    }

/// For tests with widgets (QApplication).
#define RIGIDLAB_TEST_MAIN(TestObject) RIGIDLAB_TEST_MAIN_IMPL(TestObject, QApplication)
/// For tests without (QCoreApplication).
#define RIGIDLAB_TEST_GUILESS_MAIN(TestObject) RIGIDLAB_TEST_MAIN_IMPL(TestObject, QCoreApplication)
