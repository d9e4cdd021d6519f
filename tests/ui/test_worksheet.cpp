// SPDX-License-Identifier: GPL-3.0-or-later
// The worksheet: a student answers a lesson's questions in the window (some right, some wrong,
// one shown) and hands in; the PDF is read back by poppler's pdftotext, a reader independent of
// the writer, and must hold the name, the class, the title, every question, every answer with
// the verdict the window showed, in the language played, one vector figure per plot of each
// step, and embedded fonts. The answers file saved beside it makes the same sheet through
// rigidlab-cli; the empty sheet and the teacher's key are checked likewise.

#include "build_paths.h"
#include "common/display_names.h"
#include "common/language.h"
#include "common/number_format.h"
#include "common/shortcuts.h"
#include "lesson_player/lesson_player.h"
#include "simulation/simulation_controller.h"
#include "window/main_window.h"
#include "worksheet/worksheet.h"
#include "worksheet/worksheet_plots.h"

#include "format/answers_file.h"
#include "format/lesson.h"
#include "run/measurements.h"

#include "test_main.h"

#include "question_kinds.h"
#include <QAction>
#include <QDir>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QProcess>
#include <QPushButton>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

using rigidlab::test::measuredOf;

using namespace rigidlab;

namespace {

const QString kLessonPath = rigidlab::test::sourcePath(u"/lessons/lessons/restitution.json");

struct Tool {
    int exitCode = -1;
    QString out;
    QString err;
};

Tool runTool(const QString& program, const QStringList& arguments)
{
    QProcess process;
    process.start(program, arguments);
    Tool run;
    if (!process.waitForFinished(120000))
        return run;
    run.exitCode = process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -2;
    run.out = QString::fromUtf8(process.readAllStandardOutput());
    run.err = QString::fromUtf8(process.readAllStandardError());
    return run;
}

/// Text as compared: compatibility forms folded (the PDF's "ﬁ" ligature, no-break spaces),
/// word joiners dropped, every run of white space one space (lines wrap anywhere).
QString flat(QString text)
{
    text = text.normalized(QString::NormalizationForm_KC);
    text.remove(QChar(0x2060));
    text.replace(QRegularExpression(QStringLiteral("\\s+")), QStringLiteral(" "));
    return text.trimmed();
}

/// The PDF's text as pdftotext reads it, flattened.
QString pdfText(const QString& pdf)
{
    const Tool run =
        runTool(QStringLiteral("pdftotext"),
                {QStringLiteral("-enc"), QStringLiteral("UTF-8"), pdf, QStringLiteral("-")});
    return run.exitCode == 0 ? flat(run.out) : QString();
}

/// Raster images in the PDF (pdfimages -list): the figures must be vectors, so none.
int rasterImages(const QString& pdf)
{
    const Tool run = runTool(QStringLiteral("pdfimages"), {QStringLiteral("-list"), pdf});
    if (run.exitCode != 0)
        return -1;
    return static_cast<int>(run.out.split(u'\n', Qt::SkipEmptyParts).size()) - 2; // 2 head lines
}

/// Every font of the PDF embedded (pdffonts' "emb" column); false when there is none.
bool fontsEmbedded(const QString& pdf)
{
    const Tool run = runTool(QStringLiteral("pdffonts"), {pdf});
    const QStringList lines = run.out.split(u'\n', Qt::SkipEmptyParts);
    if (run.exitCode != 0 || lines.size() < 3)
        return false;
    for (const QString& line : lines.mid(2))
        if (!line.contains(
                QRegularExpression(QStringLiteral("\\byes\\s+(yes|no)\\s+(yes|no)\\s+\\d+"))))
            return false;
    return true;
}

/// Every page A4 portrait (pdfinfo of the first and the last page).
bool pagesAreA4(const QString& pdf)
{
    const Tool run =
        runTool(QStringLiteral("pdfinfo"), {QStringLiteral("-f"), QStringLiteral("1"),
                                            QStringLiteral("-l"), QStringLiteral("1000"), pdf});
    const QStringList sizes =
        run.out.split(u'\n').filter(QRegularExpression(QStringLiteral("^Page +\\d+ size:")));
    if (run.exitCode != 0 || sizes.isEmpty())
        return false;
    for (const QString& line : sizes)
        if (!line.contains(QStringLiteral("595.28 x 841.89 pts (A4)")) &&
            !line.contains(QStringLiteral("595 x 842 pts (A4)")))
            return false;
    return true;
}

/// How many figures of step `step` (1-based) the text captions: "Figure 2.1:", "Figure 2.2:"…
int figuresOfStep(const QString& text, const QString& word, int step)
{
    int count = 0;
    while (text.contains(QStringLiteral("%1 %2.%3:").arg(word).arg(step).arg(count + 1)))
        ++count;
    return count;
}

/// The measured value a question is judged against, as the window will measure it.
std::optional<double> expectedValue(const lessons::LessonStep& step, const lessons::Question& q)
{
    // On the run the question asks for (its "set" on top of the step's settings).
    return lessons::measureAhead(lessons::askedStep(step, q), measuredOf(q).measure);
}

/// Answers every question of the open lesson, step by step, in turn: a wrong try then a right
/// one, two wrong tries, "Show me". Returns each message the window showed, in order; empty
/// when a question could not be measured or a kind of verdict was never given.
QStringList answerEveryQuestion(ui::MainWindow& w)
{
    ui::LessonPlayer& player = w.lessonPlayer();
    const lessons::Lesson& lesson = *player.lesson();
    QStringList messages;
    int pattern = 0;
    std::array<int, 3> used{0, 0, 0}; // tries of each pattern
    for (int s = 0; s < static_cast<int>(lesson.steps.size()); ++s) {
        player.goToStep(s);
        const lessons::LessonStep& step = lesson.steps[static_cast<std::size_t>(s)];
        // A step that holds back its run judges by a run without the window.
        const bool held = player.heldBack().contains(QStringLiteral("run"));
        for (int k = 0; k < 20000 && !held; ++k)
            w.controller().stepForward();
        for (int q = 0; q < static_cast<int>(step.questions.size()); ++q, ++pattern) {
            const std::optional<double> value =
                expectedValue(step, step.questions[static_cast<std::size_t>(q)]);
            if (!value)
                return {};
            const QString right = QLocale().toString(*value, 'g', 8);
            const QString wrong = QLocale().toString(*value * 3 + 1, 'g', 8);
            if (pattern % 3 == 2) {
                player.showMe(q);
            } else {
                player.answer(q, wrong);
                messages << player.result(q);
                player.answer(q, pattern % 3 == 0 ? right : wrong);
            }
            used[static_cast<std::size_t>(pattern % 3)]++;
            messages << player.result(q);
        }
    }
    for (int n : used)
        if (n == 0)
            return {};
    return messages;
}

} // namespace

class TestWorksheet : public QObject {
    Q_OBJECT
private slots:
    void init() { QVERIFY(ui::applyLanguage(QStringLiteral("en"))); }
    void cleanupTestCase() { ui::applyLanguage(QStringLiteral("en")); }
    void handInAfterAnswering_data();
    void handInAfterAnswering();
    void emptySheetAndKey_data() { handInAfterAnswering_data(); }
    void emptySheetAndKey();
    void handInNeedsAPlaceToWrite();
    void cliRefusesDamagedAnswers();
    void nameAndHandInAreReachable();
    void prematureCheckIsNoAnswer();
    void solverLineNamesTheSolverThatRan();
    void stepFigureIsTheAskedRun();
};

void TestWorksheet::handInAfterAnswering_data()
{
    QTest::addColumn<QString>("language");
    QTest::addColumn<QString>("figure");
    QTest::addColumn<QStringList>("verdicts"); // right, not right, shown
    QTest::newRow("en") << QStringLiteral("en") << QStringLiteral("Figure")
                        << QStringList{QStringLiteral("✓ right"), QStringLiteral("✗ not right"),
                                       QStringLiteral("◆ shown")};
    QTest::newRow("cs") << QStringLiteral("cs") << QStringLiteral("Obrázek")
                        << QStringList{QStringLiteral("✓ správně"), QStringLiteral("✗ nesprávně"),
                                       QStringLiteral("◆ ukázáno")};
}

void TestWorksheet::handInAfterAnswering()
{
    QFETCH(QString, language);
    QFETCH(QString, figure);
    QFETCH(QStringList, verdicts);
    QVERIFY(ui::applyLanguage(language));
    QTemporaryDir dir;
    QVERIFY(dir.isValid());

    ui::MainWindow w;
    QCOMPARE(w.openLesson(kLessonPath, true), QString());
    ui::LessonPlayer& player = w.lessonPlayer();
    player.setStudent(QStringLiteral("Jana Nováková"), QStringLiteral("2.B"));
    const lessons::Lesson& lesson = *player.lesson();
    QVERIFY(lesson.steps.size() >= 3);

    // Per step, its questions in turn: a wrong try then a right one, two wrong tries, "Show
    // me"; each message the window shows is what the sheet must say.
    const QStringList messages = answerEveryQuestion(w);
    QVERIFY(!messages.isEmpty());

    const QString pdf = dir.filePath(QStringLiteral("sheet.pdf"));
    QCOMPARE(player.handIn(pdf), QString());
    const QString text = pdfText(pdf);
    QVERIFY2(!text.isEmpty(), "pdftotext read nothing (is poppler-utils installed?)");
    for (const QString& expected :
         {QStringLiteral("Jana Nováková"), QStringLiteral("2.B"), lesson.title})
        QVERIFY2(text.contains(flat(expected)), qPrintable(expected));
    for (const QString& message : messages) {
        QVERIFY(!message.isEmpty());
        QVERIFY2(text.contains(flat(message)), qPrintable(message + QStringLiteral("\n\n") + text));
    }
    for (const QString& verdict : verdicts)
        QVERIFY2(text.contains(verdict), qPrintable(verdict));
    for (int s = 0; s < static_cast<int>(lesson.steps.size()); ++s) {
        const lessons::LessonStep& step = lesson.steps[static_cast<std::size_t>(s)];
        QVERIFY2(text.contains(flat(step.title)), qPrintable(step.title));
        for (const lessons::Question& q : step.questions)
            QVERIFY2(text.contains(flat(lessons::keepUnitsTogether(q.prompt))),
                     qPrintable(q.prompt));
        QCOMPARE(figuresOfStep(text, figure, s + 1), static_cast<int>(step.plots.size()));
    }
    QCOMPARE(rasterImages(pdf), 0);
    QVERIFY(fontsEmbedded(pdf));
    QVERIFY(pagesAreA4(pdf));

    // The answers file beside it reads back, and makes the same sheet without the window.
    const QString answersPath = ui::answersPathFor(pdf);
    const lessons::AnswersLoadResult saved = lessons::loadAnswersFile(answersPath);
    QVERIFY2(saved.ok, qPrintable(saved.error));
    QCOMPARE(saved.answers.student, QStringLiteral("Jana Nováková"));
    QCOMPARE(saved.answers.language, language);
    const QString again = dir.filePath(QStringLiteral("again.pdf"));
    const Tool cli = runTool(rigidlab::test::cliPath(),
                             {QStringLiteral("lesson"), kLessonPath, QStringLiteral("--worksheet"),
                              again, QStringLiteral("--answers"), answersPath});
    QVERIFY2(cli.exitCode == 0, qPrintable(cli.err));
    QCOMPARE(pdfText(again), text);
}

void TestWorksheet::emptySheetAndKey()
{
    QFETCH(QString, language);
    QFETCH(QString, figure);
    QFETCH(QStringList, verdicts);
    QVERIFY(ui::applyLanguage(language));
    QTemporaryDir dir;
    const lessons::LessonLoadResult loaded =
        lessons::loadLessonFile(kLessonPath, lessons::LessonLoadOptions{language});
    QVERIFY2(loaded.ok, qPrintable(loaded.error));
    const lessons::Lesson& lesson = loaded.lesson;

    const QString empty = dir.filePath(QStringLiteral("empty.pdf"));
    const QString key = dir.filePath(QStringLiteral("key.pdf"));
    const ui::WorksheetResult e =
        ui::writeWorksheet(lesson, lessons::Answers{}, ui::WorksheetKind::Empty, empty);
    QVERIFY2(e.ok, qPrintable(e.error));
    const ui::WorksheetResult k =
        ui::writeWorksheet(lesson, lessons::Answers{}, ui::WorksheetKind::Key, key);
    QVERIFY2(k.ok, qPrintable(k.error));
    const QString emptyText = pdfText(empty);
    const QString keyText = pdfText(key);
    QVERIFY(!emptyText.isEmpty() && !keyText.isEmpty());
    for (int s = 0; s < static_cast<int>(lesson.steps.size()); ++s) {
        const lessons::LessonStep& step = lesson.steps[static_cast<std::size_t>(s)];
        const int plots = static_cast<int>(step.plots.size());
        QCOMPARE(e.figures.at(static_cast<std::size_t>(s)), plots);
        QCOMPARE(k.figures.at(static_cast<std::size_t>(s)), plots);
        QCOMPARE(figuresOfStep(emptyText, figure, s + 1), plots);
        QCOMPARE(figuresOfStep(keyText, figure, s + 1), plots);
        for (const lessons::Question& q : step.questions) {
            const QString prompt = flat(lessons::keepUnitsTogether(q.prompt));
            QVERIFY2(emptyText.contains(prompt), qPrintable(prompt));
            QVERIFY2(keyText.contains(prompt), qPrintable(prompt));
            // The key gives the value the run measures, as the window writes it.
            const std::optional<double> value = expectedValue(step, q);
            QVERIFY(value);
            const QString measured = flat(ui::formatQuantity(*value, measuredOf(q).unit));
            QVERIFY2(keyText.contains(measured),
                     qPrintable(measured + QStringLiteral("\n") + keyText));
            QVERIFY2(!emptyText.contains(measured), qPrintable(measured));
        }
    }
    for (const QString& verdict : verdicts) {
        QVERIFY(!emptyText.contains(verdict));
        QVERIFY(!keyText.contains(verdict));
    }
    QCOMPARE(rasterImages(empty), 0);
    QCOMPARE(rasterImages(key), 0);
    QVERIFY(fontsEmbedded(empty) && fontsEmbedded(key));
    QVERIFY(pagesAreA4(empty) && pagesAreA4(key));

    // rigidlab-cli makes the same two sheets.
    for (const auto& [file, text, extra] :
         {std::tuple{QStringLiteral("cli-empty.pdf"), emptyText, QStringList{}},
          std::tuple{QStringLiteral("cli-key.pdf"), keyText,
                     QStringList{QStringLiteral("--key")}}}) {
        const QString out = dir.filePath(file);
        const Tool cli =
            runTool(rigidlab::test::cliPath(), QStringList{QStringLiteral("lesson"), kLessonPath,
                                                           QStringLiteral("--worksheet"), out,
                                                           QStringLiteral("--lang"), language} +
                                                   extra);
        QVERIFY2(cli.exitCode == 0, qPrintable(cli.err));
        QCOMPARE(pdfText(out), text);
    }
}

void TestWorksheet::handInNeedsAPlaceToWrite()
{
    // A folder that does not exist: an error naming the file, and nothing written.
    ui::MainWindow w;
    QCOMPARE(w.openLesson(kLessonPath, true), QString());
    QTemporaryDir dir;
    const QString pdf = dir.filePath(QStringLiteral("missing/sheet.pdf"));
    const QString error = w.lessonPlayer().handIn(pdf);
    QVERIFY2(error.contains(QStringLiteral("sheet.pdf")), qPrintable(error));
    QVERIFY(!QFile::exists(pdf));
    QVERIFY(!QFile::exists(ui::answersPathFor(pdf)));
}

void TestWorksheet::cliRefusesDamagedAnswers()
{
    // A damaged answers file, or one of another lesson: the file and the place named, the
    // exit code of bad input, and no PDF.
    QTemporaryDir dir;
    const QString out = dir.filePath(QStringLiteral("sheet.pdf"));
    const QList<std::pair<QByteArray, QString>> cases{
        {R"({"rigidlab-answers": 1, "lesson": "restitution.json", "steps": [{"dt": -0.01}]})",
         QStringLiteral("steps[0].dt: must be a positive number")},
        {R"({"rigidlab-answers": 1, "lesson": "restitution.json", "steps": [{}, {}, {}, {}, {}, {}]})",
         QStringLiteral("steps: 6 steps, the lesson has 4")},
        {R"({"rigidlab-answers": 1, "lesson": "restitution.json", "steps": [{"questions": [{}, {}, {}]}]})",
         QStringLiteral("steps[0].questions: 3 questions, the lesson's step 1 has 2")},
        {"{\"rigidlab-answers\": 1, \"lesson\"", QStringLiteral("line 1")},
        {R"({"rigidlab-answers": 1, "lesson": "r.json", "steps": [{}]})",
         QStringLiteral(R"(answers to "r.json", not to "restitution.json")")},
    };
    for (const auto& [bytes, message] : cases) {
        const QString answers = dir.filePath(QStringLiteral("bad.answers.json"));
        QFile file(answers);
        QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
        file.write(bytes);
        file.close();
        const Tool cli = runTool(rigidlab::test::cliPath(), {QStringLiteral("lesson"), kLessonPath,
                                                             QStringLiteral("--worksheet"), out,
                                                             QStringLiteral("--answers"), answers});
        QVERIFY2(cli.exitCode == 2, qPrintable(QString::number(cli.exitCode) + cli.err));
        QVERIFY2(cli.err.contains(answers + QStringLiteral(": ")), qPrintable(cli.err));
        QVERIFY2(cli.err.contains(message), qPrintable(cli.err));
        QVERIFY(!QFile::exists(out));
    }
}

void TestWorksheet::nameAndHandInAreReachable()
{
    // The name and class have accessible names and labels that lead to them (Alt+letter);
    // Hand in has a key, listed in Help › Controls, and on the last step says it finishes.
    ui::MainWindow w;
    QCOMPARE(w.openLesson(kLessonPath, true), QString());
    for (const char* name : {"studentName", "studentClass"}) {
        auto* field = w.findChild<QLineEdit*>(QLatin1String(name));
        QVERIFY2(field && field->isVisibleTo(&w), name);
        QVERIFY(!field->accessibleName().isEmpty());
        bool labelled = false;
        for (QLabel* label : w.findChildren<QLabel*>())
            labelled = labelled || (label->buddy() == field && label->text().contains(u'&'));
        QVERIFY2(labelled, name);
    }
    auto* handIn = w.findChild<QPushButton*>(QStringLiteral("handIn"));
    QVERIFY(handIn && handIn->isVisibleTo(&w));
    QVERIFY(!handIn->shortcut().isEmpty());
    QCOMPARE(handIn->shortcut(), ui::controlKeys("handIn").value(0));
    QVERIFY(
        ui::controlsHelpHtml({}).contains(handIn->shortcut().toString(QKeySequence::NativeText)));
    const QString early = handIn->text();
    w.lessonPlayer().goToStep(static_cast<int>(w.lessonPlayer().lesson()->steps.size()) - 1);
    QVERIFY(handIn->text() != early);
    // The teacher's sheets are in the File menu while a lesson is open.
    for (const char* name : {"emptyWorksheet", "worksheetKey"}) {
        auto* action = w.findChild<QAction*>(QLatin1String(name));
        QVERIFY2(action && action->isEnabled(), name);
        QVERIFY(action->text().contains(u'&'));
    }
    // The name typed is kept for the session: a new window shows it.
    w.lessonPlayer().setStudent(QStringLiteral("Petr"), QStringLiteral("3.A"));
    ui::MainWindow other;
    QCOMPARE(other.findChild<QLineEdit*>(QStringLiteral("studentName"))->text(),
             QStringLiteral("Petr"));
    QCOMPARE(other.lessonPlayer().student(), QStringLiteral("Petr"));
    QVERIFY(!other.findChild<QAction*>(QStringLiteral("worksheetKey"))->isEnabled()); // no lesson
}

void TestWorksheet::prematureCheckIsNoAnswer()
{
    // A Check before the run gets to the time asked says what to do, and the sheet lists only
    // the answer judged later.
    ui::MainWindow w;
    const QString path =
        rigidlab::test::sourcePath(u"/tests/lessons/data/one_language/english_only.rlesson");
    QCOMPARE(w.openLesson(path, true), QString());
    ui::LessonPlayer& player = w.lessonPlayer();
    player.setStudent(QStringLiteral("Jana Nováková"), QStringLiteral("2.B"));
    const lessons::LessonStep& step = player.lesson()->steps.front();
    player.answer(0, QStringLiteral("777"));
    QVERIFY2(player.result(0).contains(QStringLiteral("first")), qPrintable(player.result(0)));
    std::optional<double> value;
    for (int k = 0; k < 20000 && !value; ++k) {
        w.controller().stepForward();
        value = w.controller().lessonWatch().measurements().value(
            measuredOf(step.questions[0]).measure, step.scene);
    }
    QVERIFY(value.has_value());
    player.answer(0, QLocale().toString(*value, 'g', 8));
    QVERIFY2(player.result(0).startsWith(QStringLiteral("Right")), qPrintable(player.result(0)));
    QTemporaryDir dir;
    const QString pdf = dir.filePath(QStringLiteral("sheet.pdf"));
    QCOMPARE(player.handIn(pdf), QString());
    const QString text = pdfText(pdf);
    QVERIFY2(!text.isEmpty(), "pdftotext read nothing (is poppler-utils installed?)");
    QVERIFY2(!text.contains(QStringLiteral("777")), qPrintable(text));
    QVERIFY2(text.contains(QStringLiteral("✓ right")), qPrintable(text));
}

void TestWorksheet::solverLineNamesTheSolverThatRan()
{
    // Each step's settings line names the solver that ran, and the one asked for where another
    // stood in for it (none does since the soft step takes springs, joints and every
    // integrator; the lessons' steps with springs and other integrators are among these).
    int checked = 0;
    for (const QString& file :
         {QStringLiteral("restitution.json"), QStringLiteral("stacks.json")}) {
        const lessons::LessonLoadResult loaded =
            lessons::loadLessonFile(rigidlab::test::sourcePath(u"/lessons/lessons/") + file);
        QVERIFY2(loaded.ok, qPrintable(loaded.error));
        QTemporaryDir dir;
        const QString pdf = dir.filePath(QStringLiteral("empty.pdf"));
        const ui::WorksheetResult r =
            ui::writeWorksheet(loaded.lesson, lessons::Answers{}, ui::WorksheetKind::Empty, pdf);
        QVERIFY2(r.ok, qPrintable(r.error));
        const QString text = pdfText(pdf);
        for (const lessons::LessonStep& step : loaded.lesson.steps) {
            if (step.compare && !step.compare->solvers.empty())
                continue; // the compared solvers are named instead
            const physics::World world = lessons::buildStepWorlds(step).front();
            const QString expected =
                QStringLiteral("solver ") + ui::solverDisplayName(world.def().solver);
            ++checked;
            QVERIFY2(text.contains(flat(expected)), qPrintable(expected + u'\n' + text));
        }
    }
    QVERIFY2(checked > 0, "no step of these lessons names a solver: the check is empty");
}

void TestWorksheet::stepFigureIsTheAskedRun()
{
    // Step 3 of the restitution lesson asks "set e = 0 and run again": once the student has
    // answered it, the sheet's figure and settings line are of that run, not the step's e = 0.5.
    const lessons::LessonLoadResult loaded = lessons::loadLessonFile(kLessonPath);
    QVERIFY2(loaded.ok, qPrintable(loaded.error));
    const lessons::Lesson& lesson = loaded.lesson;
    QVERIFY(lesson.steps.size() >= 3);
    const lessons::LessonStep& step = lesson.steps[2];
    const auto asking =
        std::find_if(step.questions.begin(), step.questions.end(), [](const lessons::Question& q) {
            const auto* measured = q.as<lessons::MeasuredQuestion>();
            return measured && measured->set.has("restitution");
        });
    QVERIFY(asking != step.questions.end());
    QCOMPARE(*measuredOf(*asking).set.get<double>("restitution"), 0.0);
    QCOMPARE(step.settings.get<double>("restitution").value_or(-1), 0.5);

    lessons::Answers answers;
    answers.student = QStringLiteral("Jana Nováková");
    answers.steps.resize(lesson.steps.size());
    lessons::StepAnswers& third = answers.steps[2];
    third.questions.resize(step.questions.size());
    const auto q = static_cast<std::size_t>(asking - step.questions.begin());
    const std::optional<double> value = expectedValue(step, *asking);
    QVERIFY(value.has_value());
    third.questions[q].push_back(lessons::AnswerTry{*value, value, false, std::nullopt, {}, false});
    QCOMPARE(ui::stepAsRun(step, third).settings.get<double>("restitution").value_or(-1), 0.0);
    QCOMPARE(ui::stepAsRun(step, lessons::StepAnswers{})
                 .settings.get<double>("restitution")
                 .value_or(-1),
             0.5);

    QTemporaryDir dir;
    const QString pdf = dir.filePath(QStringLiteral("sheet.pdf"));
    const ui::WorksheetResult r =
        ui::writeWorksheet(lesson, answers, ui::WorksheetKind::Answers, pdf);
    QVERIFY2(r.ok, qPrintable(r.error));
    const QString text = pdfText(pdf);
    const qsizetype at = text.indexOf(QStringLiteral("Step 3:"));
    QVERIFY2(at >= 0, qPrintable(text));
    const QString settings = text.mid(at, text.indexOf(QStringLiteral("Step 4:"), at) - at);
    QVERIFY2(settings.contains(QStringLiteral("Restitution e = 0 ")) ||
                 settings.contains(QStringLiteral("Restitution e = 0\n")),
             qPrintable(settings));
}

RIGIDLAB_TEST_MAIN(TestWorksheet)
#include "test_worksheet.moc"
