#pragma once
// Private: stage 5 of a step, collision response on the contacts found this step.

#include "rigidlab/physics/body.h"
#include "rigidlab/physics/contact.h"
#include "rigidlab/physics/world.h"

#include <vector>

namespace rigidlab::physics {

class ContactSolver {
public:
    /// startVelocity / startAngularVelocity: each body's velocities at the start of the step,
    /// before forces, so that a bounce can be timed within the step.
    ContactSolver(std::vector<Contact>& contacts, std::vector<Body>& bodies,
                  const ContactSettings& settings, double dt,
                  const std::vector<Vec2>& startVelocity,
                  const std::vector<double>& startAngularVelocity);

    /// Seed impulse: one impulse per contact point, in order, with the full denominator
    /// 1/mA + 1/mB + (rA x n)^2/IA + (rB x n)^2/IB and Coulomb friction.
    void solveSeed();

    /// Sequential impulse: warm start with last step's impulses, then iterate, accumulating
    /// and clamping normal (>= 0) and friction (|t| <= mu n) impulses.
    void solveSequential(int iterations, bool warmStart);

    /// One pass of position correction (non-linear Gauss-Seidel on the separations).
    /// Returns true when every contact is within the allowed penetration.
    bool solvePositions();

    /// Whether any impulse was applied this step.
    bool appliedImpulse() const;
    /// For each body, the fraction of the step that passed before its first bounce (0 when it
    /// rests or was already touching). A velocity change at that moment moves the body by
    /// (1 - fraction) dt times the change by the end of the step.
    std::vector<double> impactFractions() const;

private:
    struct Point {
        Vec2 rA = Vec2::Zero(), rB = Vec2::Zero(); ///< lever arms [m]
        double normalMass = 0;                     ///< 1 / K along the normal [kg]
        double tangentMass = 0;                    ///< 1 / K along the tangent [kg]
        double bias = 0;                           ///< target normal velocity [m/s]
        bool closes = false;                       ///< touching, or the gap closes within this step
        double impact = 0; ///< fraction of the step before a bounce, 0 if no bounce
    };
    struct Constraint {
        int contact = 0;
        Vec2 normal = Vec2::Zero();
        Vec2 tangent = Vec2::Zero();
        int count = 0;
        Point p[2];
        bool block = false; ///< two points solved together
        Eigen::Matrix2d k = Eigen::Matrix2d::Zero();
        Eigen::Matrix2d normalMassBlock = Eigen::Matrix2d::Zero();
    };
    /// threshold: approaches slower than this do not bounce [m/s].
    void prepare(double threshold);
    void warmStart();
    void solveFriction(Constraint& c);
    void solveFrictionPoint(Constraint& c, int i);
    void solveNormalPoint(Constraint& c, int i);
    void solveNormalBlock(Constraint& c);
    double normalVelocity(const Constraint& c, int i) const;

    std::vector<Contact>& m_contacts;
    std::vector<Body>& m_bodies;
    const ContactSettings& m_settings;
    double m_dt;
    const std::vector<Vec2>& m_startVelocity;
    const std::vector<double>& m_startAngularVelocity;
    std::vector<Constraint> m_constraints;
};

} // namespace rigidlab::physics
