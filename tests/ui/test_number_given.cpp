// SPDX-License-Identifier: GPL-3.0-or-later
// A question whose answer the lesson gives ("number", "within"): written in the lesson editor
// (a measured question made one, its fields edited, undone, saved and reopened), played as a
// student plays it (typed, checked, the verdict in English and in Czech), and on the worksheet
// (the empty sheet's line, the key's number, a student's tries).

#include "common/language.h"
#include "lesson_editor/lesson_draft.h"
#include "lesson_editor/lesson_editor.h"
#include "lesson_player/lesson_player.h"
#include "question_kinds/question_kinds.h"
#include "window/main_window.h"
#include "worksheet/worksheet.h"

#include "format/scene_loader.h"

#include "editor_on_step.h"
#include "test_main.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QJsonArray>
#include <QLabel>
#include <QLineEdit>
#include <QProcess>
#include <QPushButton>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QtTest>

using namespace rigidlab;
using rigidlab::test::child;

namespace {

/// A lesson of one step asking for a momentum the student works out: 0.8 kg m/s, within 0.05.
const char* kLesson = R"({"rigidlab-lesson": 1, "title": "Given", "steps": [{"title": "s",
 "scene": {"rigidlab": 1, "bodies": [{"id": "ball", "shape": {"type": "circle", "radius": 0.1},
   "position": [0, 1]}]},
 "questions": [{"prompt": {"en": "What momentum has the ball?", "cs": "Jakou hybnost má míček?"},
   "hint": {"en": "p = m v", "cs": "p = m v"}, "number": 0.8, "within": 0.05,
   "unit": "kg m/s"}]}]})";

/// The PDF's text (pdftotext), its lines joined by spaces.
QString pdfText(const QString& pdf)
{
    QProcess process;
    process.start(QStringLiteral("pdftotext"),
                  {QStringLiteral("-enc"), QStringLiteral("UTF-8"), pdf, QStringLiteral("-")});
    if (!process.waitForFinished(60000) || process.exitCode() != 0)
        return {};
    return QString::fromUtf8(process.readAllStandardOutput()).simplified();
}

/// The texts of a kind's worksheet lines, in order ("~" for a line to write on, "TRIES unit").
QStringList linesOf(const std::vector<ui::SheetLine>& lines)
{
    QStringList out;
    for (const ui::SheetLine& l : lines)
        out << (l.is == ui::SheetLine::Is::WritingLine ? QStringLiteral("~")
                : l.is == ui::SheetLine::Is::Tries     ? QStringLiteral("TRIES ") + l.text
                                                       : l.text);
    return out;
}

} // namespace

class TestNumberGiven : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void cleanup();
    void playedInEnglish();
    void playedInCzech();
    void worksheetLines();
    void writtenInTheEditor();

private:
    QTemporaryDir m_dir;
    QString m_path;
};

void TestNumberGiven::initTestCase()
{
    QVERIFY(m_dir.isValid());
    m_path = m_dir.filePath(QStringLiteral("given.json"));
    QFile f(m_path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(kLesson);
}

void TestNumberGiven::cleanup()
{
    QVERIFY(ui::applyLanguage(QStringLiteral("en")));
}

void TestNumberGiven::playedInEnglish()
{
    ui::MainWindow w;
    w.show();
    QCOMPARE(w.openLesson(m_path, true), QString());
    ui::LessonPlayer& player = w.lessonPlayer();
    // The answer box is named by its question and says its unit; Show me is there.
    QLineEdit* box = nullptr;
    for (QLineEdit* e : w.findChildren<QLineEdit*>())
        if (e->placeholderText() == QStringLiteral("your answer"))
            box = e;
    QVERIFY(box);
    QCOMPARE(box->accessibleDescription(), QStringLiteral("your answer, in kg m/s"));
    // Not a number: said, not counted.
    player.answer(0, QStringLiteral("much"));
    QCOMPARE(player.result(0), QStringLiteral("Type a number first."));
    const auto triesNow = [&player] {
        const lessons::Answers a = player.answers();
        return a.steps.empty() || a.steps[0].questions.empty() ? std::vector<lessons::AnswerTry>()
                                                               : a.steps[0].questions[0];
    };
    QCOMPARE(triesNow().size(), std::size_t{0});
    // Wrong first: the hint, the number kept back.
    player.answer(0, QStringLiteral("0.5"));
    QVERIFY2(player.result(0).contains(QStringLiteral("Hint: p = m v")),
             qPrintable(player.result(0)));
    QVERIFY2(!player.result(0).contains(QStringLiteral("0.8")), qPrintable(player.result(0)));
    // Within the band: right, with the number.
    player.answer(0, QStringLiteral("0.83"));
    QCOMPARE(player.result(0), QStringLiteral("Right: the answer is 0.8\u00a0kg m/s (you "
                                              "said 0.83\u00a0kg m/s)."));
    // The tries keep the number they were judged against, for the worksheet.
    const std::vector<lessons::AnswerTry> tries = triesNow();
    QCOMPARE(tries.size(), std::size_t{2});
    QCOMPARE(tries[0].answer, std::optional<double>(0.5));
    QCOMPARE(tries[1].measured, std::optional<double>(0.8));
}

void TestNumberGiven::playedInCzech()
{
    QVERIFY(ui::applyLanguage(QStringLiteral("cs")));
    ui::MainWindow w;
    w.show();
    QCOMPARE(w.openLesson(m_path, true), QString());
    ui::LessonPlayer& player = w.lessonPlayer();
    // With the decimal comma; just outside the band is wrong, at its edge right.
    player.answer(0, QStringLiteral("0,86"));
    QVERIFY2(player.result(0).startsWith(QStringLiteral("Ne tak docela")),
             qPrintable(player.result(0)));
    player.answer(0, QStringLiteral("0,85"));
    QCOMPARE(player.result(0), QStringLiteral("Správně: výsledek je 0,8\u00a0kg m/s "
                                              "(vaše odpověď: 0,85\u00a0kg m/s)."));
}

void TestNumberGiven::worksheetLines()
{
    const lessons::NumberGivenQuestion q{0.8, 0.05, QStringLiteral("kg m/s")};
    QCOMPARE(linesOf(ui::worksheetLines(q, {ui::WorksheetKind::Empty})),
             (QStringList{QStringLiteral("Your answer (kg m/s):"), QStringLiteral("~")}));
    QCOMPARE(linesOf(ui::worksheetLines(q, {ui::WorksheetKind::Key})),
             QStringList{QStringLiteral("Right answer: 0.8\u00a0kg m/s (accepted from "
                                        "0.75\u00a0kg m/s to 0.85\u00a0kg m/s)")});
    QCOMPARE(linesOf(ui::worksheetLines(q, {ui::WorksheetKind::Answers})),
             (QStringList{QStringLiteral("TRIES kg m/s"),
                          QStringLiteral("Right answer: 0.8\u00a0kg m/s")}));
    // The key as a PDF, through the worksheet's writer.
    const lessons::LessonLoadResult loaded = lessons::loadLessonFile(m_path);
    QVERIFY2(loaded.ok, qPrintable(loaded.error));
    const QString key = m_dir.filePath(QStringLiteral("key.pdf"));
    const ui::WorksheetResult k =
        ui::writeWorksheet(loaded.lesson, lessons::Answers{}, ui::WorksheetKind::Key, key);
    QVERIFY2(k.ok, qPrintable(k.error));
    const QString text = pdfText(key);
    QVERIFY2(!text.isEmpty(), "pdftotext read nothing (is poppler-utils installed?)");
    QVERIFY2(text.contains(QStringLiteral("Right answer: 0.8 kg m/s (accepted from 0.75 kg m/s "
                                          "to 0.85 kg m/s)")),
             qPrintable(text));
}

void TestNumberGiven::writtenInTheEditor()
{
    test::EditorOnStep rig;
    QCOMPARE(rig.open(), QString());
    ui::LessonEditor& ed = rig.ed;
    ui::LessonDraft& d = ed.draft();
    const auto question = [&rig] { return rig.question(); };
    // A measured question, made one whose number the lesson gives with the kind chooser.
    QTest::mouseClick(child<QPushButton>(ed, QStringLiteral("addMeasuredQuestion")),
                      Qt::LeftButton);
    auto* kind = child<QComboBox>(ed, QStringLiteral("questionType"));
    QVERIFY(kind);
    const int given = kind->findText(QStringLiteral("a number the lesson gives"));
    QVERIFY(given > 0);
    kind->setCurrentIndex(given);
    emit kind->activated(given);
    QCOMPARE(question().value(u"number").toDouble(), 1.0);
    QCOMPARE(question().value(u"within").toDouble(), 0.05);
    QVERIFY(!question().contains(u"measure") && !question().contains(u"tolerance"));
    auto* number = child<QDoubleSpinBox>(ed, QStringLiteral("givenNumber"));
    auto* within = child<QDoubleSpinBox>(ed, QStringLiteral("givenWithin"));
    auto* unit = child<QLineEdit>(ed, QStringLiteral("givenUnit"));
    QVERIFY(number && within && unit && number->isVisible());
    QVERIFY(!child<QComboBox>(ed, QStringLiteral("questionBody"))->isVisible());
    QVERIFY(!number->accessibleName().isEmpty() && !within->accessibleName().isEmpty());
    number->setValue(2.5);
    within->setValue(0.1);
    unit->setText(QStringLiteral("m"));
    emit unit->textEdited(unit->text());
    QCOMPARE(question().value(u"number").toDouble(), 2.5);
    QCOMPARE(question().value(u"within").toDouble(), 0.1);
    QCOMPARE(question().value(u"unit").toString(), QStringLiteral("m"));
    // The line under it gives the band.
    const QString line = child<QLabel>(ed, QStringLiteral("questionAnswer"))->text();
    QVERIFY2(line.contains(QStringLiteral("from 2.4\u00a0m to 2.6\u00a0m")), qPrintable(line));
    // Undone, the last edit goes; redone, it is back.
    const QJsonObject written = question();
    d.undoStack()->undo();
    QVERIFY(question() != written);
    d.undoStack()->redo();
    QCOMPARE(question(), written);
    QCOMPARE(unit->text(), QStringLiteral("m"));
    // Saved and reopened: the same question, read by the loader as this kind.
    QCOMPARE(d.check(QStringLiteral("en")).error, QString());
    const QString saved = m_dir.filePath(QStringLiteral("written.rlesson"));
    QCOMPARE(ed.saveAs(saved), QString());
    const lessons::LessonLoadResult reread = lessons::loadLessonFile(saved);
    QVERIFY2(reread.ok, qPrintable(reread.error));
    const auto* q =
        std::get_if<lessons::NumberGivenQuestion>(&reread.lesson.steps.at(0).questions.at(0).kind);
    QVERIFY(q);
    QCOMPARE(q->number, 2.5);
    QCOMPARE(q->within, 0.1);
    QCOMPARE(q->unit, QStringLiteral("m"));
}

RIGIDLAB_TEST_MAIN(TestNumberGiven)
#include "test_number_given.moc"
