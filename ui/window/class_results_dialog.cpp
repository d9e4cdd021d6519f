// SPDX-License-Identifier: GPL-3.0-or-later
#include "window/class_results_dialog.h"

#include "common/export_folder.h"
#include "common/language.h"
#include "common/modal_scope.h"
#include "plots/plot_export.h"
#include "worksheet/class_results_pdf.h"

#include "format/atomic_file.h"
#include "results/class_table_files.h"
#include "results/class_table_model.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMessageBox>
#include <QPushButton>
#include <QTableView>
#include <QVBoxLayout>

namespace rigidlab::ui {

ClassResultsDialog::ClassResultsDialog(QWidget* parent) : QDialog(parent)
{
    setObjectName(QStringLiteral("classResultsDialog"));
    setWindowTitle(tr("Class results"));
    auto* layout = new QVBoxLayout(this);
    buildChoosers(*layout);
    buildTable(*layout);
    buildFooter(*layout);
    resize(900, 560);
    showCollected();
}

void ClassResultsDialog::buildChoosers(QVBoxLayout& layout)
{
    auto* form = new QFormLayout;
    layout.addLayout(form);
    // Where the answers files are: typed or chosen.
    m_folderEdit = new QLineEdit(this);
    m_folderEdit->setAccessibleName(tr("Folder of answers files"));
    m_folderEdit->setPlaceholderText(tr("the folder the class's answers files were saved in"));
    connect(m_folderEdit, &QLineEdit::returnPressed, this,
            [this] { setFolder(m_folderEdit->text()); });
    auto* choose = new QPushButton(tr("C&hoose folder…"), this);
    choose->setAccessibleName(tr("Choose the folder of answers files"));
    connect(choose, &QPushButton::clicked, this, &ClassResultsDialog::chooseFolder);
    auto* folderRow = new QHBoxLayout;
    folderRow->addWidget(m_folderEdit, 1);
    folderRow->addWidget(choose);
    auto* folderLabel = new QLabel(tr("&Folder:"), this);
    folderLabel->setBuddy(m_folderEdit);
    form->addRow(folderLabel, folderRow);

    m_lesson = new QComboBox(this);
    m_lesson->setAccessibleName(tr("Lesson"));
    m_lesson->setAccessibleDescription(
        tr("The lessons the folder holds answers to, the most answered first"));
    connect(m_lesson, &QComboBox::activated, this,
            [this] { setLesson(m_lesson->currentData().toString()); });
    auto* lessonLabel = new QLabel(tr("&Lesson:"), this);
    lessonLabel->setBuddy(m_lesson);
    form->addRow(lessonLabel, m_lesson);
}

void ClassResultsDialog::buildTable(QVBoxLayout& layout)
{
    m_summary = new QLabel(this);
    m_summary->setWordWrap(true);
    m_summary->setTextInteractionFlags(Qt::TextSelectableByKeyboard | Qt::TextSelectableByMouse);
    m_summary->setAccessibleName(tr("What was collected"));
    layout.addWidget(m_summary);

    m_model = new lessons::ClassTableModel(this);
    m_sorting = new lessons::ClassTableSorting(this);
    m_sorting->setSourceModel(m_model);
    m_view = new QTableView(this);
    m_view->setObjectName(QStringLiteral("classResultsTable"));
    m_view->setModel(m_sorting);
    m_view->setSortingEnabled(true);
    m_view->setAccessibleName(tr("Class results table"));
    m_view->setAccessibleDescription(tr("A row per student, per question the first answer, its "
                                        "verdict, the tries and hint or Show me used; the last "
                                        "row: the share right at the first answer"));
    m_view->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_view->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_view->setTabKeyNavigation(false); // Tab leaves the table for the next control
    m_view->verticalHeader()->setVisible(false);
    layout.addWidget(m_view, 1);

    // The header sorts by a click; these sort from the keyboard as well.
    m_sortBy = new QComboBox(this);
    m_sortBy->setAccessibleName(tr("Sort the table by"));
    m_descending = new QCheckBox(tr("&Descending"), this);
    m_descending->setAccessibleName(tr("Sort descending"));
    connect(m_sortBy, &QComboBox::activated, this, &ClassResultsDialog::sortChosen);
    connect(m_descending, &QCheckBox::toggled, this, &ClassResultsDialog::sortChosen);
    auto* sortRow = new QHBoxLayout;
    auto* sortLabel = new QLabel(tr("&Sort by:"), this);
    sortLabel->setBuddy(m_sortBy);
    sortRow->addWidget(sortLabel);
    sortRow->addWidget(m_sortBy, 1);
    sortRow->addWidget(m_descending);
    layout.addLayout(sortRow);
}

void ClassResultsDialog::buildFooter(QVBoxLayout& layout)
{
    auto* skippedLabel = new QLabel(tr("Files left &out:"), this);
    m_skipped = new QListWidget(this);
    m_skipped->setObjectName(QStringLiteral("classResultsSkipped"));
    m_skipped->setAccessibleName(tr("Files left out, one line each"));
    m_skipped->setMaximumHeight(90);
    skippedLabel->setBuddy(m_skipped);
    layout.addWidget(skippedLabel);
    layout.addWidget(m_skipped);

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    m_csv = buttons->addButton(tr("Export &CSV…"), QDialogButtonBox::ActionRole);
    m_csv->setAccessibleName(tr("Export the table as CSV"));
    m_pdf = buttons->addButton(tr("Export &PDF…"), QDialogButtonBox::ActionRole);
    m_pdf->setAccessibleName(tr("Export the table as PDF"));
    buttons->button(QDialogButtonBox::Close)->setAccessibleName(tr("Close"));
    connect(m_csv, &QPushButton::clicked, this, &ClassResultsDialog::exportCsvDialog);
    connect(m_pdf, &QPushButton::clicked, this, &ClassResultsDialog::exportPdfDialog);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout.addWidget(buttons);
}

void ClassResultsDialog::chooseFolder()
{
    const ModalScope modal;
    const QString folder = QFileDialog::getExistingDirectory(
        this, tr("Folder of answers files"), m_folder.isEmpty() ? exportFolder() : m_folder);
    if (!folder.isEmpty())
        setFolder(folder);
}

void ClassResultsDialog::setFolder(const QString& folder)
{
    m_folder = folder;
    m_folderEdit->setText(QDir::toNativeSeparators(folder));
    collect(QString());
    m_lesson->clear();
    // A teacher knows a lesson by its title; the file tells apart two of one title.
    for (qsizetype i = 0; i < m_collected.lessonFiles.size(); ++i) {
        const QString& file = m_collected.lessonFiles[i];
        const QString title = m_collected.lessonTitles.value(i);
        m_lesson->addItem(title.isEmpty() ? file : tr("%1 (%2)").arg(title, file), file);
    }
    if (!m_collected.tables.empty())
        m_lesson->setCurrentIndex(m_lesson->findData(m_collected.tables.front().lessonFile));
}

void ClassResultsDialog::setLesson(const QString& lessonFile)
{
    collect(lessonFile);
}

void ClassResultsDialog::collect(const QString& lessonFile)
{
    lessons::ClassOptions options;
    options.lessonFile = lessonFile;
    m_collected = lessons::collectClass(m_folder, options);
    showCollected();
}

void ClassResultsDialog::showCollected()
{
    const bool any = !m_collected.tables.empty() && !m_collected.tables.front().rows.empty();
    m_model->setTable(any ? m_collected.tables.front() : lessons::ClassTable{});
    m_view->sortByColumn(-1, Qt::AscendingOrder); // the files' order until asked otherwise
    m_view->resizeColumnsToContents();
    m_sortBy->clear();
    for (int c = 0; c < m_model->columnCount(); ++c)
        m_sortBy->addItem(m_model->headerData(c, Qt::Horizontal).toString());
    m_skipped->clear();
    m_skipped->addItems(m_collected.skipped);
    if (m_folder.isEmpty())
        m_summary->setText(tr("Choose the folder the class's answers files are in."));
    else if (!any)
        m_summary->setText(m_collected.error);
    else
        m_summary->setText(tr("%1: %2 students, %3 files left out")
                               .arg(m_collected.tables.front().lessonTitle)
                               .arg(m_collected.tables.front().rows.size())
                               .arg(m_collected.skipped.size()));
    m_csv->setEnabled(any);
    m_pdf->setEnabled(any);
    m_sortBy->setEnabled(any);
    m_descending->setEnabled(any);
}

void ClassResultsDialog::sortChosen()
{
    if (m_sortBy->currentIndex() >= 0)
        m_view->sortByColumn(m_sortBy->currentIndex(),
                             m_descending->isChecked() ? Qt::DescendingOrder : Qt::AscendingOrder);
}

QString ClassResultsDialog::writeCsv(const QString& path, lessons::CsvDialect dialect) const
{
    const std::string bytes = lessons::classTablesCsv(
        {m_model->table()}, lessons::csvConventions(dialect, currentLanguage()));
    return lessons::writeFileAtomically(
        path, QByteArray(bytes.data(), static_cast<qsizetype>(bytes.size())));
}

QString ClassResultsDialog::writePdf(const QString& path) const
{
    return writeClassResultsPdf({m_model->table()}, m_collected.skipped, path).error;
}

void ClassResultsDialog::exportCsvDialog()
{
    const ModalScope modal;
    const QString stem = QFileInfo(m_model->table().lessonFile).completeBaseName();
    const auto chosen =
        askCsvFile(this, tr("Export class results as CSV"), stem + QStringLiteral("-class.csv"));
    if (!chosen)
        return;
    if (const QString why = writeCsv(chosen->path, chosen->dialect); !why.isEmpty())
        QMessageBox::warning(this, tr("Export failed"), why);
}

void ClassResultsDialog::exportPdfDialog()
{
    const ModalScope modal;
    const QString stem = QFileInfo(m_model->table().lessonFile).completeBaseName();
    const QString path = QFileDialog::getSaveFileName(
        this, tr("Export class results as PDF"),
        QDir(exportFolder()).filePath(stem + QStringLiteral("-class.pdf")),
        tr("PDF document (*.pdf)"));
    if (path.isEmpty())
        return;
    rememberExportFolder(path);
    if (const QString why = writePdf(path); !why.isEmpty())
        QMessageBox::warning(this, tr("Export failed"), why);
}

} // namespace rigidlab::ui
