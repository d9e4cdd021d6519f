// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Private: semi-implicit (symplectic) Euler's update, defined once. The integrator over the
// ODE state (integrators.cpp) and the direct path over the bodies (integration.cpp) both call
// it, so that the two give the same bits by construction (the golden runs pin it).

namespace rigidlab::physics {

/// v1 = v0 + h a, then q1 = q0 + h v1: the new velocity moves the position. Works on whole
/// state vectors (Eigen) and on one body's Vec2 or angle alike.
template <typename Q, typename V, typename A>
inline void symplecticEulerUpdate(double h, const A& a, V& v, Q& q)
{
    v += h * a;
    q += h * v;
}

} // namespace rigidlab::physics
