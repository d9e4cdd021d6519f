// SPDX-License-Identifier: GPL-3.0-or-later
#include "lesson_player/lesson_panels.h"

#include "panels/fitting_table.h"
#include "panels/impulse_formula_view.h"
#include "simulation/lesson_watch.h"
#include "simulation/run_view.h"

#include "run/featured_collision.h"

#include <QCoreApplication>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QVBoxLayout>

#include <cmath>
#include <map>

namespace rigidlab::ui {

namespace {

constexpr int kBouncesShown = 4;
/// The first column of the bounce heights, after ball, e and the drop height.
constexpr int kFirstHeightColumn = 3;

/// What a cell the lesson holds back reads.
QString heldText()
{
    return QStringLiteral("?");
}

/// What a cell without a value yet reads.
QString noneText()
{
    return QStringLiteral("–");
}

/// A table's number as the window's language writes it (a decimal comma in Czech); one that
/// rounds to nothing reads "0.000", never "-0.000" (a cart that never turned).
QString num(double v, int digits = 3)
{
    if (std::abs(v) < 0.5 * std::pow(10.0, -digits))
        v = 0.0;
    return QLocale().toString(v, 'f', digits);
}

/// A vector on one line, for the wide table.
QString vec(const physics::Vec2& v)
{
    // A language with a decimal comma separates the components otherwise ("(0,5; 1,2)").
    return QCoreApplication::translate("rigidlab::ui::CollisionPanel", "(%1, %2)",
                                       "a vector's x and y")
        .arg(num(v.x()), num(v.y()));
}

/// A vector on two lines, for the narrow table.
QString vecStacked(const physics::Vec2& v)
{
    return QCoreApplication::translate("rigidlab::ui::CollisionPanel", "x %1\ny %2")
        .arg(num(v.x()), num(v.y()));
}

/// A line over the table while the run so far is measured again for it (a table opened after
/// the run went unmeasured: SimulationController::setEventsShown), gone once it is up to date.
/// The table's description says it too, so that a screen reader reading the table hears why
/// rows are missing: one change when it starts and one when it is done, not one a slice.
void addMeasuringNote(QVBoxLayout* layout, FittingTable* table, const RunView& run, QWidget* parent)
{
    auto* note = new QLabel(
        QCoreApplication::translate("rigidlab::ui::FittingTable", "Measuring the run so far…"),
        parent);
    note->setObjectName(QStringLiteral("measuringNote"));
    note->setWordWrap(true);
    layout->addWidget(note);
    const auto follow = [note, table](bool catchingUp) {
        note->setVisible(catchingUp);
        table->setAccessibleDescription(catchingUp ? note->text() : QString());
    };
    QObject::connect(&run, &RunView::eventsCatchingUpChanged, note, follow);
    follow(run.eventsCatchingUp());
}

/// The panel's layout: its note, the line said while the run so far is measured again, the
/// table at the height of its rows, and the export button.
QPushButton* addTableAndExport(QVBoxLayout* layout, FittingTable* table, const RunView& run,
                               QWidget* parent)
{
    addMeasuringNote(layout, table, run, parent);
    layout->addWidget(table);
    // Short: the button must fit the narrow column at the projector's text size.
    auto* button = new QPushButton(
        QCoreApplication::translate("rigidlab::ui::FittingTable", "Save CSV…"), parent);
    button->setToolTip(QCoreApplication::translate(
        "rigidlab::ui::FittingTable",
        "Save the table as a CSV file (decimal point, full precision) for a spreadsheet"));
    QObject::connect(button, &QPushButton::clicked, table, &FittingTable::exportCsvInteractively);
    auto* row = new QHBoxLayout;
    row->addWidget(button);
    row->addStretch(1);
    layout->addLayout(row);
    layout->addStretch(1);
    return button;
}

} // namespace

/// The collision table's rows in all three forms, one quantity at a time: a wide row, a
/// title and a row of the narrow table, and one CSV row per component. Held, the "after"
/// values read "?" (and are left out of the CSV).
struct CollisionRows {
    TableText& wide;
    TableText& narrow;
    CsvTable& csv;
    bool afterHeld = false;

    QString after(const QString& text) const
    {
        return afterHeld && !text.isEmpty() ? heldText() : text;
    }
    QString afterCsv(double v) const { return afterHeld ? QString() : csvNumber(v); }
    void addTitle(const QString& quantity)
    {
        narrow.rows << QStringList{quantity};
        narrow.titleRows.resize(narrow.rows.size());
        narrow.titleRows.last() = true;
    }
    void addVector(const QString& quantity, const QString& csvX, const QString& csvY,
                   const physics::Vec2& v0, const physics::Vec2& v1)
    {
        wide.rows << QStringList{quantity, vec(v0), after(vec(v1))};
        addTitle(quantity);
        narrow.rows << QStringList{vecStacked(v0), after(vecStacked(v1))};
        csv.rows << QStringList{csvX, csvNumber(v0.x()), afterCsv(v1.x())};
        csv.rows << QStringList{csvY, csvNumber(v0.y()), afterCsv(v1.y())};
    }
    void addScalar(const QString& quantity, const QString& csvName, double v0, double v1,
                   int digits, bool hasBefore)
    {
        const QString before = hasBefore ? num(v0, digits) : QString();
        wide.rows << QStringList{quantity, before, after(num(v1, digits))};
        addTitle(quantity);
        narrow.rows << QStringList{before, after(num(v1, digits))};
        csv.rows << QStringList{csvName, hasBefore ? csvNumber(v0) : QString(), afterCsv(v1)};
    }
};

BouncePanel::BouncePanel(const RunView& controller, QWidget* parent)
    : QWidget(parent), m_controller(controller), m_table(new FittingTable(this))
{
    m_table->setAccessibleName(tr("Bounce heights"));
    auto* layout = new QVBoxLayout(this);
    auto* note = new QLabel(tr("Heights of the centre above where it touched down. With a "
                               "coefficient of restitution e, each bounce should reach e² "
                               "times the one before."),
                            this);
    note->setWordWrap(true);
    layout->addWidget(note);
    addTableAndExport(layout, m_table, m_controller, this);
    connect(&m_controller, &RunView::worldChanged, this, &BouncePanel::refresh);
    connect(&m_controller, &RunView::sceneLoaded, this, &BouncePanel::refresh);
    refreshNow();
}

void BouncePanel::refresh()
{
    if (!isVisible()) {
        m_behind = true;
        return;
    }
    refreshNow();
}

void BouncePanel::showEvent(QShowEvent* event)
{
    QWidget::showEvent(event);
    if (m_behind)
        refreshNow();
}

void BouncePanel::refreshNow()
{
    m_behind = false;
    const QString heldTip = m_heightsHeld ? tr("Answer the lesson's question first") : QString();
    TableText wide, narrow;
    CsvTable csv;
    setHeaders(wide, narrow, csv, heldTip);

    const auto& world = m_controller.world();
    const lessons::Scene& scene = m_controller.scene();
    const auto& start = scene.bodies;
    // A ball's group is named by its e, which is what the lesson calls it ("the ball with
    // e = 0.8"); by its label too only where two balls share an e.
    std::map<double, int> ballsWithE;
    for (std::size_t id = 0; id < world.bodies().size() && id < start.size(); ++id)
        if (world.bodies()[id].isDynamic())
            ++ballsWithE[world.bodies()[id].restitution];
    for (std::size_t id = 0; id < world.bodies().size() && id < start.size(); ++id) {
        const physics::Body& b = world.bodies()[id];
        if (!b.isDynamic())
            continue;
        const QString name = scene.bodyLabel(static_cast<physics::BodyId>(id));
        const double e = b.restitution;
        const auto& apexes = m_controller.lessonWatch().measurements().apexes(static_cast<int>(id));
        // The drop height: from where the body started to where it first touched down.
        double previous = apexes.empty()
                              ? NAN
                              : start[id].position.y() + (b.position.y() - b.origin().y()) -
                                    apexes.front().bounceY;
        QStringList wideRow{name, num(e, 2) + QStringLiteral("  (e² = %1)").arg(num(e * e, 3)),
                            std::isfinite(previous) ? num(previous) : noneText()};
        QStringList csvRow{name, csvNumber(e), csvNumber(previous)};
        narrow.rows << QStringList{
            ballsWithE[e] > 1 ? tr("%1: e = %2, e² = %3").arg(name, num(e, 2), num(e * e, 3))
                              : tr("e = %1 (e² = %2)").arg(num(e, 2), num(e * e, 3))};
        narrow.titleRows.resize(narrow.rows.size());
        narrow.titleRows.last() = true;
        narrow.rows << QStringList{tr("drop"), wideRow[2], QString()};
        for (int i = 0; i < kBouncesShown; ++i) {
            QString h = noneText(), ratio = noneText();
            double height = NAN, quotient = NAN;
            if (i < static_cast<int>(apexes.size())) {
                height = apexes[static_cast<std::size_t>(i)].y -
                         apexes[static_cast<std::size_t>(i)].bounceY;
                h = num(height);
                if (previous > 1e-9) {
                    quotient = height / previous;
                    ratio = num(quotient);
                }
                previous = height;
            }
            if (m_heightsHeld) {
                h = ratio = heldText();
                height = quotient = NAN; // the file does not give the answer away either
            }
            wideRow << h << ratio;
            csvRow << csvNumber(height) << csvNumber(quotient);
            narrow.rows << QStringList{QString::number(i + 1), h, ratio};
        }
        wide.rows << wideRow;
        csv.rows << csvRow;
    }
    narrow.titleRows.resize(narrow.rows.size());
    m_table->setContent(wide, narrow);
    m_table->setCsv(csv, tr("bounces"));
}

void BouncePanel::setHeaders(TableText& wide, TableText& narrow, CsvTable& csv,
                             const QString& heldTip)
{
    wide.headers = QStringList{tr("ball"), tr("e"), tr("drop h₀ [m]")};
    csv.headers =
        QStringList{QStringLiteral("ball"), QStringLiteral("e"), QStringLiteral("drop h0 [m]")};
    wide.headerTips = QStringList{QString(), QString(), heldTip};
    for (int i = 1; i <= kBouncesShown; ++i) {
        wide.headers << tr("h%1 [m]").arg(i) << tr("h%1/h%2").arg(i).arg(i - 1);
        csv.headers << QStringLiteral("h%1 [m]").arg(i)
                    << QStringLiteral("h%1/h%2").arg(i).arg(i - 1);
        wide.headerTips << heldTip << heldTip;
    }
    // Short headers, the unit on a line of its own: the narrow column of a projector has
    // room for three short words; the bounce's number says what it is with the tooltip.
    narrow.headers = QStringList{tr("no.", "a bounce's number"), tr("h\n[m]"), tr("ratio")};
    narrow.headerTips =
        QStringList{tr("The bounce: the drop, then the first bounce, the second…"), heldTip,
                    tr("The height over the one before: compare it with e²") +
                        (heldTip.isEmpty() ? QString() : QStringLiteral("\n") + heldTip)};
}

void BouncePanel::setHeightsHeld(bool held)
{
    if (held == m_heightsHeld)
        return;
    m_heightsHeld = held;
    refreshNow();
}

CollisionPanel::CollisionPanel(const RunView& controller, QWidget* parent)
    : QWidget(parent), m_controller(controller), m_title(new QLabel(this)),
      m_table(new FittingTable(this)), m_formula(new ImpulseFormulaView(this))
{
    m_table->setAccessibleName(tr("Velocities before and after"));
    auto* layout = new QVBoxLayout(this);
    m_title->setWordWrap(true);
    layout->addWidget(m_title);
    addTableAndExport(layout, m_table, m_controller, this);
    layout->insertWidget(layout->count() - 1, m_formula); // above the closing stretch
    connect(&m_controller, &RunView::worldChanged, this, &CollisionPanel::refresh);
    connect(&m_controller, &RunView::sceneLoaded, this, [this] {
        m_shownCount = -1;
        refresh();
    });
    refresh();
}

void CollisionPanel::refresh()
{
    const auto& events = m_controller.lessonWatch().measurements().collisions();
    const int count = static_cast<int>(events.size());
    if (count == m_shownCount)
        return;
    m_shownCount = count;
    const QString heldTip = m_afterHeld ? tr("Answer the lesson's question first") : QString();
    TableText wide, narrow;
    CsvTable csv;
    wide.headers = QStringList{tr("quantity"), tr("before"), tr("after")};
    wide.headerTips = QStringList{QString(), QString(), heldTip};
    narrow.headers = QStringList{tr("before"), tr("after")};
    narrow.headerTips = QStringList{QString(), heldTip};
    csv.headers =
        QStringList{QStringLiteral("quantity"), QStringLiteral("before"), QStringLiteral("after")};
    const auto& world = m_controller.world();
    // The one the lesson is about: not the carts settling on the ground at the first step.
    const lessons::CollisionEvent* featured = lessons::featuredCollision(events, world, m_named);
    if (!featured) {
        m_title->setText(tr("No collision yet: run the simulation."));
        m_table->setContent(wide, narrow);
        m_table->setCsv(csv, tr("collision"));
        m_formula->showNone();
        return;
    }
    const lessons::CollisionEvent& e = *featured;
    const physics::Body* bodies[2] = {&world.body(e.a), &world.body(e.b)};
    const lessons::Scene& scene = m_controller.scene();
    const QString names[2] = {scene.bodyLabel(e.a), scene.bodyLabel(e.b)};
    m_title->setText(tr("Collision of %1 and %2 at t = %3 s").arg(names[0], names[1], num(e.t)));
    CollisionRows rows{wide, narrow, csv, m_afterHeld};
    physics::Vec2 pBefore = physics::Vec2::Zero(), pAfter = physics::Vec2::Zero();
    double keBefore = 0, keAfter = 0;
    for (int k = 0; k < 2; ++k) {
        const physics::Body& b = *bodies[k];
        if (!b.isDynamic())
            continue;
        const QString& name = names[k];
        const auto v0 = e.velocityBefore[k], v1 = e.velocityAfter[k];
        rows.addVector(tr("%1: velocity [m/s]").arg(name),
                       QStringLiteral("%1: velocity x [m/s]").arg(name),
                       QStringLiteral("%1: velocity y [m/s]").arg(name), v0, v1);
        rows.addScalar(tr("%1: angular velocity ω [rad/s]").arg(name),
                       QStringLiteral("%1: angular velocity [rad/s]").arg(name), e.angularBefore[k],
                       e.angularAfter[k], 3, true);
        pBefore += b.mass * v0;
        pAfter += b.mass * v1;
        keBefore += 0.5 * b.mass * v0.squaredNorm() +
                    0.5 * b.inertia * e.angularBefore[k] * e.angularBefore[k];
        keAfter += 0.5 * b.mass * v1.squaredNorm() +
                   0.5 * b.inertia * e.angularAfter[k] * e.angularAfter[k];
    }
    rows.addVector(tr("momentum p [kg m/s]"), QStringLiteral("momentum x [kg m/s]"),
                   QStringLiteral("momentum y [kg m/s]"), pBefore, pAfter);
    rows.addScalar(tr("kinetic energy [J]"), QStringLiteral("kinetic energy [J]"), keBefore,
                   keAfter, 4, true);
    for (int k = 0; k < 2; ++k)
        addPredictedSpins(rows, e, k, *bodies[k], names[k]);
    narrow.titleRows.resize(narrow.rows.size());
    m_table->setContent(wide, narrow);
    m_table->setCsv(csv, tr("collision"));
    m_formula->showHit(e, *bodies[0], *bodies[1], names[0], names[1], m_afterHeld);
}

void CollisionPanel::addPredictedSpins(CollisionRows& rows, const lessons::CollisionEvent& e, int k,
                                       const physics::Body& b, const QString& name)
{
    if (!b.isDynamic() || b.inertia <= 0)
        return;
    if (std::abs(e.predictedFull[k] - e.predictedWithoutRotation[k]) < 1e-12 &&
        std::abs(e.angularAfter[k]) < 1e-12)
        return; // no spin involved
    rows.addScalar(tr("%1: ω by the full formula").arg(name),
                   QStringLiteral("%1: angular velocity by the full formula [rad/s]").arg(name), 0,
                   e.predictedFull[k], 3, false);
    rows.addScalar(
        tr("%1: ω without (r×n)²/I terms").arg(name),
        QStringLiteral("%1: angular velocity without (r x n)^2/I terms [rad/s]").arg(name), 0,
        e.predictedWithoutRotation[k], 3, false);
}

void CollisionPanel::setNamedBodies(std::vector<physics::BodyId> bodies)
{
    if (bodies == m_named)
        return;
    m_named = std::move(bodies);
    m_shownCount = -1;
    refresh();
}

void CollisionPanel::setAfterHeld(bool held)
{
    if (held == m_afterHeld)
        return;
    m_afterHeld = held;
    m_shownCount = -1; // redraw the table even without a new collision
    refresh();
}

} // namespace rigidlab::ui
