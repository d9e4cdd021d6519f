// SPDX-License-Identifier: GPL-3.0-or-later
#include "format/atomic_file.h"

#include <QSaveFile>

namespace rigidlab::lessons {

bool commitChecked(QSaveFile& file, QString& why)
{
    if (!file.flush()) {
        why = file.errorString();
        file.cancelWriting();
        file.commit(); // with writing cancelled: drops the temporary file, keeps `path`
        return false;
    }
    if (!file.commit()) {
        why = file.errorString();
        return false;
    }
    return true;
}

QString writeFileAtomically(const QString& path, const QByteArray& bytes)
{
    const auto failed = [&path](const QString& why) {
        return QStringLiteral("cannot write %1: %2").arg(path, why);
    };
    // Never straight onto `path` (QSaveFile's default): a folder where no temporary file can be
    // made is an error, not a reason to overwrite in place.
    // Unbuffered: a write that fails says why at once ("File too large", "No space left on
    // device"); through Qt's buffer the cause would be lost at the final flush.
    QSaveFile file(path);
    file.setDirectWriteFallback(false);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Unbuffered)) {
        return failed(file.errorString());
    }
    qint64 done = 0;
    while (done < bytes.size()) {
        const qint64 n = file.write(bytes.constData() + done, bytes.size() - done);
        if (n <= 0) {
            const QString why = file.errorString();
            file.cancelWriting();
            file.commit();
            return failed(why);
        }
        done += n;
    }
    QString why;
    if (!commitChecked(file, why)) {
        return failed(why);
    }
    return QString();
}

} // namespace rigidlab::lessons
