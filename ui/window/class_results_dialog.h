// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// File › Class results…: the answers files a class handed in, collected from a folder into
// one sortable table (lessons/results/class_table_model.h), the files left out listed one
// line each, and the table exported as CSV (the spreadsheet dialect of the window's language
// unless plain is chosen) or PDF (ui/worksheet/class_results_pdf.h). Every control has an
// accessible name; the keyboard sorts the table too (Sort by, Descending).

#include "export/csv_dialect.h"
#include "results/class_folder.h"

#include <QDialog>

class QCheckBox;
class QComboBox;
class QLabel;
class QLineEdit;
class QListWidget;
class QPushButton;
class QTableView;
class QVBoxLayout;

namespace rigidlab::lessons {
class ClassTableModel;
class ClassTableSorting;
} // namespace rigidlab::lessons

namespace rigidlab::ui {

class ClassResultsDialog : public QDialog {
    Q_OBJECT
public:
    explicit ClassResultsDialog(QWidget* parent = nullptr);

    /// Collects the answers files of `folder` (the lesson most of them answer).
    void setFolder(const QString& folder);
    /// Shows the table of another lesson the folder holds answers to (its file name).
    void setLesson(const QString& lessonFile);

    const lessons::ClassCollection& collected() const { return m_collected; }
    QTableView* view() const { return m_view; }
    QListWidget* skippedList() const { return m_skipped; }

    /// Writes the table shown; empty on success, else why not.
    QString writeCsv(const QString& path, lessons::CsvDialect dialect) const;
    QString writePdf(const QString& path) const;

private:
    void buildChoosers(QVBoxLayout& layout);
    void buildTable(QVBoxLayout& layout);
    void buildFooter(QVBoxLayout& layout);
    void chooseFolder();
    void collect(const QString& lessonFile);
    void showCollected();
    void sortChosen();
    void exportCsvDialog();
    void exportPdfDialog();

    QString m_folder;
    lessons::ClassCollection m_collected;
    QLineEdit* m_folderEdit = nullptr;
    QComboBox* m_lesson = nullptr;
    QLabel* m_summary = nullptr;
    QTableView* m_view = nullptr;
    QComboBox* m_sortBy = nullptr;
    QCheckBox* m_descending = nullptr;
    QListWidget* m_skipped = nullptr;
    QPushButton* m_csv = nullptr;
    QPushButton* m_pdf = nullptr;
    lessons::ClassTableModel* m_model = nullptr;
    lessons::ClassTableSorting* m_sorting = nullptr;
};

} // namespace rigidlab::ui
