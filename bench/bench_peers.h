// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The peers' adapters, each in its own file and compiled only when its engine is installed
// (Box2D v3: when its source tree is given, CMakeLists.txt).

#include "bench.h"

#include <memory>

namespace rigidlab::bench {

#ifdef RIGIDLAB_BENCH_BOX2D
/// Box2D 2.4 (single precision) at its usual settings: 8 velocity and 3 position iterations.
std::unique_ptr<bench::BenchEngine> makeBox2dEngine();
#endif
#ifdef RIGIDLAB_BENCH_BOX2D_V3
/// Box2D v3 (single precision) at its usual settings (4 substeps), on one thread: as it
/// builds by default (SSE2) and with its AVX2 option (each in a shared library of its own).
std::unique_ptr<bench::BenchEngine> makeBox2dV3Engine_sse2();
std::unique_ptr<bench::BenchEngine> makeBox2dV3Engine_avx2();
#endif
#ifdef RIGIDLAB_BENCH_CHIPMUNK
/// Chipmunk 7 (double precision) at its usual settings: 10 iterations.
std::unique_ptr<bench::BenchEngine> makeChipmunkEngine();
#endif

} // namespace rigidlab::bench
