// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What the lab tells a screen reader, counted: EventCount records the accessibility events Qt
// hands to the platform's bridge (and the values the scene's narrator tells), and
// CountingBridge is the bridge that hands them over. The test that includes this defines the
// bridge's plugin and imports it (Q_IMPORT_PLUGIN): a plugin's metadata needs its own moc run.

#include "view/scene_narrator.h"
#include "view/world_view.h"
#include "window/main_window.h"

#include <QAccessible>
#include <QAccessibleBridge>
#include <QElapsedTimer>
#include <QList>
#include <QMap>
#include <QObject>
#include <QString>
#include <QStringList>
#include <QtTest>

#include <algorithm>
#include <functional>
#include <utility>

namespace rigidlab::test {

/// Counts the accessibility events Qt sends, and the values the scene's narrator tells (it
/// tells them only when a reader listens, which offscreen nobody does).
///
/// Qt hands its events to the platform's bridge: AT-SPI on a desktop. The offscreen platform
/// has none of its own, and passes them to the bridge plugins it finds, this test's
/// CountingBridge among them (QAccessible's update handler would see them only where a
/// reader had switched the platform's accessibility on).
class EventCount {
public:
    EventCount() { s_current = this; }
    explicit EventCount(ui::MainWindow& w) : EventCount()
    {
        QObject::connect(&w.view().narrator(), &ui::SceneNarrator::told, &m_context,
                         [this](int child, const QString&) {
                             add(QStringLiteral("narrator value of child %1").arg(child));
                         });
    }
    ~EventCount() { s_current = nullptr; }
    EventCount(const EventCount&) = delete;
    EventCount& operator=(const EventCount&) = delete;

    static void handle(QAccessibleEvent* event)
    {
        if (s_current)
            s_current->record(event);
    }

    void restart()
    {
        m_bySource.clear();
        m_shows.clear();
        m_sequence.clear();
        m_total = 0;
    }
    int total() const { return m_total; }
    /// The most frequent sources, "count × source", most first.
    QString top(int n = 5) const
    {
        QList<std::pair<int, QString>> sorted;
        for (auto it = m_bySource.begin(); it != m_bySource.end(); ++it)
            sorted.append({it.value(), it.key()});
        std::sort(sorted.begin(), sorted.end(), std::greater<>());
        QStringList out;
        for (int i = 0; i < std::min<qsizetype>(n, sorted.size()); ++i)
            out << QStringLiteral("%1 × %2").arg(sorted[i].first).arg(sorted[i].second);
        return out.join(QStringLiteral("; "));
    }
    /// How many times one object was shown or hidden, the most of any.
    int mostShowsOfOneObject() const
    {
        int most = 0;
        for (auto it = m_shows.begin(); it != m_shows.end(); ++it)
            most = std::max(most, it.value());
        return most;
    }
    /// The announcements told (a notification shown, with its message).
    const QStringList& announced() const { return m_announced; }
    /// The events of `object`, in the order they came.
    QList<QAccessible::Event> eventsOf(const QObject* object) const
    {
        QList<QAccessible::Event> out;
        for (const auto& [type, source] : m_sequence)
            if (source == object)
                out << type;
        return out;
    }
    /// The events of `object` in order, as hexadecimal codes ("11b 8005").
    QString orderOf(const QObject* object) const
    {
        QStringList out;
        for (QAccessible::Event e : eventsOf(object))
            out << QString::number(int(e), 16);
        return out.join(u' ');
    }
    /// Where the first `type` event of `object` came among all the events counted (-1: none).
    qsizetype firstIndex(const QObject* object, QAccessible::Event type) const
    {
        for (qsizetype i = 0; i < m_sequence.size(); ++i)
            if (m_sequence[i] == std::pair<QAccessible::Event, const QObject*>{type, object})
                return i;
        return -1;
    }
    /// The events of items with no object of their own, each with the item's description.
    const QList<std::pair<QAccessible::Event, QString>>& itemEvents() const { return m_items; }

private:
    void record(QAccessibleEvent* event)
    {
        const QAccessible::Event type = event->type();
        QObject* object = event->object();
        // Qt's AT-SPI bridge passes a value change only for an object with a numeric value
        // interface ("ValueChanged event and no ValueInterface"): the others reach no reader.
        if (type == QAccessible::ValueChanged) {
            QAccessibleInterface* changed = event->accessibleInterface();
            if (!(changed && changed->valueInterface()))
                return;
        }
        m_sequence.append({type, object});
        if (type == QAccessible::ObjectDestroyed || !object) {
            add(QStringLiteral("event %1").arg(int(type), 0, 16));
            // An item with no object of its own (the scene's bodies and status): what it says.
            if (QAccessibleInterface* item = object ? nullptr : event->accessibleInterface())
                m_items.append({type, item->text(QAccessible::Description)});
            return;
        }
        QAccessibleInterface* iface = event->accessibleInterface();
        const QString name = iface ? iface->text(QAccessible::Name) : QString();
        const int role = iface ? int(iface->role()) : -1;
        add(QStringLiteral("event 0x%1 on %2 '%3' role 0x%4")
                .arg(int(type), 0, 16)
                .arg(QString::fromLatin1(object->metaObject()->className()), name.left(40))
                .arg(role, 0, 16));
        if (type == QAccessible::ObjectShow || type == QAccessible::ObjectHide)
            ++m_shows[object];
        if (type == QAccessible::ObjectShow && role == int(QAccessible::Notification))
            m_announced << name;
    }

    void add(const QString& source)
    {
        ++m_total;
        ++m_bySource[source];
    }

    static inline EventCount* s_current = nullptr;
    QObject m_context;
    QMap<QString, int> m_bySource;
    QMap<QObject*, int> m_shows;
    QStringList m_announced;
    QList<std::pair<QAccessible::Event, QString>> m_items;
    QList<std::pair<QAccessible::Event, const QObject*>> m_sequence;
    int m_total = 0;
};

/// The bridge Qt hands every accessibility event to: it passes each to the EventCount counting.
class CountingBridge : public QAccessibleBridge {
public:
    void setRootObject(QAccessibleInterface*) override {}
    void notifyAccessibilityUpdate(QAccessibleEvent* event) override { EventCount::handle(event); }
};

/// Lets the window run its event loop for `ms` and returns the events a second it sent.
inline double eventsPerSecond(EventCount& count, int ms)
{
    count.restart();
    QElapsedTimer clock;
    clock.start();
    QTest::qWait(ms);
    return count.total() * 1000.0 / static_cast<double>(clock.elapsed());
}

} // namespace rigidlab::test
