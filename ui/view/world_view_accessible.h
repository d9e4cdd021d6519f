// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The scene view as a screen reader sees it. A QGraphicsView is a silent canvas to assistive
// technology; this interface gives it a tree (Qt's accessibility factory makes it for every
// WorldView):
//
//   scene view        name "Scene: <title>", description: the summary
//     summary         what is on stage, what is happening now, what the student can do
//     status          the last events, told as description changes (scene_narrator.h)
//     body 0 … n-1    name and kind; description and value: shape, mass, position, velocity
//
// The children are read from the controller's world whenever asked, so that they are never
// stale; the narrator tells assistive technology when to read them again.

#include <QAccessibleWidget>

#include <vector>

namespace rigidlab::ui {

class WorldView;

/// The factory of the scene view's interface (installed with the window's others,
/// window/accessible_factories.h).
QAccessibleInterface* worldViewInterface(const QString& className, QObject* object);

/// Tells assistive technology that child `child` of `view`'s interface (the status, or a body
/// after WorldViewAccessible::FirstBody) says something new, as a change of its description,
/// which is what it says. Not a value change: Qt 6.4's AT-SPI bridge drops that for an object
/// without a numeric value interface ("ValueChanged event and no ValueInterface"), and a
/// reader's cache of the description (libatspi keeps one) would stay stale.
void tellSceneItemChanged(WorldView& view, int child);

class WorldViewAccessible : public QAccessibleWidget {
public:
    /// The children before the bodies.
    enum Child { Summary = 0, Status = 1, FirstBody = 2 };

    explicit WorldViewAccessible(WorldView* view);
    ~WorldViewAccessible() override;

    QString text(QAccessible::Text t) const override;
    int childCount() const override;
    QAccessibleInterface* child(int index) const override;
    int indexOfChild(const QAccessibleInterface* child) const override;
    QAccessible::State state() const override;

    WorldView* view() const;

private:
    /// The child interfaces made so far, registered with QAccessible, by index.
    mutable std::vector<QAccessible::Id> m_children;
};

} // namespace rigidlab::ui
