// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A focus ring that reads on a projector: a dark ring kFocusRingPx wide (wider in
// presentation mode) with a light halo around it, drawn around whatever control has the
// keyboard focus, the scene view and the plots included. Styles draw focus as they please (a
// 1-pixel frame at 2:1, or nothing on custom views); WCAG 2.4.7 and 1.4.11 ask for a focus
// that is seen, at least 3:1 against what is next to it. The dark ring has that against the
// light windows and the halo against anything dark beneath.
//
// The ring is a child of the focused control's window, above everything, transparent for the
// mouse, and follows the control as it moves or resizes.

#include <QPointer>
#include <QWidget>

namespace rigidlab::ui {

class FocusRing : public QWidget {
    Q_OBJECT
public:
    /// Starts drawing the ring for the whole application (once; later calls return it).
    static FocusRing& install();

    /// The control the ring is drawn around now (nullptr: none).
    QWidget* target() const { return m_target; }
    /// The ring's width now [px].
    static int ringWidth();

protected:
    void paintEvent(QPaintEvent* event) override;
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    FocusRing();
    void follow(QWidget* focus);
    void place();

    QPointer<QWidget> m_target;
};

} // namespace rigidlab::ui
