// SPDX-License-Identifier: GPL-3.0-or-later
#include "results/class_table_model.h"

namespace rigidlab::lessons {

ClassTableModel::ClassTableModel(QObject* parent) : QAbstractTableModel(parent) {}

void ClassTableModel::setTable(ClassTable table)
{
    beginResetModel();
    m_table = std::move(table);
    m_columns = classColumns(m_table);
    endResetModel();
}

int ClassTableModel::rowCount(const QModelIndex& parent) const
{
    // The students, then the summary row (none for an empty table).
    return parent.isValid() || m_table.rows.empty() ? 0 : static_cast<int>(m_table.rows.size()) + 1;
}

int ClassTableModel::columnCount(const QModelIndex& parent) const
{
    return parent.isValid() ? 0 : static_cast<int>(m_columns.size());
}

ClassCell ClassTableModel::cell(int row, int column) const
{
    const ClassColumn& c = m_columns.at(static_cast<std::size_t>(column));
    return row < static_cast<int>(m_table.rows.size())
               ? classCell(m_table, static_cast<std::size_t>(row), c)
               : classSummaryCell(m_table, c);
}

QVariant ClassTableModel::data(const QModelIndex& index, int role) const
{
    if (!index.isValid() || index.row() >= rowCount() || index.column() >= columnCount())
        return {};
    const bool summary = index.row() == static_cast<int>(m_table.rows.size());
    switch (role) {
    case Qt::DisplayRole:
    case Qt::AccessibleTextRole:
        return cell(index.row(), index.column()).text;
    case Qt::ToolTipRole:
        return summary ? QVariant() : QVariant(m_table.rows.at(std::size_t(index.row())).file);
    case Qt::TextAlignmentRole: {
        const ClassCell c = cell(index.row(), index.column());
        return c.number ? QVariant(Qt::AlignRight | Qt::AlignVCenter) : QVariant();
    }
    case kSortRole: {
        const ClassCell c = cell(index.row(), index.column());
        return c.number ? QVariant(*c.number) : QVariant(c.text);
    }
    case kSummaryRole:
        return summary;
    default:
        return {};
    }
}

QVariant ClassTableModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || section < 0 || section >= columnCount())
        return QAbstractTableModel::headerData(section, orientation, role);
    if (role != Qt::DisplayRole && role != Qt::AccessibleTextRole)
        return {};
    return classColumnHead(m_table, m_columns.at(static_cast<std::size_t>(section)));
}

ClassTableSorting::ClassTableSorting(QObject* parent) : QSortFilterProxyModel(parent)
{
    setSortRole(ClassTableModel::kSortRole);
}

bool ClassTableSorting::lessThan(const QModelIndex& left, const QModelIndex& right) const
{
    // The summary row sorts last whichever way: Qt sorts descending by asking lessThan with
    // the sides swapped, so it is the least one then.
    const bool descending = sortOrder() == Qt::DescendingOrder;
    if (left.data(ClassTableModel::kSummaryRole).toBool())
        return descending;
    if (right.data(ClassTableModel::kSummaryRole).toBool())
        return !descending;
    // Numbers as numbers; a cell without one (not answered) before them; text as the
    // language orders it.
    const QVariant l = left.data(sortRole());
    const QVariant r = right.data(sortRole());
    const bool leftNumber = l.typeId() == QMetaType::Double;
    const bool rightNumber = r.typeId() == QMetaType::Double;
    if (leftNumber && rightNumber)
        return l.toDouble() < r.toDouble();
    if (leftNumber != rightNumber)
        return rightNumber;
    return QString::localeAwareCompare(l.toString(), r.toString()) < 0;
}

} // namespace rigidlab::lessons
