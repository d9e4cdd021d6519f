// SPDX-License-Identifier: GPL-3.0-or-later
// The lesson editor with the keyboard and a screen reader: letters typed into a list (its
// type-ahead) or a field stay there and fire no button or dialog; every spin box names its
// unit; every scroll area a reader meets has a name.

#include "test_lesson_editor.h"

#include <QAbstractItemView>
#include <QAbstractScrollArea>
#include <QDoubleSpinBox>
#include <QTextEdit>

namespace {

/// The suffix `box` shows after its number, without spaces ("s", "%", "min"); empty for none.
QString unitOf(const QAbstractSpinBox& box)
{
    if (const auto* d = qobject_cast<const QDoubleSpinBox*>(&box))
        return d->suffix().trimmed();
    if (const auto* i = qobject_cast<const QSpinBox*>(&box))
        return i->suffix().trimmed();
    return {};
}

/// Opens a new lesson on two balls in `ed`, with a measured question; false when their scene
/// does not load.
bool withAQuestion(ui::LessonEditor& ed)
{
    const lessons::SceneLoadResult scene =
        lessons::loadSceneFile(kSource + QStringLiteral("/lessons/scenes/two_balls.json"));
    if (!scene.ok)
        return false;
    ed.newLesson(scene.scene);
    ed.show();
    auto* add = ed.findChild<QPushButton*>(QStringLiteral("addMeasuredQuestion"));
    if (add)
        QTest::mouseClick(add, Qt::LeftButton);
    return add != nullptr;
}

} // namespace

void TestLessonEditor::lettersStayInListsAndFields_data()
{
    QTest::addColumn<QString>("language");
    QTest::newRow("en") << QStringLiteral("en");
    QTest::newRow("cs") << QStringLiteral("cs");
}

void TestLessonEditor::lettersStayInListsAndFields()
{
    QFETCH(QString, language);
    QVERIFY(ui::applyLanguage(language));
    ui::LessonEditor ed;
    QVERIFY(withAQuestion(ed));
    ed.activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(&ed));
    const int edits = ed.draft().undoStack()->count();
    const int windows = static_cast<int>(QApplication::topLevelWidgets().size());
    const QString letters = QStringLiteral("abcdefghijklmnopqrstuvwxyz");
    for (const char* name : {"questionList", "lessonSteps", "questionPrompt_en"}) {
        auto* w = ed.findChild<QWidget*>(QLatin1String(name));
        QVERIFY2(w != nullptr, name);
        w->setFocus();
        if (auto* line = qobject_cast<QLineEdit*>(w))
            line->selectAll();
        for (const QChar c : letters) {
            // As the platform sends a letter: to the window, through its shortcuts.
            QTest::keyClick(ed.windowHandle(), Qt::Key(Qt::Key_A + (c.unicode() - u'a')),
                            Qt::NoModifier);
            QVERIFY2(!QApplication::activeModalWidget(),
                     qPrintable(QStringLiteral("%1 after '%2'").arg(QLatin1String(name), c)));
        }
        QVERIFY2(QApplication::focusWidget() == w, name);
        if (qobject_cast<QLineEdit*>(w))
            QCOMPARE(static_cast<QLineEdit*>(w)->text(), letters);
        else
            QCOMPARE(ed.draft().undoStack()->count(), edits); // a list typed in: no edit
    }
    QCOMPARE(static_cast<int>(QApplication::topLevelWidgets().size()), windows);
    ui::applyLanguage(QStringLiteral("en"));
}

void TestLessonEditor::spinBoxesAndScrollAreasNamed()
{
    ui::LessonEditor ed;
    QVERIFY(withAQuestion(ed));
    QStringList wrong;
    int units = 0;
    for (QAbstractSpinBox* box : ed.findChildren<QAbstractSpinBox*>()) {
        const QString unit = unitOf(*box);
        if (unit.isEmpty())
            continue;
        ++units;
        if (!box->accessibleName().endsWith(QStringLiteral(" [%1]").arg(unit)))
            wrong << QStringLiteral("%1: '%2' without [%3]")
                         .arg(box->objectName(), box->accessibleName(), unit);
    }
    QVERIFY2(units >= 4, qPrintable(QString::number(units)));
    for (QAbstractScrollArea* area : ed.findChildren<QAbstractScrollArea*>())
        if (area->focusPolicy() != Qt::NoFocus && area->accessibleName().isEmpty() &&
            !qobject_cast<QAbstractItemView*>(area) && !qobject_cast<QPlainTextEdit*>(area) &&
            !qobject_cast<QTextEdit*>(area))
            wrong << QStringLiteral("a focusable %1 without a name")
                         .arg(QLatin1String(area->metaObject()->className()));
    QVERIFY2(wrong.isEmpty(), qPrintable(wrong.join(u'\n')));
}
