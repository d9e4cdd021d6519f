// SPDX-License-Identifier: GPL-3.0-or-later
#include "common/accessible_names.h"

#include <QComboBox>
#include <QCoreApplication>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QScrollArea>
#include <QScrollBar>
#include <QSpinBox>

namespace rigidlab::ui {

void nameScrollArea(QScrollArea& area, const QString& name)
{
    area.setAccessibleName(name);
    area.setFocusPolicy(Qt::NoFocus);
    area.verticalScrollBar()->setAccessibleName(
        QCoreApplication::translate("AccessibleNames", "Scroll %1").arg(name));
    area.horizontalScrollBar()->setAccessibleName(
        QCoreApplication::translate("AccessibleNames", "Scroll %1 sideways").arg(name));
}

void followRows(QFormLayout& form)
{
    QWidget* previous = nullptr;
    for (int row = 0; row < form.rowCount(); ++row) {
        QLayoutItem* item = form.itemAt(row, QFormLayout::FieldRole);
        QWidget* field = item ? item->widget() : nullptr;
        if (!field)
            continue;
        if (previous)
            QWidget::setTabOrder(previous, field);
        previous = field;
        QLayoutItem* labelItem = form.itemAt(row, QFormLayout::LabelRole);
        auto* label = labelItem ? qobject_cast<QLabel*>(labelItem->widget()) : nullptr;
        if (auto* list = qobject_cast<QComboBox*>(field); list && label)
            list->setAccessibleName(QString(label->text()).remove(QLatin1Char('&')));
    }
}

void nameWithUnit(QAbstractSpinBox& box, const QString& name)
{
    QString unit;
    if (const auto* d = qobject_cast<const QDoubleSpinBox*>(&box))
        unit = d->suffix().trimmed();
    else if (const auto* i = qobject_cast<const QSpinBox*>(&box))
        unit = i->suffix().trimmed();
    box.setAccessibleName(unit.isEmpty() ? name : QStringLiteral("%1 [%2]").arg(name, unit));
}

} // namespace rigidlab::ui
