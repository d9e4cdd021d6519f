// SPDX-License-Identifier: GPL-3.0-or-later
#include "window/qt_texts.h"

#include <QtGlobal>

namespace rigidlab::ui {

const std::array<QtText, 4>& supplementedQtTexts()
{
    // The file dialog's Type column (QAbstractFileIconProvider::type in Qt 6).
    static const std::array<QtText, 4> texts{{
        {"QAbstractFileIconProvider",
         QT_TRANSLATE_NOOP3("QAbstractFileIconProvider", "Folder", "All other platforms")},
        {"QAbstractFileIconProvider",
         QT_TRANSLATE_NOOP3("QAbstractFileIconProvider", "Shortcut", "All other platforms")},
        {"QAbstractFileIconProvider",
         {QT_TRANSLATE_NOOP("QAbstractFileIconProvider", "Drive"), ""}},
        {"QAbstractFileIconProvider",
         {QT_TRANSLATE_NOOP("QAbstractFileIconProvider", "Unknown"), ""}},
    }};
    return texts;
}

} // namespace rigidlab::ui
