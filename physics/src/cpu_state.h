// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Private: keeping the processor's vector state clean for the engine's SSE code.
//
// The engine is compiled for baseline x86-64 (SSE2). Code elsewhere in the process can leave
// the upper halves of the AVX registers "dirty" (measured: after Qt Core has read a scene
// file); from then on, on many Intel processors, every SSE instruction pays for merging with
// them, and a world step takes twice as long (pyramid of 820 boxes: 2.7 ms -> 5.5 ms). One
// VZEROUPPER at the start of a step puts the registers back in the clean state.

namespace rigidlab::physics {

inline void clearUpperVectorState()
{
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
    static const bool hasAvx = __builtin_cpu_supports("avx");
    if (hasAvx)
        __asm__ volatile("vzeroupper" ::: "memory");
#endif
}

} // namespace rigidlab::physics
