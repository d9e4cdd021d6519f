// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The selected body, in numbers: mass, inertia, pose, velocities, energy. Its restitution and
// friction can be edited, and the mass of a dynamic body. Numbers are shown in the locale and
// rounded to what is physically meaningful: rounding noise shows as 0 (common/number_format.h).
// Angles in degrees (the school's unit) or radians, as the student chooses.

#include <QList>
#include <QWidget>

#include <array>
#include <optional>
#include <utility>

class QFormLayout;

class QComboBox;
class QLabel;
class QPushButton;

namespace rigidlab::ui {

class ForcesView;
class NumberField;
class SimulationController;

class InspectorPanel : public QWidget {
    Q_OBJECT
public:
    explicit InspectorPanel(SimulationController& controller, QWidget* parent = nullptr);
    int body() const { return m_body; }
    QString text() const; ///< everything shown, for tests
    NumberField* massField() const { return m_massEdit; }
    NumberField* restitutionField() const { return m_restitution; }
    NumberField* frictionField() const { return m_friction; }
    /// Angles and angular velocities in degrees (the default) or radians.
    bool anglesInDegrees() const;
    void setAnglesInDegrees(bool degrees);
    /// How many times the rows were filled in (for tests: a frame that changed nothing the
    /// panel shows, or a frame while it is out of sight, fills in nothing).
    int fillCount() const { return m_fills; }

signals:
    /// A typed value was refused; `message` names the allowed range (for the status bar).
    void inputRefused(const QString& message);
    /// Graph… was pressed: graphs of the body shown.
    void graphRequested(int body);

public slots:
    /// Shows body `id` (-1: none). An edit in progress is taken for the body shown before.
    void setBody(int id);
    /// The rows again for the world as it is, where they would change: not while the panel is
    /// out of sight in a window on screen (behind another dock's tab, its dock closed; it
    /// fills them in when shown), and not for a frame of the running clock that changed
    /// nothing it shows (no step, the body as it was).
    void refresh();

protected:
    void showEvent(QShowEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;

private:
    /// What the rows were filled in from: the body, the world's step, the body's own numbers
    /// and the choices the rows follow.
    struct Shown {
        int body = -1;
        long long step = 0;
        std::array<double, 11> numbers{};
        bool degrees = true;
        bool running = false;
        bool operator==(const Shown&) const = default;
    };
    Shown shownNow() const;
    /// Fills the rows in from the world as it is.
    void fill();
    /// The angle's unit's choice, on a row of its own with its label: beside the angle it made
    /// the row too wide for a projector's side column, which then put the angle below its
    /// label.
    QWidget* angleUnitList();
    /// Without a body, one line says so instead of each row's dash.
    void showRows(bool body);
    /// A typed mass, restitution or friction to the body shown, through the controller.
    void connectEdits();
    /// Each value's row label as its buddy, and its accessible name "row: value", so that a
    /// screen reader says which number it reads.
    void labelRows(QFormLayout& form);
    void nameValues();
    /// The rows' labels at most a share of the panel's width, wrapped onto a second line past
    /// it, and the values wrapped at their spaces: in a projector's narrow side column (about
    /// 200 px at 1024 px wide) each value stays beside its label, in either language, and
    /// nothing is cut or scrolled sideways. In a wide column nothing wraps.
    void fitLabels();

    SimulationController& m_controller;
    int m_body = -1;
    QFormLayout* m_form = nullptr;
    QLabel* m_none; ///< "No body selected", the one line shown without a body
    QLabel* m_name;
    QLabel* m_mass; ///< "infinite" for static and kinematic bodies
    NumberField* m_massEdit;
    QLabel* m_massUnit;
    QLabel* m_inertia;
    QLabel* m_position;
    QLabel* m_angle;
    QLabel* m_velocity;
    QLabel* m_speed; ///< |v|
    QLabel* m_omega;
    QComboBox* m_angleUnit; ///< degrees, radians
    QLabel* m_energy;
    /// The value labels with their rows' names, for nameValues().
    QList<std::pair<QLabel*, QString>> m_rowNames;
    ForcesView* m_forces;           ///< the body's accumulators force by force, folded
    QPushButton* m_graph = nullptr; ///< Graph… of the body shown
    NumberField* m_restitution;
    NumberField* m_friction;
    std::optional<Shown> m_shown;  ///< what the rows show; none when they are to be filled in
    int m_fills = 0;               ///< see fillCount()
    std::optional<bool> m_rowsFor; ///< whether the rows are shown for a body (showRows)
};

} // namespace rigidlab::ui
