// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A test's data rows, one per language the window ships in (the languages table,
// lessons/format/languages.h), in the column "language": a language added to the table is
// checked by these tests with none of them edited.

#include "format/languages.h"

#include <QtTest>

namespace rigidlab::test {

inline void addLanguageRows()
{
    QTest::addColumn<QString>("language");
    for (const lessons::Language& language : lessons::kLanguages)
        QTest::newRow(language.code.toLatin1().constData()) << language.code.toString();
}

} // namespace rigidlab::test
