// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A file size limit on this process, for a write that fails halfway through: every write past
// the limit fails with EFBIG, for root too (permissions do not stop root, a file size limit
// does). Unix only.

#include <csignal>
#include <sys/resource.h>

namespace rigidlab::test {

/// Limits this process's files to `bytes` while it lives (and ignores SIGXFSZ, which would
/// otherwise kill the process).
class FileSizeLimit {
public:
    explicit FileSizeLimit(rlim_t bytes)
    {
        getrlimit(RLIMIT_FSIZE, &m_old);
        m_oldHandler = std::signal(SIGXFSZ, SIG_IGN);
        rlimit limited = m_old;
        limited.rlim_cur = bytes;
        m_active = setrlimit(RLIMIT_FSIZE, &limited) == 0;
    }
    ~FileSizeLimit()
    {
        setrlimit(RLIMIT_FSIZE, &m_old);
        std::signal(SIGXFSZ, m_oldHandler);
    }
    FileSizeLimit(const FileSizeLimit&) = delete;
    FileSizeLimit& operator=(const FileSizeLimit&) = delete;
    bool isActive() const { return m_active; }

private:
    rlimit m_old{};
    void (*m_oldHandler)(int) = nullptr;
    bool m_active = false;
};

} // namespace rigidlab::test
