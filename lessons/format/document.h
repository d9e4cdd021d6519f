// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Checking any RigidLab document (for `rigidlab-cli validate`). A document says what it is by
// its top-level version key: "rigidlab" for a scene. Each kind of document is one entry of
// the table in document.cpp, so lessons can be added there without touching the callers.

#include <QString>
#include <QStringList>

namespace rigidlab::lessons {

struct DocumentCheck {
    bool ok = false;
    QString error;        ///< one line when !ok: `FILE: PLACE: what is wrong`
    QStringList warnings; ///< lines in the same form
    QString kind;         ///< "scene", ... once the kind is known
    QString summary;      ///< when ok: what it holds, as "12 bodies, 1 spring, 0 joints"
};

/// Reads, recognises and checks a document file.
DocumentCheck checkDocumentFile(const QString& path);

/// "1 spring", "0 joints".
QString countNoun(qsizetype n, QStringView one, QStringView many);

} // namespace rigidlab::lessons
