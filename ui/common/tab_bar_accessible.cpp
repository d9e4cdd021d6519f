// SPDX-License-Identifier: GPL-3.0-or-later
#include "common/tab_bar_accessible.h"

#include <QAccessibleWidget>
#include <QPointer>
#include <QTabBar>
#include <QToolButton>

#include <vector>

namespace rigidlab::ui {

namespace {

/// One tab of a tab bar; it reads the bar, and is invalid once the tab is gone.
class TabAccessible : public QAccessibleInterface, public QAccessibleActionInterface {
public:
    TabAccessible(QTabBar* bar, int index) : m_bar(bar), m_index(index) {}

    void* interface_cast(QAccessible::InterfaceType t) override
    {
        return t == QAccessible::ActionInterface ? static_cast<QAccessibleActionInterface*>(this)
                                                 : nullptr;
    }
    bool isValid() const override { return m_bar && m_index < m_bar->count(); }
    QObject* object() const override { return nullptr; }
    QWindow* window() const override { return m_bar ? m_bar->window()->windowHandle() : nullptr; }
    QAccessibleInterface* parent() const override
    {
        return m_bar ? QAccessible::queryAccessibleInterface(m_bar) : nullptr;
    }
    QAccessibleInterface* childAt(int, int) const override { return nullptr; }
    QAccessibleInterface* child(int) const override { return nullptr; }
    int childCount() const override { return 0; }
    int indexOfChild(const QAccessibleInterface*) const override { return -1; }
    QAccessible::Role role() const override { return QAccessible::PageTab; }

    QString text(QAccessible::Text t) const override
    {
        if (!isValid())
            return {};
        if (t == QAccessible::Name) {
            const QString name = m_bar->accessibleTabName(m_index);
            return name.isEmpty() ? QString(m_bar->tabText(m_index)).remove(u'&') : name;
        }
        return t == QAccessible::Description ? m_bar->tabToolTip(m_index) : QString();
    }
    void setText(QAccessible::Text, const QString&) override {}

    QRect rect() const override
    {
        if (!isValid())
            return {};
        const QRect r = m_bar->tabRect(m_index);
        return QRect(m_bar->mapToGlobal(r.topLeft()), r.size());
    }

    QAccessible::State state() const override
    {
        QAccessible::State s;
        if (!isValid()) {
            s.invalid = true;
            return s;
        }
        QAccessibleInterface* bar = parent();
        if (bar)
            s = bar->state();
        const bool current = m_index == m_bar->currentIndex();
        // Where the keys go, and only there: the current tab of the bar that has the focus.
        s.focused = current && m_bar->hasFocus();
        s.selectable = true;
        s.selected = current;
        s.disabled = s.disabled || !m_bar->isTabEnabled(m_index);
        s.invisible = s.invisible || !m_bar->isTabVisible(m_index);
        return s;
    }

    QStringList actionNames() const override { return {pressAction()}; }
    void doAction(const QString& name) override
    {
        if (isValid() && name == pressAction())
            m_bar->setCurrentIndex(m_index);
    }
    QStringList keyBindingsForAction(const QString&) const override { return {}; }

private:
    QPointer<QTabBar> m_bar;
    int m_index;
};

/// A tab bar: its tabs, then its scroll buttons.
class TabBarAccessible : public QAccessibleWidget {
public:
    explicit TabBarAccessible(QTabBar* bar) : QAccessibleWidget(bar, QAccessible::PageTabList) {}
    ~TabBarAccessible() override
    {
        for (QAccessible::Id id : m_tabs)
            if (id)
                QAccessible::deleteAccessibleInterface(id);
    }

    int childCount() const override { return bar()->count() + static_cast<int>(buttons().size()); }
    QAccessibleInterface* child(int index) const override
    {
        const int tabs = bar()->count();
        if (index < 0 || index >= childCount())
            return nullptr;
        if (index >= tabs)
            return QAccessible::queryAccessibleInterface(buttons()[index - tabs]);
        if (m_tabs.size() <= static_cast<std::size_t>(index))
            m_tabs.resize(static_cast<std::size_t>(index) + 1, 0);
        QAccessible::Id& id = m_tabs[static_cast<std::size_t>(index)];
        if (!id)
            id = QAccessible::registerAccessibleInterface(new TabAccessible(bar(), index));
        return QAccessible::accessibleInterface(id);
    }
    int indexOfChild(const QAccessibleInterface* child) const override
    {
        for (int i = 0; i < childCount(); ++i)
            if (this->child(i) == child)
                return i;
        return -1;
    }
    /// Named, as Qt names it, by its current tab.
    QString text(QAccessible::Text t) const override
    {
        if (t != QAccessible::Name)
            return QAccessibleWidget::text(t);
        QAccessibleInterface* current = child(bar()->currentIndex());
        return current ? current->text(t) : QString();
    }
    QAccessibleInterface* focusChild() const override
    {
        return bar()->hasFocus() ? child(bar()->currentIndex()) : nullptr;
    }

private:
    QTabBar* bar() const { return static_cast<QTabBar*>(widget()); }
    QList<QToolButton*> buttons() const
    {
        return bar()->findChildren<QToolButton*>(Qt::FindDirectChildrenOnly);
    }

    mutable std::vector<QAccessible::Id> m_tabs;
};

} // namespace

QAccessibleInterface* tabBarInterface(const QString& className, QObject* object)
{
    if (className == QLatin1String("QTabBar"))
        if (auto* bar = qobject_cast<QTabBar*>(object))
            return new TabBarAccessible(bar);
    return nullptr;
}

} // namespace rigidlab::ui
