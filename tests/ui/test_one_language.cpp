// SPDX-License-Identifier: GPL-3.0-or-later
// A lesson written in one language only, Czech or English, each with a measured question and a
// choice question (hand-made .rlesson files in tests/lessons/data/one_language): played in both
// window languages, its texts shown in the language it has, a Check before the run gets there
// kept as no answer, its hint after a wrong one, handed in, its run stopping at its end time; in
// the lesson editor it opens with no error, the lab's measured answer shown, its step's scene
// sent to the window and tried as a student without a dialog (its copy its own: another
// editor's try does not replace it), saved and reopened unchanged.

#include "common/language.h"
#include "first_question.h"
#include "lesson_editor/lesson_editor.h"
#include "lesson_editor/question_editor.h"
#include "lesson_player/lesson_player.h"
#include "simulation/simulation_controller.h"
#include "window/main_window.h"

#include "format/lesson.h"
#include "run/measurements.h"

#include "test_main.h"

#include <QFile>
#include <QLabel>
#include <QLocale>
#include <QMessageBox>
#include <QPushButton>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

using namespace rigidlab;

namespace {

const QString kData = QStringLiteral(RIGIDLAB_SOURCE_DIR "/tests/lessons/data/one_language/");

QByteArray fileBytes(const QString& path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

} // namespace

class TestOneLanguage : public QObject {
    Q_OBJECT
private slots:
    void cleanupTestCase() { ui::applyLanguage(QStringLiteral("en")); }
    void playedInBothLanguages_data();
    void playedInBothLanguages();
    void editedWithoutADialog_data() { playedInBothLanguages_data(); }
    void editedWithoutADialog();
};

void TestOneLanguage::playedInBothLanguages_data()
{
    QTest::addColumn<QString>("file");
    QTest::addColumn<QString>("window"); // the window's language
    QTest::addColumn<QString>("title");  // the lesson's, in the one language it has
    QTest::addColumn<QString>("hint");   // its measured question's
    for (const QString& window : {QStringLiteral("cs"), QStringLiteral("en")}) {
        QTest::addRow("czech-only-%s", qPrintable(window))
            << QStringLiteral("czech_only.rlesson") << window
            << QStringLiteral("Srážka dvou vozíků") << QStringLiteral("Hybnost se zachovává.");
        QTest::addRow("english-only-%s", qPrintable(window))
            << QStringLiteral("english_only.rlesson") << window
            << QStringLiteral("Two carts collide") << QStringLiteral("Momentum is kept.");
    }
}

void TestOneLanguage::playedInBothLanguages()
{
    QFETCH(QString, file);
    QFETCH(QString, window);
    QFETCH(QString, title);
    QFETCH(QString, hint);
    QVERIFY(ui::applyLanguage(window));
    ui::MainWindow w;
    w.setUnsavedAsker([] { return int(QMessageBox::Discard); });
    QCOMPARE(w.openLesson(kData + file, true), QString());
    ui::LessonPlayer& player = w.lessonPlayer();
    QCOMPARE(player.lesson()->title, title);
    QVERIFY(w.windowTitle().startsWith(title));
    // The step waits for Play, and its run stops at its end time.
    QVERIFY(!w.controller().isRunning());

    // A Check before the run gets to t = 2 s says so and is no answer: nothing is kept.
    player.answer(0, QStringLiteral("5"));
    QVERIFY2(!player.result(0).isEmpty(), "the premature Check says what to do");
    QCOMPARE(player.work().tries.at(0).size(), std::size_t{0});

    const MeasuredQuestion measured = runToFirstQuestion(w);
    QCOMPARE(measured.step, 0);
    QVERIFY(measured.value.has_value());
    // Elastic: the heavy cart (3 kg) leaves at 2·1/(1 + 3) · 2 m/s = 1 m/s.
    QVERIFY2(std::abs(*measured.value - 1.0) < 0.02, qPrintable(QString::number(*measured.value)));
    player.answer(0, QLocale().toString(*measured.value * 3 + 1));
    QVERIFY2(player.result(0).contains(hint), qPrintable(player.result(0)));
    player.answer(0, QLocale().toString(*measured.value, 'g', 8));
    // The second try, judged again as the player judged it: right.
    const ui::StepWork work = player.work();
    const std::vector<lessons::AnswerTry>& tries = work.tries.at(0);
    QCOMPARE(tries.size(), std::size_t{2});
    lessons::TryCount count{1, false};
    const lessons::Question& question = player.lesson()->steps.front().questions.front();
    QVERIFY2(lessons::judgeTry(question, tries.back(), count).right, qPrintable(player.result(0)));
    player.choose(1, 2);
    QVERIFY2(player.result(1).startsWith(u'✓'), qPrintable(player.result(1)));

    QTemporaryDir dir;
    QCOMPARE(player.handIn(dir.filePath(QStringLiteral("sheet.pdf"))), QString());
    QVERIFY(QFileInfo(dir.filePath(QStringLiteral("sheet.pdf"))).size() > 0);

    // Played on, the run stops at the step's end time (3 s), within one step of it; Play
    // there runs on.
    ui::SimulationController& c = w.controller();
    c.setRunning(true);
    for (int frame = 0; frame < 2000 && c.isRunning(); ++frame)
        c.advanceClock(1.0 / 60);
    QVERIFY(!c.isRunning());
    const double dt = c.world().def().dt;
    QVERIFY2(std::abs(c.world().time() - 3.0) <= dt,
             qPrintable(QStringLiteral("stopped at %1 s, end time 3 s, dt %2 s")
                            .arg(c.world().time())
                            .arg(dt)));
    c.setRunning(true);
    c.advanceClock(1.0 / 60);
    QVERIFY(c.isRunning());
    QVERIFY(c.world().time() > 3.0 + dt / 2);
}

void TestOneLanguage::editedWithoutADialog()
{
    QFETCH(QString, file);
    QFETCH(QString, window);
    QFETCH(QString, title);
    QVERIFY(ui::applyLanguage(window));
    ui::LessonEditor editor;
    QCOMPARE(editor.open(kData + file), QString());
    auto* problems = editor.findChild<QLabel*>(QStringLiteral("lessonProblems"));
    QVERIFY(problems != nullptr);
    // A warning, not an error: the lesson loads.
    QVERIFY2(problems->text().contains(
                 QStringLiteral("(\"%1\")").arg(file.startsWith(u"czech") ? u"en" : u"cs")),
             qPrintable(problems->text()));
    QString error;
    QVERIFY2(editor.draft().lesson(window, error).has_value(), qPrintable(error));

    // The lab's measured answer, and the choice's without the word "measure".
    auto* answer = editor.findChild<QLabel*>(QStringLiteral("questionAnswer"));
    QVERIFY(answer != nullptr);
    QVERIFY2(!answer->text().startsWith(u'⚠'), qPrintable(answer->text()));

    // The step's scene goes to the window, and the lesson is tried, without a dialog.
    QSignalSpy scene(&editor, &ui::LessonEditor::editStepScene);
    QSignalSpy tried(&editor, &ui::LessonEditor::tryAsStudent);
    QTest::mouseClick(editor.findChild<QPushButton*>(QStringLiteral("editStepScene")),
                      Qt::LeftButton);
    QCOMPARE(scene.count(), 1);
    QCOMPARE(qvariant_cast<lessons::Scene>(scene.front().front()).bodies.size(), std::size_t{2});
    QTest::mouseClick(editor.findChild<QPushButton*>(QStringLiteral("tryAsStudent")),
                      Qt::LeftButton);
    QCOMPARE(tried.count(), 1);
    const QString triedPath = tried.front().front().toString();
    const lessons::LessonLoadResult played = lessons::loadLessonFile(triedPath, {window});
    QVERIFY2(played.ok, qPrintable(played.error));
    QCOMPARE(played.lesson.title, title);
    // Another editor trying its lesson meanwhile (another teacher's, or a test running beside
    // this one) does not write over the copy this one's student plays.
    ui::LessonEditor other;
    const QString otherFile = file.startsWith(u"czech") ? QStringLiteral("english_only.rlesson")
                                                        : QStringLiteral("czech_only.rlesson");
    QCOMPARE(other.open(kData + otherFile), QString());
    QSignalSpy otherTried(&other, &ui::LessonEditor::tryAsStudent);
    QTest::mouseClick(other.findChild<QPushButton*>(QStringLiteral("tryAsStudent")),
                      Qt::LeftButton);
    QCOMPARE(otherTried.count(), 1);
    QVERIFY2(otherTried.front().front().toString() != triedPath, qPrintable(triedPath));
    const lessons::LessonLoadResult replayed = lessons::loadLessonFile(triedPath, {window});
    QVERIFY2(replayed.ok, qPrintable(replayed.error));
    QCOMPARE(replayed.lesson.title, title);

    // Saved, reopened and saved again: the same file.
    QTemporaryDir dir;
    const QString first = dir.filePath(QStringLiteral("first.rlesson"));
    const QString second = dir.filePath(QStringLiteral("second.rlesson"));
    QCOMPARE(editor.saveAs(first), QString());
    ui::LessonEditor reopened;
    QCOMPARE(reopened.open(first), QString());
    QCOMPARE(reopened.saveAs(second), QString());
    QCOMPARE(fileBytes(second), fileBytes(first));
    const lessons::LessonLoadResult saved = lessons::loadLessonFile(second, {window});
    QVERIFY2(saved.ok, qPrintable(saved.error));
    QCOMPARE(saved.lesson.title, title);
    QCOMPARE(saved.lesson.steps.front().questions.size(), std::size_t{2});
}

RIGIDLAB_TEST_MAIN(TestOneLanguage)
#include "test_one_language.moc"
