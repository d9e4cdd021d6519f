// SPDX-License-Identifier: GPL-3.0-or-later
// `rigidlab-cli lesson LESSON --worksheet OUT.pdf` with a student's answers or name: the name
// keeps the answers file's limits (one line of the page header, at most 200 characters),
// answers handed in for another lesson are refused, and each part of the page header sits in
// a bidirectional isolate (read back from the PDF's title with poppler's pdfinfo).

#include "cli_run.h"
#include "test_main.h"

#include <QDir>
#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

using rigidlab::test::CliRun;
using rigidlab::test::runCli;

namespace {

const QString kLesson = QStringLiteral(RIGIDLAB_SOURCE_DIR "/lessons/lessons/restitution.json");

/// The restitution lesson's sheet, dir/sheet.pdf, from the answers file `json` in `dir`.
CliRun sheetFromAnswers(const QTemporaryDir& dir, const QByteArray& json)
{
    const QString answers = dir.filePath(QStringLiteral("handed-in.answers.json"));
    QFile file(answers);
    if (!file.open(QIODevice::WriteOnly) || file.write(json) != json.size())
        qFatal("cannot write %s", qPrintable(answers));
    file.close();
    return runCli({QStringLiteral("lesson"), kLesson, QStringLiteral("--worksheet"),
                   dir.filePath(QStringLiteral("sheet.pdf")), QStringLiteral("--answers"),
                   answers});
}

} // namespace

class TestWorksheetCli : public QObject {
    Q_OBJECT

private slots:
    void studentKeepsTheAnswersLimits_data()
    {
        QTest::addColumn<QString>("student");
        QTest::addColumn<QString>("message");
        QTest::newRow("two lines") << "Jana\nNovakova"
                                   << "lesson: --student: must be one line";
        QTest::newRow("too long") << QString(201, u'a')
                                  << "lesson: --student: longer than 200 characters";
    }
    void studentKeepsTheAnswersLimits()
    {
        QFETCH(QString, student);
        QFETCH(QString, message);
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString sheet = dir.filePath(QStringLiteral("sheet.pdf"));
        const CliRun run = runCli({QStringLiteral("lesson"), kLesson, QStringLiteral("--worksheet"),
                                   sheet, QStringLiteral("--student"), student});
        QVERIFY(!run.crashed);
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(QString::fromUtf8(run.err).contains(message), run.err.constData());
        QVERIFY(!QFile::exists(sheet));
    }

    void anotherLessonsAnswersAreRefused()
    {
        // Answers handed in for the stacks lesson, asked for the restitution lesson's sheet.
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const CliRun run = sheetFromAnswers(
            dir, R"({"rigidlab-answers": 1, "lesson": "stacks.json", "steps": []})");
        QVERIFY(!run.crashed);
        QCOMPARE(run.exitCode, 2); // bad input
        QVERIFY2(
            run.err.contains("lesson: answers to \"stacks.json\", not to \"restitution.json\""),
            run.err.constData());
        QVERIFY(!QFile::exists(dir.filePath(QStringLiteral("sheet.pdf"))));
    }

    void headerPartsAreIsolated()
    {
        // A name written right to left beside a class: each part of the page header sits in a
        // bidirectional isolate, so "2.B" is not pulled into the name ("أحمد محمد.B" around "2").
        // Read back from the PDF's title (pdfinfo), which is the header's line.
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const CliRun run = sheetFromAnswers(dir, R"({"rigidlab-answers": 1,
            "lesson": "restitution.json", "student": "أحمد محمد", "class": "2.B", "steps": []})");
        QVERIFY2(!run.crashed && run.exitCode == 0, run.err.constData());
        QProcess info;
        info.start(QStringLiteral("pdfinfo"), {dir.filePath(QStringLiteral("sheet.pdf"))});
        QVERIFY2(info.waitForFinished(30'000) && info.exitCode() == 0,
                 "pdfinfo failed (is poppler-utils installed?)");
        const QString title = QString::fromUtf8(info.readAllStandardOutput());
        const QString isolatedName = QChar(0x2068) + QStringLiteral("أحمد محمد") + QChar(0x2069);
        const QString isolatedClass = QChar(0x2068) + QStringLiteral("2.B") + QChar(0x2069);
        QVERIFY2(title.contains(isolatedName + QStringLiteral(" · ") + isolatedClass),
                 qPrintable(title));
    }
};

RIGIDLAB_TEST_GUILESS_MAIN(TestWorksheetCli)
#include "test_worksheet_cli.moc"
