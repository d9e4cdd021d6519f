// SPDX-License-Identifier: GPL-3.0-or-later
// The lesson editor's lesson (ui/lesson_editor/lesson_draft.h), driven as a teacher would:
// a new lesson on a scene, steps added, texts written in both languages, a measured question
// and a predict-before-reveal one, a control locked, edits undone and redone, the problems
// the loader finds shown per step, saved, opened again, played in the window; and the saved
// .rlesson exports the same plots as the same lesson written by hand. A shipped lesson
// opened and saved unchanged is the same lesson.

#include "test_lesson_editor.h"

#include "test_main.h"

namespace {

/// The lesson the test writes with the editor, as a teacher would write it by hand.
QByteArray handWritten()
{
    return R"({
  "rigidlab-lesson": 1,
  "title": {"en": "Drops", "cs": "Pády"},
  "summary": {"en": "Balls bounce.", "cs": "Míčky skáčou."},
  "minutes": 15,
  "steps": [
    {"title": {"en": "Watch", "cs": "Sledujte"},
     "text": {"en": ["Line one.", "Line two."], "cs": ["Řádek jedna.", "Řádek dva."]},
     "scene": "scenes/four_balls.json", "plots": ["energy"], "allow": ["timeScale"],
     "exportTime": 2},
    {"title": {"en": "Measure", "cs": "Změřte"},
     "text": {"en": "Measure the first bounce.", "cs": "Změřte první odskok."},
     "scene": "scenes/four_balls.json", "plots": ["energy", "drift"], "exportTime": 3,
     "questions": [{"prompt": {"en": "How high?", "cs": "Jak vysoko?"},
                    "measure": {"kind": "apex", "body": "e08", "n": 1, "above": 0.1},
                    "unit": "m", "tolerance": 0.05}]},
    {"title": {"en": "Predict", "cs": "Předpovězte"},
     "text": {"en": "First predict.", "cs": "Nejdřív předpovězte."},
     "scene": "scenes/four_balls.json", "plots": ["momentum"], "exportTime": 2,
     "questions": [{"prompt": {"en": "Speed at 1 s?", "cs": "Rychlost v čase 1 s?"},
                    "measure": {"kind": "speed", "body": "e08", "time": 1},
                    "unit": "m/s", "holdBack": ["run"]}]}
  ]
})";
}

QJsonObject parsed(const char* json)
{
    return QJsonDocument::fromJson(QByteArray(json)).object();
}

/// Writes a step's texts in both languages, as the editor's side-by-side fields do.
void writeStep(LessonDraft& d, int step, const char* enTitle, const char* csTitle,
               const QString& enText, const QString& csText)
{
    d.setText(step, QStringLiteral("title"), QStringLiteral("en"), QString::fromUtf8(enTitle));
    d.setText(step, QStringLiteral("title"), QStringLiteral("cs"), QString::fromUtf8(csTitle));
    d.setText(step, QStringLiteral("text"), QStringLiteral("en"), enText);
    d.setText(step, QStringLiteral("text"), QStringLiteral("cs"), csText);
}

} // namespace

void TestLessonEditor::initTestCase()
{
    QVERIFY(m_dir.isValid());
    m_saved = m_dir.filePath(QStringLiteral("drops.rlesson"));
}

void TestLessonEditor::newLessonWithSteps()
{
    const lessons::SceneLoadResult scene =
        lessons::loadSceneFile(kSource + QStringLiteral("/lessons/scenes/four_balls.json"));
    QVERIFY2(scene.ok, qPrintable(scene.error));

    m_draft.newLesson(QStringLiteral("Drops"), scene.scene);
    QCOMPARE(m_draft.stepCount(), 1);
    QVERIFY(m_draft.path().isEmpty());
    m_draft.setText(-1, QStringLiteral("title"), QStringLiteral("en"), QStringLiteral("Drops"));
    m_draft.setText(-1, QStringLiteral("title"), QStringLiteral("cs"), QStringLiteral("Pády"));
    m_draft.setText(-1, QStringLiteral("summary"), QStringLiteral("en"),
                    QStringLiteral("Balls bounce."));
    m_draft.setText(-1, QStringLiteral("summary"), QStringLiteral("cs"),
                    QStringLiteral("Míčky skáčou."));
    m_draft.setValue(-1, QStringLiteral("minutes"), 15, QStringLiteral("minutes"));

    // Three steps, each starting from the scene of the one before.
    m_draft.addStep(0);
    m_draft.addStep(1);
    QCOMPARE(m_draft.stepCount(), 3);
    QCOMPARE(m_draft.value(2, QStringLiteral("scene")), m_draft.value(0, QStringLiteral("scene")));
    writeStep(m_draft, 0, "Watch", "Sledujte", QStringLiteral("Line one.\nLine two."),
              QStringLiteral("Řádek jedna.\nŘádek dva."));
    writeStep(m_draft, 1, "Measure", "Změřte", QStringLiteral("Measure the first bounce."),
              QStringLiteral("Změřte první odskok."));
}

void TestLessonEditor::missingTranslationMarked()
{
    // Step 3 in English only: marked, and the loader's warning is about that step.
    m_draft.setText(2, QStringLiteral("title"), QStringLiteral("en"), QStringLiteral("Predict"));
    m_draft.setText(2, QStringLiteral("title"), QStringLiteral("cs"),
                    QStringLiteral("Předpovězte"));
    m_draft.setText(2, QStringLiteral("text"), QStringLiteral("en"),
                    QStringLiteral("First predict."));
    QCOMPARE(m_draft.missingLanguages(2, QStringLiteral("text")),
             QStringList{QStringLiteral("cs")});
    LessonDraft::Check check = m_draft.check(QStringLiteral("en"));
    QVERIFY2(check.error.isEmpty(), qPrintable(check.error));
    QVERIFY2(check.steps.contains(2), qPrintable(check.warnings.join(u'\n')));
    m_draft.setText(2, QStringLiteral("text"), QStringLiteral("cs"),
                    QStringLiteral("Nejdřív předpovězte."));
    QVERIFY(m_draft.missingLanguages(2, QStringLiteral("text")).isEmpty());
}

void TestLessonEditor::questionsLocksAndChecks()
{
    // Plots, a lock, export times, and one question of each kind.
    m_draft.setValue(0, QStringLiteral("plots"), QJsonArray{QStringLiteral("energy")},
                     QStringLiteral("plots"));
    m_draft.setValue(0, QStringLiteral("allow"), QJsonArray{QStringLiteral("timeScale")},
                     QStringLiteral("lock"));
    m_draft.setValue(0, QStringLiteral("exportTime"), 2, QStringLiteral("export time"));
    m_draft.setValue(1, QStringLiteral("plots"),
                     QJsonArray{QStringLiteral("energy"), QStringLiteral("drift")},
                     QStringLiteral("plots"));
    m_draft.setValue(1, QStringLiteral("exportTime"), 3, QStringLiteral("export time"));
    m_draft.setValue(2, QStringLiteral("plots"), QJsonArray{QStringLiteral("momentum")},
                     QStringLiteral("plots"));
    m_draft.setValue(2, QStringLiteral("exportTime"), 2, QStringLiteral("export time"));
    // A question about a body that is not there is the loader's error, placed at its step.
    m_draft.setValue(
        1, QStringLiteral("questions"),
        QJsonArray{parsed(R"({"prompt": "x", "measure": {"kind": "apex", "body": "nope"}})")},
        QStringLiteral("question"));
    const LessonDraft::Check check = m_draft.check(QStringLiteral("en"));
    QVERIFY2(check.error.contains(QStringLiteral("lesson.steps[1].questions[0].measure.body")),
             qPrintable(check.error));
    QCOMPARE(check.steps.value(0), 1);
    m_draft.undoStack()->undo();
    QVERIFY(m_draft.value(1, QStringLiteral("questions")).isUndefined());
    m_draft.setValue(1, QStringLiteral("questions"),
                     QJsonArray{parsed(R"({"prompt": {"en": "How high?", "cs": "Jak vysoko?"},
                   "measure": {"kind": "apex", "body": "e08", "n": 1, "above": 0.1},
                   "unit": "m", "tolerance": 0.05})")},
                     QStringLiteral("question"));
    m_draft.setValue(
        2, QStringLiteral("questions"),
        QJsonArray{parsed(R"({"prompt": {"en": "Speed at 1 s?", "cs": "Rychlost v čase 1 s?"},
                   "measure": {"kind": "speed", "body": "e08", "time": 1},
                   "unit": "m/s", "holdBack": ["run"]})")},
        QStringLiteral("question"));
}

void TestLessonEditor::undoAndRedo()
{
    // Undo and redo: a removed step comes back; typing into one text is one undo step.
    m_draft.removeStep(1);
    QCOMPARE(m_draft.stepCount(), 2);
    m_draft.undoStack()->undo();
    QCOMPARE(m_draft.stepCount(), 3);
    QCOMPARE(m_draft.text(1, QStringLiteral("title"), QStringLiteral("cs")),
             QStringLiteral("Změřte"));
    m_draft.setText(0, QStringLiteral("title"), QStringLiteral("en"), QStringLiteral("Watc"));
    m_draft.setText(0, QStringLiteral("title"), QStringLiteral("en"), QStringLiteral("Watch it"));
    m_draft.undoStack()->undo();
    QCOMPARE(m_draft.text(0, QStringLiteral("title"), QStringLiteral("en")),
             QStringLiteral("Watch"));
    m_draft.undoStack()->redo();
    QCOMPARE(m_draft.text(0, QStringLiteral("title"), QStringLiteral("en")),
             QStringLiteral("Watch it"));
    m_draft.undoStack()->undo();
    m_draft.moveStep(2, 0);
    QCOMPARE(m_draft.text(0, QStringLiteral("title"), QStringLiteral("en")),
             QStringLiteral("Predict"));
    m_draft.undoStack()->undo();
    m_draft.duplicateStep(0);
    QCOMPARE(m_draft.stepCount(), 4);
    m_draft.undoStack()->undo();
    QCOMPARE(m_draft.stepCount(), 3);
}

void TestLessonEditor::savedAndReopened()
{
    // Saved as one file, dated, written whole; opened again, the same lesson.
    QVERIFY(m_draft.isModified());
    QVERIFY(!m_draft.saveAs(m_dir.filePath(QStringLiteral("drops.json"))).isEmpty());
    QCOMPARE(m_draft.saveAs(m_saved), QString());
    QVERIFY(!m_draft.isModified());
    QVERIFY(!m_draft.pack().info.date.isEmpty());
    LessonDraft reopened;
    QCOMPARE(reopened.open(m_saved), QString());
    QCOMPARE(reopened.path(), QFileInfo(m_saved).absoluteFilePath());
    QCOMPARE(reopened.text(0, QStringLiteral("text"), QStringLiteral("cs")),
             QStringLiteral("Řádek jedna.\nŘádek dva."));
    QCOMPARE(reopened.save(), QString());
    QCOMPARE(readAll(m_saved), lessons::lessonPackBytes(m_draft.pack()));
}

void TestLessonEditor::playsAsAStudent()
{
    // Played in the window as a student plays it, every step.
    ui::MainWindow w;
    w.show();
    QCOMPARE(w.openLesson(m_saved, true), QString());
    QCOMPARE(static_cast<int>(w.lessonPlayer().lesson()->steps.size()), 3);
    for (int i = 0; i < 3; ++i) {
        w.lessonPlayer().goToStep(i);
        QCOMPARE(w.lessonPlayer().stepIndex(), i);
    }
}

void TestLessonEditor::samePlotsAsByHand()
{
    // The same plots as the lesson written by hand.
    const QString byHand = m_dir.filePath(QStringLiteral("hand/drops.json"));
    QVERIFY(QDir().mkpath(m_dir.filePath(QStringLiteral("hand/scenes"))));
    QVERIFY(QFile::copy(kSource + QStringLiteral("/lessons/scenes/four_balls.json"),
                        m_dir.filePath(QStringLiteral("hand/scenes/four_balls.json"))));
    QVERIFY(writeFile(byHand, handWritten()));
    const lessons::LessonLoadResult hand = lessons::loadLessonFile(byHand);
    QVERIFY2(hand.ok, qPrintable(hand.error));
    const lessons::LessonLoadResult made = lessons::loadLessonFile(m_saved);
    QVERIFY2(made.ok, qPrintable(made.error));
    QCOMPARE(made.lesson.steps.size(), hand.lesson.steps.size());
    for (std::size_t i = 0; i < hand.lesson.steps.size(); ++i) {
        QCOMPARE(made.lesson.steps[i].text, hand.lesson.steps[i].text);
        QCOMPARE(made.lesson.steps[i].allow, hand.lesson.steps[i].allow);
        QCOMPARE(made.lesson.steps[i].questions.size(), hand.lesson.steps[i].questions.size());
        const QString difference =
            lessons::sceneDifference(made.lesson.steps[i].scene, hand.lesson.steps[i].scene);
        QVERIFY2(difference.isEmpty(), qPrintable(difference));
    }
    const ui::PlotFilesResult a = ui::exportLessonPlots(made.lesson, m_dir.filePath("made"));
    const ui::PlotFilesResult b = ui::exportLessonPlots(hand.lesson, m_dir.filePath("byhand"));
    QVERIFY2(a.ok && b.ok, qPrintable(a.error + b.error));
    const QStringList files = filesUnder(m_dir.filePath("byhand"));
    QVERIFY(!files.isEmpty());
    QCOMPARE(filesUnder(m_dir.filePath("made")), files);
    for (const QString& f : files)
        if (f.endsWith(QStringLiteral(".csv")))
            QVERIFY2(readAll(QDir(m_dir.filePath("made")).filePath(f)) ==
                         readAll(QDir(m_dir.filePath("byhand")).filePath(f)),
                     qPrintable(f));
}

void TestLessonEditor::shippedLessonsOpenAndSaveUnchanged_data()
{
    QTest::addColumn<QString>("file");
    const QDir lessonsDir(kSource + QStringLiteral("/lessons/lessons"));
    for (const QString& f : lessonsDir.entryList({QStringLiteral("*.json")}, QDir::Files))
        QTest::newRow(qPrintable(f)) << lessonsDir.filePath(f);
}

void TestLessonEditor::shippedLessonsOpenAndSaveUnchanged()
{
    QFETCH(QString, file);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    LessonDraft d;
    QCOMPARE(d.open(file), QString());
    QVERIFY(d.path().isEmpty()); // a shipped lesson opens as a copy
    QVERIFY(!d.save().isEmpty());
    const QString copy = dir.filePath(QStringLiteral("copy.rlesson"));
    QCOMPARE(d.saveAs(copy), QString());
    const lessons::LessonPackResult packed = lessons::packLesson(file);
    QVERIFY(packed.ok);
    QCOMPARE(d.pack().lesson, packed.pack.lesson);
    QVERIFY(d.pack().scenes == packed.pack.scenes);
    // Opened and saved again without a change: the same bytes.
    const QByteArray first = readAll(copy);
    LessonDraft again;
    QCOMPARE(again.open(copy), QString());
    QCOMPARE(again.save(), QString());
    QCOMPARE(readAll(copy), first);
}

RIGIDLAB_TEST_MAIN(TestLessonEditor)
