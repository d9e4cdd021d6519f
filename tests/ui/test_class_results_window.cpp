// SPDX-License-Identifier: GPL-3.0-or-later
// File › Class results… in the window: the menu entry opens it, the demo class (a damaged
// file and another lesson's among five students) fills its table and its lines, the keyboard
// sorts with the summary row kept last, every control is named and its underlined letters
// are its own (in English and Czech), and the CSV export in Czech is the spreadsheet's.

#include "common/language.h"
#include "window/class_results_dialog.h"
#include "window/demo_class.h"
#include "window/main_window.h"

#include "results/class_table_model.h"

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QListWidget>
#include <QTableView>
#include <QTemporaryDir>
#include <QtTest>

#include "csv_reader.h"
#include "mnemonics.h"
#include "test_main.h"

using namespace rigidlab;

class TestClassResultsWindow : public QObject {
    Q_OBJECT
private slots:
    void init() { QVERIFY(m_dir.isValid()); }
    void cleanupTestCase() { ui::applyLanguage(QStringLiteral("en")); }
    void menuOpensTheDemoClass_data();
    void menuOpensTheDemoClass();
    void keyboardSortsWithTheSummaryLast();
    void czechCsvIsTheSpreadsheets();

private:
    QTemporaryDir m_dir;
};

void TestClassResultsWindow::menuOpensTheDemoClass_data()
{
    QTest::addColumn<QString>("language");
    QTest::newRow("en") << QStringLiteral("en");
    QTest::newRow("cs") << QStringLiteral("cs");
}

void TestClassResultsWindow::menuOpensTheDemoClass()
{
    QFETCH(QString, language);
    ui::applyLanguage(language);
    ui::MainWindow window;
    auto* entry = window.findChild<QAction*>(QStringLiteral("classResults"));
    QVERIFY(entry);
    entry->trigger();
    auto* dialog = window.findChild<ui::ClassResultsDialog*>();
    QVERIFY(dialog && dialog->isVisible());
    QVERIFY(ui::writeDemoClass(m_dir.path()).isEmpty());
    dialog->setFolder(m_dir.path());
    // Five students and the summary row; the damaged file and the other lesson's, a line each.
    QCOMPARE(dialog->view()->model()->rowCount(), 6);
    QCOMPARE(dialog->skippedList()->count(), 2);
    // The lesson is chosen by its title (the answers' own), its file beside it.
    QComboBox* lessonBox = nullptr;
    for (auto* box : dialog->findChildren<QComboBox*>())
        if (box->currentData().toString().endsWith(QLatin1String(".json")))
            lessonBox = box;
    QVERIFY(lessonBox);
    const QString file = lessonBox->currentData().toString();
    QVERIFY2(lessonBox->currentText().contains(QStringLiteral("(%1)").arg(file)) &&
                 !lessonBox->currentText().startsWith(file),
             qPrintable(lessonBox->currentText()));
    QStringList lines;
    for (int i = 0; i < dialog->skippedList()->count(); ++i)
        lines << dialog->skippedList()->item(i)->text();
    QVERIFY2(lines[0].startsWith(QStringLiteral("restitution-adam.answers.json: ")),
             qPrintable(lines.join(u'\n')));
    QVERIFY2(lines[1].startsWith(QStringLiteral("tunnelling-karel.answers.json: ")),
             qPrintable(lines.join(u'\n')));
    // Every control says what it is; no two share an underlined letter.
    for (QWidget* w : dialog->findChildren<QWidget*>()) {
        if (w->focusPolicy() == Qt::NoFocus || !w->isVisibleTo(dialog) ||
            qobject_cast<QAbstractScrollArea*>(w->parentWidget()))
            continue;
        QVERIFY2(!w->accessibleName().isEmpty(), w->metaObject()->className());
    }
    const QStringList clashes = test::sharedLetters(test::windowMnemonics(*dialog));
    QVERIFY2(clashes.isEmpty(), qPrintable(clashes.join(u'\n')));
}

void TestClassResultsWindow::keyboardSortsWithTheSummaryLast()
{
    ui::applyLanguage(QStringLiteral("en"));
    ui::ClassResultsDialog dialog;
    QVERIFY(ui::writeDemoClass(m_dir.path()).isEmpty());
    dialog.setFolder(m_dir.path());
    dialog.show();
    QComboBox* sort = nullptr;
    for (QComboBox* c : dialog.findChildren<QComboBox*>())
        if (c->accessibleName() == QStringLiteral("Sort the table by"))
            sort = c;
    QVERIFY(sort);
    auto* descending = dialog.findChild<QCheckBox*>();
    QVERIFY(descending);
    QAbstractItemModel* model = dialog.view()->model();
    // Column 0, the names: from the keyboard, the combo's first entry, then Descending.
    sort->setFocus();
    QTest::keyClick(sort, Qt::Key_Home);
    QTest::keyClick(sort, Qt::Key_Down);
    QTest::keyClick(sort, Qt::Key_Up); // activated: "Name"
    QCOMPARE(model->index(0, 0).data().toString(), QStringLiteral("Eva Dvořáková"));
    QVERIFY(model->index(5, 0).data(lessons::ClassTableModel::kSummaryRole).toBool());
    descending->setFocus();
    QTest::keyClick(descending, Qt::Key_Space);
    QCOMPARE(model->index(0, 0).data().toString(), QStringLiteral("Tomáš Černý"));
    QVERIFY(model->index(5, 0).data(lessons::ClassTableModel::kSummaryRole).toBool());
}

void TestClassResultsWindow::czechCsvIsTheSpreadsheets()
{
    ui::applyLanguage(QStringLiteral("cs"));
    ui::ClassResultsDialog dialog;
    QVERIFY(ui::writeDemoClass(m_dir.path()).isEmpty());
    dialog.setFolder(m_dir.path());
    const QString path = m_dir.filePath(QStringLiteral("class.csv"));
    QCOMPARE(dialog.writeCsv(path, lessons::CsvDialect::Spreadsheet), QString());
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const test::CsvTable csv = test::readCsv(file.readAll(), ';');
    QVERIFY(csv.bom);
    QCOMPARE(csv.rows.size(), 7); // heads, five students, the summary
    QCOMPARE(csv.rows[0][0], QStringLiteral("Jméno"));
    // Rows by file name (Eva, Jana, ...): Jana's first answer to 1.1 (0.41 m) with the
    // decimal comma, read as a number.
    QCOMPARE(csv.rows[2][0], QStringLiteral("Jana Nováková"));
    QCOMPARE(csv.rows[2][3], QStringLiteral("0,41"));
    QCOMPARE(test::readNumber(csv.rows[2][3], ','), std::optional<double>(0.41));
    QCOMPARE(csv.rows[6][0], QStringLiteral("Správně napoprvé [%]"));
    const QString pdf = m_dir.filePath(QStringLiteral("class.pdf"));
    QCOMPARE(dialog.writePdf(pdf), QString());
    QVERIFY(QFileInfo(pdf).size() > 1000);
}

RIGIDLAB_TEST_MAIN(TestClassResultsWindow)
#include "test_class_results_window.moc"
