// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What lessons measure in a running world: bounce apexes, collisions (velocities before and
// after, with the spin the full impulse formula predicts and the one the formula without its
// rotational terms would), and values read at given times. Fed once per step; questions
// are judged against it.

#include "format/answers_file.h"
#include "format/lesson.h"
#include "format/verdict.h"
#include "rigidlab/physics/world.h"

#include <QString>

#include <optional>
#include <utility>
#include <vector>

namespace rigidlab::lessons {

struct ApexEvent {
    double t = 0; ///< [s]
    double y = 0; ///< height of the centre of mass [m]
    /// Height of the centre where the body touched down at the bounce before this apex: the
    /// centre before that step, moved along the contact's normal by the gap the contact
    /// closed, so exact to rounding rather than to a step [m].
    double bounceY = 0;
};

struct CollisionEvent {
    double t = 0; ///< [s]
    physics::BodyId a = 0, b = 0;
    /// Of the centres of mass of a, b [m/s].
    physics::Vec2 velocityBefore[2] = {physics::Vec2::Zero(), physics::Vec2::Zero()};
    physics::Vec2 velocityAfter[2] = {physics::Vec2::Zero(), physics::Vec2::Zero()};
    double angularBefore[2] = {0, 0}; ///< [rad/s]
    double angularAfter[2] = {0, 0};
    /// Angular velocities right after the hit as predicted by the full impulse formula and by
    /// the paper's printed formula without the rotational terms, from the normal impulse alone
    /// (friction left out) [rad/s].
    double predictedFull[2] = {0, 0};
    double predictedWithoutRotation[2] = {0, 0};
    /// The full formula's terms for that hit, as predictedFull used them, so that the window
    /// can show j with the numbers substituted: the point the impulse acted at [m], the
    /// normal from a to b, each centre of mass's lever arm to the point [m], the approach
    /// (v_b − v_a)·n of the points before the hit (negative: approaching) [m/s], the
    /// coefficient of restitution used (0 for a slow approach that rests) and j [N s].
    physics::Vec2 point = physics::Vec2::Zero();
    physics::Vec2 normal = physics::Vec2::Zero();
    physics::Vec2 lever[2] = {physics::Vec2::Zero(), physics::Vec2::Zero()};
    double approach = 0, restitution = 0, impulse = 0;
};

class Measurements {
public:
    /// The events kept: the first ones, which lessons ask about (the n-th apex, the first
    /// collision). Later ones are not stored, so that a long run (a gas has hundreds of
    /// collisions a second) does not grow without bound.
    static constexpr std::size_t kMaxCollisions = 1000;
    static constexpr std::size_t kMaxBouncesPerBody = 1000;

    /// Starts over with this world (at its current time), reading the questions' measures.
    void reset(const physics::World& world, const std::vector<Measure>& watched);
    /// After every step.
    void observe(const physics::World& world);
    /// The world went back to time t: forget what happened after it. The next observe() then
    /// only reads the state again (a bounce or a hit in that one step is not seen); prefer the
    /// overload below when the world is at hand.
    void rewind(double t);
    /// The world went back to its current time: forget what happened after it and read its
    /// state, so that the next step is observed as usual.
    void rewind(const physics::World& world);

    const std::vector<ApexEvent>& apexes(physics::BodyId body) const;
    /// Times of the bounces of a body: its vertical velocity turned from down to up [s].
    const std::vector<double>& bounces(physics::BodyId body) const;
    const std::vector<CollisionEvent>& collisions() const { return m_collisions; }
    /// The measured value, or nullopt while the simulation has not got there yet (or when a
    /// timed measure is not among those watched).
    std::optional<double> value(const Measure& m, const Scene& scene) const;

private:
    struct Timed {
        Measure measure;
        std::optional<double> value;
        double recordedAt = 0; ///< [s]
    };
    /// Where a body's centre rose to since its last bounce, while it is still rising.
    struct Peak {
        bool armed = false;
        double t = 0;       ///< [s]
        double y = 0;       ///< [m]
        double bounceY = 0; ///< where the centre was at the bounce [m]
    };
    void recordTimed(const physics::World& world);
    void readState(const physics::World& world);
    using Pair = std::pair<physics::BodyId, physics::BodyId>;
    /// The pairs pushed apart by a positive normal impulse this step, sorted, into `pairs`.
    /// Returns whether the world's contacts came in the order of their pairs (the engine keeps
    /// them so): then they need no sort, and a walk along them can look each pair up in the
    /// step before's list with one cursor.
    static bool touchingPairs(const physics::World& world, std::vector<Pair>& pairs);
    CollisionEvent collisionEvent(const physics::World& world, const physics::Contact& c) const;
    /// Marks in m_bouncing the dynamic bodies whose centre's vertical velocity turned from down
    /// to up this step (and that have room in their log); returns whether any did.
    bool findBounces(const physics::World& world);
    /// For each body marked in m_bouncing, the height of its centre where it touched what made
    /// it bounce this step (see ApexEvent::bounceY), its height now when no contact pushed it:
    /// into m_touchdown.
    void findTouchdowns(const physics::World& world);

    std::vector<std::vector<ApexEvent>> m_apexes;
    std::vector<std::vector<double>> m_bounces; ///< bounce times per body [s]
    std::vector<std::vector<double>> m_bounceY; ///< the centre's touchdown height [m]
    std::vector<Peak> m_peaks;
    std::vector<CollisionEvent> m_collisions;
    std::vector<Timed> m_timed;
    // The state after the previous step.
    std::vector<physics::Vec2> m_lastVelocity; ///< [m/s]
    std::vector<double> m_lastAngular;         ///< [rad/s]
    std::vector<physics::Vec2> m_lastPosition; ///< centres of mass [m]
    std::vector<Pair> m_touching;
    std::vector<Pair> m_touchingNow; ///< this step's, made in observe(); kept for its memory
    std::vector<char> m_bouncing;    ///< this step, per body (findBounces)
    std::vector<double> m_touchdown; ///< this step, per body that bounces [m] (findTouchdowns)
    bool m_resync = false;           ///< the next observe() only reads the state
    /// Total minus dissipated energy at the start, and what the drift is relative to [J].
    double m_energy0 = 0, m_energyScale = 1;
};

/// A question's measure read from the step's main world run without a window, from the
/// start, as the window runs it (for a question that holds back the running of the scene);
/// nullopt when the run does not get there within the step's exportTime (or the measure's
/// time, if later) or diverges first.
std::optional<double> measureAhead(const LessonStep& step, const Measure& measure);

/// Compares an answer with the measured value.
Verdict judge(const Question& q, double answer, const Measurements& m, const Scene& scene);

/// The same with the value at hand (nullopt: not measured yet), for the student's try number
/// `attempt` (1, 2, ...): a wrong first try reads the question's hint, not the value; later
/// tries, and a right answer, give it. `ahead`: the value was measured by a run without a
/// window (the window's run is held back), so the message says what the run will measure.
Verdict judgeAttempt(const Question& q, double answer, std::optional<double> value, int attempt,
                     bool ahead = false);

/// What the student reads on asking to be shown the answer (nullopt: not measured yet).
Verdict showAnswer(const Question& q, std::optional<double> value, bool ahead = false);

/// Judges the next try at a question as the lesson player does (an answer with
/// judgeAttempt, "Show me" with showAnswer) and counts it in `count`. The lesson player and
/// the worksheet, which judges a handed-in file's tries again, both judge here.
Verdict judgeTry(const Question& q, const AnswerTry& attempt, TryCount& count);

} // namespace rigidlab::lessons
