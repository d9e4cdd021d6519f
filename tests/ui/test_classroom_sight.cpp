// SPDX-License-Identifier: GPL-3.0-or-later
// What a class sees on a 1024×768 projector, in Czech (the longest texts), in the window, with
// the Instruments open and in presentation mode, on every step of every shipped lesson,
// nothing scrolled: the window's frame on the screen; the first question's answer box, its
// Check button and its verdict in sight in the Lesson dock; the verdict as large as the step's
// text; each plot shown with a data area a class can read and no legend over its data; each
// table panel scrolled to its table, not to the description above it.

#include "classroom_util.h"
#include "test_main.h"

#include "common/language.h"
#include "measure/measurement_panel.h"
#include "measure/measurement_session.h"
#include "panels/inspector_panel.h"
#include "plots/plot_shelf.h"

#include "format/data_dirs.h"

#include "question_kinds.h"

#include <QFormLayout>
#include <QHeaderView>
#include <QMessageBox>
#include <QRadioButton>
#include <QScopeGuard>
#include <QScrollBar>

using rigidlab::test::isChoice;

using namespace rigidlab;
using rigidlab::test::visitShippedSteps;
using rigidlab::ui::MainWindow;
using namespace rigidlab::test::classroom;

namespace {

enum class Mode { Window, Instruments, Presentation };

/// `w`'s rectangle in `dock`'s coordinates, and how much of it is drawn (not cut by a scroll
/// area or the dock's edge), as "x,y WxH (drawn WxH)" for messages.
QString placeOf(const QWidget& w, const QWidget& dock)
{
    const QRect drawn = w.visibleRegion().boundingRect();
    return QStringLiteral("%1 (drawn %2x%3) in the dock's %4x%5")
        .arg(rectText(QRect(w.mapTo(&dock, QPoint(0, 0)), w.size())))
        .arg(drawn.width())
        .arg(drawn.height())
        .arg(dock.width())
        .arg(dock.height());
}

/// The layout passes a change queues, done (a scroll bar that comes or goes lays the
/// questions out again at the new width, and so on): what the class sees a moment later.
void settle()
{
    for (int pass = 0; pass < 4; ++pass)
        QCoreApplication::processEvents();
}

/// Whole in sight in `dock` as it is now, without scrolling anything.
bool inSight(const QWidget& w, const QWidget& dock)
{
    const QRect r(w.mapTo(&dock, QPoint(0, 0)), w.size());
    return w.isVisible() && dock.rect().contains(r) &&
           w.visibleRegion().boundingRect().size() == w.size();
}

} // namespace

Q_DECLARE_METATYPE(Mode)

class TestClassroomSight : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { QVERIFY(ui::applyLanguage(QStringLiteral("cs"))); }
    void cleanupTestCase() { ui::applyLanguage(QStringLiteral("en")); }

    void everyStepInSight_data()
    {
        QTest::addColumn<Mode>("mode");
        QTest::newRow("window") << Mode::Window;
        QTest::newRow("instruments") << Mode::Instruments;
        QTest::newRow("presentation") << Mode::Presentation;
    }
    void everyStepInSight()
    {
        QFETCH(Mode, mode);
        MainWindow w;
        if (mode == Mode::Presentation)
            presentOn(w, kProjector);
        else
            showOn(w, kProjector);
        QVERIFY2(frameOutside(w, kProjector).isEmpty(), qPrintable(frameOutside(w, kProjector)));
        auto* lessonDock = w.findChild<QDockWidget*>(QStringLiteral("lessonDock"));
        QVERIFY(lessonDock);
        int questions = 0;
        int plots = 0;
        int measurementPlots = 0; // steps whose Measurement panel's plots were measured
        const bool walked =
            visitShippedSteps(w, [&](const QString& path, int i, const lessons::LessonStep& step) {
                if (mode == Mode::Instruments) {
                    auto* instruments =
                        w.findChild<QDockWidget*>(QStringLiteral("instrumentsDock"));
                    QVERIFY(instruments);
                    instruments->show();
                    instruments->raise();
                    QCoreApplication::processEvents();
                }
                const QString where =
                    QStringLiteral("%1 step %2: ").arg(QFileInfo(path).baseName()).arg(i + 1);
                settle();
                // Whatever the step shows, the window stays on the screen: a wider one would
                // pass every check below with its right-hand docks off the projector.
                if (const QString off = frameOutside(w, kProjector); !off.isEmpty())
                    QFAIL(qPrintable(where + off));
                if (!step.questions.empty()) {
                    checkFirstQuestion(w, *lessonDock, step.questions.front(), where);
                    ++questions;
                }
                if (QTest::currentTestFailed())
                    return;
                plots += checkPlots(w, where);
                checkTables(w, where);
                // The Measurement panel's plots are held to the rule like the others: where
                // a step shows the panel, they are among those measured.
                if (w.measurement().panel()->comparisonPlot()->isVisible())
                    ++measurementPlots;
            });
        if (!walked)
            return;
        QVERIFY2(questions >= 10, qPrintable(QString::number(questions)));
        QVERIFY2(plots >= test::atLeast(20, 17), qPrintable(QString::number(plots)));
        QVERIFY2(measurementPlots >= test::atLeast(2, 1),
                 qPrintable(QString::number(measurementPlots)));
    }

    // A step reached by skipping those before it (a lesson's list of steps, a teacher's jump)
    // keeps the window on the screen in presentation mode: its docks, shown one by one before
    // they are grouped, grew it to 1024x794 once.
    void skippedStepsKeepTheFrame()
    {
        MainWindow w;
        presentOn(w, kProjector);
        for (const QString& path : test::shippedLessons()) {
            QCOMPARE(w.openLesson(path, true), QString());
            const int count = static_cast<int>(w.lessonPlayer().lesson()->steps.size());
            for (int i = count - 1; i >= 0; i -= 2) { // the last first, then every other
                w.lessonPlayer().goToStep(i);
                settle();
                const QString where =
                    QStringLiteral("%1 step %2: ").arg(QFileInfo(path).baseName()).arg(i + 1);
                if (const QString off = frameOutside(w, kProjector); !off.isEmpty())
                    QFAIL(qPrintable(where + off));
            }
        }
    }

    // Lesson 7's fit on the projector: once Fit has answered, every line of its result is in
    // sight in the Measurement dock (the controls' column scrolls to it). In the window only:
    // in presentation mode the panel is a few pixels taller than its dock.
    void fitResultInSight()
    {
        MainWindow w;
        w.setUnsavedAsker([] { return int(QMessageBox::Discard); });
        showOn(w, kProjector);
        QCOMPARE(
            w.openLesson(lessons::shippedLessonsDir() + QStringLiteral("/lab_vs_measurement.json"),
                         true),
            QString());
        w.lessonPlayer().goToStep(1); // "Fit e to the measurement"
        ui::MeasurementSession& session = w.measurement();
        QCOMPARE(session.load(lessons::shippedDataDir() +
                              QStringLiteral("/measure/samples/ball_tracker.csv")),
                 QString());
        settle();
        QVERIFY2(session.fitting().fit().ok, qPrintable(session.fitting().fit().error));
        settle();
        ui::MeasurementPanel& panel = *session.panel();
        QLabel* result = nullptr;
        for (QLabel* l : panel.findChildren<QLabel*>())
            if (l->isVisible() && l->text() == panel.fitText())
                result = l;
        QVERIFY2(result && panel.fitText().contains(QStringLiteral("±")),
                 qPrintable(panel.fitText()));
        QDockWidget* dock = w.dock(QStringLiteral("measurement"));
        QVERIFY(dock && !dock->visibleRegion().isEmpty());
        QVERIFY2(frameOutside(w, kProjector).isEmpty(), qPrintable(frameOutside(w, kProjector)));
        QVERIFY2(inSight(*result, *dock),
                 qPrintable(QStringLiteral("fit result at ") + placeOf(*result, *dock)));
    }

    // A body's numbers asked for on the projector (] then Enter on the scene), in the
    // restitution lesson whose Bounces table shares the side column: the Inspector does not
    // scroll sideways, and its mass field's unit is whole in sight, in Czech (the longest
    // labels: "Jednotka úhlů" beside its list once made the column scroll) and in English.
    void inspectorFitsTheProjectorColumn_data()
    {
        QTest::addColumn<QString>("language");
        QTest::addColumn<QString>("file");
        // A lesson's window (the Lesson dock beside it) and the welcome scene's (no lesson).
        const QString lesson = lessons::shippedLessonsDir() + QStringLiteral("/restitution.json");
        const QString welcome = ui::MainWindow::scenesFolder() + QStringLiteral("/welcome.json");
        for (const char* language : {"cs", "en"}) {
            QTest::addRow("%s lesson", language) << QString::fromLatin1(language) << lesson;
            QTest::addRow("%s scene", language) << QString::fromLatin1(language) << welcome;
        }
    }
    void inspectorFitsTheProjectorColumn()
    {
        QFETCH(QString, language);
        QFETCH(QString, file);
        QVERIFY(ui::applyLanguage(language));
        // Czech again afterwards, for the rest of this program's tests.
        const auto czech = qScopeGuard([] { ui::applyLanguage(QStringLiteral("cs")); });
        MainWindow w;
        showOn(w, kProjector);
        const bool lesson = !file.startsWith(ui::MainWindow::scenesFolder());
        if (!lesson)
            QCOMPARE(w.openScene(file), QString());
        else
            QCOMPARE(w.openLesson(file, true), QString());
        settle();
        QTest::keyClick(&w.view(), Qt::Key_BracketRight);
        QVERIFY(w.view().selectedBody() >= 0);
        QTest::keyClick(&w.view(), Qt::Key_Return);
        settle();
        QVERIFY(w.inspector().isVisible());
        const QScrollArea* scroll = nullptr;
        for (QWidget* p = w.inspector().parentWidget(); p && !scroll; p = p->parentWidget())
            scroll = qobject_cast<const QScrollArea*>(p);
        QVERIFY(scroll);
        QVERIFY2(!scroll->horizontalScrollBar()->isVisible(),
                 qPrintable(QStringLiteral("the inspector is %1 px wide in a %2 px column")
                                .arg(w.inspector().minimumSizeHint().width())
                                .arg(scroll->viewport()->width())));
        // The welcome scene's first body (the windmill) is driven: its mass reads "infinite".
        const auto* unit = w.inspector().findChild<QLabel*>(QStringLiteral("massUnit"));
        QVERIFY(unit && (unit->isVisible() || !lesson));
        const QRect r(unit->mapTo(scroll->viewport(), QPoint(0, 0)), unit->size());
        QVERIFY2(!unit->isVisible() || (r.left() >= 0 && r.right() < scroll->viewport()->width()),
                 qPrintable(QStringLiteral("the mass unit at %1 in a %2 px column")
                                .arg(rectText(r))
                                .arg(scroll->viewport()->width())));
        checkRowsWhole(w.inspector());
    }

    /// What Check says under the last question too, after the first was answered: whole in
    /// sight in the Lesson dock (restitution's second step, whose questions do not all fit
    /// once a verdict is shown). It was cut to its first line, or out of sight: the questions
    /// were scrolled to the verdict's first line only, or before it had its place.
    void lastVerdictInSight()
    {
        MainWindow w;
        showOn(w, kProjector);
        QCOMPARE(
            w.openLesson(lessons::shippedLessonsDir() + QStringLiteral("/restitution.json"), true),
            QString());
        w.lessonPlayer().goToStep(1);
        settle();
        auto* box = w.findChild<QWidget*>(QStringLiteral("lessonQuestions"));
        QVERIFY(box && box->layout() && box->layout()->count() >= 2);
        const auto* dock = w.findChild<QDockWidget*>(QStringLiteral("lessonDock"));
        QVERIFY(dock);
        QWidget* verdict = nullptr;
        for (int q = 0; q < 2; ++q) {
            QWidget* row = box->layout()->itemAt(q)->widget();
            auto* edit = row->findChild<QLineEdit*>();
            QVERIFY(edit);
            edit->setFocus();
            QTest::keyClicks(edit, q == 0 ? QStringLiteral("2") : QStringLiteral("-1"));
            QTest::keyClick(edit, Qt::Key_Return);
            settle();
            for (QLabel* l : row->findChildren<QLabel*>())
                if (l->isVisible() && l->wordWrap() && !l->buddy() && !l->text().isEmpty() &&
                    l->parentWidget() == row)
                    verdict = l;
        }
        QVERIFY(verdict);
        QVERIFY2(inSight(*verdict, *dock), qPrintable(placeOf(*verdict, *dock)));
    }

private:
    /// A widget as a message names it: its text if it is a label, else its object name.
    static QString nameOf(const QWidget& x)
    {
        const auto* label = qobject_cast<const QLabel*>(&x);
        return QLatin1Char('"') + (label ? label->text() : x.objectName()) + QLatin1Char('"');
    }

    /// Every row of the panel's form whole: each label as tall as its text needs at its width
    /// (a label wrapped to three lines shows all three) and no label or value over another.
    static void checkRowsWhole(const QWidget& panel)
    {
        const auto* form = qobject_cast<const QFormLayout*>(panel.layout());
        QVERIFY(form);
        QList<const QWidget*> shown;
        for (int row = 0; row < form->rowCount(); ++row)
            for (auto role :
                 {QFormLayout::LabelRole, QFormLayout::FieldRole, QFormLayout::SpanningRole}) {
                const QLayoutItem* item = form->itemAt(row, role);
                const QWidget* x = item ? item->widget() : nullptr;
                if (!x || !x->isVisible() || shown.contains(x))
                    continue;
                shown << x;
                const auto* label = qobject_cast<const QLabel*>(x);
                if (!label || label->text().isEmpty())
                    continue;
                const int needs = label->wordWrap() ? label->heightForWidth(label->width())
                                                    : label->sizeHint().height();
                QVERIFY2(label->height() >= needs,
                         qPrintable(QStringLiteral("%1 is %2x%3 px, its text needs %4 px")
                                        .arg(nameOf(*label))
                                        .arg(label->width())
                                        .arg(label->height())
                                        .arg(needs)));
            }
        for (qsizetype i = 0; i < shown.size(); ++i)
            for (qsizetype j = i + 1; j < shown.size(); ++j) {
                const QRect a = shown[i]->geometry(), b = shown[j]->geometry();
                QVERIFY2(!a.intersects(b), qPrintable(QStringLiteral("%1 at %2 over %3 at %4")
                                                          .arg(nameOf(*shown[i]), rectText(a),
                                                               nameOf(*shown[j]), rectText(b))));
            }
    }

    /// The first question's answer box (a choice's options) and Check in sight; Check pressed
    /// with no answer, its line in sight too, in a font no smaller than the step's text.
    static void checkFirstQuestion(MainWindow& w, const QDockWidget& dock,
                                   const lessons::Question& q, const QString& where)
    {
        auto* box = w.findChild<QWidget*>(QStringLiteral("lessonQuestions"));
        QVERIFY(box);
        const QLayout* rows = box->layout();
        QVERIFY(rows && rows->count() > 0 && rows->itemAt(0)->widget());
        QWidget* first = rows->itemAt(0)->widget();
        QList<QWidget*> answer;
        if (isChoice(q))
            for (QRadioButton* option : first->findChildren<QRadioButton*>())
                answer << option;
        else
            answer << first->findChild<QLineEdit*>();
        QPushButton* check = nullptr;
        for (QPushButton* b : first->findChildren<QPushButton*>())
            if (b->text() == QCoreApplication::translate("rigidlab::ui::LessonPlayer", "Check"))
                check = b;
        QVERIFY2(check && !answer.isEmpty() && answer.front(),
                 qPrintable(where + QStringLiteral("no answer box or Check")));
        for (const QWidget* x : answer)
            QVERIFY2(inSight(*x, dock),
                     qPrintable(where + QStringLiteral("answer box at ") + placeOf(*x, dock)));
        QVERIFY2(inSight(*check, dock),
                 qPrintable(where + QStringLiteral("Check at ") + placeOf(*check, dock)));
        // Nothing typed or chosen: Check says what to do first, on the verdict's line.
        check->click();
        settle();
        QLabel* verdict = nullptr;
        for (QLabel* l : first->findChildren<QLabel*>())
            if (l->isVisible() && l->wordWrap() && !l->buddy() && !l->text().isEmpty() &&
                l->parentWidget() == first)
                verdict = l;
        QVERIFY2(verdict, qPrintable(where + QStringLiteral("no verdict after Check")));
        QVERIFY2(inSight(*verdict, dock),
                 qPrintable(where + QStringLiteral("verdict \"%1\" at ").arg(verdict->text()) +
                            placeOf(*verdict, dock)));
        const auto* text = w.lessonPlayer().findChild<QTextBrowser*>();
        QVERIFY(text);
        const int verdictPx = QFontInfo(verdict->font()).pixelSize();
        const int textPx = QFontInfo(text->font()).pixelSize();
        QVERIFY2(verdictPx >= textPx,
                 qPrintable(
                     where +
                     QStringLiteral("verdict %1 px, step text %2 px").arg(verdictPx).arg(textPx)));
    }

    /// Each table panel in sight shows its table's head and first rows, not only the
    /// description above it.
    static void checkTables(MainWindow& w, const QString& where)
    {
        for (const char* name : {"sat", "bounces", "collision"}) {
            QDockWidget* dock = w.dock(QLatin1String(name));
            if (!dock || dock->isHidden() || dock->visibleRegion().isEmpty())
                continue;
            const auto* table = dock->findChild<QTableWidget*>();
            if (!table)
                continue;
            const auto* scroll = qobject_cast<const QScrollArea*>(dock->widget());
            QVERIFY(scroll);
            const int drawn = QRect(table->mapTo(scroll->viewport(), QPoint(0, 0)), table->size())
                                  .intersected(scroll->viewport()->rect())
                                  .height();
            const int wanted =
                std::min(table->height(), 3 * table->verticalHeader()->defaultSectionSize());
            QVERIFY2(drawn >= wanted,
                     qPrintable(where + QStringLiteral("%1 table: %2 px of it in sight, %3 wanted")
                                            .arg(QLatin1String(name))
                                            .arg(drawn)
                                            .arg(wanted)));
            // Sideways too: every column in sight without scrolling (a panel wider than its
            // dock hid the collision table's "after" column off to the right).
            const int across = QRect(table->mapTo(scroll->viewport(), QPoint(0, 0)), table->size())
                                   .intersected(scroll->viewport()->rect())
                                   .width();
            // Its frame's line may touch the edge: the cells are what must be in sight.
            QVERIFY2(across >= table->width() - table->frameWidth() &&
                         !table->horizontalScrollBar()->isVisible(),
                     qPrintable(where + QStringLiteral("%1 table: %2 of its %3 px across in sight")
                                            .arg(QLatin1String(name))
                                            .arg(across)
                                            .arg(table->width())));
        }
    }

    /// Each plot in sight: its data area at least kLeastDataArea, no legend over it. Returns
    /// how many were measured.
    static int checkPlots(MainWindow& w, const QString& where)
    {
        int measured = 0;
        for (ui::PlotWidget* plot : w.findChildren<ui::PlotWidget*>()) {
            // (The plot's own region is empty: its QCustomPlot, opaque, covers it.)
            const QRegion region = plot->plot()->visibleRegion();
            if (!plot->isVisible() || region.isEmpty())
                continue;
            // As the next frame draws it.
            plot->plot()->replot(QCustomPlot::rpImmediateRefresh);
            const QRect data = plot->plot()->axisRect()->rect();
            const QString name = plot->objectName().isEmpty() ? plot->title() : plot->objectName();
            const QRect drawn = region.boundingRect();
            if (!(data.width() >= ui::kLeastDataArea.width() &&
                  data.height() >= ui::kLeastDataArea.height() &&
                  drawn.size() == plot->plot()->size()))
                QTest::qFail(qPrintable(where + QStringLiteral("plot %1: data %2x%3 of %4x%5 "
                                                               "(drawn %6x%7), at least %8x%9")
                                                    .arg(name)
                                                    .arg(data.width())
                                                    .arg(data.height())
                                                    .arg(plot->width())
                                                    .arg(plot->height())
                                                    .arg(drawn.width())
                                                    .arg(drawn.height())
                                                    .arg(ui::kLeastDataArea.width())
                                                    .arg(ui::kLeastDataArea.height())),
                             __FILE__, __LINE__);
            const QCPLegend* legend = plot->plot()->legend;
            if (legend->visible() && legend->outerRect().intersects(data))
                QTest::qFail(qPrintable(where + QStringLiteral("plot %1: legend %2 over data %3")
                                                    .arg(name, rectText(legend->outerRect()),
                                                         rectText(data))),
                             __FILE__, __LINE__);
            if (QTest::currentTestFailed())
                return measured;
            ++measured;
        }
        return measured;
    }
};

RIGIDLAB_TEST_MAIN(TestClassroomSight)
#include "test_classroom_sight.moc"
