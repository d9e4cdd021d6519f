// SPDX-License-Identifier: GPL-3.0-or-later
#include "editor/edit_tools.h"

#include "editor/edit_overlay.h"
#include "editor/scene_document.h"

#include "edit/scene_edits.h"
#include "format/editor_tools.h"
#include "panels/number_field.h"
#include "simulation/simulation_controller.h"
#include "view/world_view.h"
#include "common/shortcuts.h"

#include <QAction>
#include <QActionGroup>
#include <QGraphicsScene>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QUndoStack>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rigidlab::ui {

using physics::Vec2;
namespace edit = lessons::edit;

namespace {

/// A pointer this close to another body's vertex, centre or edge snaps to it [px].
constexpr double kVertexSnapPixels = 8.0;
/// Q and E turn by this much, as they do outside Edit mode [rad].
constexpr double kTurnStep = 5.0 * std::numbers::pi / 180.0;
/// Dragging the rotate handle with the grid on turns in steps of this much [rad].
constexpr double kAngleSnap = 15.0 * std::numbers::pi / 180.0;

struct ToolInfo {
    const char* name; ///< the action's objectName and its row in shortcuts.h
    const char* text;
    const char* tip;
};

// clang-format off
constexpr std::array<ToolInfo, kEditToolCount> kTools{{
    {"toolSelect", QT_TRANSLATE_NOOP("rigidlab::ui::EditTools", "Select"),
     QT_TRANSLATE_NOOP("rigidlab::ui::EditTools", "Select and move bodies; arrow keys nudge")},
    {"toolRotate", QT_TRANSLATE_NOOP("rigidlab::ui::EditTools", "Rotate"),
     QT_TRANSLATE_NOOP("rigidlab::ui::EditTools", "Turn a body by dragging; Q and E turn by 5°")},
    {"toolCircle", QT_TRANSLATE_NOOP("rigidlab::ui::EditTools", "Circle"),
     QT_TRANSLATE_NOOP("rigidlab::ui::EditTools", "Drag from the centre to draw a circle")},
    {"toolBox", QT_TRANSLATE_NOOP("rigidlab::ui::EditTools", "Box"),
     QT_TRANSLATE_NOOP("rigidlab::ui::EditTools", "Drag a rectangle to draw a box")},
    {"toolPolygon", QT_TRANSLATE_NOOP("rigidlab::ui::EditTools", "Polygon"),
     QT_TRANSLATE_NOOP("rigidlab::ui::EditTools",
                       "Click the vertices; double-click or Enter closes the polygon")},
    {"toolGround", QT_TRANSLATE_NOOP("rigidlab::ui::EditTools", "Ground"),
     QT_TRANSLATE_NOOP("rigidlab::ui::EditTools", "Drag a rectangle to draw static ground or a wall")},
    {"toolPin", QT_TRANSLATE_NOOP("rigidlab::ui::EditTools", "Pin"),
     QT_TRANSLATE_NOOP("rigidlab::ui::EditTools",
                       "Click a point of a body, then a second body or empty space for the world")},
    {"toolSpring", QT_TRANSLATE_NOOP("rigidlab::ui::EditTools", "Spring"),
     QT_TRANSLATE_NOOP("rigidlab::ui::EditTools",
                       "Drag from one point to another; its rest length is the length drawn")},
    {"toolDelete", QT_TRANSLATE_NOOP("rigidlab::ui::EditTools", "Delete"),
     QT_TRANSLATE_NOOP("rigidlab::ui::EditTools", "Click a body to delete it with its springs and pins")},
    {"toolDuplicate", QT_TRANSLATE_NOOP("rigidlab::ui::EditTools", "Duplicate"),
     QT_TRANSLATE_NOOP("rigidlab::ui::EditTools", "Click a body to place a copy beside it")},
}};
// clang-format on

/// The smallest of 1, 2, 5 times a power of ten that is at least `v`.
double roundStep(double v)
{
    const double decade = std::pow(10.0, std::floor(std::log10(v)));
    for (double m : {1.0, 2.0, 5.0, 10.0}) {
        if (m * decade >= v) {
            return m * decade;
        }
    }
    return 10.0 * decade;
}

/// The body's width along x [m], for placing a duplicate beside it.
double bodyWidth(const physics::BodyDef& def)
{
    return def.shape.visit(
        physics::Overloaded{[](const physics::Circle& c) { return 2.0 * c.radius; },
                            [&def](const physics::Polygon& p) {
                                const physics::Rotation q(def.angle);
                                double lo = 0.0;
                                double hi = 0.0;
                                for (const Vec2& v : p.vertices) {
                                    lo = std::min(lo, q.apply(v).x());
                                    hi = std::max(hi, q.apply(v).x());
                                }
                                return hi - lo;
                            }});
}

} // namespace

EditTools::EditTools(WorldView& view, SimulationController& simulation, SceneDocument& document,
                     QObject* parent)
    : QObject(parent), m_view(view), m_simulation(simulation), m_document(document)
{
    m_editAction = new QAction(tr("Edit"), this);
    m_editAction->setObjectName(QStringLiteral("editMode"));
    m_editAction->setCheckable(true);
    m_editAction->setShortcuts(controlKeys("editMode"));
    m_editAction->setToolTip(tr("Edit the scene: draw bodies, pins and springs (%1); leave to "
                                "run it")
                                 .arg(controlKeysText("editMode")));
    connect(m_editAction, &QAction::toggled, this, &EditTools::setEditing);

    m_toolGroup = new QActionGroup(this);
    m_toolGroup->setExclusive(true);
    for (size_t i = 0; i < kTools.size(); ++i) {
        const ToolInfo& info = kTools[i];
        auto* action = new QAction(tr(info.text), this);
        action->setObjectName(QLatin1String(info.name));
        action->setCheckable(true);
        action->setShortcuts(controlKeys(info.name));
        action->setToolTip(QStringLiteral("%1 (%2)").arg(tr(info.tip), controlKeysText(info.name)));
        action->setEnabled(false);
        m_toolGroup->addAction(action);
        const auto tool = static_cast<EditTool>(i);
        connect(action, &QAction::triggered, this, [this, tool] { setTool(tool); });
        m_toolActions[i] = action;
    }
    m_toolActions[0]->setChecked(true);

    m_snapAction = new QAction(this);
    m_snapAction->setObjectName(QStringLiteral("editSnap"));
    m_snapAction->setCheckable(true);
    m_snapAction->setChecked(true);
    m_snapAction->setShortcuts(controlKeys("editSnap"));
    m_snapAction->setEnabled(false);
    connect(m_snapAction, &QAction::toggled, this, [this] { refreshOverlay(); });
    updateSnapText();

    m_deleteSelection = new QAction(tr("Delete selected body"), this);
    m_deleteSelection->setObjectName(QStringLiteral("editDelete"));
    m_deleteSelection->setShortcuts(controlKeys("editDelete"));
    m_deleteSelection->setEnabled(false);
    connect(m_deleteSelection, &QAction::triggered, this, &EditTools::deleteSelected);

    m_overlay = new EditOverlay(*this);
    m_overlay->setZValue(20);
    m_overlay->setVisible(false);
    m_view.scene()->addItem(m_overlay);

    connect(&m_document, &SceneDocument::sceneChanged, this, [this] {
        if (m_editing && m_reloadsWorld) {
            reloadWorld();
        }
    });
    // A world loaded by someone else while editing (the window's own reload after an edit):
    // the view lost its selection with its items; it comes back.
    connect(&m_simulation, &SimulationController::sceneLoaded, this, [this] {
        if (!m_editing || m_reloading) {
            return;
        }
        if (m_selected >= static_cast<int>(m_document.scene().bodies.size())) {
            m_selected = -1;
        }
        if (m_selectedSpring >= static_cast<int>(m_document.scene().springs.size())) {
            m_selectedSpring = -1;
        }
        m_view.selectBody(m_selected);
        refreshOverlay();
    });
    // Run (Space) while editing leaves Edit mode and runs the scene as edited.
    connect(&m_simulation, &SimulationController::runningChanged, this, [this](bool running) {
        if (running && m_editing) {
            setEditing(false);
        }
    });
}

QList<QAction*> EditTools::actions() const
{
    QList<QAction*> list{m_editAction};
    for (QAction* a : m_toolActions) {
        list << a;
    }
    list << m_snapAction;
    return list;
}

double EditTools::gridStep() const
{
    const double zoom = m_view.zoom();
    return roundStep(kGridPixels / (zoom > 0 ? zoom : 1.0));
}

void EditTools::setEditing(bool on)
{
    if (on == m_editing) {
        return;
    }
    m_editing = on;
    m_editAction->setChecked(on);
    for (size_t i = 0; i < m_toolActions.size(); ++i) {
        m_toolActions[i]->setEnabled(on && !locked(static_cast<EditTool>(i)));
    }
    m_snapAction->setEnabled(on);
    m_deleteSelection->setEnabled(on);
    cancelGesture();
    m_overlay->setVisible(on);
    // The view holds still under the pen while the world is rebuilt after each edit.
    m_view.setFitOnRebuild(!on);
    if (on) {
        m_view.installEventFilter(this);
        m_view.viewport()->installEventFilter(this);
        m_simulation.setRunning(false);
        m_simulation.setStepsHeld(true); // Step, Back and the clock leave the scene alone
        reloadWorld();
        say(tr("Edit mode: the world is paused at its start; leave Edit mode or press Space to "
               "run it"));
    } else {
        m_view.removeEventFilter(this);
        m_view.viewport()->removeEventFilter(this);
        m_simulation.setStepsHeld(false);
        reloadWorld();
        m_selected = -1;
        say({});
        m_simulation.setRunning(true);
    }
    updateSnapText();
    emit editingChanged(on);
}

void EditTools::setAllowedTools(const std::optional<QStringList>& names)
{
    m_allowedTools = names;
    for (size_t i = 0; i < kTools.size(); ++i) {
        const auto tool = static_cast<EditTool>(i);
        QAction* action = m_toolActions[i];
        action->setEnabled(m_editing && !locked(tool));
        action->setToolTip(locked(tool)
                               ? tr("This lesson step locks the %1 tool").arg(tr(kTools[i].text))
                               : QStringLiteral("%1 (%2)").arg(tr(kTools[i].tip),
                                                               controlKeysText(kTools[i].name)));
    }
    if (locked(m_tool)) {
        for (size_t i = 0; i < kTools.size(); ++i) {
            if (!locked(static_cast<EditTool>(i))) {
                setTool(static_cast<EditTool>(i));
                break;
            }
        }
    }
}

bool EditTools::locked(EditTool tool) const
{
    const auto i = static_cast<size_t>(tool);
    static_assert(lessons::kEditorToolNames.size() == kTools.size());
    const std::string_view name = lessons::kEditorToolNames[i];
    return m_allowedTools && !m_allowedTools->contains(
                                 QLatin1String(name.data(), static_cast<qsizetype>(name.size())));
}

void EditTools::setAllowedProperties(const std::optional<QStringList>& names)
{
    if (names == m_allowedProperties) {
        return;
    }
    m_allowedProperties = names;
    emit propertyLocksChanged();
}

bool EditTools::propertyLocked(const QString& name) const
{
    return m_allowedProperties && !m_allowedProperties->contains(name);
}

QString EditTools::propertyLockedMessage(const QString& label)
{
    return tr("This lesson step locks the %1 property").arg(label);
}

void EditTools::setTool(EditTool tool)
{
    if (locked(tool)) {
        say(tr("This lesson step locks the %1 tool")
                .arg(tr(kTools[static_cast<size_t>(tool)].text)));
        m_toolActions[static_cast<size_t>(m_tool)]->setChecked(true);
        return;
    }
    cancelGesture();
    m_tool = tool;
    m_toolActions[static_cast<size_t>(tool)]->setChecked(true);
    say(tr(kTools[static_cast<size_t>(tool)].tip));
}

void EditTools::selectBody(int body)
{
    if (body >= static_cast<int>(m_document.scene().bodies.size())) {
        body = -1;
    }
    m_selected = body;
    if (body >= 0) {
        m_selectedSpring = -1;
    }
    m_view.selectBody(body);
    refreshOverlay();
    emit selectionChanged();
}

void EditTools::selectSpring(int spring)
{
    if (spring >= static_cast<int>(m_document.scene().springs.size())) {
        spring = -1;
    }
    m_selectedSpring = spring;
    if (spring >= 0) {
        m_selected = -1;
        m_view.selectBody(-1);
    }
    refreshOverlay();
    emit selectionChanged();
}

void EditTools::rotateSelected(double radians)
{
    if (m_selected < 0) {
        say(tr("Select a body to turn it"));
        return;
    }
    const auto& def = m_document.scene().bodies[static_cast<size_t>(m_selected)];
    const int mergeId = keyRunMergeId(KeyRun::Kind::Turn);
    apply(tr("Rotate %1").arg(QString::fromStdString(def.name)),
          edit::rotateBody(m_document.scene(), m_selected, def.angle + radians), mergeId);
    m_keyRun.index = m_document.undoStack()->index();
}

void EditTools::nudgeSelected(const Vec2& offset)
{
    if (m_selected < 0) {
        return;
    }
    const auto& def = m_document.scene().bodies[static_cast<size_t>(m_selected)];
    const int mergeId = keyRunMergeId(KeyRun::Kind::Nudge);
    apply(tr("Move %1").arg(QString::fromStdString(def.name)),
          edit::moveBody(m_document.scene(), m_selected, def.position + offset), mergeId);
    m_keyRun.index = m_document.undoStack()->index();
}

int EditTools::keyRunMergeId(KeyRun::Kind kind)
{
    const QUndoStack* undo = m_document.undoStack();
    const bool sameRun = m_keyRun.body == m_selected && m_keyRun.kind == kind &&
                         m_keyRun.index == undo->index() && undo->index() == undo->count();
    if (!sameRun) {
        m_keyRun = KeyRun{kind, m_selected, m_nextMergeId++, -1};
    }
    return m_keyRun.mergeId;
}

void EditTools::deleteSelected()
{
    if (m_selectedSpring >= 0) {
        const int spring = m_selectedSpring;
        m_selectedSpring = -1;
        const auto& def = m_document.scene().springs[static_cast<size_t>(spring)];
        apply(tr("Delete spring from %1 to %2")
                  .arg(bodyName(m_document.scene(), def.a), bodyName(m_document.scene(), def.b)),
              edit::deleteSpring(m_document.scene(), spring));
        selectSpring(-1);
        return;
    }
    if (m_selected < 0) {
        say(tr("Select a body to delete it"));
        return;
    }
    const int body = m_selected;
    const QString id =
        QString::fromStdString(m_document.scene().bodies[static_cast<size_t>(body)].name);
    m_selected = -1;
    apply(tr("Delete %1").arg(id), edit::deleteBody(m_document.scene(), body));
    selectBody(-1);
}

void EditTools::closePolygon()
{
    if (m_polygon.empty()) {
        return;
    }
    const std::vector<Vec2> points = m_polygon;
    m_polygon.clear();
    const auto result = edit::addPolygon(m_document.scene(), points);
    if (apply(tr("Add polygon %1").arg(bodyName(result.scene, result.body)), result)) {
        selectBody(result.body);
    }
    refreshOverlay();
}

bool EditTools::eventFilter(QObject* watched, QEvent* event)
{
    if (!m_editing) {
        return false;
    }
    if (watched == m_view.viewport()) {
        switch (event->type()) {
        case QEvent::MouseButtonPress:
            return mousePress(static_cast<QMouseEvent*>(event));
        case QEvent::MouseButtonDblClick:
            if (auto* mouse = static_cast<QMouseEvent*>(event);
                m_tool == EditTool::Polygon && mouse->button() == Qt::LeftButton) {
                // The double-click's point, unless its first click placed it already.
                const Vec2 p = snapped(m_view.worldAt(mouse->position().toPoint()));
                if (m_polygon.empty() || m_polygon.back() != p) {
                    m_polygon.push_back(p);
                }
                closePolygon();
                return true;
            }
            return mousePress(static_cast<QMouseEvent*>(event));
        case QEvent::MouseMove:
            return mouseMove(static_cast<QMouseEvent*>(event));
        case QEvent::MouseButtonRelease:
            return mouseRelease(static_cast<QMouseEvent*>(event));
        default:
            return false;
        }
    }
    if (watched == &m_view) {
        if (event->type() == QEvent::ShortcutOverride && wantsKey(static_cast<QKeyEvent*>(event))) {
            event->accept(); // the key comes as a key press, not as the window's shortcut
            return true;
        }
        if (event->type() == QEvent::KeyPress) {
            return keyPress(static_cast<QKeyEvent*>(event));
        }
    }
    return false;
}

bool EditTools::wantsKey(const QKeyEvent* event) const
{
    if (event->modifiers() & (Qt::ControlModifier | Qt::AltModifier | Qt::MetaModifier)) {
        return false;
    }
    switch (event->key()) {
    case Qt::Key_Left:
    case Qt::Key_Right:
    case Qt::Key_Up:
    case Qt::Key_Down:
    case Qt::Key_Q:
    case Qt::Key_E:
        return m_selected >= 0;
    case Qt::Key_Delete:
        return m_selected >= 0 || m_selectedSpring >= 0;
    case Qt::Key_Return:
    case Qt::Key_Enter:
    case Qt::Key_Escape:
    case Qt::Key_Backspace:
        return !m_polygon.empty() || m_drag.active || m_pinStart.has_value();
    default:
        return false;
    }
}

bool EditTools::keyPress(QKeyEvent* event)
{
    // A locked tool's key (its action is disabled, so no shortcut takes it): said, not ignored.
    const QKeySequence pressed(event->keyCombination());
    for (size_t i = 0; i < kTools.size(); ++i) {
        if (locked(static_cast<EditTool>(i)) && m_toolActions[i]->shortcuts().contains(pressed)) {
            setTool(static_cast<EditTool>(i));
            return true;
        }
    }
    if (!wantsKey(event)) {
        return false;
    }
    // One grid step, or a tenth of one with Shift (or with the grid off).
    const double step =
        gridStep() *
        ((event->modifiers() & Qt::ShiftModifier) || !m_snapAction->isChecked() ? 0.1 : 1.0);
    switch (event->key()) {
    case Qt::Key_Left:
        nudgeSelected(Vec2(-step, 0.0));
        break;
    case Qt::Key_Right:
        nudgeSelected(Vec2(step, 0.0));
        break;
    case Qt::Key_Up:
        nudgeSelected(Vec2(0.0, step));
        break;
    case Qt::Key_Down:
        nudgeSelected(Vec2(0.0, -step));
        break;
    case Qt::Key_Q:
        rotateSelected(kTurnStep);
        break;
    case Qt::Key_E:
        rotateSelected(-kTurnStep);
        break;
    case Qt::Key_Return:
    case Qt::Key_Enter:
        closePolygon();
        break;
    case Qt::Key_Delete:
        deleteSelected();
        break;
    case Qt::Key_Backspace:
        if (!m_polygon.empty()) {
            m_polygon.pop_back();
            refreshOverlay();
        }
        break;
    case Qt::Key_Escape:
        cancelGesture();
        say({});
        break;
    default:
        return false;
    }
    return true;
}

bool EditTools::mousePress(QMouseEvent* event)
{
    if (event->button() != Qt::LeftButton) {
        return false; // the middle button pans, as outside Edit mode
    }
    m_view.setFocus(Qt::MouseFocusReason);
    const Vec2 raw = m_view.worldAt(event->position().toPoint());
    const Vec2 p = snapped(raw);
    const lessons::Scene& scene = m_document.scene();
    m_drag = Drag{};
    m_drag.start = p;
    m_drag.current = p;
    switch (m_tool) {
    case EditTool::Select:
    case EditTool::Rotate: {
        if (m_tool == EditTool::Select && pressVelocityHandle(raw)) {
            return true;
        }
        const int body =
            bodyAt(raw) >= 0 ? bodyAt(raw) : (m_tool == EditTool::Rotate ? m_selected : -1);
        if (body < 0) {
            selectBody(-1);
            if (const int spring = springAt(raw); spring >= 0 && m_tool == EditTool::Select) {
                selectSpring(spring);
                return true;
            }
            selectSpring(-1);
            return false; // empty space pans
        }
        selectBody(body);
        const auto& def = scene.bodies[static_cast<size_t>(body)];
        m_drag.active = true;
        m_drag.body = body;
        m_drag.grabOffset = def.position - raw;
        m_drag.startAngle = def.angle;
        m_drag.pointerAngle = std::atan2(raw.y() - def.position.y(), raw.x() - def.position.x());
        m_drag.mergeId = m_nextMergeId++;
        return true;
    }
    case EditTool::Circle:
    case EditTool::Box:
    case EditTool::Ground:
        m_drag.active = true;
        refreshOverlay();
        return true;
    case EditTool::Spring:
        m_drag.active = true;
        m_drag.bodyA = bodyAtOrSnapped(raw);
        refreshOverlay();
        return true;
    case EditTool::Polygon:
        m_polygon.push_back(p);
        if (const auto preview = edit::previewPolygon(m_polygon); !preview.warning.isEmpty()) {
            say(tr("Not convex: it will be replaced by the convex hull shown"));
        } else {
            say(tr("%n point(s); double-click or Enter closes the polygon, Escape drops it", "",
                   static_cast<int>(m_polygon.size())));
        }
        refreshOverlay();
        return true;
    case EditTool::Pin: {
        const int body = bodyAtOrSnapped(raw);
        if (!m_pinStart) {
            if (body < 0) {
                say(tr("Click a point of a body to pin it"));
                return true;
            }
            m_pinStart = std::pair{body, p};
            selectBody(body);
            say(tr("Now click a second body, or empty space to pin it to the world"));
            refreshOverlay();
            return true;
        }
        const auto [first, point] = *m_pinStart;
        m_pinStart.reset();
        apply(body < 0 ? tr("Pin %1 to the world").arg(bodyName(scene, first))
                       : tr("Pin %1 to %2").arg(bodyName(scene, first), bodyName(scene, body)),
              edit::addPin(scene, first, body, point));
        refreshOverlay();
        return true;
    }
    case EditTool::Delete: {
        const int body = bodyAt(raw);
        if (body >= 0) {
            selectBody(body);
            deleteSelected();
        }
        return true;
    }
    case EditTool::Duplicate: {
        const int body = bodyAt(raw);
        if (body >= 0) {
            const auto& def = scene.bodies[static_cast<size_t>(body)];
            const double width = bodyWidth(def);
            const double offset =
                m_snapAction->isChecked() ? std::ceil(width / gridStep()) * gridStep() : width;
            const auto result = edit::duplicateBody(scene, body, Vec2(offset, 0.0));
            if (apply(
                    tr("Duplicate %1 as %2")
                        .arg(QString::fromStdString(def.name), bodyName(result.scene, result.body)),
                    result)) {
                selectBody(result.body);
            }
        }
        return true;
    }
    }
    return false;
}

bool EditTools::mouseMove(QMouseEvent* event)
{
    const Vec2 raw = m_view.worldAt(event->position().toPoint());
    updateSnapText();
    m_pointer = snapped(raw, m_drag.active ? m_drag.body : -1);
    const bool hadMarker = m_bodySnap.has_value();
    updateSnapMarker(raw);
    if (!m_drag.active) {
        // Repainted for a gesture under way, or for a snap marker that shows, moves or goes;
        // a pointer crossing empty space repaints nothing.
        if (!m_polygon.empty() || m_pinStart || hadMarker || m_bodySnap) {
            refreshOverlay();
        }
        return false;
    }
    m_drag.current = m_pointer;
    m_drag.moved = true;
    if (m_drag.velocity) {
        dragVelocity(raw);
        return true;
    }
    const lessons::Scene& scene = m_document.scene();
    switch (m_tool) {
    case EditTool::Select: {
        const Vec2 target = movedBodyTarget(m_drag, raw);
        const auto& def = scene.bodies[static_cast<size_t>(m_drag.body)];
        if (apply(tr("Move %1").arg(QString::fromStdString(def.name)),
                  edit::moveBody(scene, m_drag.body, target), m_drag.mergeId)) {
            say(tr("%1 at (%2; %3) m")
                    .arg(QString::fromStdString(def.name), metres(target.x()), metres(target.y())));
        }
        return true;
    }
    case EditTool::Rotate: {
        const auto& def = scene.bodies[static_cast<size_t>(m_drag.body)];
        const double pointer = std::atan2(raw.y() - def.position.y(), raw.x() - def.position.x());
        double angle = m_drag.startAngle + (pointer - m_drag.pointerAngle);
        if (m_snapAction->isChecked()) {
            angle = std::round(angle / kAngleSnap) * kAngleSnap;
        }
        if (apply(tr("Rotate %1").arg(QString::fromStdString(def.name)),
                  edit::rotateBody(scene, m_drag.body, angle), m_drag.mergeId)) {
            say(tr("%1 at %2°")
                    .arg(QString::fromStdString(def.name),
                         formatNumber(angle * 180.0 / std::numbers::pi, 4)));
        }
        return true;
    }
    case EditTool::Circle:
        say(tr("Circle: centre (%1; %2) m, radius %3 m")
                .arg(metres(m_drag.start.x()), metres(m_drag.start.y()),
                     metres((m_drag.current - m_drag.start).norm())));
        break;
    case EditTool::Box:
    case EditTool::Ground: {
        const Vec2 size = (m_drag.current - m_drag.start).cwiseAbs();
        say(tr("%1 × %2 m").arg(metres(size.x()), metres(size.y())));
        break;
    }
    case EditTool::Spring:
        say(tr("Spring: length %1 m").arg(metres((m_drag.current - m_drag.start).norm())));
        break;
    default:
        break;
    }
    refreshOverlay();
    return true;
}

bool EditTools::mouseRelease(QMouseEvent* event)
{
    if (event->button() != Qt::LeftButton || !m_drag.active) {
        return false;
    }
    const Vec2 raw = m_view.worldAt(event->position().toPoint());
    const Drag drag = m_drag;
    m_drag = Drag{};
    const lessons::Scene& scene = m_document.scene();
    Vec2 end = snapped(raw);
    if (m_snapAction->isChecked() && (m_tool == EditTool::Box || m_tool == EditTool::Ground)) {
        // A thin box whose two edges snap to one grid line keeps one grid step across, the way
        // it was dragged, instead of being refused as flat (a ramp drawn on a 1 m grid).
        for (int k = 0; k < 2; ++k) {
            if (end[k] == drag.start[k] && raw[k] != drag.start[k]) {
                end[k] = drag.start[k] + (raw[k] > drag.start[k] ? gridStep() : -gridStep());
            }
        }
    }
    const Vec2 centre = 0.5 * (drag.start + end);
    const Vec2 size = (end - drag.start).cwiseAbs();
    edit::EditResult result;
    QString what;
    switch (m_tool) {
    case EditTool::Circle:
        what = tr("Add circle %1");
        result = edit::addCircle(scene, drag.start, (end - drag.start).norm());
        break;
    case EditTool::Box:
        what = tr("Add box %1");
        result = edit::addBox(scene, centre, size.x(), size.y());
        break;
    case EditTool::Ground:
        what = tr("Add ground %1");
        result = edit::addGround(scene, centre, size.x(), size.y());
        break;
    case EditTool::Spring:
        what = tr("Add spring from %1 to %2");
        result = edit::addSpring(scene, drag.bodyA, drag.start, bodyAtOrSnapped(raw), end,
                                 kSpringStiffness);
        if (result.ok) {
            const auto& spring = result.scene.springs.back();
            what = what.arg(bodyName(scene, spring.a), bodyName(scene, spring.b));
        }
        break;
    default:
        m_bodySnap.reset(); // the body is set down
        refreshOverlay();
        return true; // a move or a turn is applied as it goes
    }
    if (result.ok && m_tool != EditTool::Spring) {
        what = what.arg(bodyName(result.scene, result.body));
    }
    if (apply(what, result) && m_tool != EditTool::Spring) {
        selectBody(result.body);
    }
    refreshOverlay();
    return true;
}

int EditTools::bodyAt(const Vec2& p) const
{
    const auto& bodies = m_document.scene().bodies;
    for (int i = static_cast<int>(bodies.size()) - 1; i >= 0; --i) {
        const auto& def = bodies[static_cast<size_t>(i)];
        const Vec2 local = physics::Transform(def.position, def.angle).applyInverse(p);
        const bool inside = def.shape.visit(physics::Overloaded{
            [&](const physics::Circle& c) { return (local - c.center).norm() <= c.radius; },
            [&](const physics::Polygon& poly) {
                for (size_t k = 0; k < poly.vertices.size(); ++k) {
                    if (poly.normals[k].dot(local - poly.vertices[k]) > 0) {
                        return false;
                    }
                }
                return true;
            }});
        if (inside) {
            return i;
        }
    }
    return -1;
}

int EditTools::springAt(const Vec2& p) const
{
    const lessons::Scene& scene = m_document.scene();
    const double reach = kVertexSnapPixels / std::max(m_view.zoom(), 1e-9);
    const auto end = [&scene](physics::BodyId body, const Vec2& anchor) {
        if (body == physics::kWorld) {
            return anchor;
        }
        const auto& def = scene.bodies[static_cast<size_t>(body)];
        return physics::Transform(def.position, def.angle).apply(anchor);
    };
    for (int i = static_cast<int>(scene.springs.size()) - 1; i >= 0; --i) {
        const auto& s = scene.springs[static_cast<size_t>(i)];
        const Vec2 a = end(s.a, s.anchorA);
        const Vec2 b = end(s.b, s.anchorB);
        const Vec2 ab = b - a;
        const double t =
            ab.squaredNorm() > 0 ? std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0) : 0.0;
        if ((a + t * ab - p).norm() <= reach) {
            return i;
        }
    }
    return -1;
}

Vec2 EditTools::snapToGrid(const Vec2& p) const
{
    const double step = gridStep();
    return Vec2(std::round(p.x() / step) * step, std::round(p.y() / step) * step);
}

Vec2 EditTools::snapped(const Vec2& p, int except) const
{
    if (!m_snapAction->isChecked()) {
        return p;
    }
    // Another body's vertex, centre or edge first: a ball's centre exactly on a corner or on
    // a ramp's surface.
    if (const auto snap = featureSnap(p, except)) {
        return snap->point;
    }
    return snapToGrid(p);
}

std::optional<Snap> EditTools::featureSnap(const Vec2& p, int except) const
{
    if (!m_snapAction->isChecked()) {
        return std::nullopt;
    }
    const double reach = kVertexSnapPixels / std::max(m_view.zoom(), 1e-9);
    return snapToBodies(m_document.scene(), p, reach, except);
}

int EditTools::bodyAtOrSnapped(const Vec2& raw) const
{
    if (const int body = bodyAt(raw); body >= 0) {
        return body;
    }
    const auto snap = featureSnap(raw);
    return snap ? snap->body : -1;
}

Vec2 EditTools::movedBodyTarget(const Drag& drag, const Vec2& raw)
{
    const Vec2 free = raw + drag.grabOffset;
    m_bodySnap.reset();
    if (!m_snapAction->isChecked()) {
        return free;
    }
    const double reach = kVertexSnapPixels / std::max(m_view.zoom(), 1e-9);
    if (const auto snap = snapMovedBody(m_document.scene(), drag.body, free, raw, reach)) {
        m_bodySnap = snap->target;
        return snap->position;
    }
    return snapToGrid(free);
}

void EditTools::updateSnapMarker(const Vec2& raw)
{
    switch (m_tool) {
    case EditTool::Circle:
    case EditTool::Box:
    case EditTool::Polygon:
    case EditTool::Ground:
    case EditTool::Pin:
    case EditTool::Spring:
        m_bodySnap = featureSnap(raw);
        break;
    case EditTool::Select:
        if (!m_drag.active) {
            m_bodySnap.reset(); // a drag sets it as the body moves
        }
        break;
    default:
        m_bodySnap.reset();
        break;
    }
}

bool EditTools::apply(const QString& what, const edit::EditResult& result, int mergeId)
{
    if (!result.ok) {
        say(result.error);
        return false;
    }
    m_document.apply(what, result.scene, mergeId);
    QStringList words;
    if (!result.warning.isEmpty()) {
        words << result.warning;
    }
    if (const QString overlap = edit::overlapMessage(m_document.scene()); !overlap.isEmpty()) {
        words << overlap;
    }
    say(words.join(QStringLiteral("; ")));
    return true;
}

QString EditTools::bodyName(const lessons::Scene& scene, int body)
{
    if (body < 0 || static_cast<size_t>(body) >= scene.bodies.size()) {
        return tr("the world");
    }
    return QString::fromStdString(scene.bodies[static_cast<size_t>(body)].name);
}

void EditTools::say(const QString& text)
{
    m_lastMessage = text;
    emit message(text);
}

QString EditTools::metres(double v) const
{
    // Round to a hundredth of the grid step, so that snapped values read as typed.
    const double step = gridStep() / 100.0;
    return formatNumber(std::round(v / step) * step, 6);
}

void EditTools::reloadWorld()
{
    const int selected = m_selected;
    m_reloading = true;
    m_simulation.loadScene(m_document.scene(), m_document.path());
    m_reloading = false;
    if (selected >= 0 && selected < static_cast<int>(m_document.scene().bodies.size())) {
        m_selected = selected;
        m_view.selectBody(selected);
    } else {
        m_selected = -1;
    }
    if (m_selectedSpring >= static_cast<int>(m_document.scene().springs.size())) {
        m_selectedSpring = -1;
    }
    refreshOverlay();
}

void EditTools::updateSnapText()
{
    const QString text = tr("Grid %1 m").arg(formatNumber(gridStep(), 6));
    if (m_snapAction->text() != text) {
        m_snapAction->setText(text);
        m_snapAction->setToolTip(
            tr("Snap to a grid of %1 m and to other bodies' corners and edges (%2)")
                .arg(formatNumber(gridStep(), 6), controlKeysText("editSnap")));
    }
}

void EditTools::refreshOverlay()
{
    m_overlay->update();
}

void EditTools::cancelGesture()
{
    m_drag = Drag{};
    m_bodySnap.reset();
    m_polygon.clear();
    m_pinStart.reset();
    if (m_overlay) {
        refreshOverlay();
    }
}

} // namespace rigidlab::ui
