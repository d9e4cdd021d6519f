// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The window's controls in one table: every keyboard shortcut the window registers and every
// mouse action of the world view. MainWindow takes its actions' keys from here and Help ›
// Controls is generated from here, so that the help cannot drift from what the keys do.
// (The overlay keys V C B M T J live beside their overlays' names in window_names.h;
// the window passes them to controlsHelpHtml as extra rows.)

#include <QKeySequence>
#include <QList>
#include <QString>

#include <array>
#include <string_view>

namespace rigidlab::ui {

/// One row of Help › Controls. A keyboard row names its action and its keys; a mouse row has
/// no keys and names its gesture instead.
struct ControlInfo {
    std::string_view action; ///< the action's objectName, empty for a mouse row
    const char* keys;        ///< QKeySequence::PortableText, several separated by "; "
    const char* gesture;     ///< what the mouse does (translated, context "Controls")
    const char* description; ///< what happens (translated, context "Controls")
};

// clang-format off
inline constexpr std::array kControls{
    ControlInfo{"play", "Space", nullptr,
                QT_TRANSLATE_NOOP("Controls", "Play or pause the simulation")},
    ControlInfo{"step", "S; Right", nullptr,
                QT_TRANSLATE_NOOP("Controls", "One step forward (pauses)")},
    ControlInfo{"back", "Left; Backspace", nullptr,
                QT_TRANSLATE_NOOP("Controls", "One step back in time")},
    ControlInfo{"reset", "R", nullptr,
                QT_TRANSLATE_NOOP("Controls", "Back to the start of the scene")},
    ControlInfo{"nextStep", "Alt+Right; Ctrl+PgDown", nullptr,
                QT_TRANSLATE_NOOP("Controls", "The lesson's next step")},
    ControlInfo{"previousStep", "Alt+Left; Ctrl+PgUp", nullptr,
                QT_TRANSLATE_NOOP("Controls", "The lesson's previous step")},
    ControlInfo{"focusScene", "F6", nullptr,
                QT_TRANSLATE_NOOP("Controls", "Put the keyboard focus on the scene")},
    ControlInfo{"focusToolbar", "F10", nullptr,
                QT_TRANSLATE_NOOP("Controls", "Put the keyboard focus on the toolbar: arrows move "
                                              "between its buttons, Space or Enter presses one, "
                                              "Esc goes back")},
    ControlInfo{"selectNextBody", "]", nullptr,
                QT_TRANSLATE_NOOP("Controls", "Select the next body (in the scene: arrows move "
                                              "it, Shift+arrows change its velocity, Enter shows "
                                              "its numbers, Esc lets it go)")},
    ControlInfo{"selectPreviousBody", "[", nullptr,
                QT_TRANSLATE_NOOP("Controls", "Select the previous body")},
    ControlInfo{"singleKeys", "Ctrl+Shift+K", nullptr,
                QT_TRANSLATE_NOOP("Controls", "Single-key shortcuts (letters, Space, arrows) on "
                                              "or off")},
    ControlInfo{"fit", "F", nullptr,
                QT_TRANSLATE_NOOP("Controls", "Zoom to show every body")},
    ControlInfo{"turnLeft", "Q", nullptr,
                QT_TRANSLATE_NOOP("Controls", "Turn the selected body left by 5°")},
    ControlInfo{"turnRight", "E", nullptr,
                QT_TRANSLATE_NOOP("Controls", "Turn the selected body right by 5°")},
    ControlInfo{"instruments", "Ctrl+Shift+I", nullptr,
                QT_TRANSLATE_NOOP("Controls", "Instruments on the scene: ruler, protractor, "
                                              "stopwatch, probe, frame of reference")},
    ControlInfo{"graphOfBodies", "Ctrl+Shift+G", nullptr,
                QT_TRANSLATE_NOOP("Controls", "A graph of chosen bodies' quantities against "
                                              "time")},
    ControlInfo{"presentation", "F11", nullptr,
                QT_TRANSLATE_NOOP("Controls", "Presentation mode: full screen, large type and "
                                              "thick lines for a projector")},
    // Edit mode. The tools' keys work only in Edit mode, where they must not be
    // one of the keys above (S R F Q E ...) nor an overlay's (V C B M T J). In Edit mode the
    // arrows nudge and Q, E turn the selected body in the scene, not in the running world.
    ControlInfo{"editMode", "Ctrl+E", nullptr,
                QT_TRANSLATE_NOOP("Controls", "Edit mode on or off: draw the scene; leaving it "
                                              "loads the scene as edited, paused")},
    ControlInfo{"toolSelect", "A", nullptr,
                QT_TRANSLATE_NOOP("Controls", "Edit: select and move bodies (arrows nudge)")},
    ControlInfo{"toolRotate", "W", nullptr,
                QT_TRANSLATE_NOOP("Controls", "Edit: turn a body by dragging (Q, E by 5°)")},
    ControlInfo{"toolCircle", "O", nullptr,
                QT_TRANSLATE_NOOP("Controls", "Edit: draw a circle from its centre")},
    ControlInfo{"toolBox", "X", nullptr,
                QT_TRANSLATE_NOOP("Controls", "Edit: draw a box")},
    ControlInfo{"toolPolygon", "P", nullptr,
                QT_TRANSLATE_NOOP("Controls", "Edit: draw a polygon (Enter closes it)")},
    ControlInfo{"toolGround", "G", nullptr,
                QT_TRANSLATE_NOOP("Controls", "Edit: draw static ground or a wall")},
    ControlInfo{"toolPin", "N", nullptr,
                QT_TRANSLATE_NOOP("Controls", "Edit: pin a body to another or to the world")},
    ControlInfo{"toolSpring", "Z", nullptr,
                QT_TRANSLATE_NOOP("Controls", "Edit: draw a spring")},
    ControlInfo{"toolDelete", "D", nullptr,
                QT_TRANSLATE_NOOP("Controls", "Edit: click bodies to delete them")},
    ControlInfo{"toolDuplicate", "U", nullptr,
                QT_TRANSLATE_NOOP("Controls", "Edit: click bodies to duplicate them")},
    ControlInfo{"editSnap", "Ctrl+G", nullptr,
                QT_TRANSLATE_NOOP("Controls", "Edit: snap to the grid and to corners, on or off")},
    ControlInfo{"editDelete", "Del", nullptr,
                QT_TRANSLATE_NOOP("Controls", "Edit: delete the selected body")},
    ControlInfo{"editAddBody", "Ins", nullptr,
                QT_TRANSLATE_NOOP("Controls", "Edit: add a circle, a box, a polygon or ground at "
                                              "the view's centre (a menu)")},
    ControlInfo{"editZoom", "+; -", nullptr,
                QT_TRANSLATE_NOOP("Controls", "Edit: zoom in or out about the middle of the view")},
    ControlInfo{"editZoomFit", "0", nullptr,
                QT_TRANSLATE_NOOP("Controls", "Edit: zoom to show every body")},
    ControlInfo{"editPan", "Ctrl+Left; Ctrl+Right; Ctrl+Up; Ctrl+Down", nullptr,
                QT_TRANSLATE_NOOP("Controls", "Edit: pan the view")},
    ControlInfo{"undo", "Ctrl+Z", nullptr,
                QT_TRANSLATE_NOOP("Controls", "Undo the last edit of the scene")},
    ControlInfo{"redo", "Ctrl+Shift+Z", nullptr,
                QT_TRANSLATE_NOOP("Controls", "Redo the edit undone last")},
    ControlInfo{"newScene", "Ctrl+N", nullptr,
                QT_TRANSLATE_NOOP("Controls", "A new, empty scene")},
    ControlInfo{"openScene", "Ctrl+O", nullptr,
                QT_TRANSLATE_NOOP("Controls", "Open a scene")},
    ControlInfo{"saveScene", "Ctrl+S", nullptr,
                QT_TRANSLATE_NOOP("Controls", "Save the scene")},
    ControlInfo{"saveSceneAs", "Ctrl+Shift+S", nullptr,
                QT_TRANSLATE_NOOP("Controls", "Save the scene under another name")},
    ControlInfo{"openLesson", "Ctrl+L", nullptr,
                QT_TRANSLATE_NOOP("Controls", "Open a lesson")},
    ControlInfo{"backToLessonEditor", "Ctrl+Shift+L", nullptr,
                QT_TRANSLATE_NOOP("Controls", "Back to the lesson editor, at the step the student "
                                              "is on (while trying a lesson from it)")},
    ControlInfo{"importMeasurement", "Ctrl+I", nullptr,
                QT_TRANSLATE_NOOP("Controls", "Import a measurement (CSV) to compare and fit")},
    ControlInfo{"handIn", "Ctrl+H", nullptr,
                QT_TRANSLATE_NOOP("Controls", "Hand in the lesson's worksheet (PDF)")},
    ControlInfo{"quit", "Ctrl+Q", nullptr,
                QT_TRANSLATE_NOOP("Controls", "Quit RigidLab")},
    ControlInfo{"help", "F1", nullptr,
                QT_TRANSLATE_NOOP("Controls", "Help: this list of keys and mouse actions")},
    ControlInfo{{}, nullptr, QT_TRANSLATE_NOOP("Controls", "Click a body"),
                QT_TRANSLATE_NOOP("Controls", "Select it and show it in the inspector")},
    ControlInfo{{}, nullptr, QT_TRANSLATE_NOOP("Controls", "Drag a body"),
                QT_TRANSLATE_NOOP("Controls", "Pull it with a spring; release to throw it")},
    ControlInfo{{}, nullptr, QT_TRANSLATE_NOOP("Controls", "Drag empty space or the middle button"),
                QT_TRANSLATE_NOOP("Controls", "Pan the view")},
    ControlInfo{{}, nullptr, QT_TRANSLATE_NOOP("Controls", "Mouse wheel"),
                QT_TRANSLATE_NOOP("Controls", "Zoom about the pointer")},
    ControlInfo{{}, nullptr, QT_TRANSLATE_NOOP("Controls", "Drop a CSV file on the window"),
                QT_TRANSLATE_NOOP("Controls", "Import it as a measurement")},
    ControlInfo{{}, nullptr, QT_TRANSLATE_NOOP("Controls", "Drag the timeline"),
                QT_TRANSLATE_NOOP("Controls", "Go back to any earlier moment of the run")},
};
// clang-format on

/// The keys of the action named `action` in kControls (empty if it has none).
QList<QKeySequence> controlKeys(std::string_view action);

/// The same keys as text for a tooltip ("S or Right"), as the platform writes them.
QString controlKeysText(std::string_view action);

/// A row added to the help from elsewhere (the overlays' keys).
struct ControlHelpRow {
    QList<QKeySequence> keys;
    QString description;
};

/// Help › Controls as an HTML table: the keyboard rows of kControls, then `extra`, then the
/// mouse rows. Keys are shown as the platform writes them (QKeySequence::NativeText).
QString controlsHelpHtml(const QList<ControlHelpRow>& extra);

} // namespace rigidlab::ui
