// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The engine's names (physics::integratorName, solverName) are std::string_views into static
// UTF-8 text, not terminated where the view ends: read them by their size, not by data() alone.

#include <QString>

#include <string_view>

namespace rigidlab::lessons {

/// `text` as a QString, read as UTF-8 by its size.
inline QString textFromView(std::string_view text)
{
    return QString::fromUtf8(text.data(), static_cast<qsizetype>(text.size()));
}

} // namespace rigidlab::lessons
