// SPDX-License-Identifier: GPL-3.0-or-later
// The soft step's kernel (soft_kernel.cpp) again, compiled with -mavx2 (physics/CMakeLists.txt)
// on x86-64: four lanes of doubles, and eight lanes of floats (SoftStepSettings::
// singlePrecision). soft_solver.cpp calls them only where the processor has AVX2
// (soft::haveAvx2()); elsewhere the two-lane kernel, or the four lanes of floats, run.

#include "soft_kernel.h"

#if defined(__x86_64__) && defined(__AVX2__)
#define RIGIDLAB_SOFT_WIDTH 4
#define RIGIDLAB_SOFT_NAMESPACE lanes4avx2
#define RIGIDLAB_SOFT_KERNEL Kernel kernel4Avx2()
#define RIGIDLAB_SOFT_NAME "4 lanes, AVX2"
#include "soft_kernel.cpp"
#undef RIGIDLAB_SOFT_WIDTH
#undef RIGIDLAB_SOFT_REAL
#undef RIGIDLAB_SOFT_NAMESPACE
#undef RIGIDLAB_SOFT_KERNEL
#undef RIGIDLAB_SOFT_NAME

#define RIGIDLAB_SOFT_WIDTH 8
#define RIGIDLAB_SOFT_REAL float
#define RIGIDLAB_SOFT_SINGLE 1
#define RIGIDLAB_SOFT_NAMESPACE single8avx2
#define RIGIDLAB_SOFT_KERNEL SingleKernel singleKernel8Avx2()
#define RIGIDLAB_SOFT_NAME "8 lanes, single precision, AVX2"
#include "soft_kernel.cpp"
#else
namespace rigidlab::physics::soft {
Kernel kernel4Avx2()
{
    return {nullptr, nullptr, 0, "none"};
}
SingleKernel singleKernel8Avx2()
{
    return {nullptr, nullptr, 0, "none"};
}
} // namespace rigidlab::physics::soft
#endif
