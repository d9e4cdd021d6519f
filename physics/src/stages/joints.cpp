// SPDX-License-Identifier: GPL-3.0-or-later
// Pin joints, solved exactly: inside every force evaluation the joint forces lambda solve
//   K lambda = -C''_free,   K = J M^-1 J^T,
// so that each joint's relative acceleration is zero (Lagrange multipliers). Integration
// error still lets the joints drift, so after each step positions are moved back onto
// C(q) = 0 (Newton iterations) and velocities projected onto J v = 0, both mass-weighted.
//
// For a pin between points pA = xA + rA and pB = xB + rB (r: lever arm from the centre of
// mass, turned with the body), C = pA - pB and
//   C'  = vA + wA x rA - vB - wB x rB
//   C'' = aA + alphaA x rA - wA^2 rA - (aB + alphaB x rB - wB^2 rB).
// A force f at lever r changes (a, alpha) by (f / m, (r x f) / I).

#include "dynamics.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace rigidlab::physics {

namespace {

constexpr int kMaxPositionIterations = 8;
constexpr double kPositionTolerance = 1e-12; // [m]

} // namespace

Dynamics::JointFrame Dynamics::jointFrame(const PinJointDef& j, const Eigen::VectorXd& q) const
{
    JointFrame f;
    auto end = [&](BodyId id, const Vec2& anchor, Vec2& r, Vec2& p) {
        if (id == kWorld) {
            r = Vec2::Zero();
            p = anchor;
            return;
        }
        const Body& body = m_bodies[static_cast<size_t>(id)];
        const int s = m_slot[static_cast<size_t>(id)];
        Vec2 x = body.position;
        Rotation rot(body.angle);
        if (s >= 0) {
            const Eigen::Index i = 3 * static_cast<Eigen::Index>(s);
            x = Vec2(q[i], q[i + 1]);
            rot = Rotation(q[i + 2]);
        }
        r = lever(id, rot, anchor);
        p = x + r;
    };
    end(j.a, j.anchorA, f.rA, f.pA);
    end(j.b, j.anchorB, f.rB, f.pB);
    return f;
}

void Dynamics::factorJointMatrix(const std::vector<JointFrame>& frames)
{
    // K_jk = sum over bodies X shared by joints j and k of
    //        s_j s_k (invM I + invI perp(r_jX) perp(r_kX)^T),  s = +1 for end A, -1 for end B.
    const Eigen::Index n = 2 * static_cast<Eigen::Index>(m_joints.size());
    m_k.setZero(n, n);
    auto ends = [&](size_t j, int e, BodyId& id, Vec2& r, double& sign) {
        id = e == 0 ? m_joints[j].a : m_joints[j].b;
        r = e == 0 ? frames[j].rA : frames[j].rB;
        sign = e == 0 ? 1.0 : -1.0;
    };
    for (size_t j = 0; j < m_joints.size(); ++j) {
        for (size_t k = 0; k < m_joints.size(); ++k) {
            for (int ej = 0; ej < 2; ++ej) {
                for (int ek = 0; ek < 2; ++ek) {
                    BodyId idj, idk;
                    Vec2 rj, rk;
                    double sj, sk;
                    ends(j, ej, idj, rj, sj);
                    ends(k, ek, idk, rk, sk);
                    if (idj == kWorld || idj != idk)
                        continue;
                    const Body& b = m_bodies[static_cast<size_t>(idj)];
                    if (!b.isDynamic())
                        continue;
                    const Eigen::Matrix2d block = b.invMass * Eigen::Matrix2d::Identity() +
                                                  b.invInertia * perp(rj) * perp(rk).transpose();
                    m_k.block<2, 2>(2 * static_cast<Eigen::Index>(j),
                                    2 * static_cast<Eigen::Index>(k)) += sj * sk * block;
                }
            }
        }
    }
    // A tiny regularisation keeps redundant joints (two pins locking one body) solvable.
    const double scale = m_k.diagonal().cwiseAbs().maxCoeff();
    m_k.diagonal().array() += 1e-12 * (scale > 0 ? scale : 1.0);
}

void Dynamics::applyJointVector(const std::vector<JointFrame>& frames,
                                const Eigen::VectorXd& lambda, Eigen::VectorXd& out) const
{
    auto apply = [&](BodyId id, const Vec2& r, const Vec2& f) {
        if (id == kWorld)
            return;
        const Body& b = m_bodies[static_cast<size_t>(id)];
        const int s = m_slot[static_cast<size_t>(id)];
        if (s < 0 || !b.isDynamic())
            return;
        const Eigen::Index i = 3 * static_cast<Eigen::Index>(s);
        out[i] += b.invMass * f.x();
        out[i + 1] += b.invMass * f.y();
        out[i + 2] += b.invInertia * cross(r, f);
    };
    for (size_t j = 0; j < m_joints.size(); ++j) {
        const Vec2 f = lambda.segment<2>(2 * static_cast<Eigen::Index>(j));
        apply(m_joints[j].a, frames[j].rA, f);
        apply(m_joints[j].b, frames[j].rB, Vec2(-f));
    }
}

void Dynamics::addJointAccelerations(const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                                     Eigen::VectorXd& a)
{
    const Eigen::Index n = 2 * static_cast<Eigen::Index>(m_joints.size());
    m_frames.resize(m_joints.size());
    m_rhs.resize(n);
    for (size_t j = 0; j < m_joints.size(); ++j) {
        const JointFrame f = jointFrame(m_joints[j], q);
        m_frames[j] = f;
        // Free relative acceleration C''_free from the applied accelerations.
        Vec2 c = Vec2::Zero();
        auto endTerm = [&](BodyId id, const Vec2& r) -> Vec2 {
            if (id == kWorld)
                return Vec2::Zero();
            const int s = m_slot[static_cast<size_t>(id)];
            if (s < 0)
                return Vec2::Zero();
            const Eigen::Index i = 3 * static_cast<Eigen::Index>(s);
            const double w = v[i + 2];
            return Vec2(a[i], a[i + 1]) + cross(a[i + 2], r) - w * w * r;
        };
        c = endTerm(m_joints[j].a, f.rA) - endTerm(m_joints[j].b, f.rB);
        m_rhs.segment<2>(2 * static_cast<Eigen::Index>(j)) = -c;
    }
    factorJointMatrix(m_frames);
    m_lambda = m_k.ldlt().solve(m_rhs);
    applyJointVector(m_frames, m_lambda, a);
}

void Dynamics::projectJointPositions(Eigen::VectorXd& q)
{
    if (m_joints.empty())
        return;
    const Eigen::Index n = 2 * static_cast<Eigen::Index>(m_joints.size());
    Eigen::VectorXd dq(q.size());
    for (int it = 0; it < kMaxPositionIterations; ++it) {
        m_frames.resize(m_joints.size());
        m_rhs.resize(n);
        double worst = 0.0;
        for (size_t j = 0; j < m_joints.size(); ++j) {
            m_frames[j] = jointFrame(m_joints[j], q);
            const Vec2 c = m_frames[j].pA - m_frames[j].pB;
            worst = std::max(worst, c.norm());
            m_rhs.segment<2>(2 * static_cast<Eigen::Index>(j)) = -c;
        }
        if (worst <= kPositionTolerance)
            return;
        // One Newton step: the position change dq = M^-1 J^T mu with J dq = -C.
        factorJointMatrix(m_frames);
        m_lambda = m_k.ldlt().solve(m_rhs);
        dq.setZero();
        applyJointVector(m_frames, m_lambda, dq);
        q += dq;
    }
}

Vec2 Dynamics::pointVelocity(BodyId id, const Vec2& r, const Eigen::VectorXd& v) const
{
    if (id == kWorld)
        return Vec2::Zero();
    const int s = m_slot[static_cast<size_t>(id)];
    if (s < 0)
        return Vec2::Zero();
    const Eigen::Index i = 3 * static_cast<Eigen::Index>(s);
    return Vec2(v[i], v[i + 1]) + cross(v[i + 2], r);
}

void Dynamics::projectJointVelocities(const Eigen::VectorXd& q, Eigen::VectorXd& v)
{
    if (m_joints.empty())
        return;
    const Eigen::Index n = 2 * static_cast<Eigen::Index>(m_joints.size());
    m_frames.resize(m_joints.size());
    m_rhs.resize(n);
    for (size_t j = 0; j < m_joints.size(); ++j) {
        const JointFrame f = jointFrame(m_joints[j], q);
        m_frames[j] = f;
        const Vec2 cdot =
            pointVelocity(m_joints[j].a, f.rA, v) - pointVelocity(m_joints[j].b, f.rB, v);
        m_rhs.segment<2>(2 * static_cast<Eigen::Index>(j)) = -cdot;
    }
    factorJointMatrix(m_frames);
    m_lambda = m_k.ldlt().solve(m_rhs);
    applyJointVector(m_frames, m_lambda, v);
}

// For symplectic Euler the SHAKE form (Ryckaert, Ciccotti and Berendsen 1977): the position
// correction dq is made by the velocity, v += dq / h, as if the joint's impulse had acted at
// the start of the step (q1 = q0 + h v1 still holds), which keeps a pendulum's energy in a
// bounded band. The projection uses the joint's direction at the end of the step, so this
// holds while a step turns the bodies through a small angle; past that (a fast spin) only the
// positions are corrected, which is stable but loses a little energy. For the other
// integrators RATTLE's two projections (Andersen 1983): positions, then velocities.
void Dynamics::projectAfterStep(IntegratorKind kind, double h, Eigen::VectorXd& q,
                                Eigen::VectorXd& v, Eigen::VectorXd& before)
{
    if (kind == IntegratorKind::SymplecticEuler && !m_joints.empty()) {
        constexpr double kSmallTurn = 0.1; // [rad per step]
        double turn = 0.0;
        for (Eigen::Index i = 2; i < v.size(); i += 3)
            turn = std::max(turn, std::abs(v[i]) * h);
        before = q;
        projectJointPositions(q);
        if (turn < kSmallTurn)
            v += (q - before) / h;
    } else {
        projectJointPositions(q);
        projectJointVelocities(q, v);
    }
}

} // namespace rigidlab::physics
