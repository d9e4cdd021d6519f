// SPDX-License-Identifier: GPL-3.0-or-later
// Colours a student with a colour-vision deficiency tells apart: every two series of every
// plot the lab ships (the window's plots and those of each lesson step), and every two moving
// bodies of the restitution lesson, stay at least kMinDeltaE apart after a simulation of
// deuteranopia and of protanopia, and each has at least 3:1 against what it is drawn on.
//
// The simulation is Machado, Oliveira and Fernandes (2009), "A physiologically-based model for
// simulation of color vision deficiency", IEEE TVCG 15(6), at severity 1.0: their 3×3 matrices
// applied to linear sRGB. The difference is CIELAB ΔE*ab (CIE 1976) under D65. The contrast is
// WCAG 2.x's, computed here apart from the theme's own function.

#include "lesson_player/lesson_player.h"
#include "plots/plot_widget.h"
#include "simulation/simulation_controller.h"
#include "view/body_item.h"
#include "view/world_view.h"
#include "window/main_window.h"

#include "common/theme.h"

#include <QtTest>
#include <qcustomplot.h>

#include <array>
#include <cmath>

#include "test_main.h"

using namespace rigidlab;
using rigidlab::ui::MainWindow;

namespace {

/// The least ΔE*ab between two colours that must be told apart: a clearly seen difference
/// (a ΔE of 2.3 is barely seen side by side; lines and small markers need far more).
constexpr double kMinDeltaE = 10.0;
/// WCAG 1.4.11: graphical objects against their background.
constexpr double kMinContrast = 3.0;

using Vec3 = std::array<double, 3>;
using Matrix = std::array<Vec3, 3>;

/// Machado et al. (2009), severity 1.0.
constexpr Matrix kProtanopia{{{0.152286, 1.052583, -0.204868},
                              {0.114503, 0.786281, 0.099216},
                              {-0.003882, -0.048116, 1.051998}}};
constexpr Matrix kDeuteranopia{{{0.367322, 0.860646, -0.227968},
                                {0.280085, 0.672501, 0.047413},
                                {-0.011820, 0.042940, 0.968881}}};

double linear(int channel)
{
    const double c = channel / 255.0;
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

Vec3 linearRgb(const QColor& c)
{
    return {linear(c.red()), linear(c.green()), linear(c.blue())};
}

Vec3 simulate(const Vec3& rgb, const Matrix& m)
{
    Vec3 out{};
    for (int i = 0; i < 3; ++i)
        out[i] = std::clamp(m[i][0] * rgb[0] + m[i][1] * rgb[1] + m[i][2] * rgb[2], 0.0, 1.0);
    return out;
}

/// CIELAB of a linear sRGB colour, D65 white.
Vec3 lab(const Vec3& rgb)
{
    const double x = 0.4124564 * rgb[0] + 0.3575761 * rgb[1] + 0.1804375 * rgb[2];
    const double y = 0.2126729 * rgb[0] + 0.7151522 * rgb[1] + 0.0721750 * rgb[2];
    const double z = 0.0193339 * rgb[0] + 0.1191920 * rgb[1] + 0.9503041 * rgb[2];
    const auto f = [](double t) {
        return t > 216.0 / 24389.0 ? std::cbrt(t) : (24389.0 / 27.0 * t + 16.0) / 116.0;
    };
    const double fx = f(x / 0.95047), fy = f(y), fz = f(z / 1.08883);
    return {116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz)};
}

double deltaE(const Vec3& a, const Vec3& b)
{
    return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
}

/// ΔE*ab of two colours as a deuteranope and as a protanope sees them, the smaller.
double dichromatDeltaE(const QColor& a, const QColor& b)
{
    double least = 1e9;
    for (const Matrix* m : {&kDeuteranopia, &kProtanopia})
        least = std::min(least,
                         deltaE(lab(simulate(linearRgb(a), *m)), lab(simulate(linearRgb(b), *m))));
    return least;
}

double contrast(const QColor& a, const QColor& b)
{
    const auto luminance = [](const QColor& c) {
        const Vec3 l = linearRgb(c);
        return 0.2126 * l[0] + 0.7152 * l[1] + 0.0722 * l[2];
    };
    const double la = luminance(a), lb = luminance(b);
    return (std::max(la, lb) + 0.05) / (std::min(la, lb) + 0.05);
}

/// What is wrong with `colours` (named): pairs too close for a dichromat, colours too faint
/// on `background`. Empty when nothing is.
QStringList problems(const QList<std::pair<QString, QColor>>& colours, const QColor& background)
{
    QStringList out;
    for (qsizetype i = 0; i < colours.size(); ++i) {
        const auto& [name, colour] = colours[i];
        if (const double c = contrast(colour, background); c < kMinContrast)
            out << QStringLiteral("%1 %2: contrast %3 < %4")
                       .arg(name, colour.name())
                       .arg(c, 0, 'f', 2)
                       .arg(kMinContrast);
        for (qsizetype j = i + 1; j < colours.size(); ++j)
            if (const double d = dichromatDeltaE(colour, colours[j].second); d < kMinDeltaE)
                out << QStringLiteral("%1 %2 and %3 %4: ΔE %5 < %6")
                           .arg(name, colour.name(), colours[j].first, colours[j].second.name())
                           .arg(d, 0, 'f', 1)
                           .arg(kMinDeltaE);
    }
    return out;
}

QStringList plotProblems(const ui::PlotWidget& plot)
{
    QList<std::pair<QString, QColor>> colours;
    for (int s = 0; s < plot.model().seriesCount(); ++s)
        colours.append({plot.model().seriesName(s), plot.graph(s)->pen().color()});
    QStringList out;
    for (const QString& p : problems(colours, ui::theme::plotBackground()))
        out << plot.title() + QStringLiteral(": ") + p;
    return out;
}

QString lesson(const char* file)
{
    return QDir(MainWindow::lessonsFolder()).filePath(QLatin1String(file));
}

} // namespace

class TestColours : public QObject {
    Q_OBJECT
private slots:
    /// The simulation itself, on colours whose answer is known: Machado's matrices keep
    /// white white and grey grey (their rows sum to 1), and make the classic confusion of
    /// red and green for a deuteranope.
    void simulationKnowsTheConfusions()
    {
        for (const QColor& c : {QColor(Qt::white), QColor(0x80, 0x80, 0x80)})
            for (const Matrix* m : {&kDeuteranopia, &kProtanopia}) {
                const double d = deltaE(lab(simulate(linearRgb(c), *m)), lab(linearRgb(c)));
                QVERIFY2(d < 0.1, qPrintable(QStringLiteral("%1: ΔE %2").arg(c.name()).arg(d)));
            }
        const QColor red(0xd0, 0x50, 0x30), green(0x70, 0x80, 0x20);
        const double normal = deltaE(lab(linearRgb(red)), lab(linearRgb(green)));
        QVERIFY2(normal > 40 && dichromatDeltaE(red, green) < kMinDeltaE,
                 qPrintable(QStringLiteral("normal %1, dichromat %2")
                                .arg(normal)
                                .arg(dichromatDeltaE(red, green))));
    }

    /// The palettes as a whole: any two of the plots' colours apart and 3:1 on the plots'
    /// background, any two of the bodies' apart and 3:1 on the world's.
    void paletteIsApartForDichromats()
    {
        QList<std::pair<QString, QColor>> colours;
        constexpr int kPaletteSize = 7; // six hues, then ink
        for (int i = 0; i < kPaletteSize; ++i)
            colours.append({QStringLiteral("plotColor(%1)").arg(i), ui::plotColor(i)});
        const QStringList onPlots = problems(colours, ui::theme::plotBackground());
        QVERIFY2(onPlots.isEmpty(), qPrintable(onPlots.join(u'\n')));
        QList<std::pair<QString, QColor>> bodies;
        constexpr int kBodyColours = 6; // then they repeat
        for (int i = 0; i < kBodyColours; ++i)
            bodies.append({QStringLiteral("bodyColor(%1)").arg(i), ui::bodyColor(i)});
        const QStringList onWorld = problems(bodies, ui::theme::worldBackground());
        QVERIFY2(onWorld.isEmpty(), qPrintable(onWorld.join(u'\n')));
    }

    /// Every plot the window shows, and every plot of every lesson step (the compared
    /// worlds' too).
    void everyShippedPlotIsApart()
    {
        MainWindow w;
        w.fitToScreen(QRect(0, 0, 1024, 768));
        QStringList found;
        int plots = 0;
        for (auto* plot : w.plots()) {
            found << plotProblems(*plot);
            ++plots;
        }
        const QDir folder(MainWindow::lessonsFolder());
        for (const QString& file : folder.entryList({QStringLiteral("*.json")}, QDir::Files)) {
            QCOMPARE(w.openLesson(folder.filePath(file), true), QString());
            const int steps = static_cast<int>(w.lessonPlayer().lesson()->steps.size());
            for (int s = 0; s < steps; ++s) {
                w.lessonPlayer().goToStep(s);
                for (const ui::PlotWidget* plot : w.comparePlots()) {
                    found << plotProblems(*plot);
                    ++plots;
                }
            }
        }
        QVERIFY2(plots > w.plots().size(), qPrintable(QString::number(plots)));
        QVERIFY2(found.isEmpty(), qPrintable(found.join(u'\n')));
    }

    /// The restitution lesson's balls: each step's moving bodies apart from each other and
    /// 3:1 on the world's background.
    void restitutionBallsAreApart()
    {
        MainWindow w;
        QCOMPARE(w.openLesson(lesson("restitution.json"), true), QString());
        const int steps = static_cast<int>(w.lessonPlayer().lesson()->steps.size());
        QStringList found;
        int most = 0;
        for (int s = 0; s < steps; ++s) {
            w.lessonPlayer().goToStep(s);
            QList<std::pair<QString, QColor>> colours;
            const auto& bodies = w.controller().world().bodies();
            for (int id = 0; id < static_cast<int>(bodies.size()); ++id)
                if (bodies[static_cast<std::size_t>(id)].moves() && w.view().itemFor(id))
                    colours.append(
                        {w.controller().scene().bodyLabel(id), w.view().itemFor(id)->fill()});
            most = std::max(most, static_cast<int>(colours.size()));
            for (const QString& p : problems(colours, ui::theme::worldBackground()))
                found << QStringLiteral("step %1: %2").arg(s + 1).arg(p);
        }
        QVERIFY2(most >= 4, qPrintable(QString::number(most))); // the four dropped balls
        QVERIFY2(found.isEmpty(), qPrintable(found.join(u'\n')));
    }
};

RIGIDLAB_TEST_MAIN(TestColours)
#include "test_colours.moc"
