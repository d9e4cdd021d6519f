// SPDX-License-Identifier: GPL-3.0-or-later
#include "panels/sat_panel.h"

#include "simulation/run_view.h"
#include "view/world_view.h"

#include <QApplication>
#include <QEvent>
#include <QGraphicsScene>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QMenu>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <array>
#include <cmath>

namespace rigidlab::ui {

namespace {

/// Pixels kept free around what the overlay draws when the view follows it.
constexpr double kFitMarginPx = 16.0;

/// A length on screen, in the user's locale [m]: `decimals` after the point; one that rounds
/// to nothing reads "0.000", never "-0.000".
QString num(double v, int decimals = 3)
{
    if (std::abs(v) < 0.5 * std::pow(10.0, -decimals))
        v = 0.0;
    return QLocale().toString(v, 'f', decimals);
}

} // namespace

SatPanel::SatPanel(const RunView& run, QWidget* parent)
    : QWidget(parent), m_run(run), m_model(run), m_overlay(new SatOverlayItem(m_model)),
      m_verdict(new QLabel(this)), m_table(new QTableWidget(0, 3, this)),
      m_summary(new QLabel(this)), m_prev(new QPushButton(tr("◀ Previous"), this)),
      m_next(new QPushButton(tr("Next ▶"), this)), m_all_button(new QPushButton(tr("All"), this))
{
    m_table->setAccessibleName(tr("Axes tested"));
    m_overlay->setOnDestroyed([this] { m_overlay = nullptr; });
    connect(&m_run, &QObject::destroyed, this, [this] {
        if (m_overlay)
            m_overlay->detach();
    });
    // The panel fits the window's right column (about 245 px at 1024 px wide): short column
    // texts, the full explanation in each cell's tooltip.
    m_prev->setToolTip(tr("Show the previous axis tested"));
    m_next->setToolTip(tr("Test the next axis"));
    m_all_button->setToolTip(tr("Test every axis, up to the verdict"));
    auto* layout = new QVBoxLayout(this);
    QFont f = m_verdict->font();
    f.setBold(true);
    f.setPointSizeF(f.pointSizeF() * 1.15);
    m_verdict->setFont(f);
    m_verdict->setWordWrap(true);
    layout->addWidget(m_verdict);
    buildTable();
    layout->addWidget(m_table, 1);
    m_summary->setWordWrap(true);
    layout->addWidget(m_summary);
    buildButtons(layout);
    connect(&m_run, &RunView::worldChanged, this, &SatPanel::refresh);
    fitFonts();
    updateTable();
}

void SatPanel::buildTable()
{
    // Three columns: what an axis means ("separates", "least overlap") is a second line under
    // its overlap rather than a fourth column, empty on most rows.
    // Two lines each, the unit on the second, so that the headers fit a narrow column whole.
    const QStringList headers{tr("axis"), tr("interval\n[m]"), tr("overlap\n[m]")};
    const QStringList headerTips{
        tr("The axis is the normal of this edge: polygon A or B, then the edge's number."),
        tr("The interval each polygon covers when projected on the axis (A above, B below)."),
        tr("How far the intervals overlap, in metres; \"gap\" when they do not, and the axis "
           "separates. Below it, what the axis means for the test.")};
    m_table->setHorizontalHeaderLabels(headers);
    for (int c = 0; c < headerTips.size(); ++c)
        m_table->horizontalHeaderItem(c)->setToolTip(headerTips[c]);
    m_table->verticalHeader()->setVisible(false);
    m_table->verticalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    // As wide as the column, never wider: the intervals take what the axis and the overlap
    // leave, and wrap when that is too little.
    QHeaderView* columns = m_table->horizontalHeader();
    columns->setMinimumSectionSize(24);
    columns->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    columns->setSectionResizeMode(1, QHeaderView::Stretch);
    columns->setSectionResizeMode(2, QHeaderView::ResizeToContents);
    m_table->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    columns->setTextElideMode(Qt::ElideRight);
    connect(columns, &QHeaderView::sectionResized, m_table,
            [this] { m_table->resizeRowsToContents(); });
    m_table->viewport()->installEventFilter(this);
    m_table->setWordWrap(true);
    m_table->setTextElideMode(Qt::ElideNone);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionMode(QAbstractItemView::NoSelection);
    m_table->setContextMenuPolicy(Qt::CustomContextMenu);
    connect(m_table, &QWidget::customContextMenuRequested, this, [this](const QPoint& pos) {
        QMenu menu(this);
        QAction* exportAction = menu.addAction(tr("Export as CSV…"));
        exportAction->setEnabled(active());
        connect(exportAction, &QAction::triggered, this,
                [this] { exportCsvInteractively(this, csv(), tr("separating_axes")); });
        menu.exec(m_table->viewport()->mapToGlobal(pos));
    });
}

void SatPanel::buildButtons(QBoxLayout* layout)
{
    // Side by side where they fit with their whole text, else one under the other
    // (resizeEvent()).
    auto* buttons = new QBoxLayout(QBoxLayout::LeftToRight);
    m_buttons = buttons;
    buttons->addWidget(m_prev);
    buttons->addWidget(m_next);
    buttons->addWidget(m_all_button);
    layout->addLayout(buttons);
    auto* hint = new QLabel(tr("Drag a polygon to move it; Q and E turn the selected one."), this);
    hint->setWordWrap(true);
    hint->setStyleSheet(QStringLiteral("color: #555;"));
    layout->addWidget(hint);
    connect(m_prev, &QPushButton::clicked, this, &SatPanel::previousAxis);
    connect(m_next, &QPushButton::clicked, this, &SatPanel::nextAxis);
    connect(m_all_button, &QPushButton::clicked, this, &SatPanel::showAll);
}

void SatPanel::fitFonts()
{
    // Item views may have a smaller font of their own (the platform's), which does not follow
    // the window's: they keep its size relative to the window's font, so that presentation
    // mode enlarges them too.
    const double scale = font().pointSizeF() / QApplication::font().pointSizeF();
    for (QWidget* w :
         {static_cast<QWidget*>(m_table), static_cast<QWidget*>(m_table->horizontalHeader())}) {
        QFont f = QApplication::font(w);
        f.setPointSizeF(f.pointSizeF() * scale);
        w->setFont(f);
    }
    for (QPushButton* b : {m_prev, m_next, m_all_button}) // narrower than the style's 80 px
        b->setMinimumWidth(b->fontMetrics().horizontalAdvance(b->text()) + 16);
    fitButtons();
    fitColumns();
}

void SatPanel::fitColumns()
{
    // The axis and overlap columns as wide as their header and cells where that leaves the
    // intervals their width; in a narrower column, as wide as their cells alone (the header
    // elided, its tooltip in full), so that the intervals keep room to wrap in.
    QHeaderView* columns = m_table->horizontalHeader();
    // (Public in QAbstractItemView, protected in QTableView.)
    const auto cells = [view = static_cast<const QAbstractItemView*>(m_table)](int column) {
        return view->sizeHintForColumn(column);
    };
    const int wanted = cells(0) + cells(1) + cells(2);
    const int headers = columns->sectionSizeHint(0) + columns->sectionSizeHint(2) + cells(1);
    if (std::max(wanted, headers) <= m_table->viewport()->width()) {
        columns->setSectionResizeMode(0, QHeaderView::ResizeToContents);
        columns->setSectionResizeMode(2, QHeaderView::ResizeToContents);
    } else {
        // The headers whole too (their unit is on a line of its own) where that leaves the
        // intervals a bound and its polygon per line ("A -0,50", then "… 0,50").
        const int least = m_table->fontMetrics().horizontalAdvance(QStringLiteral("0.00")) + 8;
        const int interval =
            m_table->fontMetrics().horizontalAdvance(QStringLiteral("A -00.00")) + 12;
        const bool headersFit =
            columns->sectionSizeHint(0) + columns->sectionSizeHint(2) + interval <=
            m_table->viewport()->width();
        for (int c : {0, 2}) {
            columns->setSectionResizeMode(c, QHeaderView::Fixed);
            columns->resizeSection(
                c, std::max({least, cells(c), headersFit ? columns->sectionSizeHint(c) : 0}));
        }
    }
    m_table->resizeRowsToContents();
}

void SatPanel::fitButtons()
{
    int needed = 2 * m_buttons->spacing() + layout()->contentsMargins().left() +
                 layout()->contentsMargins().right();
    for (QPushButton* b : {m_prev, m_next, m_all_button})
        needed += b->minimumWidth();
    const auto direction = width() >= needed ? QBoxLayout::LeftToRight : QBoxLayout::TopToBottom;
    if (m_buttons->direction() != direction)
        m_buttons->setDirection(direction);
}

void SatPanel::resizeEvent(QResizeEvent* event)
{
    QWidget::resizeEvent(event);
    fitButtons();
}

void SatPanel::changeEvent(QEvent* event)
{
    QWidget::changeEvent(event);
    if (event->type() == QEvent::FontChange)
        fitFonts();
}

SatPanel::~SatPanel()
{
    if (m_view)
        m_view->setFitExtra({});
    // The panel owns its overlay, unless the scene went first and deleted it (then the
    // overlay has said so).
    if (m_overlay) {
        m_overlay->detach();
        m_overlay->setOnDestroyed({});
        if (m_overlay->scene())
            m_overlay->scene()->removeItem(m_overlay);
        delete m_overlay;
    }
}

void SatPanel::setBodies(int a, int b)
{
    if (m_overlay)
        m_overlay->dataChanging();
    m_model.setBodies(a, b);
    updateTable();
    followAxis(true);
}

void SatPanel::nextAxis()
{
    if (m_overlay)
        m_overlay->dataChanging();
    m_model.nextAxis();
    updateTable();
    followAxis(true);
}

void SatPanel::previousAxis()
{
    if (m_overlay)
        m_overlay->dataChanging();
    m_model.previousAxis();
    updateTable();
    followAxis(true);
}

void SatPanel::showAll()
{
    if (m_overlay)
        m_overlay->dataChanging();
    m_model.showAll();
    updateTable();
    followAxis(true);
}

void SatPanel::refresh()
{
    // Nothing to do for a pair that did not move (every frame of a running clock, a pile at
    // rest): the axes, the overlay and the table stay as they are.
    if (!m_model.outOfDate()) {
        if (m_tableBehind && !outOfSight())
            updateTable();
        return;
    }
    if (m_overlay)
        m_overlay->dataChanging();
    m_model.refresh();
    // The overlay in the view reads the model; the table, out of sight, is filled in when shown.
    if (outOfSight())
        m_tableBehind = true;
    else
        updateTable();
    // Follow only a pair that moved, so that a student's own zoom holds while nothing moves.
    followAxis(false);
}

bool SatPanel::outOfSight() const
{
    return window()->isVisible() && !isVisible();
}

void SatPanel::showEvent(QShowEvent* event)
{
    QWidget::showEvent(event);
    if (m_tableBehind)
        updateTable();
}

WorldView* SatPanel::worldView()
{
    if (!m_overlay)
        return nullptr;
    if (m_view && m_overlay->scene() == m_view->scene())
        return m_view;
    if (m_view) {
        m_view->setFitExtra({});
        m_view->removeEventFilter(this);
    }
    m_view = nullptr;
    if (m_overlay->scene())
        for (QGraphicsView* v : m_overlay->scene()->views())
            if ((m_view = qobject_cast<WorldView*>(v)))
                break;
    if (m_view) {
        m_view->setFitExtra(
            [this] { return active() && m_overlay ? m_overlay->geometry().drawn : QRectF(); });
        m_view->installEventFilter(this);
    }
    return m_view;
}

bool SatPanel::eventFilter(QObject* watched, QEvent* event)
{
    // When the view changes size (a dock opens beside it), follow the axis again once the
    // view has handled the resize itself.
    // (Types first: a view being destroyed is no longer a WorldView to compare with.)
    if (event->type() == QEvent::Resize && watched == m_table->viewport())
        fitColumns();
    if (event->type() == QEvent::Resize && watched == static_cast<QObject*>(m_view.data()))
        QMetaObject::invokeMethod(
            this, [this] { followAxis(false); }, Qt::QueuedConnection);
    return QWidget::eventFilter(watched, event);
}

void SatPanel::followAxis(bool always)
{
    WorldView* view = worldView();
    if (!view || !active())
        return;
    // The overlay's offsets and text are sized in pixels, so its extent in metres changes
    // with the zoom: fit, measure again at the new zoom, and refit if something still sticks
    // out (it converges in a few rounds, as the pixel-sized parts are small beside the view).
    for (int attempt = 0; attempt < 8; ++attempt) {
        const SatOverlayItem::Geometry g = m_overlay->geometry();
        if (!g.valid)
            return;
        const QRectF visible = view->mapToScene(view->viewport()->rect()).boundingRect();
        if (!always && visible.contains(g.drawn))
            return;
        view->fitRect(g.drawn, kFitMarginPx);
        always = false;
    }
}

void SatPanel::updateTable()
{
    m_tableBehind = false;
    ++m_tableFills;
    const physics::SatResult& result = m_model.result();
    const int total = static_cast<int>(result.axes.size());
    const int shown = m_model.shown();
    m_table->setRowCount(shown);
    for (int i = 0; i < shown; ++i) {
        const RowText row = rowText(i);
        for (int c = 0; c < row.cells.size(); ++c) {
            auto* item = new QTableWidgetItem(row.cells[c]);
            item->setToolTip(row.tip);
            item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
            if (i == shown - 1)
                item->setBackground(QColor(255, 244, 200));
            m_table->setItem(i, c, item);
        }
    }
    m_prev->setEnabled(active() && shown > 1);
    m_next->setEnabled(active() && shown < total);
    m_all_button->setEnabled(active() && shown < total);
    if (!active()) {
        m_verdict->setText(tr("No pair of polygons to test."));
        m_summary->clear();
    } else if (shown < total) {
        m_verdict->setText(
            tr("Axis %1 of %2 tested so far: no separating axis yet.").arg(shown).arg(total));
        m_summary->setText(summary());
    } else if (!result.intersects) {
        m_verdict->setText(tr("Separated: axis %1 has a gap, so the test stops there.")
                               .arg(result.separatingAxis + 1));
        m_summary->setText(summary());
    } else {
        m_verdict->setText(tr("Overlapping: no axis separates them."));
        m_summary->setText(summary());
    }
    fitColumns();
    if (m_overlay)
        m_overlay->update();
}

SatPanel::RowText SatPanel::rowText(int i) const
{
    const physics::SatResult& result = m_model.result();
    auto name = [&](int owner) {
        const int id = owner == 0 ? m_model.bodyA() : m_model.bodyB();
        return id >= 0 ? m_run.scene().bodyLabel(id) : QString();
    };
    const physics::SatAxis& ax = result.axes[static_cast<std::size_t>(i)];
    const bool separates = i == result.separatingAxis;
    const bool least = i == result.leastAxis && m_model.complete();
    const QString overlap =
        ax.overlap < 0 ? tr("gap %1").arg(num(-ax.overlap, 2)) : num(ax.overlap, 2);
    const QString note = separates ? tr("separates") : least ? tr("least overlap") : QString();
    RowText row;
    row.cells =
        QStringList{tr("%1 %2", "polygon (A or B), edge number")
                        .arg(ax.owner == 0 ? tr("A") : tr("B"))
                        .arg(ax.edge),
                    tr("A %1 … %2\nB %3 … %4")
                        .arg(num(ax.minA, 2), num(ax.maxA, 2), num(ax.minB, 2), num(ax.maxB, 2)),
                    note.isEmpty() ? overlap : overlap + QLatin1Char('\n') + note};
    row.tip = tr("Axis %1: the normal of edge %2 of %3. On it, %4 covers [%5, %6] m and %7 covers "
                 "[%8, %9] m.")
                  .arg(i + 1)
                  .arg(ax.edge)
                  .arg(name(ax.owner), name(0), num(ax.minA), num(ax.maxA), name(1), num(ax.minB),
                       num(ax.maxB));
    row.tip +=
        QLatin1Char(' ') + (ax.overlap < 0 ? tr("They are %1 m apart: a gap.").arg(num(-ax.overlap))
                                           : tr("They overlap by %1 m.").arg(num(ax.overlap)));
    if (separates)
        row.tip += QLatin1Char(' ') + tr("This axis separates the polygons: they cannot touch, "
                                         "and the test stops here (no collision).");
    else if (least)
        row.tip += QLatin1Char(' ') + tr("The least overlap of all axes: this axis is the "
                                         "contact normal, and the overlap is the depth.");
    return row;
}

CsvTable SatPanel::csv() const
{
    CsvTable table;
    table.headers = QStringList{
        QStringLiteral("axis"),        QStringLiteral("polygon"),   QStringLiteral("edge"),
        QStringLiteral("normal x"),    QStringLiteral("normal y"),  QStringLiteral("A min [m]"),
        QStringLiteral("A max [m]"),   QStringLiteral("B min [m]"), QStringLiteral("B max [m]"),
        QStringLiteral("overlap [m]"), QStringLiteral("note")};
    const physics::SatResult& result = m_model.result();
    const int total = static_cast<int>(result.axes.size());
    for (int i = 0; i < m_model.shown() && i < total; ++i) {
        const physics::SatAxis& ax = result.axes[static_cast<std::size_t>(i)];
        const bool separates = i == result.separatingAxis;
        const bool least = i == result.leastAxis && m_model.complete();
        table.rows << QStringList{QString::number(i + 1),
                                  ax.owner == 0 ? QStringLiteral("A") : QStringLiteral("B"),
                                  QString::number(ax.edge),
                                  csvNumber(ax.axis.x()),
                                  csvNumber(ax.axis.y()),
                                  csvNumber(ax.minA),
                                  csvNumber(ax.maxA),
                                  csvNumber(ax.minB),
                                  csvNumber(ax.maxB),
                                  csvNumber(ax.overlap),
                                  separates ? QStringLiteral("separates")
                                  : least   ? QStringLiteral("least overlap")
                                            : QString()};
    }
    return table;
}

QString SatPanel::summary() const
{
    if (!active())
        return QString();
    const physics::SatResult& result = m_model.result();
    const auto& bodies = m_run.world().bodies();
    const auto vertexCount = [&](int id) {
        const physics::Polygon* p = bodies[static_cast<std::size_t>(id)].shape.asPolygon();
        return p ? static_cast<int>(p->vertices.size()) : 0;
    };
    const int kA = vertexCount(m_model.bodyA());
    const int kB = vertexCount(m_model.bodyB());
    const int k = kA + kB;
    QString text = tr("The test needed %1 of at most %2 axes (one per edge, %3 + %4), each "
                      "projecting all %2 vertices: %5 projections, against the paper's worst "
                      "case of (k₁ + k₂)² = %6.")
                       .arg(result.axesTested)
                       .arg(k)
                       .arg(kA)
                       .arg(kB)
                       .arg(result.axesTested * k)
                       .arg(k * k);
    if (result.intersects && m_model.complete()) {
        text += QStringLiteral("\n") +
                tr("Least overlap on axis %1: normal (%2, %3) from A to B, depth %4 m, "
                   "%5 contact point(s) from clipping.")
                    .arg(result.leastAxis + 1)
                    .arg(num(result.normal.x()), num(result.normal.y()), num(result.depth))
                    .arg(result.manifold.pointCount);
    }
    return text;
}

} // namespace rigidlab::ui
