// SPDX-License-Identifier: GPL-3.0-or-later
#include "plots/sat_handout.h"

#include "common/number_format.h"
#include "plots/plot_widget.h"

#include "export/csv_writer.h"
#include "format/atomic_file.h"
#include "run/scene_run.h"

#include <QBuffer>
#include <QCoreApplication>
#include <QDir>
#include <QPainter>

#include <algorithm>

namespace rigidlab::ui {

namespace {

/// The translation context of the SAT handout.
struct SatHandout {
    Q_DECLARE_TR_FUNCTIONS(SatHandout)
};

constexpr int kMargin = 16;     ///< around the figure [logical px]
constexpr int kHeadHeight = 96; ///< title, caption, verdict and legend [logical px]

struct Pair {
    physics::BodyId a = 0, b = 0;
    QString labelA, labelB;
};

std::optional<Pair> pairOf(const lessons::LessonStep& step)
{
    if (!step.sat)
        return std::nullopt;
    const auto a = step.scene.bodyIndex(step.sat->first);
    const auto b = step.scene.bodyIndex(step.sat->second);
    if (!a || !b)
        return std::nullopt;
    return Pair{*a, *b, step.scene.bodyLabel(*a), step.scene.bodyLabel(*b)};
}

QString number(double v)
{
    return formatReadable(v, 3);
}

/// A length with its unit, a no-break space between.
QString metres(double v)
{
    return formatQuantity(v, QStringLiteral("m"), 3);
}

/// "The test stops on axis 6 of 7: a gap, no collision" or the intersection's verdict.
QString verdict(const physics::SatResult& sat)
{
    const int total = static_cast<int>(sat.axes.size());
    if (!sat.intersects && sat.separatingAxis >= 0)
        return SatHandout::tr("The test stops at axis %1 of the %2 it tried: a gap, so no "
                              "collision.")
            .arg(sat.separatingAxis + 1)
            .arg(total);
    return SatHandout::tr("All %1 axes overlap: the polygons intersect. Least penetration: "
                          "axis %2, depth %3.")
        .arg(total)
        .arg(sat.leastAxis + 1)
        .arg(metres(sat.depth));
}

/// One tested axis as a strip: its name, the two intervals on a number line and the verdict.
void drawStrip(QPainter& p, const QRectF& r, const physics::SatAxis& axis, int index,
               bool separating, bool least, const Pair& pair)
{
    const QColor colourA = plotColor(0), colourB = plotColor(1);
    if (separating || least) {
        p.setPen(
            QPen(Qt::black, separating ? 2.5 : 1.5, separating ? Qt::SolidLine : Qt::DashLine));
        p.setBrush(QColor(0, 0, 0, 18));
        p.drawRect(r.adjusted(1, 1, -1, -1));
    }
    QFont small = p.font();
    small.setPointSizeF(7.5);
    p.setFont(small);
    p.setPen(Qt::black);
    const QString owner = axis.owner == 0 ? pair.labelA : pair.labelB;
    const QString name = SatHandout::tr("%1. normal of %2, edge %3\nn = (%4, %5)")
                             .arg(index + 1)
                             .arg(owner)
                             .arg(axis.edge + 1)
                             .arg(number(axis.axis.x()), number(axis.axis.y()));
    const qreal labelWidth = std::min<qreal>(150, r.width() * 0.3);
    const qreal verdictWidth = std::min<qreal>(150, r.width() * 0.3);
    p.drawText(QRectF(r.left() + 6, r.top(), labelWidth - 6, r.height()),
               Qt::AlignVCenter | Qt::AlignLeft | Qt::TextWordWrap, name);
    QString says = axis.overlap < 0 ? SatHandout::tr("gap %1").arg(metres(-axis.overlap))
                                    : SatHandout::tr("overlap %1").arg(metres(axis.overlap));
    if (separating)
        says += u'\n' + SatHandout::tr("separating axis");
    else if (least)
        says += u'\n' + SatHandout::tr("least penetration");
    QFont bold = small;
    bold.setBold(separating || least);
    p.setFont(bold);
    p.drawText(QRectF(r.right() - verdictWidth, r.top(), verdictWidth - 6, r.height()),
               Qt::AlignVCenter | Qt::AlignRight | Qt::TextWordWrap, says);
    p.setFont(small);

    // The number line: both intervals on one scale, padded.
    const double lo = std::min(axis.minA, axis.minB), hi = std::max(axis.maxA, axis.maxB);
    const double pad = std::max(1e-6, (hi - lo) * 0.08);
    const QRectF line(r.left() + labelWidth + 8, r.top() + 4,
                      r.width() - labelWidth - verdictWidth - 16, r.height() - 8);
    const auto xOf = [&](double v) {
        return line.left() + (v - (lo - pad)) / (hi - lo + 2 * pad) * line.width();
    };
    const qreal barHeight = std::min<qreal>(10, line.height() / 4);
    const qreal yA = line.center().y() - barHeight - 2, yB = line.center().y() + 2;
    // A filled, B hatched: told apart without their colours.
    p.setPen(QPen(colourA.darker(130), 1));
    p.setBrush(colourA);
    p.drawRect(QRectF(QPointF(xOf(axis.minA), yA), QPointF(xOf(axis.maxA), yA + barHeight)));
    p.setPen(QPen(colourB.darker(130), 1));
    p.setBrush(QBrush(colourB, Qt::BDiagPattern));
    p.drawRect(QRectF(QPointF(xOf(axis.minB), yB), QPointF(xOf(axis.maxB), yB + barHeight)));
    p.setPen(Qt::black);
    p.setBrush(Qt::NoBrush);
    p.drawText(QPointF(xOf(axis.minA) - 2, yA - 1),
               SatHandout::tr("A [%1, %2]").arg(number(axis.minA), number(axis.maxA)));
    p.drawText(QPointF(xOf(axis.minB) - 2, yB + barHeight + p.fontMetrics().ascent()),
               SatHandout::tr("B [%1, %2]").arg(number(axis.minB), number(axis.maxB)));
}

/// The strips' grid: one column up to six axes, two beyond.
QRectF stripRect(const QRectF& area, int i, int count)
{
    const int columns = count > 6 ? 2 : 1;
    const int rows = (count + columns - 1) / columns;
    const qreal w = area.width() / columns, h = area.height() / std::max(1, rows);
    return QRectF(area.left() + (i / rows) * w, area.top() + (i % rows) * h, w - 4, h - 4);
}

} // namespace

std::optional<physics::SatResult> stepSatResult(const lessons::LessonStep& step)
{
    const std::optional<Pair> pair = pairOf(step);
    if (!pair)
        return std::nullopt;
    const physics::World world = lessons::buildStepWorlds(step).front();
    const physics::Body& a = world.body(pair->a);
    const physics::Body& b = world.body(pair->b);
    const physics::Polygon* pa = a.shape.asPolygon();
    const physics::Polygon* pb = b.shape.asPolygon();
    if (!pa || !pb)
        return std::nullopt;
    return physics::satPolygons(*pa, a.transform(), *pb, b.transform());
}

QImage satFigure(const lessons::LessonStep& step, const physics::SatResult& sat,
                 const QString& caption, const ExportOptions& options)
{
    const Pair pair = pairOf(step).value_or(Pair{});
    const QSize size = options.logicalSize;
    QImage image(qRound(size.width() * options.pngPixelRatio),
                 qRound(size.height() * options.pngPixelRatio), QImage::Format_ARGB32);
    image.fill(Qt::white);
    QPainter p(&image);
    p.setRenderHint(QPainter::Antialiasing);
    p.scale(options.pngPixelRatio, options.pngPixelRatio);
    QFont title = p.font();
    title.setPointSizeF(11);
    title.setBold(true);
    p.setFont(title);
    p.setPen(Qt::black);
    const QRectF head(kMargin, kMargin / 2.0, size.width() - 2 * kMargin, kHeadHeight);
    p.drawText(
        head, Qt::AlignTop | Qt::AlignHCenter,
        SatHandout::tr("Separating axis test: %1 (A) and %2 (B)").arg(pair.labelA, pair.labelB));
    QFont text = title;
    text.setBold(false);
    text.setPointSizeF(8);
    p.setFont(text);
    const QString lines =
        caption + u'\n' + verdict(sat) + u'\n' +
        SatHandout::tr("Projections on each axis the test tried, in metres: A filled, B hatched.");
    p.drawText(head.adjusted(0, 20, 0, 0), Qt::AlignTop | Qt::AlignHCenter, lines);
    const QRectF area(kMargin, kMargin / 2.0 + kHeadHeight, size.width() - 2 * kMargin,
                      size.height() - kHeadHeight - kMargin);
    const int count = static_cast<int>(sat.axes.size());
    for (int i = 0; i < count; ++i)
        drawStrip(p, stripRect(area, i, count), sat.axes[static_cast<std::size_t>(i)], i,
                  i == sat.separatingAxis, sat.intersects && i == sat.leastAxis, pair);
    p.end();
    return image;
}

QByteArray satTable(const lessons::LessonStep& step, const physics::SatResult& sat,
                    const ExportOptions& options)
{
    lessons::CsvWriter csv(options.csv);
    // Code names as column heads, for the scripts that read handouts; A and B as the step's
    // `sat` pair names them.
    csv.row({QStringLiteral("axis"), QStringLiteral("body"), QStringLiteral("edge"),
             QStringLiteral("n_x"), QStringLiteral("n_y"), QStringLiteral("A_min [m]"),
             QStringLiteral("A_max [m]"), QStringLiteral("B_min [m]"), QStringLiteral("B_max [m]"),
             QStringLiteral("overlap [m]"), QStringLiteral("separating"),
             QStringLiteral("least_penetration")});
    for (std::size_t i = 0; i < sat.axes.size(); ++i) {
        const physics::SatAxis& axis = sat.axes[i];
        const int index = static_cast<int>(i);
        csv.integer(index + 1);
        csv.text(axis.owner == 0 ? step.sat->first : step.sat->second);
        csv.integer(axis.edge + 1);
        for (double v : {axis.axis.x(), axis.axis.y(), axis.minA, axis.maxA, axis.minB, axis.maxB,
                         axis.overlap})
            csv.number(std::abs(v) < 1e-12 ? 0.0 : v); // rounding noise as 0, as the plots write it
        csv.integer(index == sat.separatingAxis ? 1 : 0);
        csv.integer(sat.intersects && index == sat.leastAxis ? 1 : 0);
        csv.endRow();
    }
    return QByteArray::fromStdString(csv.data());
}

PlotFilesResult exportSatHandout(const lessons::Lesson& lesson, int step, const QString& dir,
                                 const ExportOptions& options)
{
    const lessons::LessonStep& s = lesson.steps.at(static_cast<std::size_t>(step));
    const std::optional<physics::SatResult> sat = stepSatResult(s);
    PlotFilesResult result;
    if (!sat) {
        result.ok = true;
        return result;
    }
    if (!QDir().mkpath(dir)) {
        result.error =
            SatHandout::tr("cannot make the folder %1").arg(QDir::toNativeSeparators(dir));
        return result;
    }
    const physics::WorldDef settings = lessons::buildStepWorlds(s).front().def();
    const QImage figure = satFigure(s, *sat, stepCaption(lesson, step, settings), options);
    QByteArray png;
    QBuffer buffer(&png);
    buffer.open(QIODevice::WriteOnly);
    figure.save(&buffer, "PNG");
    const QString pngPath = QDir(dir).filePath(QStringLiteral("sat-projections.png"));
    const QString csvPath = QDir(dir).filePath(QStringLiteral("sat-projections.csv"));
    for (const auto& [path, bytes] :
         {std::pair{pngPath, png}, std::pair{csvPath, satTable(s, *sat, options)}}) {
        const QString error = lessons::writeFileAtomically(path, bytes);
        if (!error.isEmpty()) {
            result.error = error;
            return result;
        }
        result.files.append(path);
    }
    result.ok = true;
    return result;
}

} // namespace rigidlab::ui
