// SPDX-License-Identifier: GPL-3.0-or-later
#include "editor/edit_tools.h"

#include "editor/edit_overlay.h"
#include "editor/scene_document.h"
#include "editor/tools/all_tools.h"

#include "common/shortcuts.h"
#include "edit/scene_edits.h"
#include "format/editor_tools.h"
#include "panels/number_field.h"
#include "simulation/simulation_controller.h"
#include "view/world_view.h"

#include <QAction>
#include <QActionGroup>
#include <QGraphicsScene>
#include <QUndoStack>

#include <cmath>

namespace rigidlab::ui {

using physics::Vec2;
namespace edit = lessons::edit;

namespace {

/// Q and E turn by this much, as they do outside Edit mode [rad].
constexpr double kTurnStep = 5.0 * std::numbers::pi / 180.0;

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

} // namespace

EditTools::EditTools(WorldView& view, SimulationController& simulation, SceneDocument& document,
                     QObject* parent)
    : QObject(parent), m_view(view), m_simulation(simulation), m_document(document)
{
    for (size_t i = 0; i < m_tools.size(); ++i) {
        m_tools[i] = makeTool(static_cast<EditTool>(i), *this);
    }
    createActions();

    m_overlay = new EditOverlay(*this);
    m_overlay->setZValue(20);
    m_overlay->setVisible(false);
    m_view.scene()->addItem(m_overlay);
    followSimulation();
}

EditTools::~EditTools() = default;

void EditTools::createActions()
{
    m_editAction = new QAction(tr("Edit"), this);
    m_editAction->setObjectName(QStringLiteral("editMode"));
    m_editAction->setCheckable(true);
    m_editAction->setShortcuts(controlKeys("editMode"));
    m_editAction->setToolTip(tr("Edit the scene: draw bodies, pins and springs (%1); leaving it "
                                "keeps the world paused at its start")
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
}

void EditTools::followSimulation()
{
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
    // Run (Space) while editing leaves Edit mode and runs the scene as edited (leaving Edit
    // mode reloads the world, which pauses it).
    connect(&m_simulation, &SimulationController::runningChanged, this, [this](bool running) {
        if (running && m_editing) {
            setEditing(false);
            m_simulation.setRunning(true);
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
    // The view holds still under the pen while the world is rebuilt after each edit, and as
    // Edit mode is left: the class sees the scene as it was drawn (a long floor would make a
    // view fitted to it small).
    m_view.setFitOnRebuild(false);
    if (on) {
        m_view.installEventFilter(this);
        m_view.viewport()->installEventFilter(this);
        m_simulation.setRunning(false);
        m_simulation.setStepsHeld(true); // Step, Back and the clock leave the scene alone
        reloadWorld();
        say(tr("Edit mode: the world is paused at its start; press Space to run it"));
    } else {
        m_view.removeEventFilter(this);
        m_view.viewport()->removeEventFilter(this);
        m_simulation.setStepsHeld(false);
        reloadWorld(); // paused at the start of the scene as edited: the class predicts first
        m_view.setFitOnRebuild(true);
        m_selected = -1;
        say({});
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
    say(current().status());
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

void EditTools::selectNextBody()
{
    const int count = static_cast<int>(m_document.scene().bodies.size());
    if (count == 0) {
        say(tr("The scene has no body to select"));
        return;
    }
    selectBody((m_selected + 1) % count);
    say(tr("%1 selected").arg(bodyName(m_document.scene(), m_selected)));
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
    apply(tr("Rotate %1").arg(bodyName(m_document.scene(), m_selected)),
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
    apply(tr("Move %1").arg(bodyName(m_document.scene(), m_selected)),
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
    const QString name = bodyName(m_document.scene(), body);
    m_selected = -1;
    apply(tr("Delete %1").arg(name), edit::deleteBody(m_document.scene(), body));
    selectBody(-1);
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
    return scene.bodyLabel(body);
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
    for (const auto& tool : m_tools) {
        tool->cancel();
    }
    m_bodySnap.reset();
    if (m_overlay) {
        refreshOverlay();
    }
}

} // namespace rigidlab::ui
