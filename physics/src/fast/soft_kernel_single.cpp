// SPDX-License-Identifier: GPL-3.0-or-later
// The soft step's kernel (soft_kernel.cpp) again in single precision
// (SoftStepSettings::singlePrecision), four lanes of floats: SSE on every x86-64.

#include "soft_kernel.h"

#define RIGIDLAB_SOFT_WIDTH 4
#define RIGIDLAB_SOFT_REAL float
#define RIGIDLAB_SOFT_SINGLE 1
#define RIGIDLAB_SOFT_NAMESPACE single4
#define RIGIDLAB_SOFT_KERNEL SingleKernel singleKernel4()
#define RIGIDLAB_SOFT_NAME "4 lanes, single precision"
#include "soft_kernel.cpp"
