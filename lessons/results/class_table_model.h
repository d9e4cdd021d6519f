// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The class's table for a view (the window's File › Class results…): one row per student and
// the summary row last, its columns those of classColumns(). Numbers sort as numbers (the
// sort role holds them); ClassTableSorting keeps the summary row last in either order.

#include "results/class_table.h"

#include <QAbstractTableModel>
#include <QSortFilterProxyModel>

#include <vector>

namespace rigidlab::lessons {

class ClassTableModel : public QAbstractTableModel {
    Q_OBJECT
public:
    /// The role that holds what a column sorts by: the number of a number, else the text.
    static constexpr int kSortRole = Qt::UserRole + 1;
    /// The role that is true on the summary row.
    static constexpr int kSummaryRole = Qt::UserRole + 2;

    explicit ClassTableModel(QObject* parent = nullptr);

    void setTable(ClassTable table);
    const ClassTable& table() const { return m_table; }

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

private:
    ClassCell cell(int row, int column) const;

    ClassTable m_table;
    std::vector<ClassColumn> m_columns;
};

/// Sorts by ClassTableModel::kSortRole and keeps the summary row at the bottom.
class ClassTableSorting : public QSortFilterProxyModel {
    Q_OBJECT
public:
    explicit ClassTableSorting(QObject* parent = nullptr);

protected:
    bool lessThan(const QModelIndex& left, const QModelIndex& right) const override;
};

} // namespace rigidlab::lessons
