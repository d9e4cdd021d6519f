// SPDX-License-Identifier: GPL-3.0-or-later
#include "format/atomic_file.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QSaveFile>

#include <sys/stat.h>

#include <cerrno>
#include <cstring>

namespace rigidlab::lessons {

namespace {

struct OutputMessages {
    Q_DECLARE_TR_FUNCTIONS(OutputMessages)
};

/// What a path holds now, as far as writing to it goes.
enum class Target {
    File,     ///< a regular file or nothing yet: replaced whole
    Straight, ///< a character device or a FIFO: written into as it is
    Folder,   ///< refused
    Other,    ///< a block device or a socket: refused
};

Target targetAt(const QString& path)
{
    // stat(), not lstat(): a link is judged by what it points to (QSaveFile writes there too).
    struct stat st {};
    if (::stat(QFile::encodeName(path).constData(), &st) != 0)
        return Target::File; // missing (or unreachable: QSaveFile reports why)
    if (S_ISREG(st.st_mode))
        return Target::File;
    if (S_ISCHR(st.st_mode) || S_ISFIFO(st.st_mode))
        return Target::Straight;
    if (S_ISDIR(st.st_mode))
        return Target::Folder;
    return Target::Other;
}

} // namespace

OutputFile::OutputFile(QString path) : m_path(std::move(path)) {}

OutputFile::~OutputFile() = default; // QSaveFile's destructor drops an uncommitted temporary

QString OutputFile::failed(const QString& why) const
{
    return OutputMessages::tr("cannot write %1: %2").arg(QDir::toNativeSeparators(m_path), why);
}

QString OutputFile::writeError() const
{
    // A full device or disk (ENOSPC) said as such: Qt files it as a ResourceError, in the
    // system's words.
    const QString why = m_file->errorString();
    if (m_file->error() == QFileDevice::ResourceError ||
        why == QString::fromLocal8Bit(std::strerror(ENOSPC)))
        return failed(OutputMessages::tr("the disk is full (%1)").arg(why));
    return failed(why);
}

bool OutputFile::open(QString& error)
{
    switch (targetAt(m_path)) {
    case Target::Folder:
        error = failed(OutputMessages::tr("it is a folder, not a file"));
        return false;
    case Target::Other:
        error = failed(OutputMessages::tr(
            "it is neither a file nor a character device or pipe the lab can write to"));
        return false;
    case Target::Straight:
        m_file = std::make_unique<QFile>(m_path);
        break;
    case Target::File: {
        auto save = std::make_unique<QSaveFile>(m_path);
        // Never straight onto a file (QSaveFile's fallback): a folder where no temporary file
        // can be made is an error, not a reason to overwrite in place.
        save->setDirectWriteFallback(false);
        m_save = save.get();
        m_file = std::move(save);
        break;
    }
    }
    // Unbuffered: a write that fails says why at once ("File too large", "No space left on
    // device"); through Qt's buffer the cause would be lost at the final flush.
    if (!m_file->open(QIODevice::WriteOnly | QIODevice::Unbuffered)) {
        error = failed(m_file->errorString());
        m_file.reset();
        m_save = nullptr;
        return false;
    }
    return true;
}

bool OutputFile::write(const char* data, qint64 size, QString& error)
{
    // A write that stops short is tried again: the second attempt is the one that fails and
    // says why ("File too large").
    qint64 done = 0;
    while (done < size) {
        const qint64 n = m_file->write(data + done, size - done);
        if (n <= 0) {
            error = writeError();
            return false;
        }
        done += n;
    }
    return true;
}

bool OutputFile::flush(QString& error)
{
    if (m_file->flush())
        return true;
    error = writeError();
    return false;
}

bool OutputFile::commit(QString& error)
{
    // QSaveFile::commit() alone does not report a failing final flush (QTBUG-75077).
    if (!flush(error)) {
        if (m_save != nullptr) {
            m_save->cancelWriting();
            m_save->commit(); // with writing cancelled: drops the temporary file, keeps the old
        }
        return false;
    }
    if (m_save != nullptr && !m_save->commit()) {
        error = failed(m_save->errorString());
        return false;
    }
    return true;
}

QString writeFileAtomically(const QString& path, const QByteArray& bytes)
{
    OutputFile file(path);
    QString error;
    if (!file.open(error) || !file.write(bytes.constData(), bytes.size(), error) ||
        !file.commit(error))
        return error;
    return {};
}

} // namespace rigidlab::lessons
