// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A made-up class that handed in the shipped lesson "restitution.json", for the Class results
// screenshot (and anyone who wants to try File › Class results… without a class): five
// students' answers files written by the lab's own answers writer (answersJson), one damaged
// file and one answers file of another lesson, so that the skipped lines show too. The
// answers are fixed here, so that every run writes the same files.

#include <QString>

namespace rigidlab::ui {

/// Writes the demo class's files into `folder` (which must exist); empty on success, else why
/// not.
QString writeDemoClass(const QString& folder);

} // namespace rigidlab::ui
