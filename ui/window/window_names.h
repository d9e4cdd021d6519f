// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The window's one table of names for its overlays and standard plots: what the menus and the
// toolbar say, the key the settings file keeps, the name a lesson step uses (the lesson
// format's lists, lessons/format/lesson.h) and the key that toggles it. Every part of
// the window that names an overlay or a plot reads it from here. (The docks' names, and their
// entries in View › Panels: common/dock_names.h.)

#include "common/step_part_names.h"
#include "view/overlays.h"

#include "format/lesson.h"

#include <QCoreApplication>
#include <QLatin1String>
#include <QString>
#include <QtGlobal>

#include <array>
#include <cstddef>
#include <string_view>

namespace rigidlab::ui {

/// A name from the tables below in the window's language (their translation context is the
/// window's, where they were first written).
inline QString windowNameText(const char* text)
{
    return QCoreApplication::translate("rigidlab::ui::MainWindow", text);
}

struct OverlayNames {
    Overlay overlay;
    const char* text; ///< the View menu's entry, for tr() in context "rigidlab::ui::MainWindow"
    const char* shortText;  ///< on the toolbar, likewise
    const char* settingKey; ///< under "overlays/" in the settings file
    const char* shortcut;
};

/// In the order of `Overlay`: kOverlayNames[static_cast<size_t>(o)].overlay == o.
inline constexpr std::array<OverlayNames, kOverlayCount> kOverlayNames{{
    {Overlay::Velocities, QT_TRANSLATE_NOOP("rigidlab::ui::MainWindow", "&Velocity vectors"),
     QT_TRANSLATE_NOOP("rigidlab::ui::MainWindow", "Velocities"), "velocities", "V"},
    {Overlay::Contacts,
     QT_TRANSLATE_NOOP("rigidlab::ui::MainWindow", "&Contact points and normals"),
     QT_TRANSLATE_NOOP("rigidlab::ui::MainWindow", "Contacts"), "contacts", "C"},
    {Overlay::BoundingBoxes, QT_TRANSLATE_NOOP("rigidlab::ui::MainWindow", "&Bounding boxes"),
     QT_TRANSLATE_NOOP("rigidlab::ui::MainWindow", "Boxes"), "boxes", "B"},
    {Overlay::CentresOfMass, QT_TRANSLATE_NOOP("rigidlab::ui::MainWindow", "Centres of &mass"),
     QT_TRANSLATE_NOOP("rigidlab::ui::MainWindow", "Centres"), "com", "M"},
    {Overlay::Trails, QT_TRANSLATE_NOOP("rigidlab::ui::MainWindow", "Motion &trails"),
     QT_TRANSLATE_NOOP("rigidlab::ui::MainWindow", "Trails"), "trails", "T"},
    {Overlay::SpringsJoints, QT_TRANSLATE_NOOP("rigidlab::ui::MainWindow", "&Springs and joints"),
     QT_TRANSLATE_NOOP("rigidlab::ui::MainWindow", "Springs"), "springs", "J"},
}};

static_assert(
    [] {
        for (std::size_t i = 0; i < kOverlayNames.size(); ++i)
            if (static_cast<std::size_t>(kOverlayNames[i].overlay) != i)
                return false;
        return true;
    }(),
    "kOverlayNames is in the order of Overlay");

/// The name a lesson step gives `overlay` in its "overlays" (the lesson format's list, in the
/// order of Overlay).
inline QLatin1String lessonOverlayName(Overlay overlay)
{
    static_assert(lessons::kStepOverlayNames.size() == kOverlayCount);
    const std::string_view name = lessons::kStepOverlayNames[static_cast<std::size_t>(overlay)];
    return QLatin1String(name.data(), static_cast<qsizetype>(name.size()));
}

} // namespace rigidlab::ui
