// SPDX-License-Identifier: GPL-3.0-or-later
// The soft step's kernel (soft_kernel.cpp) again, four lanes wide, compiled with -mavx2
// (physics/CMakeLists.txt) on x86-64. soft_solver.cpp calls it only where the processor has
// AVX2 (soft::haveAvx2()); elsewhere the two-lane kernel runs.

#include "soft_kernel.h"

#if defined(__x86_64__) && defined(__AVX2__)
#define RIGIDLAB_SOFT_WIDTH 4
#define RIGIDLAB_SOFT_NAMESPACE lanes4avx2
#include "soft_kernel.cpp"
#else
namespace rigidlab::physics::soft {
Kernel kernel4Avx2()
{
    return {nullptr, nullptr, 0, "none"};
}
} // namespace rigidlab::physics::soft
#endif
