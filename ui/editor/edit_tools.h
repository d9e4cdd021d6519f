// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Edit mode and the editor's tools on the world view.
//
// EditTools watches the view's mouse and keys through an event filter while Edit mode is on
// and hands each gesture to the tool in use (editor/tools/: one class per tool), which turns
// it into one of the pure scene edits of lessons/edit/; EditTools applies it to the
// SceneDocument (one undo step per gesture: a drag merges). It never touches a world: while
// editing it reloads the simulation from the document, at t = 0, after each change, so what
// the view shows is the scene as edited. Entering Edit mode pauses; leaving it keeps the
// world paused at the start of the scene as edited, so that a class can predict before the
// teacher presses Run (Run while editing leaves Edit mode and runs). Refusals, warnings and
// what the tool in use does go out through message() for the status bar.

#include "editor/edit_snap.h"
#include "editor/tools/tool.h"
#include "editor/velocity_arrow.h"

#include "rigidlab/physics/forces.h"
#include "rigidlab/physics/math.h"

#include <QObject>
#include <QPoint>
#include <QString>
#include <QStringList>

#include <array>
#include <memory>
#include <optional>
#include <vector>

class QAction;
class QActionGroup;
class QEvent;
class QKeyEvent;
class QMouseEvent;

namespace rigidlab::lessons::edit {
struct EditResult;
}

namespace rigidlab::ui {

class EditOverlay;
class SceneDocument;
class SimulationController;
class WorldView;

/// The editor's tools, in the order of the toolbar.
enum class EditTool {
    Select,    ///< select and drag a body; arrow keys nudge
    Rotate,    ///< turn a body by its handle; Q and E by 5°
    Circle,    ///< drag from the centre
    Box,       ///< drag a rectangle
    Polygon,   ///< click the vertices; double-click or Enter closes
    Ground,    ///< a static box: ground, a wall
    Pin,       ///< click a body point, then a second body or empty space (the world)
    Spring,    ///< drag from one point to another (a body or the world at each end)
    Delete,    ///< click a body to delete it
    Duplicate, ///< click a body to copy it beside itself
};
inline constexpr int kEditToolCount = 10;

class EditTools : public QObject {
    Q_OBJECT
public:
    EditTools(WorldView& view, SimulationController& simulation, SceneDocument& document,
              QObject* parent = nullptr);
    ~EditTools() override;

    /// Edit mode on and off (checkable).
    QAction* editAction() const { return m_editAction; }
    QAction* toolAction(EditTool tool) const { return m_toolActions[static_cast<size_t>(tool)]; }
    /// Snap to the grid (checkable; the grid step is shown in its text).
    QAction* snapAction() const { return m_snapAction; }
    /// Deletes the selected body (Delete).
    QAction* deleteSelectionAction() const { return m_deleteSelection; }
    /// Every action, in toolbar order (the Edit toggle first).
    QList<QAction*> actions() const;

    bool editing() const { return m_editing; }
    /// The view the tools work on.
    const WorldView& view() const { return m_view; }
    EditTool tool() const { return m_tool; }
    /// The selected body (an index into the document's scene), -1 for none.
    int selectedBody() const { return m_selected; }
    /// The selected spring (an index into the document's springs), -1 for none.
    int selectedSpring() const { return m_selectedSpring; }
    /// The grid's step now [m]: a round number about kGridPixels wide at this zoom.
    double gridStep() const;
    /// A lesson step's lock: only the tools named (lessons::kEditorToolNames) may be used, the
    /// others are disabled, say so in their tooltip, and their keys are refused with a message;
    /// nullopt unlocks every tool.
    void setAllowedTools(const std::optional<QStringList>& names);
    /// Whether a lesson step locks this tool.
    bool locked(EditTool tool) const;
    /// A lesson step's lock on the properties (lessons::kEditorPropertyNames): only those named
    /// may be changed, by the inspector's fields or by any gesture that sets them (a velocity
    /// dragged); nullopt unlocks them all.
    void setAllowedProperties(const std::optional<QStringList>& names);
    /// Whether a lesson step locks this property ("mass", "velocity", ...).
    bool propertyLocked(const QString& name) const;
    /// "This lesson step locks the Mass property", with the property's label as shown.
    static QString propertyLockedMessage(const QString& label);

    /// Whether the editor reloads the simulation from the document after each change (the
    /// default). A window that does so itself for every change turns it off.
    void setReloadsWorld(bool on) { m_reloadsWorld = on; }
    /// Whether the editor is reloading the simulation from its document just now (a window
    /// that follows every scene loaded into the simulation leaves these alone).
    bool reloading() const { return m_reloading; }
    /// The last message sent (refusal, warning or the size being drawn).
    const QString& lastMessage() const { return m_lastMessage; }
    /// The polygon being drawn, its points [m] (for tests and the overlay).
    const std::vector<physics::Vec2>& polygonPoints() const;
    /// Where the pointer snaps to another body now (a vertex, a centre, an edge), shown by a
    /// marker; nullopt when it snaps to the grid or not at all.
    const std::optional<Snap>& bodySnap() const { return m_bodySnap; }
    /// The tool in use, for the overlay.
    const Tool& activeTool() const { return *m_tools[static_cast<size_t>(m_tool)]; }

    /// Body `body` as the History and the messages name it: its label as the rest of the window
    /// shows it, its id when it has none ("Add circle circle1"); "the world" for kWorld.
    static QString bodyName(const lessons::Scene& scene, int body);

    /// The stiffness of a new spring [N/m] (the inspector changes it).
    static constexpr double kSpringStiffness = 50.0;
    /// The grid's step is a round number of metres about this many pixels wide.
    static constexpr double kGridPixels = 40.0;

    // What the tools (editor/tools/) work with: the scene, snapping, the history, the status.
    const lessons::Scene& scene() const;
    WorldView& worldView() { return m_view; }
    bool snapping() const;
    /// `pixels` of the view at its zoom now, in metres.
    double pixelsToMetres(double pixels) const;
    /// The grid point nearest the middle of what the view shows [m] (where a key adds a body).
    physics::Vec2 viewCentre() const;
    /// The body under a world point, the topmost (last drawn), or -1.
    int bodyAt(const physics::Vec2& p) const;
    /// The spring within a few pixels of a world point, or -1.
    int springAt(const physics::Vec2& p) const;
    /// A point snapped to another body's vertex or centre, else to its edge, within a few
    /// pixels, else to the grid, when snapping is on; `except` is left out (the body being
    /// moved). A grid point that lies on the edge snapped to is taken instead of the edge's
    /// nearest point, so that sizes drawn on the grid along a floor are grid sizes.
    physics::Vec2 snapped(const physics::Vec2& p, int except = -1) const;
    /// The body snapping would put p on (snapped()), nullopt for the grid or no snapping.
    std::optional<Snap> featureSnap(const physics::Vec2& p, int except = -1) const;
    /// The body under the pointer, else the one its point snaps to (a spring's or pin's end
    /// put on an edge from just outside it), else -1 (the world).
    int bodyAtOrSnapped(const physics::Vec2& raw) const;
    /// Where body `body` dragged by `raw` goes (`grabOffset`, its origin minus the press, kept):
    /// onto another body when one of its points comes within a few pixels of one (bodySnap()
    /// says which), else its origin on the grid when snapping is on.
    physics::Vec2 movedBodyTarget(int body, const physics::Vec2& grabOffset,
                                  const physics::Vec2& raw);
    void clearBodySnap() { m_bodySnap.reset(); }
    physics::Vec2 snapToGrid(const physics::Vec2& p) const;
    /// Applies an edit (or says why not); returns whether it was applied.
    bool apply(const QString& what, const lessons::edit::EditResult& result, int mergeId = -1);
    void say(const QString& text);
    /// "r = 0,5 m" and the like, in the locale.
    QString metres(double v) const;
    /// A new merge id: the edits of one drag made with it are one step of the history.
    int newMergeId() { return m_nextMergeId++; }
    /// The selected body's velocity arrow (editor/velocity_arrow.h), when it moves.
    std::optional<VelocityArrow> selectedArrow() const;
    void refreshOverlay();

public slots:
    void setEditing(bool on);
    void setTool(rigidlab::ui::EditTool tool);
    void selectBody(int body);
    void selectSpring(int spring);
    /// Selects the body after the selected one (the first when none is), for the keyboard.
    void selectNextBody();
    /// Turns the selected body by `radians` about its origin (Q, E).
    void rotateSelected(double radians);
    /// Moves the selected body by `offset` [m] (arrow keys).
    void nudgeSelected(const physics::Vec2& offset);
    void deleteSelected();
    /// Closes the polygon being drawn (Enter, double-click).
    void closePolygon();
    /// Offers the bodies the tools add at the view's centre, in a menu under it (Insert).
    void chooseBodyToAdd();
    /// Takes `tool` (Circle, Box, Polygon or Ground) and adds its body at the view's centre,
    /// as its Enter does; a tool a lesson step locks is refused with a message.
    void addBodyAtCentre(rigidlab::ui::EditTool tool);

signals:
    void editingChanged(bool on);
    /// For the status bar: a refusal, a warning, the size being drawn; empty clears it.
    void message(const QString& text);
    /// A body or a spring was selected, or the selection cleared.
    void selectionChanged();
    /// setAllowedProperties changed what is locked.
    void propertyLocksChanged();

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    /// A run of arrow keys (or of Q and E) on one body, one step of the history as a drag
    /// is: anything else in between (an edit, an undo) starts a new run.
    struct KeyRun {
        enum class Kind { None, Nudge, Turn };
        Kind kind = Kind::None;
        int body = -1;
        int mergeId = -1;
        int index = -1; ///< the undo stack's index after the run's last key
    };
    int keyRunMergeId(KeyRun::Kind kind);

    void createActions();
    void followSimulation();
    bool viewportEvent(QEvent* event);
    bool mousePress(QMouseEvent* event);
    bool mouseMove(QMouseEvent* event);
    bool mouseRelease(QMouseEvent* event);
    bool keyPress(QKeyEvent* event);
    /// Keys the window's shortcuts would take that Edit mode uses (arrows, Q, E, Enter...).
    bool wantsKey(const QKeyEvent* event) const;
    /// Insert, +, −, 0 and Ctrl+arrows: adding a body, zooming and panning the view
    /// (edit_tools_keys.cpp).
    static bool isViewKey(const QKeyEvent& event);
    bool viewKey(const QKeyEvent& event);
    /// Arrows, Q, E, Delete and Escape, for the selection and the gesture under way.
    bool selectionKey(const QKeyEvent* event);
    ToolPointer pointerAt(const QMouseEvent* event) const;
    Tool& current() { return *m_tools[static_cast<size_t>(m_tool)]; }
    void reloadWorld();
    void updateSnapText();
    void cancelGesture();

    WorldView& m_view;
    SimulationController& m_simulation;
    SceneDocument& m_document;
    EditOverlay* m_overlay = nullptr;
    QAction* m_editAction = nullptr;
    QActionGroup* m_toolGroup = nullptr;
    std::array<QAction*, kEditToolCount> m_toolActions{};
    std::array<std::unique_ptr<Tool>, kEditToolCount> m_tools;
    QAction* m_snapAction = nullptr;
    QAction* m_deleteSelection = nullptr;
    bool m_editing = false;
    bool m_reloading = false;
    bool m_reloadsWorld = true;
    std::optional<QStringList> m_allowedTools;      ///< see setAllowedTools
    std::optional<QStringList> m_allowedProperties; ///< see setAllowedProperties
    EditTool m_tool = EditTool::Select;
    int m_selected = -1;
    int m_selectedSpring = -1;
    std::optional<Snap> m_bodySnap; ///< see bodySnap()
    int m_nextMergeId = 1000;
    KeyRun m_keyRun;
    QString m_lastMessage;
};

} // namespace rigidlab::ui
