// SPDX-License-Identifier: GPL-3.0-or-later
// PlotWidget's context menu (export, describe, follow, time range), its keys, and how a screen
// reader finds it.

#include "plots/plot_widget.h"

#include "common/modal_scope.h"
#include "plots/plot_accessible.h"
#include "plots/plot_exporter.h"

#include <qcustomplot.h>

#include <QActionGroup>
#include <QMenu>
#include <QMessageBox>
#include <QShortcut>

#include <algorithm>
#include <utility>
#include <vector>

namespace rigidlab::ui {

void PlotWidget::showContextMenu(const QPoint& pos)
{
    auto* menu = new QMenu(this);
    menu->setAttribute(Qt::WA_DeleteOnClose);

    const std::pair<ExportFormat, QString> exports[] = {
        {ExportFormat::Png, tr("Export as PNG…")},
        {ExportFormat::Pdf, tr("Export as PDF…")},
        {ExportFormat::Svg, tr("Export as SVG…")},
        {ExportFormat::Csv, tr("Export data as CSV…")},
    };
    for (const auto& entry : exports) {
        const ExportFormat format = entry.first;
        if (!canExport(format))
            continue;
        connect(menu->addAction(entry.second), &QAction::triggered, m_exporter,
                [this, format] { m_exporter->exportInteractively(format); });
    }
    QAction* copy = menu->addAction(tr("Copy data shown"), m_exporter, &PlotExporter::copyData);
    copy->setShortcut(QKeySequence::Copy); // shown in the menu; the plot's own shortcut acts
    menu->addAction(tr("Describe this plot…"), this, [this] {
        drain();
        QMessageBox box(QMessageBox::Information, title(), describePlot(*this), QMessageBox::Ok,
                        this);
        box.setTextInteractionFlags(Qt::TextSelectableByMouse | Qt::TextSelectableByKeyboard);
        const ModalScope modal;
        box.exec();
    });
    menu->addSeparator();

    QAction* followAction = menu->addAction(tr("Follow"));
    followAction->setCheckable(true);
    followAction->setChecked(m_following);
    connect(followAction, &QAction::toggled, this, &PlotWidget::setFollowing);
    menu->addSeparator();

    // Last N s (a few usual lengths, and the current one) or the whole run.
    auto* modes = new QActionGroup(menu);
    const double window = m_model->windowSeconds();
    std::vector<double> lengths{5, 10, 30, 60}; // [s]
    if (std::find(lengths.begin(), lengths.end(), window) == lengths.end())
        lengths.insert(std::upper_bound(lengths.begin(), lengths.end(), window), window);
    const bool windowMode = m_model->rangeMode() == RangeMode::Window;
    for (const double seconds : lengths) {
        QAction* action = modes->addAction(tr("Last %1 s").arg(seconds));
        action->setCheckable(true);
        action->setChecked(windowMode && seconds == window);
        connect(action, &QAction::triggered, this, [this, seconds] {
            m_model->setWindowSeconds(seconds);
            m_model->setRangeMode(RangeMode::Window);
        });
    }
    QAction* wholeRun = modes->addAction(tr("Whole run"));
    wholeRun->setCheckable(true);
    wholeRun->setChecked(!windowMode);
    connect(wholeRun, &QAction::triggered, this,
            [this] { m_model->setRangeMode(RangeMode::WholeRun); });
    menu->addActions(modes->actions());
    for (QAction* action : std::as_const(m_menuActions))
        if (action) {
            menu->addSeparator();
            menu->addAction(action);
        }

    menu->popup(m_plot->mapToGlobal(pos));
}

void PlotWidget::installMenuAndCopy()
{
    m_plot->setContextMenuPolicy(Qt::CustomContextMenu);
    connect(m_plot, &QWidget::customContextMenuRequested, this, &PlotWidget::showContextMenu);
    // Ctrl+C while the plot has the focus (a click or Tab gives it) copies the data shown;
    // the menu key or Shift+F10 opens the menu from the keyboard.
    setFocusPolicy(Qt::StrongFocus);
    setContextMenuPolicy(Qt::CustomContextMenu);
    connect(this, &QWidget::customContextMenuRequested, this,
            [this](const QPoint& pos) { showContextMenu(m_plot->mapFrom(this, pos)); });
    auto* copy = new QShortcut(QKeySequence::Copy, this, m_exporter, &PlotExporter::copyData);
    copy->setContext(Qt::WidgetWithChildrenShortcut);
}

} // namespace rigidlab::ui
