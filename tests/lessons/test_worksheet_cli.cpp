// SPDX-License-Identifier: GPL-3.0-or-later
// `rigidlab-cli lesson LESSON --worksheet OUT.pdf` with a student's answers or name: the name
// keeps the answers file's limits (one line of the page header, at most 200 characters),
// answers handed in for another lesson are refused, and each part of the page header sits in
// a bidirectional isolate (read back from the PDF's title with poppler's pdfinfo); an emoji no
// font of the machine has is printed as a placeholder naming it, never lost (pdftotext).

#include "build_paths.h"
#include "cli_run.h"
#include "test_main.h"

#include <QDir>
#include <QFile>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

#include <utility>

using rigidlab::test::CliRun;
using rigidlab::test::runCli;

namespace {

const QString kLesson = rigidlab::test::sourcePath(u"/lessons/lessons/restitution.json");

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

    void emojiIsNeverLost();
};

namespace {

/// A poppler tool's output, or empty when it failed.
QString toolOutput(const QString& program, const QStringList& arguments)
{
    QProcess tool;
    tool.start(program, arguments);
    if (!tool.waitForFinished(30'000) || tool.exitStatus() != QProcess::NormalExit ||
        tool.exitCode() != 0)
        return {};
    return QString::fromUtf8(tool.readAllStandardOutput());
}

} // namespace

void TestWorksheetCli::emojiIsNeverLost()
{
    // A crab (U+1F980) and a grin (U+1F600) in a student's name. Whether a font of this
    // machine has each is fontconfig's answer (fc-list), independent of the lab. One no font
    // has is printed as "[U+1F980]", which pdftotext reads back. One a font has is printed as
    // itself, in that font, embedded (pdffonts; pdftotext cannot read a glyph beyond the
    // 16-bit plane back from the PDFs Qt writes, so its text is not the check).
    const QString crab = QString::fromUcs4(U"\U0001F980");
    const QString grin = QString::fromUcs4(U"\U0001F600");
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString sheet = dir.filePath(QStringLiteral("sheet.pdf"));
    const CliRun run =
        runCli({QStringLiteral("lesson"), kLesson, QStringLiteral("--worksheet"), sheet,
                QStringLiteral("--student"), QStringLiteral("Anna %1 %2 Nová").arg(crab, grin)});
    QVERIFY2(!run.crashed && run.exitCode == 0, run.err.constData());
    const QString text = toolOutput(QStringLiteral("pdftotext"),
                                    {QStringLiteral("-raw"), QStringLiteral("-enc"),
                                     QStringLiteral("UTF-8"), sheet, QStringLiteral("-")});
    QVERIFY2(!text.isEmpty(), "pdftotext read nothing (is poppler-utils installed?)");
    const QString fonts = toolOutput(QStringLiteral("pdffonts"), {sheet});
    for (const auto& [character, code] :
         {std::pair{crab, QStringLiteral("1F980")}, std::pair{grin, QStringLiteral("1F600")}}) {
        const QString placeholder = QStringLiteral("[U+%1]").arg(code);
        const QStringList families =
            toolOutput(QStringLiteral("fc-list"),
                       {QStringLiteral(":charset=") + code.toLower(), QStringLiteral("family")})
                .split(QRegularExpression(QStringLiteral("[,\n]")), Qt::SkipEmptyParts);
        if (families.isEmpty()) {
            QVERIFY2(text.contains(QStringLiteral("Anna ") + placeholder),
                     qPrintable(QStringLiteral("no font has %1: expected %2 in\n%3")
                                    .arg(code, placeholder, text.left(400))));
            continue;
        }
        QVERIFY2(!text.contains(placeholder), qPrintable(text.left(400)));
        bool embedded = false;
        for (QString family : families)
            embedded = embedded || fonts.contains(family.remove(u' '));
        QVERIFY2(embedded, qPrintable(QStringLiteral("%1 is in %2; the PDF embeds\n%3")
                                          .arg(code, families.join(u','), fonts)));
    }
}

RIGIDLAB_TEST_GUILESS_MAIN(TestWorksheetCli)
#include "test_worksheet_cli.moc"
