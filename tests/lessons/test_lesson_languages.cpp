// SPDX-License-Identifier: GPL-3.0-or-later
// Lessons in languages: every text a student reads, in English or per language; the fallback
// to English, the warnings for a missing language, and what a bad language object gets.

#include "test_lesson.h"
#include "test_lesson_json.h"

#include "format/document.h"
#include "format/languages.h"
#include "format/lesson_pack.h"

#include "question_kinds.h"
#include <QFile>
#include <QFileInfo>
#include <QRegularExpression>
#include <QTemporaryDir>

using namespace rigidlab;
using namespace rigidlab::test;
using namespace rigidlab::test::lesson_json;

// --- languages: every text a student reads, in English or per language ------------------

namespace {

/// A lesson whose texts are all in the object form, each with "en" and, where `czech`, "cs".
QByteArray bilingualLesson(bool czech)
{
    const auto text = [czech](const char* en, const char* cs) {
        return QByteArray(R"({"en": ")") + en + '"' +
               (czech ? QByteArray(R"(, "cs": ")") + cs + '"' : QByteArray()) + '}';
    };
    const QByteArray paragraphs =
        QByteArray(R"({"en": ["One.", "Two."])") +
        (czech ? QByteArray(R"(, "cs": ["Jedna.", "Dvě."])") : QByteArray()) + '}';
    const QByteArray goals = QByteArray(R"({"en": ["Predict."])") +
                             (czech ? QByteArray(R"(, "cs": ["Předpovědět."])") : QByteArray()) +
                             '}';
    return R"({"rigidlab-lesson": 1, "title": )" + text("Bounces", "Odrazy") + R"(, "summary": )" +
           text("Drop balls.", "Pouštějte míčky.") + R"(, "level": )" +
           text("first year", "první ročník") + R"(, "description": )" +
           text("Bounce heights", "Výšky odrazů") + R"(, "goals": )" + goals +
           R"(, "steps": [{"title": )" + text("Four balls", "Čtyři míčky") + R"(, "text": )" +
           paragraphs + R"(, "scene": )" + kScene + R"(, "questions": [{"prompt": )" +
           text("How high?", "Jak vysoko?") +
           R"(, "measure": {"kind": "apex", "body": "ball"}, "unit": )" + text("m", "m") +
           R"(, "hint": )" + text("e squared", "e na druhou") + "}]}]}";
}

} // namespace

void TestLesson::textsInBothForms()
{
    // The object form, in each language.
    const QByteArray both = bilingualLesson(true);
    const lessons::LessonLoadResult en =
        lessons::loadLessonJson(both, QStringLiteral("l.json"), {QStringLiteral("en")});
    QVERIFY2(en.ok, qPrintable(en.error));
    QVERIFY2(en.warnings.isEmpty(), qPrintable(en.warnings.join(u'\n')));
    QCOMPARE(en.lesson.title, QStringLiteral("Bounces"));
    QCOMPARE(en.lesson.steps.front().text, QStringLiteral("One.\nTwo."));
    const lessons::LessonLoadResult cs =
        lessons::loadLessonJson(both, QStringLiteral("l.json"), {QStringLiteral("cs")});
    QVERIFY2(cs.ok, qPrintable(cs.error));
    const lessons::Lesson& l = cs.lesson;
    QCOMPARE(l.title, QStringLiteral("Odrazy"));
    QCOMPARE(l.summary, QStringLiteral("Pouštějte míčky."));
    QCOMPARE(l.level, QStringLiteral("první ročník"));
    QCOMPARE(l.description, QStringLiteral("Výšky odrazů"));
    QCOMPARE(l.goals, QStringList{QStringLiteral("Předpovědět.")});
    const lessons::LessonStep& step = l.steps.front();
    QCOMPARE(step.title, QStringLiteral("Čtyři míčky"));
    QCOMPARE(step.text, QStringLiteral("Jedna.\nDvě."));
    QCOMPARE(step.questions.front().prompt, QStringLiteral("Jak vysoko?"));
    QCOMPARE(step.questions.front().hint, QStringLiteral("e na druhou"));

    // The plain form is English, whatever the language; goals may also be a list of texts.
    const QByteArray plain =
        oneStep(R"("text": ["a", "b"], "questions": [{"prompt": "p", "measure": {"kind": )"
                R"("apex", "body": "ball"}, "hint": {"en": "h", "cs": "n"}}])");
    const lessons::LessonLoadResult mixed =
        lessons::loadLessonJson(plain, QStringLiteral("l.json"), {QStringLiteral("cs")});
    QVERIFY2(mixed.ok, qPrintable(mixed.error));
    QCOMPARE(mixed.lesson.steps.front().text, QStringLiteral("a\nb"));
    QCOMPARE(mixed.lesson.steps.front().questions.front().hint, QStringLiteral("n"));
    const QByteArray goalItems =
        R"({"rigidlab-lesson": 1, "title": "t", "goals": ["g1", {"en": "g2", "cs": "c2"}],)"
        R"( "steps": [{"title": "s", "scene": )" +
        QByteArray(kScene) + "}]}";
    const lessons::LessonLoadResult items =
        lessons::loadLessonJson(goalItems, QStringLiteral("l.json"), {QStringLiteral("cs")});
    QVERIFY2(items.ok, qPrintable(items.error));
    QCOMPARE(items.lesson.goals, (QStringList{QStringLiteral("g1"), QStringLiteral("c2")}));
}

void TestLesson::textsFallBackToEnglish()
{
    // Czech asked for, none there: every text is the English one, and so it is for a language
    // the lab does not ship.
    const QByteArray english = bilingualLesson(false);
    for (const char* language : {"cs", "de"}) {
        const lessons::LessonLoadResult r = lessons::loadLessonJson(
            english, QStringLiteral("l.json"), {QString::fromLatin1(language)});
        QVERIFY2(r.ok, qPrintable(r.error));
        QCOMPARE(r.lesson.title, QStringLiteral("Bounces"));
        QCOMPARE(r.lesson.goals, QStringList{QStringLiteral("Predict.")});
        QCOMPARE(r.lesson.steps.front().text, QStringLiteral("One.\nTwo."));
        QCOMPARE(measuredOf(r.lesson.steps.front().questions.front()).unit, QStringLiteral("m"));
    }
    // Without options the loader reads the language chosen for the app.
    QCOMPARE(lessons::lessonLanguage(), QStringLiteral("en"));
    QVERIFY(!lessons::setLessonLanguage(QStringLiteral("de")));
    QVERIFY(lessons::setLessonLanguage(QStringLiteral("cs")));
    const lessons::LessonLoadResult chosen =
        lessons::loadLessonJson(bilingualLesson(true), QStringLiteral("l.json"));
    QVERIFY(lessons::setLessonLanguage(QStringLiteral("en")));
    QCOMPARE(chosen.lesson.title, QStringLiteral("Odrazy"));
}

void TestLesson::missingLanguageWarns()
{
    // A translated lesson warns of each text without Czech, saying where; it still loads.
    QByteArray json = bilingualLesson(true);
    json.replace(R"(, "cs": "Čtyři míčky")", "");
    json.replace(R"(, "cs": "e na druhou")", "");
    const lessons::LessonLoadResult r = lessons::loadLessonJson(json, QStringLiteral("l.json"));
    QVERIFY2(r.ok, qPrintable(r.error));
    const QString tail = QStringLiteral(": no Czech text (\"cs\"): it will show in English");
    QCOMPARE(r.warnings,
             (QStringList{QStringLiteral("l.json: steps[0].title") + tail,
                          QStringLiteral("l.json: steps[0].questions[0].hint") + tail}));

    // A plain string in a translated lesson lacks Czech too.
    json = bilingualLesson(true);
    json.replace(R"({"en": "first year", "cs": "první ročník"})", R"("first year")");
    const lessons::LessonLoadResult plain = lessons::loadLessonJson(json, QStringLiteral("l.json"));
    QCOMPARE(plain.warnings, QStringList{QStringLiteral("l.json: level") + tail});

    // A lesson all in plain strings is an English lesson: nothing to warn of.
    QVERIFY(lessons::loadLessonJson(oneStep(R"("text": "x")"), QStringLiteral("l.json"))
                .warnings.isEmpty());

    // validate prints the warning, and still exits 0 (test_cli runs it); checkDocumentFile
    // carries the same lines.
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("l.json"));
    QVERIFY(writeFile(path, bilingualLesson(true).replace(R"(, "cs": "Odrazy")", "")));
    const lessons::DocumentCheck check = lessons::checkDocumentFile(path);
    QVERIFY2(check.ok, qPrintable(check.error));
    QCOMPARE(check.warnings, QStringList{path + QStringLiteral(": title") + tail});
}

void TestLesson::badLanguageObjectRefused_data()
{
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<QString>("message");
    const auto lesson = [](const char* title, const char* fields) {
        return QByteArray(R"({"rigidlab-lesson": 1, "title": )") + title +
               R"(, "steps": [{"title": "s", "scene": )" + kScene + fields + "}]}";
    };
    const QString s0 = QStringLiteral("steps[0].");
    QTest::newRow("unknown-language") << lesson(R"({"en": "t", "de": "T"})", "")
                                      << R"(title.de: unknown language "de" (expected en, cs))";
    QTest::newRow("empty-object") << lesson("{}", "")
                                  << R"(title: needs a text in at least one language (en, cs))";
    QTest::newRow("empty-prompt-object")
        << lesson(R"("t")", R"(, "questions": [{"prompt": {}, "measure": {"kind": "apex", )"
                            R"("body": "ball"}}])")
        << s0 + R"(questions[0].prompt: needs a text in at least one language (en, cs))";
    QTest::newRow("number-value") << lesson(R"({"en": "t", "cs": 3})", "")
                                  << R"(title.cs: must be a string "...", got 3)";
    QTest::newRow("array-for-a-line")
        << lesson(R"(["t"])", "")
        << R"(title: must be a string "...", or an object of languages {"en": "...", "cs": )"
           R"("..."}, got an array)";
    QTest::newRow("empty-czech-title")
        << lesson(R"({"en": "t", "cs": " "})", "") << "title.cs: must not be empty";
    QTest::newRow("text-number-in-language")
        << lesson(R"("t")", R"(, "text": {"en": ["a"], "cs": [1]})")
        << s0 + R"(text.cs[0]: must be a string "...", got 1)";
    QTest::newRow("text-object-in-language")
        << lesson(R"("t")", R"(, "text": {"en": "a", "cs": {"cs": "b"}})")
        << s0 + R"(text.cs: must be a string or an array of strings, got an object)";
    QTest::newRow("text-number")
        << lesson(R"("t")", R"(, "text": 5)")
        << s0 + R"(text: must be a string or an array of strings, or an object of languages )"
                R"({"en": ..., "cs": ...}, got 5)";
    QTest::newRow("goals-language-not-a-list")
        << QByteArray(R"({"rigidlab-lesson": 1, "title": "t", "goals": {"en": "g"}, "steps": []})")
        << R"(goals.en: must be an array [...], got "g")";
    QTest::newRow("goals-empty-in-czech")
        << QByteArray(
               R"({"rigidlab-lesson": 1, "title": "t", "goals": {"en": ["g"], "cs": [""]}, "steps": []})")
        << R"(goals.cs[0]: must be a non-empty string "...", got "")";
    QTest::newRow("description-two-lines-in-czech")
        << lesson(R"("t", "description": {"en": "d", "cs": "a\nb"})", "")
        << R"(description.cs: must be one line (it is shown in the lesson menu); put longer )"
           R"(text in "summary")";
    QTest::newRow("prompt-unknown-language")
        << lesson(R"("t")",
                  R"(, "questions": [{"prompt": {"en": "p", "sk": "q"}, "measure": {"kind": )"
                  R"("apex", "body": "ball"}}])")
        << s0 + R"(questions[0].prompt.sk: unknown language "sk" (expected en, cs))";
}

void TestLesson::badLanguageObjectRefused()
{
    QFETCH(QByteArray, json);
    QFETCH(QString, message);
    const lessons::LessonLoadResult r = lessons::loadLessonJson(json, QStringLiteral("l.json"));
    QVERIFY(!r.ok);
    QCOMPARE(r.error, QStringLiteral("l.json: ") + message);
}

void TestLesson::oneLanguageLessons_data()
{
    QTest::addColumn<QString>("file");
    QTest::addColumn<QString>("written"); // the one language it is written in
    QTest::addColumn<QString>("title");
    QTest::addColumn<QString>("choice"); // its first option
    QTest::addColumn<QString>("label");  // the heavy cart's label
    QTest::newRow("czech-only") << QStringLiteral("czech_only.rlesson") << QStringLiteral("cs")
                                << QStringLiteral("Srážka dvou vozíků") << QStringLiteral("lehký")
                                << QStringLiteral("těžký vozík");
    QTest::newRow("english-only") << QStringLiteral("english_only.rlesson") << QStringLiteral("en")
                                  << QStringLiteral("Two carts collide")
                                  << QStringLiteral("the light one")
                                  << QStringLiteral("heavy cart");
}

void TestLesson::oneLanguageLessons()
{
    // A lesson written in one language only is a lesson like any other: it loads in every
    // language, each text shown in the one it has, with one warning for the language it lacks.
    QFETCH(QString, file);
    QFETCH(QString, written);
    QFETCH(QString, title);
    QFETCH(QString, choice);
    QFETCH(QString, label);
    const QString path = kOneLanguageDir + u'/' + file;
    for (const lessons::Language& language : lessons::kLanguages) {
        const QString code = language.code.toString();
        const lessons::LessonLoadResult r = lessons::loadLessonFile(path, {code});
        QVERIFY2(r.ok, qPrintable(r.error));
        const lessons::Lesson& l = r.lesson;
        QCOMPARE(l.title, title);
        QCOMPARE(l.goals.size(), 1);
        const lessons::LessonStep& step = l.steps.front();
        QVERIFY(!step.title.isEmpty());
        QVERIFY(!step.text.isEmpty());
        QCOMPARE(step.scene.labels.at(1), label);
        QCOMPARE(step.endTime, std::optional<double>(3.0));
        QCOMPARE(step.questions.size(), std::size_t{2});
        QVERIFY(!isChoice(step.questions[0]));
        QVERIFY(!step.questions[0].hint.isEmpty());
        QVERIFY(isChoice(step.questions[1]));
        QCOMPARE(choiceOf(step.questions[1]).choices.front(), choice);
        // One warning for the lesson's missing language, one for its scene's: never one per
        // text, and none at all for the language asked for when it is the one written.
        for (const lessons::Language& other : lessons::kLanguages) {
            const QString missing = other.code.toString();
            const QString line =
                QStringLiteral("no %1 text (\"%2\") in the whole lesson: it "
                               "will show in %3")
                    .arg(lessons::languageTitle(missing), missing, lessons::languageTitle(written));
            const qsizetype count =
                std::count_if(r.warnings.begin(), r.warnings.end(),
                              [&](const QString& w) { return w.endsWith(line); });
            QCOMPARE(count, missing == written ? 0 : 1);
        }
        QCOMPARE(r.warnings.size(), 2);
    }
    // Saved and read back, it is the same lesson.
    QFile in(path);
    QVERIFY(in.open(QIODevice::ReadOnly));
    const lessons::LessonPackResult read = lessons::readLessonPack(in.readAll(), path);
    QVERIFY2(read.ok, qPrintable(read.error));
    QTemporaryDir dir;
    const QString copy = dir.filePath(file);
    QVERIFY(writeFile(copy, lessons::lessonPackBytes(read.pack)));
    const lessons::LessonLoadResult again = lessons::loadLessonFile(copy, {written});
    QVERIFY2(again.ok, qPrintable(again.error));
    QCOMPARE(again.lesson.title, title);
    QCOMPARE(choiceOf(again.lesson.steps.front().questions[1]).choices.front(), choice);
}
