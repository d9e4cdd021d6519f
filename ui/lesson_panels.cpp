#include "lesson_panels.h"

#include "simulation_controller.h"

#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QTableWidget>
#include <QVBoxLayout>

#include <cmath>

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

/// A table's number as the window's language writes it (a decimal comma in Czech).
QString num(double v, int digits = 3)
{
    return QLocale().toString(v, 'f', digits);
}

void setCell(QTableWidget* t, int row, int col, const QString& text)
{
    auto* item = t->item(row, col);
    if (!item) {
        item = new QTableWidgetItem;
        t->setItem(row, col, item);
    }
    if (item->text() != text)
        item->setText(text);
}

QTableWidget* makeTable(QWidget* parent, const QStringList& headers)
{
    auto* t = new QTableWidget(0, static_cast<int>(headers.size()), parent);
    t->setHorizontalHeaderLabels(headers);
    t->verticalHeader()->setVisible(false);
    t->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    t->setEditTriggers(QAbstractItemView::NoEditTriggers);
    t->setSelectionMode(QAbstractItemView::NoSelection);
    return t;
}

} // namespace

BouncePanel::BouncePanel(SimulationController& controller, QWidget* parent)
    : QWidget(parent), m_controller(controller)
{
    QStringList headers{tr("ball"), tr("e"), tr("drop h₀ [m]")};
    for (int i = 1; i <= kBouncesShown; ++i)
        headers << tr("h%1 [m]").arg(i) << tr("h%1/h%2").arg(i).arg(i - 1);
    m_table = makeTable(this, headers);
    setMinimumWidth(440);
    auto* layout = new QVBoxLayout(this);
    auto* note = new QLabel(tr("Heights of the centre above where it touched down. With a "
                               "coefficient of restitution e, each bounce should reach e² "
                               "times the one before."),
                            this);
    note->setWordWrap(true);
    layout->addWidget(note);
    layout->addWidget(m_table);
    connect(&m_controller, &SimulationController::worldChanged, this, &BouncePanel::refresh);
    connect(&m_controller, &SimulationController::sceneLoaded, this, &BouncePanel::refresh);
}

void BouncePanel::refresh()
{
    if (!isVisible())
        return;
    const auto& world = m_controller.world();
    const auto& start = m_controller.scene().bodies;
    std::vector<int> balls;
    for (std::size_t i = 0; i < world.bodies().size(); ++i)
        if (world.bodies()[i].isDynamic())
            balls.push_back(static_cast<int>(i));
    m_table->setRowCount(static_cast<int>(balls.size()));
    for (std::size_t r = 0; r < balls.size(); ++r) {
        const int id = balls[r];
        const int row = static_cast<int>(r);
        const physics::Body& b = world.body(id);
        setCell(m_table, row, 0, QString::fromStdString(b.name));
        setCell(m_table, row, 1,
                num(b.restitution, 2) +
                    QStringLiteral("  (e² = %1)").arg(num(b.restitution * b.restitution, 3)));
        const auto& apexes = m_controller.measurements().apexes(id);
        // The drop height: from where the body started to where it first touched down.
        double previous = apexes.empty()
                              ? NAN
                              : start[static_cast<std::size_t>(id)].position.y() +
                                    (b.position.y() - b.origin().y()) - apexes.front().bounceY;
        setCell(m_table, row, 2, std::isfinite(previous) ? num(previous) : QStringLiteral("–"));
        for (int i = 0; i < kBouncesShown; ++i) {
            QString h = QStringLiteral("–"), ratio = QStringLiteral("–");
            if (i < static_cast<int>(apexes.size())) {
                const double height = apexes[static_cast<std::size_t>(i)].y -
                                      apexes[static_cast<std::size_t>(i)].bounceY;
                h = num(height);
                if (previous > 1e-9)
                    ratio = num(height / previous);
                previous = height;
            }
            if (m_heightsHeld)
                h = ratio = heldText();
            setCell(m_table, row, kFirstHeightColumn + 2 * i, h);
            setCell(m_table, row, kFirstHeightColumn + 1 + 2 * i, ratio);
        }
    }
}

void BouncePanel::setHeightsHeld(bool held)
{
    if (held == m_heightsHeld)
        return;
    m_heightsHeld = held;
    const QString tip = held ? tr("Answer the lesson's question first") : QString();
    for (int c = kFirstHeightColumn; c < m_table->columnCount(); ++c)
        if (QTableWidgetItem* header = m_table->horizontalHeaderItem(c))
            header->setToolTip(tip);
    refresh();
}

CollisionPanel::CollisionPanel(SimulationController& controller, QWidget* parent)
    : QWidget(parent), m_controller(controller), m_title(new QLabel(this))
{
    m_table = makeTable(this, {tr("quantity"), tr("before"), tr("after")});
    m_table->horizontalHeader()->setStretchLastSection(true);
    setMinimumWidth(400);
    auto* layout = new QVBoxLayout(this);
    m_title->setWordWrap(true);
    layout->addWidget(m_title);
    layout->addWidget(m_table);
    connect(&m_controller, &SimulationController::worldChanged, this, &CollisionPanel::refresh);
    connect(&m_controller, &SimulationController::sceneLoaded, this, [this] {
        m_shownCount = -1;
        refresh();
    });
}

void CollisionPanel::refresh()
{
    const auto& events = m_controller.measurements().collisions();
    const int count = static_cast<int>(events.size());
    if (count == m_shownCount)
        return;
    m_shownCount = count;
    if (events.empty()) {
        m_title->setText(tr("No collision yet: run the simulation."));
        m_table->setRowCount(0);
        return;
    }
    // The first collision is the one the lesson is about.
    const lessons::CollisionEvent& e = events.front();
    const auto& world = m_controller.world();
    const physics::Body* bodies[2] = {&world.body(e.a), &world.body(e.b)};
    m_title->setText(tr("Collision of %1 and %2 at t = %3 s")
                         .arg(QString::fromStdString(bodies[0]->name),
                              QString::fromStdString(bodies[1]->name), num(e.t)));
    QList<QStringList> rows;
    physics::Vec2 pBefore = physics::Vec2::Zero(), pAfter = physics::Vec2::Zero();
    double keBefore = 0, keAfter = 0;
    for (int k = 0; k < 2; ++k) {
        const physics::Body& b = *bodies[k];
        if (!b.isDynamic())
            continue;
        const QString name = QString::fromStdString(b.name);
        const auto v0 = e.velocityBefore[k], v1 = e.velocityAfter[k];
        rows << QStringList{tr("%1: velocity [m/s]").arg(name),
                            QStringLiteral("(%1, %2)").arg(num(v0.x()), num(v0.y())),
                            QStringLiteral("(%1, %2)").arg(num(v1.x()), num(v1.y()))};
        rows << QStringList{tr("%1: angular velocity ω [rad/s]").arg(name), num(e.angularBefore[k]),
                            num(e.angularAfter[k])};
        pBefore += b.mass * v0;
        pAfter += b.mass * v1;
        keBefore += 0.5 * b.mass * v0.squaredNorm() +
                    0.5 * b.inertia * e.angularBefore[k] * e.angularBefore[k];
        keAfter += 0.5 * b.mass * v1.squaredNorm() +
                   0.5 * b.inertia * e.angularAfter[k] * e.angularAfter[k];
    }
    rows << QStringList{tr("momentum p [kg m/s]"),
                        QStringLiteral("(%1, %2)").arg(num(pBefore.x()), num(pBefore.y())),
                        QStringLiteral("(%1, %2)").arg(num(pAfter.x()), num(pAfter.y()))};
    rows << QStringList{tr("kinetic energy [J]"), num(keBefore, 4), num(keAfter, 4)};
    for (int k = 0; k < 2; ++k) {
        const physics::Body& b = *bodies[k];
        if (!b.isDynamic() || b.inertia <= 0)
            continue;
        const QString name = QString::fromStdString(b.name);
        if (std::abs(e.predictedFull[k] - e.predictedWithoutRotation[k]) < 1e-12 &&
            std::abs(e.angularAfter[k]) < 1e-12)
            continue; // no spin involved
        rows << QStringList{tr("%1: ω by the full formula").arg(name), QString(),
                            num(e.predictedFull[k])};
        rows << QStringList{tr("%1: ω without (r×n)²/I terms").arg(name), QString(),
                            num(e.predictedWithoutRotation[k])};
    }
    m_table->setRowCount(static_cast<int>(rows.size()));
    for (int r = 0; r < rows.size(); ++r)
        for (int c = 0; c < 3; ++c)
            setCell(m_table, r, c,
                    c == 2 && m_afterHeld && !rows[r][c].isEmpty() ? heldText() : rows[r][c]);
}

void CollisionPanel::setAfterHeld(bool held)
{
    if (held == m_afterHeld)
        return;
    m_afterHeld = held;
    if (QTableWidgetItem* header = m_table->horizontalHeaderItem(2))
        header->setToolTip(held ? tr("Answer the lesson's question first") : QString());
    m_shownCount = -1; // redraw the table even without a new collision
    refresh();
}

} // namespace rigidlab::ui
