// SPDX-License-Identifier: GPL-3.0-or-later
// The collision panel's impulse formula with the numbers of the lesson's off-centre hit
// substituted: each term as the formula evaluated here gives it, j kept back while the
// velocities after the hit are, and the numbers in the language's own format. And the
// inspector's forces on the accumulator lesson's crate, summed as its text sums them.

#include "build_paths.h"
#include "common/language.h"
#include "common/number_format.h"
#include "panels/forces_view.h"
#include "panels/impulse_formula_view.h"

#include "format/lesson.h"
#include "run/measurements.h"
#include "run/scene_run.h"

#include <QTextDocumentFragment>
#include <QtTest>

#include "test_main.h"

using namespace rigidlab;

namespace {

struct Hit {
    physics::World world;
    lessons::CollisionEvent event;
};

/// The first step of the impulse lesson run past its one hit.
std::optional<Hit> offCentreHit()
{
    const lessons::LessonLoadResult loaded = lessons::loadLessonFile(
        rigidlab::test::sourcePath(u"/lessons/lessons/impulse_formula.json"));
    if (!loaded.ok)
        return std::nullopt;
    physics::World world = lessons::buildStepWorlds(loaded.lesson.steps.at(0)).front();
    lessons::Measurements m;
    world.updateDiagnostics();
    m.reset(world, {});
    for (int i = 0; i < 1000 && m.collisions().empty(); ++i) {
        world.step();
        m.observe(world);
    }
    if (m.collisions().empty())
        return std::nullopt;
    return Hit{world, m.collisions().front()};
}

/// The text a reader gets (toPlainText() gives a no-break space as a plain one).
QString plain(const QString& html)
{
    return QTextDocumentFragment::fromHtml(html).toPlainText();
}

} // namespace

class TestImpulseFormula : public QObject {
    Q_OBJECT

private slots:
    void termsOfTheOffCentreHit()
    {
        const std::optional<Hit> hit = offCentreHit();
        QVERIFY(hit);
        const physics::Body& a = hit->world.body(hit->event.a);
        const physics::Body& b = hit->world.body(hit->event.b);
        // Rod 1 kg, I = 0.3342 kg m², hit 0.8 m off its centre; ball 0.5 kg; e = 1, 3 m/s.
        const double rotational = 0.8 * 0.8 / a.inertia;
        const double j = 2.0 * 3.0 / (1.0 + 2.0 + rotational);
        const QString text = plain(ui::impulseFormulaText(hit->event, a, b, QStringLiteral("rod"),
                                                          QStringLiteral("ball"), false));
        for (const QString& expected :
             {QStringLiteral("= −(1 + 1) × (%1 m/s) / (1 + 2 + %2 + 0)")
                  .arg(ui::formatReadable(-3.0, 4), QString::number(rotational, 'f', 3)),
              QStringLiteral("= %1 N·s").arg(QString::number(j, 'f', 3)),
              QStringLiteral("n = (0, 1)"), QStringLiteral("A: rod, B: ball")})
            QVERIFY2(text.contains(expected),
                     qPrintable(expected + QStringLiteral("\nin\n") + text));
        // Held back: the terms stay, j reads "?".
        const QString held = plain(ui::impulseFormulaText(hit->event, a, b, QStringLiteral("rod"),
                                                          QStringLiteral("ball"), true));
        QVERIFY(!held.contains(QString::number(j, 'f', 3)));
        QVERIFY(held.contains(QStringLiteral("= ?")));
        QVERIFY(held.contains(QString::number(rotational, 'f', 3)));
        // In Czech, with the decimal comma.
        QVERIFY(ui::applyLanguage(QStringLiteral("cs")));
        const QString cs = plain(ui::impulseFormulaText(hit->event, a, b, QStringLiteral("tyč"),
                                                        QStringLiteral("koule"), false));
        QVERIFY(ui::applyLanguage(QStringLiteral("en")));
        QVERIFY2(
            cs.contains(
                QStringLiteral("= %1 N·s").arg(QString::number(j, 'f', 3).replace(u'.', u','))),
            qPrintable(cs));
        QVERIFY2(cs.contains(QStringLiteral("normála")), qPrintable(cs));
    }

    void forcesOfTheCrate()
    {
        const lessons::LessonLoadResult loaded = lessons::loadLessonFile(
            rigidlab::test::sourcePath(u"/lessons/lessons/force_accumulators.json"));
        QVERIFY2(loaded.ok, qPrintable(loaded.error));
        const lessons::LessonStep& step = loaded.lesson.steps.at(0);
        const physics::World world = lessons::buildStepWorlds(step).front();
        const physics::BodyId crate = *step.scene.bodyIndex(QStringLiteral("crate"));
        ui::ForcesView view;
        view.showBody(world, crate);
        const QString text = plain(view.text());
        // Weight, drag, the cord and the push; their sums (4, 0) N and 0.5 N m; a and α.
        for (const QString& expected :
             {QStringLiteral("weight m g"), QStringLiteral("(0, -20)"), QStringLiteral("(-1, 0)"),
              QStringLiteral("(0, 20)"), QStringLiteral("(5, 0)"), QStringLiteral("(-0.2, -0.1)"),
              QStringLiteral("the accumulators"), QStringLiteral("(4, 0)"),
              QStringLiteral("a = F / m = (2, 0) m/s², α = τ / I = %1 rad/s²")
                  .arg(ui::formatReadable(0.5 / world.body(crate).inertia, 3))})
            QVERIFY2(text.contains(expected),
                     qPrintable(expected + QStringLiteral("\nin\n") + text));
        view.showNone();
        QVERIFY(!plain(view.text()).contains(QStringLiteral("(4, 0)")));
    }
};

RIGIDLAB_TEST_MAIN(TestImpulseFormula)
#include "test_impulse_formula.moc"
