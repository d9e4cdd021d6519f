// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What the fuzz targets share: a failed invariant is a crash with a message, so that libFuzzer
// keeps the input that made it (as it does for a sanitizer report).

#include <cstdio>
#include <cstdlib>

namespace rigidlab::fuzz {

[[noreturn]] inline void invariantFailed(const char* what, const char* file, int line)
{
    std::fprintf(stderr, "%s:%d: invariant failed: %s\n", file, line, what);
    std::abort();
}

} // namespace rigidlab::fuzz

/// Like assert, but also in builds with NDEBUG.
#define FUZZ_CHECK(condition)                                                                      \
    ((condition) ? void(0) : ::rigidlab::fuzz::invariantFailed(#condition, __FILE__, __LINE__))
