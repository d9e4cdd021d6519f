// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Tells a screen reader what happens in the scene, politely: the bodies' values at a calm
// rate while the world runs (kValueIntervalMs), and events (the first contact, everything
// coming to rest, the run diverging) merged into one status line, at most once per
// kValueIntervalMs. Qt 6.4 has no announcement event, so the status is a child of the
// scene view (world_view_accessible.h) whose description changes; a reader finds it up to
// date without the focus moving. A body's value is told again only when it changed. What the
// student does (a body chosen or moved, play and pause) and a divergence are announced
// (announcer.h). The narrator only reads the world.

#include <QElapsedTimer>
#include <QHash>
#include <QObject>
#include <QStringList>
#include <QTimer>

namespace rigidlab::ui {

class RunView;
class WorldView;

class SceneNarrator : public QObject {
    Q_OBJECT
public:
    /// The least time between two updates told to assistive technology [ms].
    static constexpr int kValueIntervalMs = 1000;
    /// A body slower than this is at rest [m/s]; faster than kMovingSpeed, it moves.
    static constexpr double kRestSpeed = 0.01;
    static constexpr double kMovingSpeed = 0.05;

    SceneNarrator(const RunView& run, WorldView& view);

    /// The events told last, merged: "Ball and ground touch. Everything is at rest."
    QString status() const { return m_status; }
    /// How many times the status changed (for tests: it is rate limited).
    int statusChanges() const { return m_changes; }
    /// Tells now what is pending (the timer does it at its calm rate).
    void flush();

    /// How long the keys must rest before a moved body's new place is told [ms].
    static constexpr int kSettleMs = 600;
    /// Announces the body the student chose: its name and speed ("ball 1, speed 2.1 m/s").
    void tellChosen(int id);
    /// Announces where body `id`, moved or pushed with the keys, is and how fast it goes, once
    /// the keys have rested for kSettleMs (one announcement for a run of presses).
    void tellMoved(int id);

signals:
    /// A value told to assistive technology (as a description change when it listens): of
    /// the scene view's child `child` (WorldViewAccessible::Child, or a body's index after
    /// FirstBody).
    void told(int child, const QString& value);

private:
    void onWorldChanged();
    void onSceneLoaded();
    void tellValues();
    void note(const QString& event);
    void tell(int child, const QString& value);

    const RunView& m_run;
    WorldView& m_view;
    QTimer m_tick;
    QTimer m_settle; ///< tells the moved body once the keys rest
    int m_moved = -1;
    QElapsedTimer m_sinceTold;
    QStringList m_pending;
    QHash<int, QString> m_toldValues; ///< each body's value as last told, by body id
    QString m_status;
    int m_changes = 0;
    bool m_touched = false;  ///< some bodies touched since the scene (re)started
    bool m_moving = false;   ///< some body moved since it last came to rest
    bool m_diverged = false; ///< the divergence was told
};

} // namespace rigidlab::ui
