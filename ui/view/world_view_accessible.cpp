// SPDX-License-Identifier: GPL-3.0-or-later
#include "view/world_view_accessible.h"

#include "simulation/run_view.h"
#include "view/body_item.h"
#include "view/scene_narrator.h"
#include "view/scene_words.h"
#include "view/world_view.h"

#include <QPointer>

namespace rigidlab::ui {

namespace {

/// One child of the scene view: the summary, the status or a body. It has no QObject of its
/// own; it reads the view it belongs to, and is invalid once the view is gone.
class SceneItemAccessible : public QAccessibleInterface {
public:
    SceneItemAccessible(WorldView* view, int index) : m_view(view), m_index(index) {}

    bool isValid() const override
    {
        return m_view && index() < static_cast<int>(bodyCount()) + WorldViewAccessible::FirstBody;
    }
    QObject* object() const override { return nullptr; }
    QWindow* window() const override { return m_view ? m_view->window()->windowHandle() : nullptr; }
    QAccessibleInterface* childAt(int, int) const override { return nullptr; }
    QAccessibleInterface* parent() const override
    {
        return m_view ? QAccessible::queryAccessibleInterface(m_view) : nullptr;
    }
    QAccessibleInterface* child(int) const override { return nullptr; }
    int childCount() const override { return 0; }
    int indexOfChild(const QAccessibleInterface*) const override { return -1; }

    QString text(QAccessible::Text t) const override
    {
        if (!isValid())
            return {};
        const RunView& c = m_view->run();
        switch (index()) {
        case WorldViewAccessible::Summary:
            if (t == QAccessible::Name)
                return scene_words::SceneWords::tr("Summary");
            return t == QAccessible::Description || t == QAccessible::Value
                       ? scene_words::summary(c, m_view->selectedBody())
                       : QString();
        case WorldViewAccessible::Status:
            if (t == QAccessible::Name)
                return scene_words::SceneWords::tr("What happened");
            return t == QAccessible::Description || t == QAccessible::Value
                       ? m_view->narrator().status()
                       : QString();
        default:
            break;
        }
        const int id = body();
        if (t == QAccessible::Name)
            return scene_words::bodyName(c, id);
        if (t == QAccessible::Description || t == QAccessible::Value)
            return scene_words::bodyValue(c, id);
        return {};
    }
    void setText(QAccessible::Text, const QString&) override {}

    QRect rect() const override
    {
        if (!isValid())
            return {};
        const QRect whole(m_view->mapToGlobal(QPoint(0, 0)), m_view->size());
        const BodyItem* item =
            index() >= WorldViewAccessible::FirstBody ? m_view->itemFor(body()) : nullptr;
        if (!item)
            return whole;
        const QRect inView = m_view->mapFromScene(item->sceneBox())
                                 .boundingRect()
                                 .intersected(m_view->viewport()->rect());
        return QRect(m_view->viewport()->mapToGlobal(inView.topLeft()), inView.size());
    }
    QAccessible::Role role() const override
    {
        switch (index()) {
        case WorldViewAccessible::Summary:
            return QAccessible::StaticText;
        case WorldViewAccessible::Status:
            return QAccessible::StatusBar;
        default:
            return QAccessible::ListItem;
        }
    }
    QAccessible::State state() const override
    {
        QAccessible::State s;
        if (!isValid()) {
            s.invalid = true;
            return s;
        }
        // A status bar is what readers speak politely when its value changes (AT-SPI has
        // no "live" state for Qt 6.4 to set).
        if (index() >= WorldViewAccessible::FirstBody) {
            s.selectable = true;
            s.selected = m_view->selectedBody() == body();
        }
        s.readOnly = true;
        return s;
    }

private:
    int index() const { return m_index; }
    int body() const { return m_index - WorldViewAccessible::FirstBody; }
    std::size_t bodyCount() const { return m_view->run().world().bodies().size(); }

    QPointer<WorldView> m_view;
    int m_index;
};

} // namespace

QAccessibleInterface* worldViewInterface(const QString& className, QObject* object)
{
    if (className == QLatin1String(WorldView::staticMetaObject.className()) && object &&
        object->isWidgetType())
        return new WorldViewAccessible(static_cast<WorldView*>(object));
    return nullptr;
}

void tellSceneItemChanged(WorldView& view, int child)
{
    QAccessibleInterface* scene = QAccessible::queryAccessibleInterface(&view);
    if (QAccessibleInterface* item = scene ? scene->child(child) : nullptr) {
        QAccessibleEvent event(item, QAccessible::DescriptionChanged);
        QAccessible::updateAccessibility(&event);
    }
}

WorldViewAccessible::WorldViewAccessible(WorldView* view)
    : QAccessibleWidget(view, QAccessible::Graphic)
{
}

WorldViewAccessible::~WorldViewAccessible()
{
    for (QAccessible::Id id : m_children)
        if (id)
            QAccessible::deleteAccessibleInterface(id);
}

WorldView* WorldViewAccessible::view() const
{
    return static_cast<WorldView*>(widget());
}

QString WorldViewAccessible::text(QAccessible::Text t) const
{
    if (t == QAccessible::Name)
        return scene_words::sceneName(view()->run());
    if (t == QAccessible::Description)
        return scene_words::summary(view()->run(), view()->selectedBody());
    return QAccessibleWidget::text(t);
}

QAccessible::State WorldViewAccessible::state() const
{
    QAccessible::State s = QAccessibleWidget::state();
    s.focusable = true;
    return s;
}

int WorldViewAccessible::childCount() const
{
    return FirstBody + static_cast<int>(view()->run().world().bodies().size());
}

QAccessibleInterface* WorldViewAccessible::child(int index) const
{
    if (index < 0 || index >= childCount())
        return nullptr;
    if (m_children.size() <= static_cast<std::size_t>(index))
        m_children.resize(static_cast<std::size_t>(index) + 1, 0);
    QAccessible::Id& id = m_children[static_cast<std::size_t>(index)];
    if (!id)
        id = QAccessible::registerAccessibleInterface(new SceneItemAccessible(view(), index));
    return QAccessible::accessibleInterface(id);
}

int WorldViewAccessible::indexOfChild(const QAccessibleInterface* child) const
{
    for (std::size_t i = 0; i < m_children.size(); ++i)
        if (m_children[i] && QAccessible::accessibleInterface(m_children[i]) == child)
            return static_cast<int>(i);
    return -1;
}

} // namespace rigidlab::ui
