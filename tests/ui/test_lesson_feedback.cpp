// SPDX-License-Identifier: GPL-3.0-or-later
// What a Czech class is told in the lesson window at 1024×768, by keyboard: Check on an empty
// answer says so under that question, tells a screen reader and puts the focus in the box;
// every line under a question of one kind (right, wrong, wait) looks the same, bold, its words
// saying which; a step's table reads in whole words (it scrolls sideways when it is too wide);
// a run whose every moving body has left the view pauses and says why.

#include "classroom_util.h"
#include "test_main.h"

#include "common/announcer.h"
#include "common/language.h"

#include "format/data_dirs.h"

#include <QScopeGuard>
#include <QTextBlock>
#include <QTextBoundaryFinder>
#include <QTextDocument>
#include <QTextLayout>
#include <QTextTable>

using namespace rigidlab;
using namespace rigidlab::test::classroom;

namespace {

QString lessonPath(const char* name)
{
    return lessons::shippedLessonsDir() + u'/' + QLatin1String(name);
}

void settle()
{
    for (int pass = 0; pass < 4; ++pass)
        QCoreApplication::processEvents();
}

/// `w` shown on the projector with the restitution lesson at its second step (the light ball
/// hits the heavy one); empty, or what went wrong.
QString showRestitutionStep2(ui::MainWindow& w)
{
    showOn(w, kProjector);
    const QString refused = w.openLesson(lessonPath("restitution.json"), true);
    if (!refused.isEmpty())
        return refused;
    w.lessonPlayer().goToStep(1);
    settle();
    return {};
}

/// Question `q`'s box in the Lesson dock (its prompt, answer, buttons and verdict line).
QWidget* questionRow(ui::MainWindow& w, int q)
{
    auto* box = w.findChild<QWidget*>(QStringLiteral("lessonQuestions"));
    if (!box || !box->layout() || box->layout()->count() <= q)
        return nullptr;
    return box->layout()->itemAt(q)->widget();
}

/// The verdict line of question box `row`: a wrapped label that names no field.
QLabel* verdictOf(QWidget& row)
{
    for (QLabel* l : row.findChildren<QLabel*>())
        if (l->wordWrap() && !l->buddy() && l->parentWidget() == &row)
            return l;
    return nullptr;
}

QPushButton* checkOf(QWidget& row)
{
    for (QPushButton* b : row.findChildren<QPushButton*>())
        if (b->text() == QCoreApplication::translate("rigidlab::ui::LessonPlayer", "Check"))
            return b;
    return nullptr;
}

/// How a verdict line is drawn: weight, pixel size and colour, as "bold 17 px #1e7b34".
QString lookOf(QLabel& label)
{
    label.ensurePolished();
    const QFontInfo font(label.font());
    return QStringLiteral("%1 %2 px %3")
        .arg(font.bold() ? QStringLiteral("bold") : QStringLiteral("normal"))
        .arg(font.pixelSize())
        .arg(label.palette().color(label.foregroundRole()).name());
}

/// Where in `text` a laid-out line starts that is no place to break a line (inside a word),
/// as "…integrá|tor…"; empty when every line starts where a line may break.
QString brokenWord(const QTextBlock& block)
{
    const QString text = block.text();
    const QTextLayout* layout = block.layout();
    for (int k = 1; k < layout->lineCount(); ++k) {
        const int at = layout->lineAt(k).textStart();
        QTextBoundaryFinder breaks(QTextBoundaryFinder::Line, text);
        breaks.setPosition(at);
        if (!breaks.isAtBoundary())
            return text.left(at) + u'|' + text.mid(at);
    }
    return {};
}

} // namespace

class TestLessonFeedback : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { QVERIFY(ui::applyLanguage(QStringLiteral("cs"))); }
    void cleanupTestCase() { ui::applyLanguage(QStringLiteral("en")); }

    // Return on Check with the box empty: "Nejdřív zadejte číslo." under that question, told to
    // a screen reader, and the focus in the box, where the number is to be typed (typed at the
    // button, it was lost).
    void emptyCheckSaysWhereAndWhat()
    {
        ui::MainWindow w;
        QCOMPARE(showRestitutionStep2(w), QString());
        QWidget* row = questionRow(w, 1);
        QVERIFY(row);
        QPushButton* check = checkOf(*row);
        auto* edit = row->findChild<QLineEdit*>();
        QLabel* verdict = verdictOf(*row);
        QVERIFY(check && edit && verdict && edit->text().isEmpty());
        check->setFocus(Qt::TabFocusReason);
        QTest::keyClick(check, Qt::Key_Return);
        settle();
        const QString said = QStringLiteral("Nejdřív zadejte číslo.");
        QVERIFY2(verdict->isVisible() && verdict->text() == said, qPrintable(verdict->text()));
        const QWidget* told = ui::announcer(w);
        QVERIFY2(told && told->accessibleName() == said,
                 qPrintable(QStringLiteral("told \"%1\"")
                                .arg(told ? told->accessibleName() : QStringLiteral("nothing"))));
        QVERIFY2(edit->hasFocus(),
                 qPrintable(QStringLiteral("the focus is on %1")
                                .arg(QApplication::focusWidget()
                                         ? QApplication::focusWidget()->metaObject()->className()
                                         : "nothing")));
        // Typed now, the number goes in the box, and Return judges it.
        QTest::keyClicks(edit, QStringLiteral("-1"));
        QTest::keyClick(edit, Qt::Key_Return);
        settle();
        QCOMPARE(edit->text(), QStringLiteral("-1"));
        QVERIFY2(verdict->text() != said, qPrintable(verdict->text()));
    }

    // Every line under a question of one kind is drawn alike (bold, as large as the others, one
    // colour), and its words say which: "Správně", "Ne tak docela", "Nejdřív …". The wait for
    // the run was plain and the wrong answer bold before, in the same colour.
    void verdictsOfAKindLookAlike()
    {
        ui::MainWindow w;
        // Both speeds are measured at t = 1.5 s; the run is not held.
        QCOMPARE(showRestitutionStep2(w), QString());
        QWidget* first = questionRow(w, 0);
        QWidget* second = questionRow(w, 1);
        QVERIFY(first && second);
        QLabel* firstLine = verdictOf(*first);
        QLabel* secondLine = verdictOf(*second);
        QVERIFY(firstLine && secondLine);
        QMap<QString, QStringList> looks; // kind → "look: words" of each line of that kind
        const auto keep = [&](const QString& kind, QLabel& line) {
            settle();
            looks[kind] << lookOf(line) + QStringLiteral(": ") + line.text();
        };
        checkOf(*first)->click(); // nothing typed
        keep(QStringLiteral("wait"), *firstLine);
        first->findChild<QLineEdit*>()->setText(QStringLiteral("2"));
        checkOf(*first)->click(); // before the run got to 1.5 s
        keep(QStringLiteral("wait"), *firstLine);
        ui::SimulationController& c = w.controller();
        runFor(c, 1.6);
        first->findChild<QLineEdit*>()->setText(QStringLiteral("0,5"));
        checkOf(*first)->click();
        keep(QStringLiteral("wrong"), *firstLine); // a second try to come
        first->findChild<QLineEdit*>()->setText(QStringLiteral("0,6"));
        checkOf(*first)->click();
        keep(QStringLiteral("wrong"), *firstLine); // the value given
        second->findChild<QLineEdit*>()->setText(QStringLiteral("-1"));
        checkOf(*second)->click();
        keep(QStringLiteral("right"), *secondLine);
        const QMap<QString, QString> words{{QStringLiteral("wait"), QStringLiteral("Nejdřív")},
                                           {QStringLiteral("wrong"), QStringLiteral("Ne tak")},
                                           {QStringLiteral("right"), QStringLiteral("Správně")}};
        QSet<QString> colours;
        int size = -1;
        for (auto it = looks.cbegin(); it != looks.cend(); ++it) {
            const QString all = it.value().join(QStringLiteral(" | "));
            for (const QString& line : it.value()) {
                const QString look = line.section(QStringLiteral(": "), 0, 0);
                QVERIFY2(look == it.value().front().section(QStringLiteral(": "), 0, 0) &&
                             look.startsWith(QStringLiteral("bold ")),
                         qPrintable(it.key() + QStringLiteral(": ") + all));
                QVERIFY2(line.section(QStringLiteral(": "), 1).startsWith(words[it.key()]),
                         qPrintable(it.key() + QStringLiteral(": ") + all));
            }
            const int px = it.value().front().section(u' ', 1, 1).toInt();
            QVERIFY2(size < 0 || px == size,
                     qPrintable(QStringLiteral("%1 px, %2 px: %3").arg(px).arg(size).arg(all)));
            size = px;
            colours << it.value().front().section(QStringLiteral(": "), 0, 0).section(u' ', 3);
        }
        QCOMPARE(looks.size(), 3);
        QCOMPARE(colours.size(), 3); // one colour a kind, besides the words
    }

    // energy_drift step 4's table (integrator | order | h = 0.01 s | h = 0.001 s) at 1024×768
    // and 1366×768, in Czech and English: no word of it broken ("integrá/tor", "explicitn/í",
    // "h = 0,00/1 s" were); a table too wide for the column then scrolls sideways, and the
    // arrow keys scroll it.
    void stepTableReadsInWholeWords_data()
    {
        QTest::addColumn<QString>("language");
        QTest::addColumn<QSize>("screen");
        for (const char* language : {"cs", "en"}) {
            QTest::addRow("%s 1024x768", language)
                << QString::fromLatin1(language) << QSize(1024, 768);
            QTest::addRow("%s 1366x768", language)
                << QString::fromLatin1(language) << QSize(1366, 768);
        }
    }
    void stepTableReadsInWholeWords()
    {
        QFETCH(QString, language);
        QFETCH(QSize, screen);
        QVERIFY(ui::applyLanguage(language));
        const auto czech = qScopeGuard([] { ui::applyLanguage(QStringLiteral("cs")); });
        ui::MainWindow w;
        showOn(w, screen);
        QCOMPARE(w.openLesson(lessonPath("energy_drift.json"), true), QString());
        w.lessonPlayer().goToStep(3);
        settle();
        auto* text = w.lessonPlayer().findChild<QTextBrowser*>();
        QVERIFY(text && text->isVisible());
        QTextDocument* doc = text->document();
        int cells = 0;
        for (QTextBlock block = doc->begin(); block.isValid(); block = block.next()) {
            QTextCursor at(block);
            if (!at.currentTable())
                continue;
            ++cells;
            const QString broken = brokenWord(block);
            QVERIFY2(broken.isEmpty(), qPrintable(QStringLiteral("\"%1\" in a %2 px column")
                                                      .arg(broken)
                                                      .arg(text->viewport()->width())));
        }
        QVERIFY2(cells >= 8, qPrintable(QString::number(cells)));
        // Wider than the column, the table scrolls sideways, by keyboard too; the text is as
        // tall as its lines and that scroll bar.
        QScrollBar* sideways = text->horizontalScrollBar();
        if (std::ceil(doc->size().width()) > text->viewport()->width()) {
            QVERIFY2(sideways->isVisible() && sideways->maximum() > 0,
                     qPrintable(QStringLiteral("%1 px of text in a %2 px column, scroll bar %3")
                                    .arg(doc->size().width())
                                    .arg(text->viewport()->width())
                                    .arg(sideways->maximum())));
            QVERIFY2(text->viewport()->height() >= std::floor(doc->size().height()),
                     qPrintable(QStringLiteral("%1 px shown of %2")
                                    .arg(text->viewport()->height())
                                    .arg(doc->size().height())));
            text->setFocus(Qt::TabFocusReason);
            QTest::keyClick(text, Qt::Key_Right);
            QVERIFY2(sideways->value() > 0, qPrintable(QString::number(sideways->value())));
        } else {
            QVERIFY(!sideways->isVisible());
        }
    }

    // restitution step 2: after the collision both balls fly out of the view, one to each
    // side. The run pauses when the last has gone and says why (status bar, screen reader);
    // Play runs on. It ran on with nothing to see (10.9 s, 17.7 s).
    void runPausesWhenTheViewIsEmpty()
    {
        ui::MainWindow w;
        QCOMPARE(showRestitutionStep2(w), QString());
        ui::SimulationController& c = w.controller();
        c.setRunning(true);
        for (int frame = 0; frame < 60 * 30 && c.isRunning(); ++frame) {
            c.advanceClock(1.0 / 60);
            QCoreApplication::processEvents();
        }
        QVERIFY2(!c.isRunning(),
                 qPrintable(QStringLiteral("still running at t = %1 s").arg(c.world().time())));
        const double t = c.world().time();
        QVERIFY2(t > 1.5 && t < 15, qPrintable(QString::number(t)));
        const QString shown = w.statusBar()->currentMessage();
        QVERIFY2(shown.contains(QStringLiteral("zorné")) ||
                     shown.contains(QStringLiteral("pohled")),
                 qPrintable(shown));
        const QWidget* told = ui::announcer(w);
        QVERIFY2(told && told->accessibleName() == shown.simplified(),
                 qPrintable(QStringLiteral("told \"%1\", shown \"%2\"")
                                .arg(told ? told->accessibleName() : QString(), shown)));
        // Play runs on, and the run does not pause for it again.
        c.setRunning(true);
        for (int frame = 0; frame < 60; ++frame)
            c.advanceClock(1.0 / 60);
        QVERIFY2(c.isRunning() && c.world().time() > t + 0.5,
                 qPrintable(QString::number(c.world().time())));
        c.setRunning(false);
    }

    // billiards_momentum step 4 opens the scene editor, its Properties in the right column
    // above the Collision table. The Properties get the settings' share of the column's
    // height, whatever an earlier step left them: they kept 60 px (the World group and half a
    // field) under a half-empty table after the screenshot run's earlier steps.
    void editorPropertiesGetTheirShare()
    {
        ui::MainWindow w;
        showOn(w, kProjector);
        QCOMPARE(w.openLesson(lessonPath("billiards_momentum.json"), true), QString());
        w.lessonPlayer().goToStep(3);
        settle();
        auto* properties = w.findChild<QDockWidget*>(QStringLiteral("propertiesDock"));
        QDockWidget* collision = w.dock(QStringLiteral("collision"));
        QVERIFY(properties && collision && properties->isVisible() && collision->isVisible());
        // What an earlier step may leave: the Properties squeezed.
        w.resizeDocks({properties, collision}, {40, 600}, Qt::Vertical);
        settle();
        QVERIFY2(
            properties->height() < collision->height() / 2,
            qPrintable(
                QStringLiteral("%1 px, %2 px").arg(properties->height()).arg(collision->height())));
        // The column shared again (here by the View menu's Collision shown again).
        collision->toggleViewAction()->trigger();
        collision->toggleViewAction()->trigger();
        settle();
        QVERIFY(properties->isVisible() && collision->isVisible());
        // Settings 5, tables 4 (window_layout.cpp's kCompactHeightWeights).
        QVERIFY2(properties->height() >= collision->height(),
                 qPrintable(QStringLiteral("Properties %1 px, Collision %2 px")
                                .arg(properties->height())
                                .arg(collision->height())));
    }
};

RIGIDLAB_TEST_MAIN(TestLessonFeedback)
#include "test_lesson_feedback.moc"
