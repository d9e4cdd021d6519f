// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Files written whole or not at all. Every file the lab writes (traces, diagnostics, sweep and
// stress tables, exported scenes and plots) goes to a temporary file beside its destination,
// is flushed and checked to the last byte, and only then renamed over it: a failing write (a
// full disk, a file size limit, a read-only folder) leaves the previous file as it was, and
// the caller gets the reason.

#include <QByteArray>
#include <QString>

class QSaveFile;

namespace rigidlab::lessons {

/// Writes `bytes` to `path` atomically. Returns empty on success, else one line
/// "cannot write PATH: REASON" (the operating system's words).
QString writeFileAtomically(const QString& path, const QByteArray& bytes);

/// Puts an open QSaveFile in place: flushes what Qt still buffers and checks it (commit()
/// alone does not report a failing final flush, QTBUG-75077), then commits. On failure the
/// temporary file is dropped, `path` is untouched, and `why` holds the reason.
bool commitChecked(QSaveFile& file, QString& why);

} // namespace rigidlab::lessons
