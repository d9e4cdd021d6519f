// SPDX-License-Identifier: GPL-3.0-or-later
// The lesson loader: the shipped lessons, every check with its place and message, scene paths
// that may not leave the lesson's folder, and the step's worlds.

#include "build_paths.h"
#include "test_lesson.h"
#include "test_lesson_json.h"

#include "format/data_dirs.h"
#include "format/document.h"
#include "format/editor_tools.h"
#include "format/languages.h"
#include "format/lesson_catalog.h"
#include "format/scene_schema.h"
#include "format/view_text.h"

#include "question_kinds.h"
#include <QFileInfo>
#include <QRegularExpression>
#include <QTemporaryDir>

using namespace rigidlab;
using namespace rigidlab::test;
using namespace rigidlab::test::lesson_json;

void TestLesson::sceneTextsInLessonLanguage()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    QVERIFY(writeFile(dir.filePath(QStringLiteral("drop.json")),
                      R"({"rigidlab": 1, "title": {"en": "Drop", "cs": "Pád"}, "bodies": []})"));
    const QByteArray json =
        R"({"rigidlab-lesson": 1, "title": "t", "steps": [
             {"title": "s", "scene": {"rigidlab": 1, "title": {"en": "Inline"},
                                      "description": {"en": "D", "cs": "P"}, "bodies": []}},
             {"title": "s", "scene": "drop.json"}]})";
    const QString path = dir.filePath(QStringLiteral("l.json"));
    for (const QString& language : {QStringLiteral("en"), QStringLiteral("cs")}) {
        const lessons::LessonLoadResult r =
            lessons::loadLessonJson(json, path, lessons::LessonLoadOptions{language});
        QVERIFY2(r.ok, qPrintable(r.error));
        QCOMPARE(r.lesson.steps.size(), size_t{2});
        const bool cs = language == QStringLiteral("cs");
        QCOMPARE(r.lesson.steps[0].scene.title, QStringLiteral("Inline"));
        QCOMPARE(r.lesson.steps[0].scene.description,
                 cs ? QStringLiteral("P") : QStringLiteral("D"));
        QCOMPARE(r.lesson.steps[1].scene.title,
                 cs ? QStringLiteral("Pád") : QStringLiteral("Drop"));
        // The inline scene lacks a Czech title, whatever language the lesson is read in.
        QCOMPARE(r.warnings.size(), 1);
        QVERIFY2(r.warnings[0].contains(QStringLiteral("steps[0].scene.title: no Czech text")),
                 qPrintable(r.warnings[0]));
    }
}

void TestLesson::shippedLessonsLoad_data()
{
    QTest::addColumn<QString>("path");
    const QStringList required = {
        QStringLiteral("energy_drift"), QStringLiteral("separating_axis"),
        QStringLiteral("restitution"),  QStringLiteral("billiards_momentum"),
        QStringLiteral("stacks"),
    };
    const QStringList files =
        QDir(kLessonsDir).entryList({QStringLiteral("*.json")}, QDir::Files, QDir::Name);
    for (const QString& name : required)
        QVERIFY2(files.contains(name + QStringLiteral(".json")), qPrintable(name));
    for (const QString& file : files)
        QTest::newRow(qPrintable(file)) << QDir(kLessonsDir).filePath(file);
}

void TestLesson::shippedLessonsLoad()
{
    QFETCH(QString, path);
    const lessons::LessonLoadResult loaded = lessons::loadLessonFile(path);
    QVERIFY2(loaded.ok, qPrintable(loaded.error));
    for (const QString& w : loaded.warnings)
        QVERIFY2(!w.contains(QStringLiteral(": it will show in ")), qPrintable(w));
    const lessons::Lesson& lesson = loaded.lesson;
    QCOMPARE(lesson.path, QFileInfo(path).absoluteFilePath());
    QVERIFY(!lesson.title.isEmpty());
    QVERIFY2(lesson.summary.size() >= 80, "a summary a teacher can use");
    QVERIFY(!lesson.level.isEmpty());
    QVERIFY(lesson.minutes > 0);
    QVERIFY(lesson.order > 0);
    QVERIFY(!lesson.description.isEmpty());
    QVERIFY(!lesson.goals.isEmpty());
    for (const lessons::LessonStep& step : lesson.steps) {
        QVERIFY2(step.text.size() >= 200, qPrintable(step.title));
        // Every question helps a wrong first try along, and keeps its answer off the screen
        // until it is answered.
        for (const lessons::Question& q : step.questions) {
            QVERIFY2(!q.hint.isEmpty(), qPrintable(q.prompt));
            QVERIFY2(!q.holdBack.isEmpty(), qPrintable(q.prompt));
        }
        // A step that tells the student to use a control shows the controls and allows it.
        for (const char* control : {"restitution", "dt", "integrator", "solver", "iterations"}) {
            const bool told = step.text.contains(QStringLiteral("the %1 control").arg(control)) ||
                              step.text.contains(QStringLiteral("Raise %1").arg(control));
            if (told) {
                QVERIFY2(step.panels.contains(QStringLiteral("controls")), qPrintable(step.title));
                QVERIFY2(!step.allow || step.allow->contains(QLatin1StringView(control)),
                         qPrintable(step.title));
            }
        }
        QVERIFY(!step.scene.bodies.empty());
        // Scene files are the shipped scenes, in the one scenes folder.
        if (!step.scenePath.isEmpty())
            QVERIFY2(step.scenePath.startsWith(QFileInfo(kScenesDir).absoluteFilePath() + u'/'),
                     qPrintable(step.scenePath));
        // A short run of every world stays finite; a world may diverge (the lab then stops
        // it with a diagnosis) only in a step whose text tells the student it will.
        std::vector<physics::World> worlds = lessons::buildStepWorlds(step);
        QCOMPARE(static_cast<int>(worlds.size()), step.compare ? step.compare->count() : 1);
        for (physics::World& w : worlds) {
            for (int i = 0; i < 100; ++i)
                w.step();
            QVERIFY2(!w.divergence() || step.text.contains(QStringLiteral("diverge")),
                     qPrintable(step.title));
            for (const physics::Body& b : w.bodies())
                QVERIFY(std::isfinite(b.position.x()) && std::isfinite(b.position.y()));
        }
    }
    // rigidlab-cli validate agrees.
    const lessons::DocumentCheck check = lessons::checkDocumentFile(path);
    QVERIFY2(check.ok, qPrintable(check.error));
    QCOMPARE(check.kind, QStringLiteral("lesson"));
    // The only warning a shipped lesson may give is the SAT lesson's non-convex cup.
    for (const QString& w : loaded.warnings)
        QVERIFY2(w.contains(QStringLiteral("sat_non_convex.json")), qPrintable(w));
}

void TestLesson::shippedLessonsLabelEveryBody_data()
{
    shippedLessonsLoad_data();
}

void TestLesson::shippedLessonsLabelEveryBody()
{
    QFETCH(QString, path);
    const lessons::LessonLoadResult loaded = lessons::loadLessonFile(path);
    QVERIFY2(loaded.ok, qPrintable(loaded.error));
    // Every shipped language reads the same lesson, and a translated one lacks no text.
    std::vector<lessons::Lesson> inLanguage;
    for (const lessons::Language& language : lessons::kLanguages) {
        const lessons::LessonLoadResult in =
            lessons::loadLessonFile(path, {language.code.toString()});
        QVERIFY2(in.ok, qPrintable(in.error));
        QCOMPARE(in.lesson.steps.size(), loaded.lesson.steps.size());
        inLanguage.push_back(in.lesson);
    }
    // Tables, the inspector and the SAT panel name bodies by their labels: every body of a
    // shipped lesson has one of its own in every language, and a translated one is not the
    // English label copied (nor the id).
    const lessons::Lesson& english = inLanguage.front();
    for (std::size_t l = 0; l < inLanguage.size(); ++l) {
        for (std::size_t s = 0; s < english.steps.size(); ++s) {
            const lessons::Scene& scene = inLanguage[l].steps[s].scene;
            const lessons::Scene& en = english.steps[s].scene;
            for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
                const auto id = static_cast<physics::BodyId>(b);
                const QString where =
                    QStringLiteral("%1, step %2, body \"%3\"")
                        .arg(lessons::kLanguages[l].code.toString(), QString::number(s + 1),
                             QString::fromStdString(scene.bodies[b].name));
                QVERIFY2(scene.hasLabel(id), qPrintable(where));
                if (l > 0) {
                    QVERIFY2(scene.bodyLabel(id) != en.bodyLabel(id), qPrintable(where));
                    QVERIFY2(scene.bodyLabel(id) != QString::fromStdString(scene.bodies[b].name),
                             qPrintable(where));
                }
            }
        }
    }
}

void TestLesson::validateRecognisesLessons()
{
    const lessons::DocumentCheck check = lessons::checkDocumentFile(lessonPath("restitution"));
    QVERIFY2(check.ok, qPrintable(check.error));
    QCOMPARE(check.kind, QStringLiteral("lesson"));
    QCOMPARE(check.summary,
             QStringLiteral("lesson \"Bounces and collisions: the coefficient of restitution\": "
                            "4 steps, 7 questions, 7 plots"));

    const lessons::DocumentCheck sat = lessons::checkDocumentFile(lessonPath("separating_axis"));
    QVERIFY2(sat.ok, qPrintable(sat.error));
    QCOMPARE(sat.warnings.size(), 1);
    QVERIFY(sat.warnings[0].contains(QStringLiteral("separating_axis.json: steps[3].scene: ")));
    QVERIFY(sat.warnings[0].contains(QStringLiteral("replaced by its convex hull")));
}

void TestLesson::shippedLessonsInTeachingOrder()
{
    const std::vector<lessons::LessonEntry> entries = lessons::lessonsInOrder(kLessonsDir);
    const QStringList files =
        QDir(kLessonsDir).entryList({QStringLiteral("*.json")}, QDir::Files, QDir::Name);
    QCOMPARE(static_cast<qsizetype>(entries.size()), files.size());
    // Every shipped lesson has its own place, and the list follows the places.
    for (std::size_t i = 1; i < entries.size(); ++i)
        QVERIFY2(entries[i - 1].order < entries[i].order, qPrintable(entries[i].path));
    // The teaching order: how a step works first, then collisions, their detection, stacks,
    // stiffness, the billiards break that puts collisions and momentum together, and last the
    // lab checked against a measurement.
    QStringList names;
    for (const lessons::LessonEntry& e : entries)
        names << QFileInfo(e.path).baseName();
    const QStringList expected{
        QStringLiteral("energy_drift"),       QStringLiteral("restitution"),
        QStringLiteral("separating_axis"),    QStringLiteral("stacks"),
        QStringLiteral("stiff_springs"),      QStringLiteral("billiards_momentum"),
        QStringLiteral("lab_vs_measurement"), QStringLiteral("rotation_inertia"),
        QStringLiteral("force_accumulators"), QStringLiteral("impulse_formula"),
        QStringLiteral("tunnelling")};
    QCOMPARE(names, expected);
    // The menu line: number, title, description and time, each as the file gives it.
    const lessons::LessonEntry& first = entries.front();
    const lessons::Lesson lesson = shippedLesson("energy_drift");
    QCOMPARE(lessons::lessonMenuText(first, 1), QStringLiteral("1. %1 — %2 (≈%3 min)")
                                                    .arg(lesson.title, lesson.description)
                                                    .arg(lesson.minutes));
}

void TestLesson::lessonsWithoutOrderComeLast()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    QVERIFY(QDir(dir.path()).mkdir(QStringLiteral("scenes")));
    QVERIFY(writeFile(dir.filePath(QStringLiteral("scenes/ok.json")), kScene));
    const auto lesson = [](const char* title, const char* more) {
        return QByteArray(R"({"rigidlab-lesson": 1, "title": ")") + title + '"' + more +
               R"(, "steps": [{"title": "s", "scene": "scenes/ok.json"}]})";
    };
    QVERIFY(writeFile(dir.filePath(QStringLiteral("a.json")), lesson("A", "")));
    QVERIFY(writeFile(dir.filePath(QStringLiteral("b.json")), lesson("B", R"(, "order": 7)")));
    QVERIFY(writeFile(dir.filePath(QStringLiteral("c.json")),
                      lesson("C", R"(, "order": 2, "description": "the first", "minutes": 5)")));
    QVERIFY(writeFile(dir.filePath(QStringLiteral("d.json")), lesson("D", R"(, "order": "x")")));
    const std::vector<lessons::LessonEntry> entries = lessons::lessonsInOrder(dir.path());
    QStringList titles;
    for (const lessons::LessonEntry& e : entries)
        titles << e.title;
    // d.json does not load and is left out; a.json has no place and comes after the others.
    QCOMPARE(titles, (QStringList{QStringLiteral("C"), QStringLiteral("B"), QStringLiteral("A")}));
    QCOMPARE(lessons::lessonMenuText(entries[0], 1), QStringLiteral("1. C — the first (≈5 min)"));
    QCOMPARE(lessons::lessonMenuText(entries[2], 3), QStringLiteral("3. A"));
    QVERIFY(lessons::lessonsInOrder(QString()).empty());
}

void TestLesson::userLessonsListedAfterShipped()
{
    // The test's $HOME is fresh: the user's folder does not exist yet, and the list is the
    // shipped one.
    const QString own = lessons::userLessonsDir();
    QVERIFY2(!QFileInfo::exists(own), qPrintable(own));
    const std::vector<lessons::LessonEntry> shipped = lessons::shippedLessonsInOrder();
    QVERIFY(!shipped.empty());
    QCOMPARE(lessons::allLessonsInOrder().size(), shipped.size());

    // A lesson of the user's own, with its scene beside it as in the shipped folder; a place
    // before every shipped one still lists it after them.
    QVERIFY(QDir().mkpath(QDir(own).filePath(QStringLiteral("scenes"))));
    QVERIFY(writeFile(QDir(own).filePath(QStringLiteral("scenes/ok.json")), kScene));
    QVERIFY(writeFile(QDir(own).filePath(QStringLiteral("my_lesson.json")),
                      R"({"rigidlab-lesson": 1, "title": "Mine", "order": 1, "minutes": 10,
                  "steps": [{"title": "s", "scene": "scenes/ok.json"}]})"));
    const std::vector<lessons::LessonEntry> all = lessons::allLessonsInOrder();
    QCOMPARE(all.size(), shipped.size() + 1);
    for (std::size_t i = 0; i < shipped.size(); ++i) {
        QCOMPARE(all[i].path, shipped[i].path);
        QVERIFY(!all[i].own);
    }
    const lessons::LessonEntry& mine = all.back();
    QCOMPARE(QFileInfo(mine.path).canonicalFilePath(),
             QFileInfo(QDir(own).filePath(QStringLiteral("my_lesson.json"))).canonicalFilePath());
    QVERIFY(mine.own);
    QCOMPARE(mine.title, QStringLiteral("Mine"));
    QCOMPARE(lessons::lessonMenuText(mine, 7), QStringLiteral("7. Mine (≈10 min) (your own)"));
    // The user's folder is not the shipped one.
    QVERIFY(!mine.path.startsWith(lessons::shippedLessonsDir()));
}

void TestLesson::rejectsSymbolicLinkOutOfFolder()
{
    QTemporaryDir outside;
    QTemporaryDir dir;
    QVERIFY(outside.isValid() && dir.isValid());
    QVERIFY(writeFile(outside.filePath(QStringLiteral("secret.json")), kScene));
    QVERIFY(QFile::link(outside.filePath(QStringLiteral("secret.json")),
                        dir.filePath(QStringLiteral("link.json"))));
    const QString path = dir.filePath(QStringLiteral("lesson.json"));
    QVERIFY(writeFile(path, stepWithScene(R"("link.json")")));
    const lessons::LessonLoadResult loaded = lessons::loadLessonFile(path);
    QVERIFY(!loaded.ok);
    QCOMPARE(loaded.error,
             path + QStringLiteral(R"(: steps[0].scene: "link.json" leads out of the lesson's )"
                                   "folder (through a symbolic link)"));

    // A scene file that is missing says so, with both places.
    QVERIFY(writeFile(path, stepWithScene(R"("scenes/none.json")")));
    const lessons::LessonLoadResult missing = lessons::loadLessonFile(path);
    QVERIFY(!missing.ok);
    QVERIFY2(missing.error.startsWith(path + QStringLiteral(": steps[0].scene: ")) &&
                 missing.error.contains(QStringLiteral("scenes/none.json: cannot read")),
             qPrintable(missing.error));
}

void TestLesson::sceneFileErrorsCarryBothPlaces()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    QVERIFY(QDir(dir.path()).mkdir(QStringLiteral("scenes")));
    QVERIFY(writeFile(
        dir.filePath(QStringLiteral("scenes/bad.json")),
        R"({"rigidlab": 1, "bodies": [{"id": "b", "shape": {"type": "circle", "radius": -1}}]})"));
    const QString path = dir.filePath(QStringLiteral("lesson.json"));
    QVERIFY(writeFile(path, stepWithScene(R"("scenes/bad.json")")));
    const lessons::LessonLoadResult loaded = lessons::loadLessonFile(path);
    QVERIFY(!loaded.ok);
    QCOMPARE(loaded.error, path + QStringLiteral(": steps[0].scene: ") + dir.path() +
                               QStringLiteral("/scenes/bad.json: bodies[0].shape.radius: must be "
                                              "a positive number, got -1"));
}

void TestLesson::inlineSceneErrorsContinueThePlace()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("lesson.json"));
    QVERIFY(writeFile(
        path,
        stepWithScene(R"({"rigidlab": 1, "bodies": [{"id": "b", "shape": )"
                      R"({"type": "polygon", "vertices": [[0, 0], [1, 0], [0.2, 0.2], [0, 1]]}}, )"
                      R"({"id": "c", "color": 1}]})")));
    const lessons::LessonLoadResult loaded = lessons::loadLessonFile(path);
    QVERIFY(!loaded.ok);
    QVERIFY2(loaded.error.startsWith(path + QStringLiteral(": steps[0].scene.bodies[1].color: "
                                                           "unknown key")),
             qPrintable(loaded.error));
    QCOMPARE(loaded.warnings.size(), 1);
    QVERIFY2(loaded.warnings[0].startsWith(
                 path + QStringLiteral(": steps[0].scene.bodies[0].shape.vertices: the polygon "
                                       "is not convex")),
             qPrintable(loaded.warnings[0]));
}

/// A lesson with every field of a lesson and a step set (none at its default).
QByteArray everyFieldLesson()
{
    return QByteArray(R"({"rigidlab-lesson": 1, "title": "T", "summary": "S", "level": "L", )"
                      R"("minutes": 12, "goals": ["g1", "g2"], "steps": [{"title": "s", )"
                      R"("text": ["a", "", "b"], "scene": )") +
           kScene +
           R"(, "settings": {"dt": 0.002, "solver": "seed-impulse", "iterations": 7, )"
           R"("restitution": 0.25, "friction": 0.5, "gravity": false, "timeScale": 0.5}, )"
           R"("compare": {"integrators": ["rk4", "euler"], "offset": [1, -2]}, )"
           R"("plots": ["compare-energy", "momentum"], "overlays": ["trails"], )"
           R"("panels": ["sat", "controls"], "allow": [], "sat": {"a": "box", "b": "wedge"}, )"
           R"("editor": {"tools": ["select", "box"], "properties": []}, )"
           R"("questions": [{"prompt": "p", "measure": {"kind": "apex", "body": "ball", )"
           R"("n": 3, "above": 0.1}, "unit": "m", "tolerance": 0.1, "absoluteTolerance": 0.01, )"
           R"("hint": "h", "holdBack": ["run", "panel:controls", "plot:momentum"]}, )"
           R"({"prompt": "q", "measure": {"kind": "momentum-y", "time": 2.5}, )"
           R"("holdBack": ["plot:momentum"]}], )"
           R"("exportTime": 3, "autoplay": false}]})";
}

void TestLesson::everyField()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("lesson.json"));
    QVERIFY(writeFile(path, everyFieldLesson()));
    const lessons::LessonLoadResult loaded = lessons::loadLessonFile(path);
    QVERIFY2(loaded.ok, qPrintable(loaded.error));
    const lessons::Lesson& l = loaded.lesson;
    QCOMPARE(l.title, QStringLiteral("T"));
    QCOMPARE(l.summary, QStringLiteral("S"));
    QCOMPARE(l.level, QStringLiteral("L"));
    QCOMPARE(l.minutes, 12);
    QCOMPARE(l.goals, (QStringList{QStringLiteral("g1"), QStringLiteral("g2")}));
    QCOMPARE(l.steps.size(), std::size_t{1});
    const lessons::LessonStep& s = l.steps[0];
    QCOMPARE(s.text, QStringLiteral("a\n\nb"));
    QVERIFY(s.scenePath.isEmpty());
    QCOMPARE(s.scene.bodies.size(), std::size_t{4});
    QVERIFY(!s.settings.has("integrator"));
    QCOMPARE(*s.settings.get<double>("dt"), 0.002);
    QCOMPARE(physics::solverFromName(s.settings.get<QString>("solver")->toStdString()),
             physics::SolverKind::PaperImpulse);
    QCOMPARE(*s.settings.get<int>("iterations"), 7);
    QCOMPARE(*s.settings.get<double>("restitution"), 0.25);
    QCOMPARE(*s.settings.get<double>("friction"), 0.5);
    QCOMPARE(*s.settings.get<bool>("gravity"), false);
    QCOMPARE(*s.settings.get<double>("timeScale"), 0.5);
    QVERIFY(s.compare);
    QCOMPARE(s.compare->count(), 2);
    QCOMPARE(s.compare->label(0), QStringLiteral("rk4"));
    QCOMPARE(s.compare->label(1), QStringLiteral("euler"));
    QCOMPARE(s.compare->offset, physics::Vec2(1, -2));
    QCOMPARE(s.plots, (QStringList{QStringLiteral("compare-energy"), QStringLiteral("momentum")}));
    QCOMPARE(s.overlays, QStringList{QStringLiteral("trails")});
    QCOMPARE(s.panels, (QStringList{QStringLiteral("sat"), QStringLiteral("controls")}));
    QVERIFY(s.allow && s.allow->isEmpty());
    QCOMPARE(*s.sat, std::pair(QStringLiteral("box"), QStringLiteral("wedge")));
    QVERIFY(s.editor);
    QCOMPARE(s.editor->tools, (QStringList{QStringLiteral("select"), QStringLiteral("box")}));
    QCOMPARE(s.editor->properties, QStringList()); // [] locks them all
    QCOMPARE(s.questions.size(), std::size_t{2});
    const lessons::Question& q = s.questions[0];
    QCOMPARE(q.prompt, QStringLiteral("p"));
    QCOMPARE(measuredOf(q).measure.kind, lessons::Measure::Kind::Apex);
    QCOMPARE(measuredOf(q).measure.body, QStringLiteral("ball"));
    QCOMPARE(measuredOf(q).measure.n, 3);
    QCOMPARE(measuredOf(q).measure.above, 0.1);
    QCOMPARE(measuredOf(q).unit, QStringLiteral("m"));
    QCOMPARE(measuredOf(q).tolerance, 0.1);
    QCOMPARE(measuredOf(q).absoluteTolerance, 0.01);
    QCOMPARE(measuredOf(s.questions[1]).measure.kind, lessons::Measure::Kind::MomentumY);
    QCOMPARE(measuredOf(s.questions[1]).measure.time, 2.5);
    QCOMPARE(measuredOf(s.questions[1]).tolerance, 0.05);
    QCOMPARE(q.hint, QStringLiteral("h"));
    const QString run = QStringLiteral("run"), controls = QStringLiteral("panel:controls"),
                  momentum = QStringLiteral("plot:momentum");
    QCOMPARE(q.holdBack, (QStringList{run, controls, momentum}));
    QVERIFY(s.questions[1].hint.isEmpty());
    // What both questions hold back stays held until both are answered.
    QCOMPARE(s.heldBack({}), (QStringList{run, controls, momentum}));
    QCOMPARE(s.heldBack({true, false}), QStringList{momentum});
    QCOMPARE(s.heldBack({false, true}), (QStringList{run, controls, momentum}));
    QVERIFY(s.heldBack({true, true}).isEmpty());
    QCOMPARE(s.exportTime, 3.0);
    QCOMPARE(s.autoplay, false);

    // Defaults.
    QVERIFY(writeFile(path, oneStep("")));
    const lessons::LessonLoadResult bare = lessons::loadLessonFile(path);
    QVERIFY2(bare.ok, qPrintable(bare.error));
    const lessons::LessonStep& d = bare.lesson.steps[0];
    QVERIFY(d.text.isEmpty() && d.plots.isEmpty() && d.panels.isEmpty() && d.overlays.isEmpty());
    QVERIFY(!d.allow && !d.sat && !d.compare && d.questions.empty());
    QVERIFY(d.heldBack({}).isEmpty());
    QCOMPARE(d.exportTime, 10.0);
    QVERIFY(d.autoplay);
}

void TestLesson::editorListsDefaultToAll()
{
    // "editor": {} opens the editor with everything unlocked; no "editor", no editor.
    const lessons::LessonLoadResult open =
        lessons::loadLessonJson(oneStep(R"("editor": {})"), QStringLiteral("l.json"));
    QVERIFY2(open.ok, qPrintable(open.error));
    const auto& editor = open.lesson.steps[0].editor;
    QVERIFY(editor);
    QCOMPARE(editor->tools.size(), qsizetype(lessons::kEditorToolNames.size()));
    QCOMPARE(editor->properties.size(), qsizetype(lessons::schema::editorPropertyNames().size()));
    QVERIFY(editor->tools.contains(QStringLiteral("duplicate")));
    QVERIFY(editor->properties.contains(QStringLiteral("iterations")));
    const lessons::LessonLoadResult none =
        lessons::loadLessonJson(oneStep(""), QStringLiteral("l.json"));
    QVERIFY2(none.ok, qPrintable(none.error));
    QVERIFY(!none.lesson.steps[0].editor);
}

void TestLesson::formatDocumentExampleLoads()
{
    // The complete example of LESSON_FORMAT.md loads, beside copies of the shipped scenes it
    // names.
    QFile doc(rigidlab::test::sourcePath(u"/lessons/LESSON_FORMAT.md"));
    QVERIFY(doc.open(QIODevice::ReadOnly));
    const QString text = QString::fromUtf8(doc.readAll());
    const QRegularExpression block(QStringLiteral("```json\\n(.*?)```"),
                                   QRegularExpression::DotMatchesEverythingOption);
    const QRegularExpressionMatch match = block.match(text);
    QVERIFY(match.hasMatch());
    QTemporaryDir dir;
    QVERIFY(QDir(dir.path()).mkdir(QStringLiteral("scenes")) &&
            QDir(dir.path()).mkdir(QStringLiteral("lessons")));
    for (const char* scene : {"four_balls.json", "sat_apart.json"})
        QVERIFY(QFile::copy(QDir(kScenesDir).filePath(QLatin1StringView(scene)),
                            dir.filePath(QStringLiteral("scenes/") + scene)));
    const QString path = dir.filePath(QStringLiteral("lessons/example.json"));
    QVERIFY(writeFile(path, match.captured(1).toUtf8()));
    const lessons::LessonLoadResult loaded = lessons::loadLessonFile(path);
    QVERIFY2(loaded.ok, qPrintable(loaded.error));
    QCOMPARE(loaded.lesson.steps.size(), std::size_t{3});
}

void TestLesson::originalVerticesOfNonConvexPolygon()
{
    const lessons::Lesson lesson = shippedLesson("separating_axis");
    QCOMPARE(lesson.steps.size(), std::size_t{4});
    const lessons::Scene& cup = lesson.steps[3].scene;
    QCOMPARE(cup.originalVertices.size(), cup.bodies.size());
    QCOMPARE(cup.originalVertices[0].size(), std::size_t{8}); // the cup, as the file gives it
    QVERIFY(cup.bodies[0].shape.asPolygon());
    QCOMPARE(cup.bodies[0].shape.asPolygon()->vertices.size(), std::size_t{4}); // its hull
    QCOMPARE(cup.originalVertices[0][4], physics::Vec2(0.3, -0.2));
    QVERIFY(cup.originalVertices[1].empty()); // the box was not replaced
    for (const auto& v : lesson.steps[0].scene.originalVertices)
        QVERIFY(v.empty());
}

void TestLesson::buildStepWorldsMakesOneWorldPerVariant()
{
    const lessons::Lesson lesson = shippedLesson("energy_drift");
    const lessons::LessonStep& step = lesson.steps[0];
    std::vector<physics::World> worlds = lessons::buildStepWorlds(step);
    QCOMPARE(worlds.size(), std::size_t{4});
    const physics::IntegratorKind kinds[] = {
        physics::IntegratorKind::Euler, physics::IntegratorKind::SymplecticEuler,
        physics::IntegratorKind::Verlet, physics::IntegratorKind::RK4};
    for (std::size_t i = 0; i < 4; ++i) {
        QCOMPARE(worlds[i].def().integrator, kinds[i]);
        QCOMPARE(worlds[i].integrator().kind(), kinds[i]);
        QCOMPARE(worlds[i].def().dt, 0.01);
        QCOMPARE(worlds[i].bodies().size(), step.scene.bodies.size());
    }
    QCOMPARE(step.compare->label(2), QStringLiteral("verlet"));

    const lessons::Lesson stacks = shippedLesson("stacks");
    std::vector<physics::World> solvers = lessons::buildStepWorlds(stacks.steps[0]);
    QCOMPARE(solvers.size(), std::size_t{2});
    QCOMPARE(solvers[0].def().solver, physics::SolverKind::PaperImpulse);
    QCOMPARE(solvers[1].def().solver, physics::SolverKind::SequentialImpulse);
    QCOMPARE(stacks.steps[0].compare->label(0), QStringLiteral("seed-impulse"));
    // Without a comparison, one world.
    QCOMPARE(lessons::buildStepWorlds(stacks.steps[1]).size(), std::size_t{1});
}

void TestLesson::applySettingsOverridesScene()
{
    lessons::StepSettings settings;
    settings.set("integrator",
                 lessons::textFromView(physics::integratorName(physics::IntegratorKind::RK4)));
    settings.set("dt", 0.004);
    settings.set("solver",
                 lessons::textFromView(physics::solverName(physics::SolverKind::PaperImpulse)));
    settings.set("iterations", 3);
    settings.set("restitution", 0.3);
    settings.set("friction", 0.7);
    settings.set("gravity", false);
    const lessons::Lesson lesson = shippedLesson("restitution");
    physics::World world = lessons::buildWorld(lesson.steps[0].scene);
    lessons::applySettings(settings, world);
    QCOMPARE(world.def().integrator, physics::IntegratorKind::RK4);
    QCOMPARE(world.def().dt, 0.004);
    QCOMPARE(world.def().solver, physics::SolverKind::PaperImpulse);
    QCOMPARE(world.def().iterations, 3);
    QCOMPARE(world.def().gravity, physics::Vec2::Zero());
    for (const physics::Body& b : world.bodies()) {
        QCOMPARE(b.restitution, 0.3);
        QCOMPARE(b.friction, 0.7);
    }
    // Gravity on for a weightless scene gives it the Earth's.
    physics::World space = lessons::buildWorld(lesson.steps[1].scene);
    lessons::StepSettings on;
    on.set("gravity", true);
    lessons::applySettings(on, space);
    QCOMPARE(space.def().gravity, physics::Vec2(0, -9.81));
}
