// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The Measurement dock: the measured points as markers over the simulated line of the same
// quantity, the residuals (measured − simulated) as a plot of their own, and the fit. Markers
// and line differ in shape as well as colour, and the legend names both. The panel only
// shows; MeasurementSession (measurement_session.h) reads and compares, MeasurementFit
// (measurement_fit.h) fits.
//
// The choices and the fit form a column that scrolls on its own, beside the plots where the
// dock is wide enough for both (under the world on a 1024×768 projector), else above them;
// the plots are side by side, stacked or behind tabs as keeps each one's data area readable
// (PlotShelf). So the dock never scrolls its plots out of sight, and it is not put in a
// scroll area of its own.

#include "measure/measurement.h"
#include "measure/measurement_files.h"

#include <QString>
#include <QWidget>

#include <vector>

class QBoxLayout;
class QCheckBox;
class QComboBox;
class QGridLayout;
class QGroupBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QScrollArea;

namespace rigidlab::ui {

class PlotShelf;
class PlotWidget;

class MeasurementPanel : public QWidget {
    Q_OBJECT
public:
    explicit MeasurementPanel(QWidget* parent = nullptr);

    /// Series of the comparison plot and of the residual plot.
    enum Series { kMeasured = 0, kSimulated = 1 };
    enum ResidualSeries { kResidual = 0 };

    /// What was imported, one line ("ball.csv: 97 points of y").
    void setSource(const QString& text);
    /// A body to compare with: its id, which the choice is kept by, and what a class reads
    /// for it (its label, lessons::Scene::bodyLabel).
    struct BodyChoice {
        QString id;
        QString label;
    };
    /// The bodies to compare with and the measured quantities; keeps the choice where it
    /// still exists.
    void setChoices(const std::vector<BodyChoice>& bodies,
                    const std::vector<measure::Quantity>& quantities);
    int body() const;
    measure::Quantity quantity() const;
    void setBody(int index);

    /// Draws the measured points, the simulated line and the residuals; `error` (a run that
    /// failed) replaces them with a message.
    void showComparison(const measure::Series& measured, const std::vector<double>& lineT,
                        const std::vector<double>& lineValue, const std::vector<double>& residuals,
                        const QString& error);
    /// The same quantity measured in other files, each as markers of a shape of its own named
    /// by its file, beside the points compared, which come from `comparedFile` (the last file
    /// imported that has the quantity: the residuals and the fit use it, and its legend says
    /// so). Without others the points compared are "measured". After showComparison().
    void showOtherFiles(const QString& comparedFile, const std::vector<FileSeries>& others);
    void clearPlots();
    /// Back to how it was before anything was imported: no source, no choices, no plots, no fit.
    void clear();

    PlotWidget* comparisonPlot() const { return m_comparison; }
    PlotWidget* residualPlot() const { return m_residual; }
    QCheckBox* residualsShown() const { return m_showResiduals; }
    /// The comparison, and the residuals unless hidden: what File › Export plot offers.
    std::vector<PlotWidget*> plotsShown() const;
    QLabel* message() const { return m_message; }

    // The fit.
    /// The parameters ticked: 0 restitution, 1 friction, 2 vx, 3 vy.
    std::vector<int> fitChoices() const;
    void setFitChoice(int parameter, bool on);
    static constexpr int kFitParameters = 4;
    /// The fit's result in words, and whether it can be applied; ends showFitRunning.
    void showFit(const QString& text, bool applicable);
    /// A fit is running (`runs` of the model so far): a busy bar and Cancel in place of Fit.
    void showFitRunning(int runs);
    bool fitRunning() const;
    /// e from bounce times alone, in words; empty hides it.
    void showBounceFit(const QString& text, bool applicable);
    QString fitText() const;
    QString bounceFitText() const;
    QPushButton* fitButton() const { return m_fit; }
    QPushButton* cancelFitButton() const { return m_cancelFit; }
    QProgressBar* fitProgress() const { return m_fitProgress; }
    QPushButton* applyButton() const { return m_apply; }
    QPushButton* applyBounceButton() const { return m_applyBounce; }

signals:
    void choiceChanged();
    /// The comparison's legend names other series (another file's): it may take another row
    /// from the data area.
    void legendChanged();
    void fitRequested();
    void cancelFitRequested();
    void applyRequested();
    void applyBounceRequested();

protected:
    void resizeEvent(QResizeEvent* event) override;

private:
    /// Scrolls the fit's results into sight once they are laid out.
    void showResultsSoon();
    QWidget* buildControls();
    QWidget* buildFit(QWidget& parent);
    /// The controls beside the plots or above them, for the panel's size now.
    void arrange();
    /// The fit's choices and buttons one under another, or two by two and in a row.
    void setFitNarrow(bool narrow);
    /// The controls' least width as they are placed now, with room for their scroll bar [px].
    int leastControlsWidth() const;

    QBoxLayout* m_layout = nullptr;
    QScrollArea* m_controls = nullptr;
    PlotShelf* m_plots = nullptr;
    QLabel* m_source = nullptr;
    QComboBox* m_body = nullptr;
    QComboBox* m_quantity = nullptr;
    PlotWidget* m_comparison = nullptr;
    PlotWidget* m_residual = nullptr;
    std::vector<int> m_otherSeries; ///< the other files' series in m_comparison, in order
    std::size_t m_othersShown = 0;  ///< how many of them the legend names
    QCheckBox* m_showResiduals = nullptr;
    QLabel* m_message = nullptr;
    QGroupBox* m_fitBox = nullptr;
    QGridLayout* m_fitGrid = nullptr;
    QBoxLayout* m_fitButtons = nullptr;
    bool m_fitNarrow = false;
    QCheckBox* m_parameters[kFitParameters] = {};
    QPushButton* m_fit = nullptr;
    QPushButton* m_cancelFit = nullptr;
    QProgressBar* m_fitProgress = nullptr;
    QLabel* m_fitResult = nullptr;
    QPushButton* m_apply = nullptr;
    QLabel* m_bounceResult = nullptr;
    QPushButton* m_applyBounce = nullptr;
};

} // namespace rigidlab::ui
