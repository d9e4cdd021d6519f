// SPDX-License-Identifier: GPL-3.0-or-later
// What a screen reader says of a text field as it takes the focus: its value (and the unit it
// is in), in each language. Orca speaks a focused field as its label, its role and the line
// at the caret, which it gathers run by run of the field's text attributes; Qt 6.4's runs
// covered nothing, and Orca said "Mass m text." without the 6 the field held
// (common/line_edit_accessible.h). Here the line is gathered as Orca gathers it, from the
// interface a reader is given.

#include "common/language.h"
#include "lesson_player/lesson_player.h"
#include "panels/control_panel.h"
#include "panels/inspector_panel.h"
#include "panels/number_field.h"
#include "simulation/simulation_controller.h"
#include "view/world_view.h"
#include "window/main_window.h"

#include <QAccessible>
#include <QApplication>
#include <QLineEdit>
#include <QtTest>

#include <algorithm>

#include "first_question.h"
#include "language_rows.h"
#include "projector_window.h"
#include "test_main.h"

using namespace rigidlab;
using rigidlab::test::shippedLessonFile;
using rigidlab::ui::MainWindow;
using rigidlab::ui::NumberField;

namespace {

/// The text Orca says of a focused one-line field: for each attribute run from the start,
/// the part of the text it covers (Orca 43's getAllTextAttributesForObject, then
/// splitSubstringByLanguage).
QString spokenLine(QWidget& field)
{
    QAccessibleInterface* a = QAccessible::queryAccessibleInterface(&field);
    QAccessibleTextInterface* text = a ? a->textInterface() : nullptr;
    if (!text)
        return QStringLiteral("(no text interface)");
    const int count = text->characterCount();
    QString said;
    int offset = 0;
    while (offset < count) {
        int start = 0;
        int end = 0;
        text->attributes(offset, &start, &end);
        start = std::max(start, offset);
        if (end > start)
            said += text->text(start, std::min(end, count));
        offset = std::max(end, offset + 1);
    }
    return said;
}

QString description(QWidget& field)
{
    QAccessibleInterface* a = QAccessible::queryAccessibleInterface(&field);
    return a ? a->text(QAccessible::Description) : QString();
}

QString welcome()
{
    return QDir(MainWindow::scenesFolder()).filePath(QStringLiteral("welcome.json"));
}

} // namespace

class TestFieldSpeech : public QObject {
    Q_OBJECT
private slots:
    void cleanup() { ui::applyLanguage(QStringLiteral("en")); }

    /// The welcome scene running, the wrecking ball chosen with ] ] and its numbers asked for
    /// with Return: the mass field has the focus, and says its 6 and that it is in kg.
    void theMassFieldSaysItsValueAndUnit_data() { test::addLanguageRows(); }
    void theMassFieldSaysItsValueAndUnit()
    {
        QFETCH(QString, language);
        QVERIFY(ui::applyLanguage(language));
        MainWindow w;
        QCOMPARE(w.openScene(welcome(), true), QString());
        QVERIFY(test::showActiveOnProjector(w));
        w.controller().setRunning(true);
        const int body = test::askWreckingBallNumbers(w);
        QVERIFY(body >= 0);
        NumberField* mass = w.inspector().massField();
        QVERIFY(mass);
        QTRY_COMPARE(QApplication::focusWidget(), static_cast<QWidget*>(mass));
        QCOMPARE(mass->text(), ui::formatNumber(w.controller().world().body(body).mass));
        const QString said = spokenLine(*mass);
        QVERIFY2(
            said == mass->text() && !said.isEmpty(),
            qPrintable(QStringLiteral("said “%1”, the field holds “%2”").arg(said, mass->text())));
        // The unit stands beside the field, not in its label: the description says it first.
        QCOMPARE(mass->unit(), QStringLiteral("kg"));
        const QString unit =
            QCoreApplication::translate("rigidlab::ui::NumberField", "in %1",
                                        "the unit a number field holds its value in")
                .arg(mass->unit());
        QVERIFY2(description(*mass).startsWith(unit), qPrintable(description(*mass)));
        QVERIFY2(description(*mass).contains(mass->toolTip()), qPrintable(description(*mass)));
    }

    /// Every field of the Inspector and the Controls says its value, a decimal one as the
    /// language writes it (Czech "0,8").
    void everyPanelFieldSaysItsValue_data() { test::addLanguageRows(); }
    void everyPanelFieldSaysItsValue()
    {
        QFETCH(QString, language);
        QVERIFY(ui::applyLanguage(language));
        MainWindow w;
        test::showOnProjector(w);
        QCOMPARE(w.openLesson(shippedLessonFile("restitution.json"), true), QString());
        for (int i = 0; i < static_cast<int>(w.controller().world().bodies().size()); ++i)
            if (w.controller().world().body(i).isDynamic())
                w.inspector().setBody(i);
        QList<NumberField*> fields = w.inspector().findChildren<NumberField*>();
        fields << w.controls().findChildren<NumberField*>();
        int decimal = 0;
        for (NumberField* f : std::as_const(fields)) {
            if (f->isHidden())
                continue; // the mass field of a body that has no mass to edit
            const QString said = spokenLine(*f);
            QVERIFY2(said == f->text() && !said.isEmpty(),
                     qPrintable(QStringLiteral("%1 said “%2”, holds “%3”")
                                    .arg(f->objectName(), said, f->text())));
            decimal += f->text().contains(QLocale().decimalPoint()) ? 1 : 0;
        }
        QVERIFY2(decimal >= 1, qPrintable(QString::number(decimal))); // the ball's 0.5 kg
    }

    /// A lesson's answer field says what was typed into it.
    void anAnswerSaysWhatWasTyped()
    {
        MainWindow w;
        test::showOnProjector(w);
        QCOMPARE(w.openLesson(shippedLessonFile("restitution.json"), true), QString());
        const MeasuredQuestion q = runToFirstQuestion(w);
        QVERIFY(q.step >= 0 && q.value);
        // The questions sit in the Lesson dock, below the player's text.
        QWidget* box = w.findChild<QWidget*>(QStringLiteral("lessonQuestions"));
        QVERIFY(box);
        const QList<QLineEdit*> answers = box->findChildren<QLineEdit*>();
        QVERIFY(!answers.isEmpty());
        QLineEdit* answer = answers.first();
        QCOMPARE(spokenLine(*answer), QString()); // nothing typed yet
        answer->setFocus();
        QTest::keyClicks(answer, QStringLiteral("0.75"));
        QCOMPARE(spokenLine(*answer), QStringLiteral("0.75"));
    }
};

RIGIDLAB_TEST_MAIN(TestFieldSpeech)
#include "test_field_speech.moc"
