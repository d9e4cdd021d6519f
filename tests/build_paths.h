// SPDX-License-Identifier: GPL-3.0-or-later
// Where the tests find the project's files and this build's programs. CMake writes the paths
// into one small file of the build folder (build_paths.cpp.in) instead of onto every test's
// command line: a test's object is then the same in every clone, and ccache gives a fresh clone
// (the CI's) the objects an earlier clone compiled.
#pragma once

#include <QString>
#include <QStringView>

namespace rigidlab::test {

/// The source tree's root with `relative` ("/lessons/scenes") after it.
QString sourcePath(QStringView relative = {});
/// This build's rigidlab-cli and rigidlab programs.
QString cliPath();
QString guiPath();
/// The list of translated sources lupdate reads (the translations' build writes it).
QString translatedSourcesList();

} // namespace rigidlab::test
