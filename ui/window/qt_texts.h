// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Qt's own texts that Qt's Czech translation (qtbase_cs.qm) lacks in Qt 6: the file dialog's
// "Folder" and the like, which Qt 6 moved to a context the shipped translation does not know.
// They are listed here in Qt's contexts, so that lupdate puts them into rigidlab_cs.ts and
// the lab's translator answers where Qt's has nothing.

#include <array>

namespace rigidlab::ui {

struct QtText {
    const char* context;
    struct {
        const char* source;
        const char* comment; ///< Qt's disambiguation, "" when none
    } text;
};

/// The supplemented texts, as Qt asks for them (context, source, disambiguation).
const std::array<QtText, 4>& supplementedQtTexts();

} // namespace rigidlab::ui
