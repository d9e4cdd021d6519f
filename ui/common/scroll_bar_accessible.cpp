// SPDX-License-Identifier: GPL-3.0-or-later
#include "common/scroll_bar_accessible.h"

#include <QAccessibleValueInterface>
#include <QAccessibleWidget>
#include <QScrollBar>

namespace rigidlab::ui {

namespace {

class ScrollBarAccessible : public QAccessibleWidget, public QAccessibleValueInterface {
public:
    explicit ScrollBarAccessible(QScrollBar* bar) : QAccessibleWidget(bar, QAccessible::ScrollBar)
    {
    }

    void* interface_cast(QAccessible::InterfaceType t) override
    {
        if (t == QAccessible::ValueInterface)
            return bar()->isVisible() ? static_cast<QAccessibleValueInterface*>(this) : nullptr;
        return QAccessibleWidget::interface_cast(t);
    }

    QString text(QAccessible::Text t) const override
    {
        if (t == QAccessible::Value)
            return QString::number(bar()->value());
        return QAccessibleWidget::text(t);
    }

    QVariant currentValue() const override { return bar()->value(); }
    void setCurrentValue(const QVariant& value) override { bar()->setValue(value.toInt()); }
    QVariant maximumValue() const override { return bar()->maximum(); }
    QVariant minimumValue() const override { return bar()->minimum(); }
    QVariant minimumStepSize() const override { return bar()->singleStep(); }

private:
    QScrollBar* bar() const { return static_cast<QScrollBar*>(widget()); }
};

} // namespace

QAccessibleInterface* scrollBarInterface(const QString& className, QObject* object)
{
    if (className == QLatin1String("QScrollBar") && object && object->isWidgetType())
        return new ScrollBarAccessible(static_cast<QScrollBar*>(object));
    return nullptr;
}

} // namespace rigidlab::ui
