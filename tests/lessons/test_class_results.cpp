// SPDX-License-Identifier: GPL-3.0-or-later
// A class's answers files collected into one table (lessons/results): the numbers of each
// cell from answers files written here with known tries, the files left out with their
// lines, the CSV read back in both dialects, the table model's sorting, and rigidlab-cli
// results as a user runs it (text, CSV, PDF through pdftotext, its errors).

#include "format/answers_file.h"
#include "format/data_dirs.h"
#include "results/class_folder.h"
#include "results/class_table_files.h"
#include "results/class_table_model.h"

#include <QDir>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

#include "cli_run.h"
#include "csv_reader.h"
#include "near.h"
#include "test_files.h"
#include "test_main.h"

using namespace rigidlab;

namespace {

// What the lab measured for restitution.json's first two questions (the third bounce of the
// e = 0.8 ball and the third of e = 0.5), as the window stores it with each try [m]. The
// questions' tolerances are 3 %: 0.41 is right, 0.3 and 0.125 are not.
constexpr double kBounce = 0.4096;
constexpr double kThird = 0.0156;
constexpr double kHeavy = 0.333; // step 2, question 1 [m/s]

lessons::AnswerTry checked(double answer, std::optional<double> measured)
{
    lessons::AnswerTry t;
    t.answer = answer;
    t.measured = measured;
    return t;
}

lessons::AnswerTry showMe(double measured)
{
    lessons::AnswerTry t;
    t.measured = measured;
    return t;
}

lessons::Answers answers(const QString& lesson, const QString& student,
                         std::vector<std::vector<std::vector<lessons::AnswerTry>>> steps)
{
    lessons::Answers a;
    a.lessonFile = lesson;
    a.student = student;
    a.className = QStringLiteral("2.B");
    a.date = QStringLiteral("2026-12-03");
    for (auto& questions : steps)
        a.steps.push_back({std::move(questions), std::nullopt, std::nullopt, std::nullopt});
    return a;
}

QString restitution()
{
    return QDir(lessons::shippedLessonsDir()).filePath(QStringLiteral("restitution.json"));
}

/// The class: Anna right at once on 1.1, wrong then right on 1.2; Bára checks 1.1 before the
/// run measured it, then answers wrong, then asks Show me, and is right on 2.1; Cyril's file
/// names no lesson, he asks Show me on 1.1 and checks 1.2 only before it was measured. Beside
/// them a damaged file, another lesson's, and files that are not answers.
void writeClass(const QString& folder)
{
    const QString lesson = QStringLiteral("restitution.json");
    const QDir dir(folder);
    const auto put = [&](const char* name, const QByteArray& bytes) {
        QVERIFY(test::writeFile(dir.filePath(QLatin1StringView(name)), bytes));
    };
    put("anna.answers.json",
        lessons::answersJson(answers(
            lesson, QStringLiteral("Anna Malá"),
            {{{checked(0.41, kBounce)}, {checked(0.125, kThird), checked(0.0156, kThird)}}})));
    put("bara.answers.json",
        lessons::answersJson(
            answers(lesson, QStringLiteral("Bára Nová"),
                    {{{checked(0.5, std::nullopt), checked(0.3, kBounce), showMe(kBounce)}, {}},
                     {{checked(0.333, kHeavy)}, {}}})));
    put("cyril.answers.json",
        lessons::answersJson(answers(QString(), QStringLiteral("Cyril Starý"),
                                     {{{showMe(kBounce)}, {checked(0.02, std::nullopt)}}})));
    put("damaged.answers.json", QByteArrayLiteral("{\"rigidlab-answers\": 1, \"lesson\": "));
    put("other.answers.json", lessons::answersJson(answers(QStringLiteral("tunnelling.json"),
                                                           QStringLiteral("Dana Jiná"), {})));
    put("notes.txt", "not an answers file");
}

/// The one line of `lines` that starts with `file`, or empty.
QString lineOf(const QStringList& lines, const QString& file)
{
    for (const QString& line : lines)
        if (line.startsWith(file + u':'))
            return line;
    return QString();
}

/// Column `kind` of question `q` (0-based over the lesson) in classColumns().
int columnOf(const lessons::ClassTable& table, lessons::ClassColumnKind kind, int q)
{
    const std::vector<lessons::ClassColumn> columns = lessons::classColumns(table);
    for (std::size_t c = 0; c < columns.size(); ++c)
        if (columns[c].kind == kind && columns[c].question == q)
            return static_cast<int>(c);
    return -1;
}

} // namespace

class TestClassResults : public QObject {
    Q_OBJECT
private slots:
    void init();
    void outcomesOfTheTries();
    void numberGivenColumn();
    void filesLeftOutWithALineEach();
    void lessonFoundByItsName();
    void everyLessonWhenAsked();
    void folderErrors();
    void csvInBothDialects();
    void modelKeepsTheSummaryLast();
    void cliWritesTheTable();
    void cliWritesCsvAndPdf();
    void cliErrors();

private:
    QTemporaryDir m_dir;
    QString m_class;
};

void TestClassResults::init()
{
    QVERIFY(m_dir.isValid());
    m_class = m_dir.filePath(QStringLiteral("class"));
    QDir(m_class).removeRecursively();
    QVERIFY(QDir().mkpath(m_class));
    writeClass(m_class);
}

void TestClassResults::outcomesOfTheTries()
{
    lessons::ClassOptions options;
    options.lessonPath = restitution();
    const lessons::ClassCollection c = lessons::collectClass(m_class, options);
    QVERIFY2(c.ok, qPrintable(c.error));
    QCOMPARE(c.tables.size(), std::size_t{1});
    const lessons::ClassTable& t = c.tables.front();
    QCOMPARE(t.lessonFile, QStringLiteral("restitution.json"));
    QCOMPARE(t.questions.size(), std::size_t{7}); // 2 + 2 + 2 + 1
    QCOMPARE(t.rows.size(), std::size_t{3});
    QCOMPARE(t.rows[0].student, QStringLiteral("Anna Malá"));
    QCOMPARE(t.rows[1].file, QStringLiteral("bara.answers.json"));
    QCOMPARE(t.rows[2].className, QStringLiteral("2.B"));
    using V = lessons::FirstVerdict;
    const auto& anna = t.rows[0].questions;
    QCOMPARE(anna[0].first, V::Right);
    QCOMPARE(anna[0].firstNumber, std::optional<double>(0.41));
    QCOMPARE(anna[0].tries, 1);
    QVERIFY(!anna[0].hint && !anna[0].showMe);
    QCOMPARE(anna[1].first, V::NotRight); // 0.125 for 0.0156
    QCOMPARE(anna[1].firstNumber, std::optional<double>(0.125));
    QCOMPARE(anna[1].tries, 2);
    QVERIFY(anna[1].hint);            // the wrong first answer read the hint
    QCOMPARE(anna[2].first, V::None); // step 2 not reached
    const auto& bara = t.rows[1].questions;
    QCOMPARE(bara[0].first, V::NotRight); // the check before the run is no answer
    QCOMPARE(bara[0].firstNumber, std::optional<double>(0.3));
    QCOMPARE(bara[0].tries, 1);
    QVERIFY(bara[0].hint && bara[0].showMe);
    QCOMPARE(bara[1].first, V::None);
    QCOMPARE(bara[2].first, V::Right);
    const auto& cyril = t.rows[2].questions;
    QCOMPARE(cyril[0].first, V::None);
    QCOMPARE(cyril[0].tries, 0);
    QVERIFY(cyril[0].showMe && !cyril[0].hint);
    QCOMPARE(cyril[1].first, V::NotMeasured);
    QCOMPARE(cyril[1].firstNumber, std::optional<double>(0.02));
    QCOMPARE(cyril[1].tries, 0);

    // Right at the first answer: Anna on 1.1, nobody on 1.2, Bára on 2.1; of three students.
    QCOMPARE(t.rightFirst(0), 1);
    QCOMPARE(t.rightFirst(1), 0);
    QCOMPARE(t.rightFirst(2), 1);
    QCOMPARE(t.rightFirstPercent(0), std::optional<double>(33.3));
    QCOMPARE(t.rightFirstPercent(1), std::optional<double>(0.0));
    const lessons::ClassCell share =
        lessons::classSummaryCell(t, {lessons::ClassColumnKind::Verdict, 0});
    QCOMPARE(share.number, std::optional<double>(33.3));
    QVERIFY2(share.text.contains(QStringLiteral("(1 of 3)")), qPrintable(share.text));
    // The cells read what the outcomes hold.
    QCOMPARE(lessons::classCell(t, 0, {lessons::ClassColumnKind::FirstAnswer, 0}).number,
             std::optional<double>(0.41));
    QCOMPARE(lessons::classCell(t, 0, {lessons::ClassColumnKind::Tries, 1}).text,
             QStringLiteral("2"));
    QCOMPARE(lessons::classCell(t, 1, {lessons::ClassColumnKind::Help, 0}).text,
             QStringLiteral("hint, Show me"));
    QCOMPARE(lessons::classColumnHead(t, {lessons::ClassColumnKind::FirstAnswer, 1}),
             QStringLiteral("1.2 first answer [m]"));
    // One list of columns: the student's three, then four per question.
    QCOMPARE(lessons::classColumns(t).size(), std::size_t{3 + 4 * 7});
}

void TestClassResults::numberGivenColumn()
{
    // A question whose answer the lesson gives: its column names its unit, a typed number is
    // judged against it as the player judged it.
    lessons::Lesson lesson;
    lesson.path = QStringLiteral("/l/given.json");
    lessons::LessonStep step;
    lessons::Question q;
    q.prompt = QStringLiteral("p");
    q.hint = QStringLiteral("p = m v");
    q.kind = lessons::NumberGivenQuestion{0.8, 0.05, QStringLiteral("kg m/s")};
    step.questions = {q};
    lesson.steps = {step};
    lessons::ClassTable t = lessons::emptyClassTable(lesson);
    QCOMPARE(t.questions.size(), std::size_t{1});
    QCOMPARE(t.questions[0].unit, QStringLiteral("kg m/s"));
    QVERIFY(!t.questions[0].choice);
    QCOMPARE(lessons::classColumnHead(t, {lessons::ClassColumnKind::FirstAnswer, 0}),
             QStringLiteral("1.1 first answer [kg m/s]"));
    const auto row = [&](std::vector<lessons::AnswerTry> tries) {
        return lessons::studentRow(
            lesson, answers(QStringLiteral("given.json"), QStringLiteral("A"), {{tries}}),
            QStringLiteral("a.answers.json"));
    };
    using V = lessons::FirstVerdict;
    const lessons::StudentRow right = row({checked(0.84, 0.8)});
    QCOMPARE(right.questions[0].first, V::Right);
    QCOMPARE(right.questions[0].firstNumber, std::optional<double>(0.84));
    const lessons::StudentRow wrong = row({checked(0.9, 0.8), checked(0.8, 0.8)});
    QCOMPARE(wrong.questions[0].first, V::NotRight);
    QCOMPARE(wrong.questions[0].tries, 2);
    QVERIFY(wrong.questions[0].hint);
    const lessons::StudentRow shown = row({showMe(0.8)});
    QCOMPARE(shown.questions[0].first, V::None);
    QVERIFY(shown.questions[0].showMe);
}

void TestClassResults::filesLeftOutWithALineEach()
{
    lessons::ClassOptions options;
    options.lessonPath = restitution();
    const lessons::ClassCollection c = lessons::collectClass(m_class, options);
    QVERIFY2(c.ok, qPrintable(c.error));
    QCOMPARE(c.skipped.size(), 2); // notes.txt is not an answers file: not read at all
    const QString damaged = lineOf(c.skipped, QStringLiteral("damaged.answers.json"));
    QVERIFY2(!damaged.isEmpty(), qPrintable(c.skipped.join(u'\n')));
    QVERIFY2(!damaged.contains(u'\n') && !damaged.contains(m_class), qPrintable(damaged));
    const QString other = lineOf(c.skipped, QStringLiteral("other.answers.json"));
    QVERIFY2(other.contains(QStringLiteral("\"tunnelling.json\"")) &&
                 other.contains(QStringLiteral("\"restitution.json\"")),
             qPrintable(other));
    QCOMPARE(c.lessonFiles,
             (QStringList{QStringLiteral("restitution.json"), QStringLiteral("tunnelling.json")}));

    // More answers than the lesson has questions: the lesson changed since; left out too.
    lessons::Answers tooMany = answers(QStringLiteral("restitution.json"), QStringLiteral("Eva"),
                                       {{{}, {}, {checked(1, 1)}}});
    QVERIFY(test::writeFile(QDir(m_class).filePath(QStringLiteral("eva.answers.json")),
                            lessons::answersJson(tooMany)));
    const lessons::ClassCollection again = lessons::collectClass(m_class, options);
    QCOMPARE(again.tables.front().rows.size(), std::size_t{3});
    QVERIFY2(lineOf(again.skipped, QStringLiteral("eva.answers.json"))
                 .contains(QStringLiteral("steps[0].questions")),
             qPrintable(again.skipped.join(u'\n')));
}

void TestClassResults::lessonFoundByItsName()
{
    // Without a lesson file: the one most files answer, found among the shipped lessons.
    const lessons::ClassCollection c = lessons::collectClass(m_class);
    QVERIFY2(c.ok, qPrintable(c.error));
    QCOMPARE(c.tables.front().lessonFile, QStringLiteral("restitution.json"));
    QCOMPARE(c.tables.front().rows.size(), std::size_t{3});
    // Asked for the other lesson by name: its one student; the restitution files left out.
    lessons::ClassOptions other;
    other.lessonFile = QStringLiteral("tunnelling.json");
    const lessons::ClassCollection t = lessons::collectClass(m_class, other);
    QVERIFY2(t.ok, qPrintable(t.error));
    // Cyril's file names no lesson: it goes with the lesson asked for.
    QCOMPARE(t.tables.front().rows.size(), std::size_t{2});
    QCOMPARE(t.tables.front().rows.back().student, QStringLiteral("Dana Jiná"));
    QCOMPARE(t.skipped.size(), 3); // damaged, Anna's and Bára's
    // A lesson the lab does not have.
    other.lessonFile = QStringLiteral("no_such_lesson.json");
    const lessons::ClassCollection none = lessons::collectClass(m_class, other);
    QVERIFY(!none.ok);
    QVERIFY2(none.error.contains(QStringLiteral("no_such_lesson.json")), qPrintable(none.error));
}

void TestClassResults::everyLessonWhenAsked()
{
    lessons::ClassOptions options;
    options.allLessons = true;
    const lessons::ClassCollection c = lessons::collectClass(m_class, options);
    QVERIFY2(c.ok, qPrintable(c.error));
    QCOMPARE(c.tables.size(), std::size_t{2});
    QCOMPARE(c.tables[0].lessonFile, QStringLiteral("restitution.json"));
    QCOMPARE(c.tables[1].lessonFile, QStringLiteral("tunnelling.json"));
    QCOMPARE(c.tables[1].rows.size(), std::size_t{1});
    QCOMPARE(c.skipped.size(), 1); // only the damaged one
}

void TestClassResults::folderErrors()
{
    const lessons::ClassCollection missing =
        lessons::collectClass(m_dir.filePath(QStringLiteral("nowhere")));
    QVERIFY(!missing.ok);
    QVERIFY2(missing.error.contains(QStringLiteral("no such folder")), qPrintable(missing.error));
    const QString empty = m_dir.filePath(QStringLiteral("empty"));
    QVERIFY(QDir().mkpath(empty));
    const lessons::ClassCollection none = lessons::collectClass(empty);
    QVERIFY(!none.ok);
    QVERIFY2(none.error.contains(QStringLiteral("no answers files")), qPrintable(none.error));
    // Only damaged files: nothing to collect, and each still has its line.
    const QString bad = m_dir.filePath(QStringLiteral("bad"));
    QVERIFY(QDir().mkpath(bad));
    QVERIFY(test::writeFile(QDir(bad).filePath(QStringLiteral("x.answers.json")), "[]"));
    const lessons::ClassCollection unreadable = lessons::collectClass(bad);
    QVERIFY(!unreadable.ok);
    QCOMPARE(unreadable.skipped.size(), 1);
}

void TestClassResults::csvInBothDialects()
{
    lessons::ClassOptions options;
    options.lessonPath = restitution();
    const lessons::ClassCollection c = lessons::collectClass(m_class, options);
    QVERIFY2(c.ok, qPrintable(c.error));
    const lessons::ClassTable& t = c.tables.front();
    const int first = columnOf(t, lessons::ClassColumnKind::FirstAnswer, 0);
    const int verdict = columnOf(t, lessons::ClassColumnKind::Verdict, 0);
    const int tries = columnOf(t, lessons::ClassColumnKind::Tries, 1);
    struct Dialect {
        lessons::CsvDialect dialect;
        const char* language;
        char separator, decimal;
    };
    for (const Dialect d : {Dialect{lessons::CsvDialect::Plain, "en", ',', '.'},
                            Dialect{lessons::CsvDialect::Spreadsheet, "cs", ';', ','}}) {
        const std::string bytes = lessons::classTablesCsv(
            {t}, lessons::csvConventions(d.dialect, QLatin1StringView(d.language)));
        const test::CsvTable csv = test::readCsv(QByteArray::fromStdString(bytes), d.separator);
        QCOMPARE(csv.bom, d.dialect == lessons::CsvDialect::Spreadsheet);
        QCOMPARE(csv.rows.size(), 5); // heads, three students, the summary
        QCOMPARE(csv.rows[0].size(), 3 + 4 * 7);
        QCOMPARE(csv.rows[0][first], QStringLiteral("1.1 first answer [m]"));
        QCOMPARE(csv.rows[1][0], QStringLiteral("Anna Malá"));
        QCOMPARE(test::readNumber(csv.rows[1][first], d.decimal), std::optional<double>(0.41));
        QCOMPARE(test::readNumber(csv.rows[1][tries], d.decimal), std::optional<double>(2));
        QCOMPARE(test::readNumber(csv.rows[2][first], d.decimal), std::optional<double>(0.3));
        // The summary row: the share right at the first answer, in per cent, as a number.
        QCOMPARE(test::readNumber(csv.rows[4][verdict], d.decimal), std::optional<double>(33.3));
    }
}

void TestClassResults::modelKeepsTheSummaryLast()
{
    lessons::ClassOptions options;
    options.lessonPath = restitution();
    const lessons::ClassCollection c = lessons::collectClass(m_class, options);
    QVERIFY2(c.ok, qPrintable(c.error));
    lessons::ClassTableModel model;
    model.setTable(c.tables.front());
    QCOMPARE(model.rowCount(), 4);
    QCOMPARE(model.columnCount(), 3 + 4 * 7);
    QCOMPARE(model.headerData(0, Qt::Horizontal).toString(), QStringLiteral("Name"));
    lessons::ClassTableSorting sorting;
    sorting.setSourceModel(&model);
    const int first = columnOf(c.tables.front(), lessons::ClassColumnKind::FirstAnswer, 0);
    for (const Qt::SortOrder order : {Qt::AscendingOrder, Qt::DescendingOrder}) {
        sorting.sort(first, order);
        QVERIFY(sorting.index(3, 0).data(lessons::ClassTableModel::kSummaryRole).toBool());
        // Numbers as numbers: 0.3 before 0.41; Cyril's empty cell before them both.
        const QStringList names = {sorting.index(0, 0).data().toString(),
                                   sorting.index(1, 0).data().toString(),
                                   sorting.index(2, 0).data().toString()};
        const QStringList ascending = {QStringLiteral("Cyril Starý"), QStringLiteral("Bára Nová"),
                                       QStringLiteral("Anna Malá")};
        QStringList expected = ascending;
        if (order == Qt::DescendingOrder)
            std::reverse(expected.begin(), expected.end());
        QCOMPARE(names, expected);
    }
}

void TestClassResults::cliWritesTheTable()
{
    const test::CliRun run = test::runCli(
        {QStringLiteral("results"), m_class, QStringLiteral("--lesson"), restitution()});
    QVERIFY2(run.exitCode == 0, run.err.constData());
    const QString out = QString::fromLocal8Bit(run.out);
    QVERIFY2(out.contains(QStringLiteral("Anna Malá")) && out.contains(QStringLiteral("Cyril")),
             qPrintable(out));
    QVERIFY2(out.contains(QStringLiteral("33.3 % (1 of 3)")), qPrintable(out));
    const QString err = QString::fromLocal8Bit(run.err);
    QVERIFY2(err.contains(QStringLiteral("skipped: damaged.answers.json: ")), qPrintable(err));
    QVERIFY2(err.contains(QStringLiteral("skipped: other.answers.json: answers to "
                                         "\"tunnelling.json\"")),
             qPrintable(err));
    QCOMPARE(err.count(QStringLiteral("skipped: ")), 2);
    // Asked for: every lesson's table.
    const test::CliRun all =
        test::runCli({QStringLiteral("results"), m_class, QStringLiteral("--all-lessons")});
    QVERIFY2(all.exitCode == 0, all.err.constData());
    QVERIFY2(QString::fromLocal8Bit(all.out).contains(QStringLiteral("Dana Jiná")),
             all.out.constData());
}

void TestClassResults::cliWritesCsvAndPdf()
{
    const QString csvPath = m_dir.filePath(QStringLiteral("class.csv"));
    const test::CliRun csv =
        test::runCli({QStringLiteral("results"), m_class, QStringLiteral("-o"), csvPath,
                      QStringLiteral("--lang"), QStringLiteral("cs")});
    QVERIFY2(csv.exitCode == 0, csv.err.constData());
    QFile file(csvPath);
    QVERIFY(file.open(QIODevice::ReadOnly));
    // --lang cs: the Czech spreadsheet's file, numbers with a decimal comma.
    const test::CsvTable table = test::readCsv(file.readAll(), ';');
    QVERIFY(table.bom);
    QCOMPARE(table.rows.size(), 5);
    QCOMPARE(test::readNumber(table.rows[1][3], ','), std::optional<double>(0.41));
    QCOMPARE(table.rows[1][0], QStringLiteral("Anna Malá"));

    const QString pdfPath = m_dir.filePath(QStringLiteral("class.pdf"));
    const test::CliRun pdf =
        test::runCli({QStringLiteral("results"), m_class, QStringLiteral("-o"), pdfPath});
    QVERIFY2(pdf.exitCode == 0, pdf.err.constData());
    QVERIFY(QFileInfo(pdfPath).size() > 0);
    QFile head(pdfPath);
    QVERIFY(head.open(QIODevice::ReadOnly));
    QCOMPARE(head.read(5), QByteArray("%PDF-"));
    const QString pdftotext = QStandardPaths::findExecutable(QStringLiteral("pdftotext"));
    if (pdftotext.isEmpty()) {
        qWarning("pdftotext not found: the PDF's text is not checked");
        return;
    }
    const test::CliRun text = test::runProgram(pdftotext, {pdfPath, QStringLiteral("-")});
    QCOMPARE(text.exitCode, 0);
    // As a reader searches it: ligatures ("ﬁ") as their letters, table cells' line breaks as
    // spaces.
    const QString words =
        QString::fromUtf8(text.out).normalized(QString::NormalizationForm_KC).simplified();
    for (const QString& expected :
         {QStringLiteral("Anna Malá"), QStringLiteral("Bára Nová"),
          QStringLiteral("Right at the first answer"), QStringLiteral("(1 of 3)"),
          QStringLiteral("damaged.answers.json")})
        QVERIFY2(words.contains(expected), qPrintable(expected + u'\n' + words));
}

void TestClassResults::cliErrors()
{
    struct Case {
        QStringList arguments;
        int exit;
        QString message;
    };
    const QString empty = m_dir.filePath(QStringLiteral("empty-cli"));
    QVERIFY(QDir().mkpath(empty));
    const QString r = QStringLiteral("results");
    const QList<Case> cases = {
        {{r}, 2, QStringLiteral("which folder?")},
        {{r, m_dir.filePath(QStringLiteral("nowhere"))}, 2, QStringLiteral("no such folder")},
        {{r, empty}, 2, QStringLiteral("no answers files")},
        {{r, m_class, QStringLiteral("-o"), QStringLiteral("out.txt")},
         2,
         QStringLiteral("neither .csv nor .pdf")},
        {{r, m_class, QStringLiteral("--csv-dialect"), QStringLiteral("plain")},
         2,
         QStringLiteral("only with -o")},
        {{r, m_class, QStringLiteral("--lang"), QStringLiteral("xx")},
         2,
         QStringLiteral("unknown language")},
        {{r, m_class, QStringLiteral("--colour")}, 2, QStringLiteral("unknown option --colour")},
        {{r, m_class, QStringLiteral("--lesson")}, 2, QStringLiteral("--lesson: needs a")},
        {{r, m_class, QStringLiteral("--lesson"), m_dir.filePath(QStringLiteral("none.json"))},
         2,
         QStringLiteral("none.json")},
        {{r, m_class, QStringLiteral("-o"), m_dir.filePath(QStringLiteral("no/such/out.csv"))},
         1,
         QStringLiteral("cannot write")},
    };
    for (const Case& c : cases) {
        const test::CliRun run = test::runCli(c.arguments);
        const QString err = QString::fromLocal8Bit(run.err);
        QVERIFY2(run.exitCode == c.exit && err.contains(c.message),
                 qPrintable(c.arguments.join(u' ') + QStringLiteral(" → ") +
                            QString::number(run.exitCode) + u' ' + err));
    }
    const test::CliRun help = test::runCli({QStringLiteral("--help")});
    QVERIFY(QString::fromLocal8Bit(help.out).contains(QStringLiteral("results FOLDER")));
}

RIGIDLAB_TEST_GUILESS_MAIN(TestClassResults)
#include "test_class_results.moc"
