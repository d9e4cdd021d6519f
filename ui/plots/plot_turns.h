// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The plots that follow one run take turns after its frames. Each drains (and so replots) at
// most every refresh interval (PlotWidget::kRefreshIntervalMs), and a frame drains at most
// half of them, rounded up, those that waited longest first. Without turns every plot starts
// on the run's first frame and keeps that phase: at 60 frames a second all of them replotted
// in every second frame and none in the others, so that one frame in two carried every replot
// (three on the window's plots). With turns the window's three plots replot two in one frame
// and one in the next. When frames come slower than the refresh interval, a plot waits a
// frame more now and then instead of every plot replotting in every frame (at 30 frames a
// second each of three plots replots about 20 times a second instead of 30); every plot
// still shows all of its samples.

#include <QElapsedTimer>
#include <QObject>
#include <QPointer>

#include <vector>

namespace rigidlab::ui {

class PlotWidget;

class PlotTurns : public QObject {
    Q_OBJECT
public:
    explicit PlotTurns(QObject* parent = nullptr);

    /// Lets `plot` take turns from the next frame on (its first turn as soon as there is
    /// room), and staggers its own timer after those added before (PlotWidget::staggerRefresh);
    /// a plot destroyed leaves.
    void add(PlotWidget* plot);
    /// The plots taking turns (those not destroyed).
    int count() const;

    /// A frame of the run ended at `nowMs` [ms, from any fixed origin]: tells every plot that
    /// frames come (its own timer stands down) and drains those whose turn it is. Returns the
    /// plots drained, in the order drained.
    std::vector<PlotWidget*> frame(qint64 nowMs);

public slots:
    /// A frame of the run ended: frame() at the turns' own monotonic clock.
    void frameAdvanced();

private:
    struct Turn {
        QPointer<PlotWidget> plot;
        qint64 lastMs = 0;    ///< when it last drained [ms]; see `drained`
        bool drained = false; ///< whether it drained since it joined
        long long order = 0;  ///< which drain of these turns was its last (ties: older first)
    };

    std::vector<Turn> m_turns;
    long long m_drains = 0; ///< drains so far, to order plots drained in the same frame
    QElapsedTimer m_clock;
};

} // namespace rigidlab::ui
