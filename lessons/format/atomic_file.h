// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Every file the lab writes (traces, diagnostics, sweep and stress tables, exported scenes,
// lessons, plots, worksheets, answers) goes through OutputFile, which looks at what the name
// holds before it writes:
//   - a regular file or a name not yet taken is replaced whole or not at all: written to a
//     temporary file beside it, flushed and checked to the last byte, and only then renamed
//     over it; a failing write (a full disk, a file size limit, a read-only folder) leaves the
//     previous file as it was, and the caller gets the reason;
//   - a character device or a FIFO (/dev/null, /dev/full, a pipe to another program) is
//     written straight into: renaming a file over it would replace the device for the whole
//     machine when the lab runs as root, and fail with a false "Permission denied" otherwise.
//     Its errors are reported as they are (a full device as a full disk);
//   - a folder or any other kind of file (a block device, a socket) is refused in one line.

#include <QByteArray>
#include <QString>

#include <memory>

class QFileDevice;
class QSaveFile;

namespace rigidlab::lessons {

/// One output, opened by what its path holds (see above). Destroyed without commit(), a
/// temporary file is dropped and the previous file stays; what went into a device stays sent.
class OutputFile {
public:
    explicit OutputFile(QString path);
    ~OutputFile();
    OutputFile(const OutputFile&) = delete;
    OutputFile& operator=(const OutputFile&) = delete;

    /// Opens the output; false with `error` = "cannot write PATH: REASON".
    bool open(QString& error);
    /// Writes all of `size` bytes, or says why not (same form as open()).
    bool write(const char* data, qint64 size, QString& error);
    /// Hands everything to the system and checks it (a full disk shows here at the latest).
    bool flush(QString& error);
    /// Flushes, then puts a replaced file in place. A device is only flushed.
    bool commit(QString& error);
    /// True when the output replaces a file whole on commit() (false for a device or FIFO,
    /// and before open()). Only such an output may be removed or put back by the caller.
    bool replacesWhole() const { return m_save != nullptr; }
    bool isOpen() const { return m_file != nullptr; }
    const QString& path() const { return m_path; }

private:
    QString failed(const QString& why) const;
    QString writeError() const;

    QString m_path;
    std::unique_ptr<QFileDevice> m_file; ///< the open output: a QSaveFile or a straight QFile
    QSaveFile* m_save = nullptr;         ///< m_file when it replaces a file whole, else null
};

/// Writes `bytes` to `path` through an OutputFile: atomically for a file, straight into a
/// device or FIFO. Returns empty on success, else one line "cannot write PATH: REASON".
QString writeFileAtomically(const QString& path, const QByteArray& bytes);

} // namespace rigidlab::lessons
