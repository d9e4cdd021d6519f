// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Private: the soft step's solver (SolverKind::SoftStep), driven substep by substep from
// soft_step.cpp. It keeps its own copy of what the substeps change (velocities, positions,
// angles), the contacts as coloured blocks of lanes (soft_kernel.h), and writes the bodies
// and the contacts' impulses back at the end of the step.

#include "rigidlab/physics/body.h"
#include "rigidlab/physics/contact.h"
#include "rigidlab/physics/world.h"

#include "soft_kernel.h"

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

namespace rigidlab::physics {

/// A soft constraint's coefficients for one substep (soft_solver.cpp).
using soft::Softness;

/// The soft contact's coefficients at the substep h [s]: between two moving bodies [0],
/// against a body that does not move [1] (twice the frequency).
void softContactCoefficients(const SoftStepSettings& settings, double h, Softness (&out)[2]);

/// The step's substeps, as the step context has them (StepContext::substeps, h, invH).
struct Substeps {
    int count = 1;   ///< substeps per step
    double h = 0;    ///< the substep [s]
    double invH = 0; ///< 1 / h [1/s]
};

class SoftSolver {
public:
    /// Takes this step's contacts and bodies, before anything moved. acceleration and
    /// angularAcceleration: each body's applied load over its mass, constant over the step.
    /// substeps: the step's, from its context; softness: the contact's coefficients at the
    /// substep (softContactCoefficients). plain: colour anew and solve one contact per block.
    void begin(std::vector<Contact>& contacts, const std::vector<Body>& bodies,
               const std::vector<Vec2>& acceleration,
               const std::vector<double>& angularAcceleration, const Substeps& substeps,
               const Softness (&softness)[2], const SoftStepSettings& settings, bool plain);

    /// The smooth motion's share of each body's displacement that the velocities do not carry
    /// (soft_step.cpp: what the chosen integrator's step adds to the substeps' symplectic
    /// Euler on its mean acceleration), per body [m/s] and [rad/s]; integratePositions() moves
    /// by h (v + drift). Set after begin(); none by default.
    void setDrift(const std::vector<Vec2>& drift, const std::vector<double>& angularDrift);
    /// The pin joints solved with the contacts in every pass, as soft constraints like them
    /// (soft_pins.cpp): a point-to-point constraint of the two anchors, pushed back softly in
    /// the biased pass and held rigidly in the relax pass. Set after begin(); none by default.
    void setPins(const std::vector<PinJointDef>& pins, const std::vector<Body>& bodies);

    // A substep, in this order (Catto's soft step).
    /// sumBefore: kineticEnergy() and loadPower() of the velocities before, in the same pass
    /// (energyBefore()).
    void integrateVelocities(bool sumBefore = false);
    void warmStart();
    /// useBias: the soft solve that pushes overlaps apart; false: the relax pass, rigid and
    /// without bias, which takes the push's velocity out again. lookAhead: a gap may close
    /// within the next substep but no more (speculative); false: gaps ask nothing (the last
    /// relax pass, whose next substep is the next step's, with its collision phase).
    void solve(bool useBias, bool lookAhead = true);
    void integratePositions();

    /// Velocities, positions and angles to the bodies, impulses (per step) to the contacts.
    void end(std::vector<Body>& bodies);

    /// Kinetic energy of the bodies the step moves [J], for the energy the contacts took.
    double kineticEnergy() const;
    /// Power of the applied loads at the present velocities, sum m a.v + I alpha w [W].
    double loadPower() const;
    /// Power of the applied loads at the velocities the last integratePositions() moved the
    /// bodies with [W]: the load's work over that substep is h times it.
    double movePower() const { return m_movePower; }
    /// kineticEnergy() [J] and loadPower() [W] as they were before the last
    /// integrateVelocities(true), the same bits as asked for then.
    std::pair<double, double> energyBefore() const { return {m_energyBefore, m_powerBefore}; }

    int constraintCount() const { return static_cast<int>(m_slots.size()); }

    /// Colours a deterministic graph colouring may use; more contacts at one body overflow.
    static constexpr int kMaxColours = 64;

private:
    /// Where a contact's lane is.
    struct Slot {
        int contact = 0;
        int block = 0;
        int lane = 0;
        /// The contact's point count when its lane was filled: end() writes its impulses
        /// without reading the contact's first cache line again.
        int points = 0;
    };
    /// What the colouring of a contact depends on: its bodies and whether each moves.
    struct ColourKey {
        int a = 0, b = 0;
        bool movesA = false, movesB = false;
        bool operator==(const ColourKey&) const = default;
    };
    /// begin()'s copy of what the substeps read of the bodies: each body's state, centre,
    /// angle, inverse inertia and flags, and the moving bodies' loads, masses and inertias.
    void takeBodies(const std::vector<Body>& bodies, const std::vector<Vec2>& acceleration,
                    const std::vector<double>& angularAcceleration);
    /// From the bodies as begin() took them (m_active). Inline: sameColouring() asks it of
    /// every contact in every step.
    ColourKey colourKey(const Contact& ct) const
    {
        return {ct.a, ct.b, m_active[static_cast<size_t>(ct.a)] != 0,
                m_active[static_cast<size_t>(ct.b)] != 0};
    }
    /// Colours the contacts (fast/soft_colouring.cpp), or keeps last step's colouring.
    void buildBlocks(const std::vector<Contact>& contacts, const std::vector<Body>& bodies);
    /// Packs the coloured contacts into blocks of m_width lanes, the overflow last.
    void layBlocks(const std::vector<Contact>& contacts, const std::vector<Body>& bodies);
    /// Whether the colouring of the last buildBlocks() holds for these contacts: the same keys
    /// in the same order, the same bodies and lanes (a pile at rest, step after step). Then
    /// the blocks only need their lanes filled again.
    bool sameColouring(const std::vector<Contact>& contacts, const std::vector<Body>& bodies) const;
    /// `count` blocks for the colouring, holding whatever they held: layBlocks() fills every
    /// field of a lane it gives a contact, and empties the others (emptyLanes()).
    void resetBlocks(int count);
    /// Empties lanes [from, the block's width) of block `block`: on the spare body, every
    /// number 0, as a block made anew.
    void emptyLanes(int block, int from, int spare);
    // The constraint rows (soft_lanes.cpp, with resetBlocks() and emptyLanes()).
    /// Fills lane `lane` of block k (of m_blocks, or m_singleBlocks when m_single) with the
    /// contact ct, from the bodies as begin() took them; every field of the lane.
    template <typename BlockType> void fillLaneOf(const Contact& ct, BlockType& k, int lane);
    /// Single precision: adds to m_singleWarm of ct's bodies what the impulse of its point
    /// `point` at the start of the step gives them in a warm start (lever arms rA, rB). Always
    /// inline: called, it took a third more instructions than fillLaneOf() itself.
    [[gnu::always_inline]] inline void addSingleWarm(const Contact& ct, int point, const Vec2& rA,
                                                     const Vec2& rB);
    // The passes over the bodies of either precision (soft_solver.cpp).
    template <bool SumBefore, typename State> void integrateVelocitiesOf(std::vector<State>& state);
    template <typename State> void integratePositionsOf(std::vector<State>& state);
    template <typename State> void sumEnergyOf(const std::vector<State>& state) const;
    /// Adds twice moving body k's kinetic energy to energy, its loads' power to power (the one
    /// formula of integrateVelocitiesOf() and sumEnergyOf()). Always inline: GCC called it
    /// instead, three times per body and substep.
    template <typename State>
    [[gnu::always_inline]] inline void addEnergy(size_t k, const State& s, double& energy,
                                                 double& power) const;
    template <typename State, typename BlockType>
    void endOf(std::vector<Body>& bodies, const std::vector<State>& state,
               const std::vector<BlockType>& blocks);
    /// A pin as the substeps see it (soft_pins.cpp): its bodies (-1 for the world), its anchors
    /// from the centres of mass in the bodies' frames (the world point for the world), and its
    /// accumulated impulse in a substep [N s], on B (-impulse on A).
    struct Pin {
        int a = -1, b = -1;
        Vec2 localA = Vec2::Zero(), localB = Vec2::Zero();
        Vec2 impulse = Vec2::Zero();
    };
    /// A pin's lever arm and anchor point in the world for one end, and its body's state.
    struct PinEnd {
        Vec2 r = Vec2::Zero(), p = Vec2::Zero();
        double invMass = 0, invInertia = 0;
        soft::BodyState* state = nullptr;
    };
    PinEnd pinEnd(int body, const Vec2& local);
    /// One pass over the pins (soft_pins.cpp): with the soft bias, or rigid without it.
    void solvePins(bool useBias);
    void warmStartPins();

    /// Single precision: the velocities are the double state's (m_state), and the float copy
    /// (m_singleState) is what the kernel's solve and relax passes change; the warm start is
    /// double (warmStart(), m_singleWarm). It holds each body's velocity less
    /// its velocity at the start of the step (m_singleOrigin), and its rotation less the
    /// identity (qc - 1, qs), so that a float rounds the change, not the speed or the lever
    /// arm. toSingle: each moving body's velocity to the copy (motion: the displacements and
    /// rotations too, and the kinematic bodies'); fromSingle: the change the passes made, back
    /// to the double velocities (soft_single.cpp).
    void toSingle(bool motion);
    void fromSingle();

    /// Both sums of kineticEnergy() and loadPower() in one pass over the bodies, kept until
    /// the velocities change (each pass of the substep asks for both, some twice).
    void sumEnergy() const;

    /// The sums of sumEnergy() for the present velocities, valid while m_energyValid.
    mutable double m_energy = 0, m_power = 0;
    double m_movePower = 0;                       ///< see movePower() [W]
    double m_energyBefore = 0, m_powerBefore = 0; ///< see energyBefore()
    mutable bool m_energyValid = false;

    std::vector<Contact>* m_contacts = nullptr;
    SoftStepSettings m_settings;
    Substeps m_substeps;
    soft::Kernel m_kernel{};
    soft::SingleKernel m_singleKernel{};
    int m_width = 1;       ///< lanes filled per block: the kernel's, 1 on the plain path
    bool m_plain = false;  ///< the plain path: no colouring kept from step to step
    bool m_single = false; ///< the contact passes in single precision (m_single* below)
    soft::PassSettings m_pass;

    std::vector<soft::BodyState> m_state;             ///< per body, and a spare one for empty lanes
    std::vector<soft::SingleBodyState> m_singleState; ///< the kernel's float copy, when m_single
    std::vector<std::array<float, 3>> m_singleBase;   ///< its velocities as toSingle() wrote them
    std::vector<int> m_moving;                        ///< awake dynamic bodies
    std::vector<int> m_kinematic;                     ///< kinematic bodies
    std::vector<Vec2> m_position;                     ///< centre of mass [m], per body
    std::vector<double> m_angle;                      ///< [rad], per body
    std::vector<Vec2> m_acceleration;                 ///< per moving body [m/s^2]
    std::vector<double> m_angularAcceleration;        ///< per moving body [rad/s^2]
    std::vector<double> m_mass, m_inertia;            ///< per moving body
    /// Per body, when m_single: its velocity at the start of the step [m/s, rad/s]; the float
    /// copy holds the velocity less this (SingleLanesOf, soft_kernel.h).
    std::vector<std::array<double, 3>> m_singleOrigin;
    /// Per body, when m_single: the velocity its contacts' impulses give it in a warm start
    /// [m/s, rad/s], in double: at the start of the step from the contacts' impulses
    /// (fillLaneOf), and after each pass plus the velocity change the pass made (fromSingle).
    std::vector<std::array<double, 3>> m_singleWarm;

    std::vector<Vec2> m_drift;          ///< per body, empty: none (setDrift())
    std::vector<double> m_angularDrift; ///< per body
    std::vector<Pin> m_pins;
    std::vector<double> m_invInertia; ///< per body, 0 for a body the step does not move
    /// Per body: whether its contacts' lever arms turn with it (integratePositions()); not for
    /// a circle about its centre of mass, whose touching point stays where the normal meets it.
    std::vector<char> m_turns;
    /// Per body: whether the step moves it (Body::isActive()), read where the colouring is
    /// made or checked without reaching into the bodies' large records.
    std::vector<char> m_active;

    std::vector<soft::Block> m_blocks;
    std::vector<soft::SingleBlock> m_singleBlocks; ///< instead of m_blocks when m_single
    std::vector<Slot> m_slots;
    /// The blocks the kernel is given in one call, [m_ranges[i], m_ranges[i + 1]): a colour's,
    /// or one overflow block (soft_kernel.h, KernelOf).
    std::vector<int> m_ranges;
    /// Calls pass(first, count) for each range of m_ranges, in order.
    template <typename Pass> void forEachRange(const Pass& pass) const
    {
        for (size_t r = 0; r + 1 < m_ranges.size(); ++r)
            pass(m_ranges[r], m_ranges[r + 1] - m_ranges[r]);
    }
    std::vector<std::uint64_t> m_colourMask; ///< per body: colours of its contacts
    std::vector<int> m_colourOf;             ///< per candidate contact, -1 overflow
    std::vector<int> m_candidates;           ///< contacts with a body to solve
    std::vector<int> m_colourSize;
    std::vector<int> m_nextBlock, m_nextLane; ///< per colour, while the blocks are filled
    int m_colourCount = 0;
    int m_overflow = 0;
    std::vector<ColourKey> m_keys; ///< per contact, of the colouring in m_blocks
    size_t m_keyBodies = 0;        ///< the body count of that colouring
    int m_keyWidth = 0;            ///< the kernel width of that colouring
    bool m_keySingle = false;      ///< the precision of that colouring
};

} // namespace rigidlab::physics
