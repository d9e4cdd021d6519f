// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The one table of what the window calls the panels a lesson step may show: the lesson
// format's name (lessons/format/lesson.h) and the full title. The window gives its docks the
// full title as their tooltip and the lesson editor lists a step's panels by it, so the two say
// the same (the plots' titles are their rows', plot_table.h; a dock's short title, on its tab,
// is its entry's, dock_names.h). Here in common/ because both the window and the lesson editor
// include it.

#include "format/lesson.h"

#include <QCoreApplication>
#include <QString>

#include <array>
#include <string_view>

namespace rigidlab::ui {

/// The translation context of the titles below (the window's, where they were first written).
inline constexpr const char* kStepPartContext = "rigidlab::ui::MainWindow";

struct StepPartName {
    const char* name;  ///< the lesson format's name (and the dock's object name)
    const char* title; ///< the full title, for translate() in kStepPartContext
};

/// A title from the tables below in the window's language.
inline QString stepPartText(const char* text)
{
    return QCoreApplication::translate(kStepPartContext, text);
}

/// In the order of lessons::kStepPanelNames.
inline constexpr std::array<StepPartName, 6> kStepPanelTitles{{
    {lessons::kStepPanelNames[0].data(), QT_TRANSLATE_NOOP("rigidlab::ui::MainWindow", "Controls")},
    {lessons::kStepPanelNames[1].data(),
     QT_TRANSLATE_NOOP("rigidlab::ui::MainWindow", "Inspector")},
    {lessons::kStepPanelNames[2].data(),
     QT_TRANSLATE_NOOP("rigidlab::ui::MainWindow", "Separating axis test")},
    {lessons::kStepPanelNames[3].data(), QT_TRANSLATE_NOOP("rigidlab::ui::MainWindow", "Bounces")},
    {lessons::kStepPanelNames[4].data(),
     QT_TRANSLATE_NOOP("rigidlab::ui::MainWindow", "Collision")},
    {lessons::kStepPanelNames[5].data(),
     QT_TRANSLATE_NOOP("rigidlab::ui::MainWindow", "Measurement")},
}};

/// The titles of the panel that the lesson format calls `name` ("controls", "collision"):
/// found by name, so that no caller depends on the table's order. A name that is not in the
/// table is a programming error.
constexpr const StepPartName& stepPanel(std::string_view name)
{
    std::size_t i = 0;
    while (i + 1 < kStepPanelTitles.size() && std::string_view(kStepPanelTitles[i].name) != name)
        ++i;
    Q_ASSERT(std::string_view(kStepPanelTitles[i].name) == name);
    return kStepPanelTitles[i];
}

/// Every panel the lesson format names has its titles, under the same name.
constexpr bool everyPanelTitled()
{
    if (kStepPanelTitles.size() != lessons::kStepPanelNames.size())
        return false;
    for (const std::string_view name : lessons::kStepPanelNames)
        if (std::string_view(stepPanel(name).name) != name)
            return false;
    return true;
}
static_assert(everyPanelTitled(), "a title for each of lessons::kStepPanelNames");

} // namespace rigidlab::ui
