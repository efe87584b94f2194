#pragma once
// Joints as constrained dynamics (Witkin & Baraff, "Physically Based Modeling", constrained
// dynamics; CONTRACT §6). Each equality joint is up to three scalar constraints C(q) = 0 with
// Jacobian J. In every derivative evaluation the constraint forces Jᵀλ solve
//
//     (J·M⁻¹·Jᵀ)·λ = −J̇·u − J·M⁻¹·F
//
// so that the constrained acceleration keeps C̈ = 0: an integrator sees a smooth force and keeps
// its order on a jointed scene. There is no feedback term in the derivative; what drift the
// integrator leaves is removed after the step by projection (positions onto C = 0 by Newton
// steps in the mass metric, velocities onto J·u = 0), whose energy the world books as
// correction. Inequalities act after the step: a hinge past its limits is projected back and
// its outward rate removed, and a motor drives the joint's rate with a clamped impulse (its
// work is physical, work_nc). What holds a body still is an equality of the step too, while it
// holds: a rope taut and pulling, a hinge resting on a limit and pushing (HingeJoint.h).
//
// The system J·M⁻¹·Jᵀ couples joints that share a body. It is factored as a block LDLᵀ over
// the joint graph (one block per joint: 2×2 unless a weld or a hinge limit needs a third row,
// then 3×3), eliminated in minimum-fill order (physics/linear/BlockLdlt.h).
// For a chain or a tree of bodies this order makes no fill (tst_joints counts the blocks), so
// a solve is O(n) (the result Baraff 1996 gets by factoring the body–joint graph); loops add
// the fill they need. A body that holds many joints (a star's centre) would make them a
// clique: it enters the system as a node of its own (hubs_ below), and the star is a tree
// again. The symbolic part is built once in bind(); evaluations allocate nothing.

#include "physics/core/Bodies.h"
#include "physics/core/Types.h"
#include "physics/joints/JointRows.h"
#include "physics/linear/BlockLdlt.h"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

namespace phasebox {

struct JointErrors {
    double position = 0.0;  // m: the largest positional violation of any joint
    double angle = 0.0;     // rad: the largest angular one (welds, hinge limits)
};

class JointSolver {
public:
    // Resolves every joint's bodies to state indices (a static or pinned body is fixed where
    // it is) and builds the elimination order. Call after the world's layout is built.
    // A joint whose two ends are both fixed (bodies asleep, static or the world: a sleeping
    // island's joints) has nothing to act on: it is left out of the system and costs nothing;
    // its points and last forces are kept for drawing and the readouts.
    // carry: the layout changed only because islands fell asleep or woke (World's sleeping):
    // what the joints and bodies still held carry over by joint and body, so that a joint that
    // sleeps and wakes, and one that stayed awake meanwhile, steps on as it would have.
    void bind(const Bodies& bodies, bool carry = false);
    // The joints in the system: those that hold a body with a state (not sleeping ones). The
    // accessors below take a joint's index in the scene (Bodies::joints).
    int jointCount() const { return static_cast<int>(joints_.size()); }
    // Off-diagonal blocks of the factor L (pairs of joints coupled after elimination): the
    // pairs that share a body plus the fill. For chains and trees there is no fill.
    int factorBlocks() const { return pattern_.blockCount(); }
    bool hasMotors() const { return hasMotors_; }
    // Ropes or hinge limits: rows that switch on and off.
    bool hasInequalities() const { return hasInequalities_; }
    // A step starts: its first derivative evaluation finds which hinge limits the hinges rest on
    // and push against, and the step's evaluations hold those (HingeJoint.h). From the step's
    // start and the limits the last step held (heldLimit_, which snapshots keep with the rest).
    void holdLimitsFromNextEvaluation() { findLimits_ = true; }
    // The caller has changed the contents of weights: factors made with them do not stand.
    void weightsChanged(const Vec& weights) {
        if (factoredMass_ == &weights) factoredValid_ = false;
    }

    // accel holds M⁻¹·F of every other force; adds M⁻¹·Jᵀ·λ so that the joints' second
    // derivatives vanish.
    void constrainAccelerations(const Vec& q, const Vec& u, const Vec& invMass, Vec& accel);
    // The same in force form, for the implicit methods' residuals: force += Jᵀ·λ with λ from
    // M⁻¹·force. scratch is resized to the state's size.
    void constrainForces(const Vec& q, const Vec& u, const Vec& invMass, Vec& force, Vec& scratch);

    // After a step of h, in this order (the world books each phase's energy):
    // 1. shake: the equality joints' positions (and those of the ropes pulling at q0) back onto
    //    C = 0 along their directions at the step's start q0, the same impulse moving the
    //    velocities (Δu = Δq/h); the iterations are Anderson-mixed (accelerate()). This is SHAKE,
    //    the discrete constraint force of the method: with it symplectic Euler stays
    //    symplectic on the constraint manifold and a pendulum keeps its period, and its energy
    //    is the method's own (drift). Where the directions of the start do not converge (a
    //    link turning far in the step: a whip's tip), the iterations go on along the
    //    directions at the iterate (Newton's projection), still moving the velocities with the
    //    positions: a constraint force along the end's directions, the method's too. False
    //    when neither converged. With setImplicitStiffness(limit), the hinges and welds
    //    stiffer than the limit are first taken implicitly (see there).
    // alongEnd: the constraint force of a method that takes it at the step's end (backward
    //    Euler, IntegratorInfo::constraintsAtEnd): straight to the directions at the iterate.
    bool shake(double h, const Vec& q0, const Vec& u0, Vec& q, Vec& u, const Vec& invMass,
               bool alongEnd = false);
    // For the methods whose step ends x' = x + h·v' (symplectic and implicit Euler): a joint
    // under a force F holds a body's point at a lever arm r with a stiffness k = F·r on the
    // body's angle (geometricFrequency()), which those methods meet explicitly, stable only
    // while w = h²·k/I stays below 4: a chain's links zig-zag apart under a heavy weight or in
    // a whip. For a hinge or a weld k is the body's own (the point is linear in the body's
    // translation, curved only in its angle), so shake() can give a body with w > limit the
    // inertia I·w/limit for the step (the step's change of its rate shrinks by that factor, and
    // the constraint impulses act on the larger inertia), and its zig-zag then meets w = limit:
    // stable at any force, without sub-steps. This is selective mass scaling, as explicit
    // finite element codes use it: nothing is damped, and since the added inertia is h²·k/limit
    // and k is what makes the whole chain swing back, a slow mode of frequency ω changes its
    // period by about ½·(ω·h)²/limit (a 10 m pendulum on light links, at dt 1/60: 1.4e-4). What it
    // changes is the method's own error (drift). Bodies with w ≤ limit (a pendulum, a chain
    // below the tension that needs it) are untouched. 0: off.
    // The k a body is scaled for is held: the most of this step's and the held one decayed over
    // 2 s. Scaled for each step's k alone, the inertia followed the tension, which the scaled
    // zig-zag itself modulates at twice its frequency (a period of 2π steps at w = limit), and
    // the mode pumped itself: 1000 kg on 20 links gained 4-6 kJ of 12.5 kJ in 30 s, 5000 kg
    // 2-47 kJ of 62.5 kJ, as chaotic in the push's last digits. Held, the same chains stay
    // within 160 J and 640 J, whatever those digits.
    void setImplicitStiffness(double limit) { implicitLimit_ = limit; }
    // The inverse masses the last shake() moved the bodies with (invMass, or with the scaled
    // inertia of setImplicitStiffness): the velocity projection that completes the step takes
    // the same, so that the step is symplectic Euler on one mass matrix. Projected with the
    // true inertia instead, the light links took the projection's whole correction, and 2000 kg
    // on 20 hinged boxes pushed at 5 m/s diverged within 0.8 s (5000 kg within 2.4 s).
    const Vec& shakeWeights(const Vec& invMass) const {
        return stiffened_ ? stiffInvMass_ : invMass;
    }
    // 2. Newton steps in positions only for what remains: inequalities past their bounds (a
    //    rope snapping taut, a hinge past a limit) and whatever shake left. Error correction:
    //    its energy is `correction`.
    void correctPositions(Vec& q, const Vec& u, const Vec& invMass);
    // 3. Velocities onto the tangent: J·u = 0 for the equalities and the inequalities at their
    //    bounds moving outward. True when an inequality took part (an inelastic catch).
    // sameQ: q has not changed since the last call (the rows are reused when no inequality can
    // switch with the velocities).
    bool projectVelocities(const Vec& q, Vec& u, const Vec& invMass, bool sameQ = false);
    // A velocity change x onto the tangent of the rows the last projectVelocities() held:
    // x ← x − W·Jᵀ·(J·W·Jᵀ)⁻¹·J·x (the contacts' joined relax, ContactSolver::relaxJoined).
    void projectChange(Vec& x, const Vec& invMass);
    // 4. Motors: a clamped impulse on the hinge's rate (|τ| ≤ max_torque), alternating with
    //    step 3 (Box2D's motor with the joints re-projected). Where the method's step has given
    //    each motor its held torque's impulse already (held: addHeldMotorTorques() was in it),
    //    the impulse starts from that, the total clamped, as a contact's from its warm start.
    //    Returns the kinetic energy this adds or takes: the motors' work beyond their held
    //    torques'.
    double driveMotors(double h, const Vec& q, Vec& u, const Vec& mass, const Vec& invMass,
                       bool held);
    double lastMotorWork() const { return lastMotorWork_; }
    // The motors' torques of their last drive (its impulse over its step, |τ| ≤ max_torque),
    // held over the next method step as forces: −τ on end A's angle, +τ on end B's. The motor
    // then pushes inside the method's step as a contact's held force does, so the contacts meet
    // a wheel the motor keeps turning. Adds them to force; false when none is held.
    bool addHeldMotorTorques(Vec& force) const;

    // How many sub-steps a step of h needs so that no joint's geometry turns by more than
    // kMaxTurnPerStep in one (a rod's direction, a hinge's lever arm). Beyond that the step
    // is poor where it turns: SHAKE's directions of the start are far from the end's (it goes
    // on along the end's, shake()), and the velocity projection keeps about cos(φ/2) of the
    // speed of a link that turned by φ. A 1 m pendulum at 90° needs 1 up to dt 1/45; a chain's
    // whip needs a few to a dozen. A larger bound saves sub-steps on a whip but lets contacts
    // and joints trade energy over the longer steps, which books far more correction on a
    // ragdoll falling down stairs; the figures are in docs/performance.md ("Joint sub-steps").
    int substepsFor(double h, const Vec& q, const Vec& u) const;
    static constexpr double kMaxTurnPerStep = 0.1;  // rad
    static constexpr int kMaxSubsteps = 64;
    // A wanted count of sub-steps (rounded up already) as one from 1 to kMaxSubsteps; a
    // non-finite rate (the guard reports it) asks for 1.
    static int substepCount(double wanted) {
        if (std::isnan(wanted) || wanted < 1.0) return 1;
        return wanted >= kMaxSubsteps ? kMaxSubsteps : static_cast<int>(wanted);
    }
    // The highest frequency the joints' forces give the bodies they hold (rad/s): a joint
    // under a force F turns the lever arm r it holds a body by with a stiffness F·r (and a
    // distance joint of length d moves its ends sideways with F/d), so a chain pulled hard, as
    // by a heavy weight or in a whip, has fast modes in which its links zig-zag that an explicit
    // method steps stably only while ω·h stays below its bound. The bound taken here is
    // Gershgorin's on W·K with K the joints' geometric stiffness (the Hessian of λᵀ·C): no mode
    // of the free bodies is faster, and holding them by the joints only slows the modes down.
    // From the forces of the last derivative evaluation (forcesKnown()).
    // The hinges and welds are left out where setImplicitStiffness() takes them implicitly.
    double geometricFrequency(const Vec& q, const Vec& invMass);
    // False from bind() until a derivative evaluation has found the joints' forces.
    bool forcesKnown() const { return forcesKnown_; }

    // Where a pulley's rope end stops at its pulley: each side keeps at least this length, 1%
    // of the rope's (the pulleys are points; a body run up to one would otherwise go through
    // it, where the rope's direction turns over, and the light side of a 1000 : 0.1 kg pair
    // flew off). The stop is speculative, as Box2D's contacts are: the velocity projection
    // lets a side close in by at most what it has left in the next step, so that a fast body
    // cannot pass it within one. A body caught there is an inelastic catch (work_nc).
    static double pulleyStop(const Joint& j) { return std::max(0.01 * j.length, 1e-3); }
    // A rope counts as taut within this fraction of its length (a pulley's side at its stop
    // likewise), and within tautBand(length) of it.
    static constexpr double kTautFraction = 1e-9;
    static double tautBand(double length) { return kTautFraction * std::max(length, 1e-3); }
    // The joints' violation at q (every joint, inequalities by how far they are past).
    JointErrors errors(const Vec& q) const;
    // The magnitude of joint i's constraint force at the last evaluation (N; a weld's or a
    // hinge's force on its point, a rod's, rope's or pulley's tension, a track's normal force).
    // A joint left out of the system (asleep) keeps the force it had when it fell asleep.
    double force(int joint) const {
        const int k = active_[joint];
        return k >= 0 ? forces_[k] : idle_[joint].force;
    }
    // The constraint force on body a at its point, and on body b at its (N), at the last
    // evaluation: what force arrows draw.
    Vec2 forceOnA(int joint) const {
        const int k = active_[joint];
        return k >= 0 ? forceOn_[k][0] : idle_[joint].forceOn[0];
    }
    Vec2 forceOnB(int joint) const {
        const int k = active_[joint];
        return k >= 0 ? forceOn_[k][1] : idle_[joint].forceOn[1];
    }
    // What the last evaluations leave for the run's next step, kept across evaluations that are
    // not the run's (World::estimateLocalError's trial steps): the forces force() and forceOn*()
    // report, which the joints' sub-steps are taken from, and the cached rotations, which SHAKE
    // turned step by step (turnRotations(): bits a fresh rotation() does not give, so a trial step
    // that cached its own changed the run's next step), and the limits the step holds. Assigning
    // reuses the vectors' room.
    struct EvaluationRecord {
        std::vector<double> forces;
        std::vector<std::array<Vec2, 2>> forceOn;
        bool forcesKnown = false;
        std::vector<Mat2> rotations;
        Vec rotationsQ;
        bool rotationsKnown = false;
        std::vector<int> heldLimit;
        bool findLimits = true;
    };
    void keepEvaluation(EvaluationRecord& out) const {
        out.forces = forces_;
        out.forceOn = forceOn_;
        out.forcesKnown = forcesKnown_;
        out.rotations = rotations_;
        out.rotationsQ = rotationsQ_;
        out.rotationsKnown = rotationsKnown_;
        out.heldLimit = heldLimit_;
        out.findLimits = findLimits_;
    }
    void restoreEvaluation(const EvaluationRecord& kept) {
        forces_ = kept.forces;
        forceOn_ = kept.forceOn;
        forcesKnown_ = kept.forcesKnown;
        rotations_ = kept.rotations;
        rotationsQ_ = kept.rotationsQ;
        rotationsKnown_ = kept.rotationsKnown;
        heldLimit_ = kept.heldLimit;
        findLimits_ = kept.findLimits;
    }
    // World position of a joint's point on body a or b at q (for drawing).
    Vec2 pointA(int joint, const Vec& q) const;
    Vec2 pointB(int joint, const Vec& q) const;

private:
    using Mat3 = Eigen::Matrix3d;
    using Vec3 = Eigen::Vector3d;

    // A joint's ends, their state and its rows (JointRows.h).
    using End = joints::End;
    using EndState = joints::EndState;
    using Rows = joints::Rows;
    using Mode = joints::Mode;

    // cached: take the rotation from cacheRotations() (of this q) instead of cos and sin.
    EndState evaluate(const End& e, const Vec& q, const Vec& u, bool cached = false) const;
    // Each turning body's rotation at q, once, for the rows of every joint that holds it.
    void cacheRotations(const Vec& q);
    // rotations_ are those of q: cacheRotations(q), or SHAKE's turned ones where it ended at q.
    bool rotationsAreAt(const Vec& q) const { return rotationsKnown_ && sameBits(rotationsQ_, q); }
    void rotationsNowAt(const Vec& q) {
        rotationsQ_ = q;  // same size after the first: no allocation
        rotationsKnown_ = true;
    }
    // The last evaluateRows() was at this very q (bit for bit: a −0 that was +0 only costs an
    // evaluation).
    bool rowsAreAt(const Vec& q) const { return sameBits(rowsQ_, q); }
    // The cached rotations of bodies turned further by delta's angles (a SHAKE iteration's).
    void turnRotations(const Vec& delta);
    // The active rows of joint k at (q, u) in the given mode; without jacobian, all but J (the
    // rows' J of this q stand).
    void rowsOf(int k, Mode mode, const Vec& q, const Vec& u, Rows& rows, bool cached = false,
                bool jacobian = true) const;
    // rowsOf() with the Jacobian for a hinge's two point rows alone (no limit row), its ends at
    // a and b; centripetal: a's centripetal acceleration less b's.
    static void pointRowsOf(const Joint& j, const End& ea, const End& eb, const EndState& a,
                            const EndState& b, const Vec2& centripetal, Rows& r);
    // The equality rows' C of joint k at q (as rowsOf in Position mode computes it, without
    // the Jacobian), the rotations cached: what each SHAKE iteration needs.
    Vec3 violationOf(int k, const Vec& q) const;
    void evaluateRows(Mode mode, const Vec& q, const Vec& u);
    // λ of the equality rows for the unconstrained acceleration accel (a rope that would
    // push goes slack); keeps forces_.
    void solveDynamics(const Vec& q, const Vec& u, const Vec& invMass, const Vec& accel);
    // Leaves only the equality rows, the ropes pulling at the step's start and the limits the
    // step holds (heldLimit_: another hinge limit's and a pulley stop's rows go).
    void dropInequalities();
    double worstViolation() const;
    // Factors, solves J·W·Jᵀ·λ = −C (Target::Violation), target − J·u (Target::Rate) or −J·u
    // (Target::Zero), and adds scale·W·Jᵀ·λ to x.
    enum class Target { Violation, Rate, Zero };
    void solveFor(const Vec& invMass, Vec& x, double scale, Target target, const Vec& u);
    // J·x for joint k's rows (x a state-sized vector).
    Vec3 jTimes(int k, const Vec& x) const;
    // add(dof, W[dof], (Jᵀ·λ)[dof]) over every joint's dynamic ends (W = M⁻¹).
    template <class Add>
    void forEachJTranspose(const Vec& invMass, Add&& add) const;
    // x += scale·W·Jᵀ·λ over every joint.
    void addJTranspose(const Vec& invMass, double scale, Vec& x) const;
    // Assembles J·W·Jᵀ from rows_, factors it and solves for lambda_ from rhs_.
    void factor(const Vec& invMass);
    // SHAKE's iterations: turns the plain step in lambda_ into the Anderson-mixed one, from the
    // last iteration's (withPrevious) or, at the first, keeps it.
    void accelerate(bool withPrevious);
    // shake()'s implicit stiffness: the velocities and positions of the bodies it scales, and
    // the inverse masses their impulses take (invMass itself when no body needs it).
    const Vec& stiffen(double h, const Vec& u0, Vec& q, Vec& u, const Vec& invMass);
    // shake()'s continuation along the directions at the iterate; true once converged.
    bool shakeAlongEnd(double h, Vec& q, Vec& u, const Vec& weights);
    // SHAKE's violation at q (the rotations cached) into rhs_ as −C; returns the largest.
    double shakeViolation(const Vec& q);
    // q += W·Jᵀ·λ and u += W·Jᵀ·λ/h, W the given weights; the move stays in impulse_.
    void applyShakeImpulse(double h, const Vec& weights, Vec& q, Vec& u);

    void solve();

    std::vector<Joint> joints_;  // those in the system
    // Per scene joint: its index in joints_, or −1 for one left out (bind()); per joint in
    // joints_: its scene index.
    std::vector<int> active_, sceneIndex_;
    // What a joint left out keeps: its fixed ends and its last forces.
    struct Idle {
        End a, b;
        double force = 0.0;
        std::array<Vec2, 2> forceOn{Vec2::Zero(), Vec2::Zero()};
    };
    std::vector<Idle> idle_;
    // What bind(carry) carries over from the joints and bodies of the last bind().
    void carryFrom(const JointSolver& old);
    std::vector<int> turningBodies_;  // per slot: the turning body's index (Bodies::rigidBodies)
    // Per rigid body asleep: the stiffness it held when it fell asleep (bind(carry)).
    std::vector<double> sleptStiffness_;
    std::vector<int> turningDofs_;  // per slot: the turning body's first state index
    std::vector<Mat2> rotations_;   // per slot: R(θ) at rotationsQ_
    Vec rotationsQ_;                // the q of rotations_, where rotationsKnown_
    bool rotationsKnown_ = false;
    Vec impulse_;  // SHAKE: the last move W·Jᵀ·λ per state index
    std::vector<End> endA_, endB_;
    bool hasMotors_ = false, hasInequalities_ = false;
    // Per joint: the hinge limit the step holds in its evaluations (joints::kNoLimit, …), found
    // by the first evaluation after holdLimitsFromNextEvaluation().
    std::vector<int> heldLimit_;
    bool findLimits_ = true;
    // shakeAlongEnd() is projecting: its rows in positions hold the step's limits too (the
    // position projections after the step and after the contacts take only limits passed).
    bool shakingAlongEnd_ = false;
    // projectVelocities(): the rows of its last pass, and how many passes follow the first.
    std::vector<Rows> keptRows_;
    static constexpr int kVelocityPasses = 4;
    double lastMotorWork_ = 0.0;
    double shakeReach_ = 0.01;        // m: the largest violation SHAKE answers with an impulse
    double shakeCeiling_ = 0.0;       // m: the most SHAKE leaves (kShakeCeiling, below ropes' band)
    double shakeTolerance_ = 1e-10;   // m: where the last shake() stopped (correctPositions() too)
    double projectionFloor_ = 1e-14;  // m: the least error a projection aims at (shake())
    double stepLength_ = 0.0;         // s: the last shake()'s h, for the pulleys' stops
    double implicitLimit_ = 0.0;      // setImplicitStiffness()
    Vec stiffInvMass_;                // stiffen(): invMass with the stiff bodies' larger inertia
    bool stiffened_ = false;          // the last stiffen() scaled a body: stiffInvMass_ holds
    std::vector<double> heldStiffness_;  // stiffen(): per turning body, the stiffness it holds

    // Per evaluation (sized in bind).
    std::vector<Rows> rows_;
    Vec rowsQ_;                       // the q of the last evaluateRows()
    Mode rowsMode_ = Mode::Position;  // and its mode
    std::vector<char> ropeShaken_;    // per joint: a rope the last shake() held
    std::vector<Vec3> rhs_, lambda_;
    // SHAKE's Anderson mixing: the last plain step f and the last move, and a ring of the last
    // kAndersonDepth differences of f and of λ.
    static constexpr int kAndersonDepth = 3;
    std::vector<Vec3> previousStep_, lastDelta_;
    std::array<std::vector<Vec3>, kAndersonDepth> andersonDf_, andersonDl_;
    int andersonCount_ = 0, andersonNext_ = 0;
    // The Δf's products with each other, by ring slot (those of the filled slots hold).
    Eigen::Matrix<double, kAndersonDepth, kAndersonDepth> andersonGram_;
    std::vector<double> forces_;
    bool forcesKnown_ = false;
    std::vector<double> stiffness_;  // per state index: geometric stiffness (geometricFrequency)
    std::vector<std::array<Vec2, 2>> forceOn_;
    std::vector<double> motorImpulse_;
    std::vector<double> heldMotorTorque_;  // N·m per joint: the last drive's (driveMotors())
    // Joint k's held torque: 0 without a motor that both ends take, within its max_torque.
    double heldTorque(int k) const;

    // The block LDLᵀ of J·W·Jᵀ (physics/linear/BlockLdlt.h): a node per joint, by elimination
    // position. B = 2 when no joint can have a third row (no weld, no hinge with limits).
    BlockLdltPattern pattern_;
    BlockLdlt<2> factors2_;
    BlockLdlt<3> factors3_;
    int blockRows_ = 3;  // B: the most rows any joint can have
    // Assembles J·W·Jᵀ of rows_ into f's blocks and factors it.
    template <int B>
    void factorBlocks(BlockLdlt<B>& f, const Vec& invMass);
    // lambda_ from rhs_ with f's factors.
    template <int B>
    void solveBlocks(BlockLdlt<B>& f);
    // The rows' Jacobians change only where rowsChanged() says so: the factors of the same
    // version and inverse masses stand (a step's end is the next step's start: the velocity
    // projection, the next derivative evaluation and SHAKE all ask for J(q1)).
    void rowsChanged() { ++rowsVersion_; }
    std::uint64_t rowsVersion_ = 0, factoredVersion_ = 0;
    const Vec* factoredMass_ = nullptr;
    bool factoredValid_ = false;
    // Couplings of the assembly: off-diagonal block t gets J_i,side·W·J_k,sideᵀ over a shared
    // body.
    struct Coupling {
        int block, i, sideI, k, sideK;
    };
    std::vector<Coupling> couplings_;
    // A body holding more than kHubJoints joints (a star's centre) is a node of the system
    // with its own unknowns, its velocity change, instead of coupling each pair of its joints:
    // a star of n joints is then a tree of n + 1 nodes, factored in O(n), where the pairs make
    // a clique whose dense factor is O(n³). Kept for larger bodies only, as the pairs are fewer
    // blocks below that and keep the blocks at 2×2 where every joint has two rows.
    static constexpr int kHubJoints = 8;
    struct Hub {
        int dof, dofs;  // first state index; 2 (particle) or 3 (rigid body)
    };
    std::vector<Hub> hubs_;
    struct HubCoupling {
        int block, joint, side, hub;
        bool jointLater;  // the joint is eliminated after the hub
    };
    std::vector<HubCoupling> hubCouplings_;
};

// In the header: every row evaluation takes it twice, and as a call it was a tenth of their cost.
inline JointSolver::EndState JointSolver::evaluate(const End& e, const Vec& q, const Vec& u,
                                                   bool cached) const {
    EndState s;
    if (e.dof < 0) {
        s.p = e.fixed;
        s.angle = e.angle0;
        return s;
    }
    if (!e.turns) {
        s.p = q.segment<2>(e.dof);
        s.v = u.segment<2>(e.dof);
        return s;
    }
    s.angle = q[e.dof + 2];
    s.omega = u[e.dof + 2];
    s.arm = (cached ? rotations_[e.slot] : rotation(s.angle)) * e.local;
    s.p = q.segment<2>(e.dof) + s.arm;
    s.v = u.segment<2>(e.dof) + s.omega * perp(s.arm);
    return s;
}

inline JointSolver::Vec3 JointSolver::jTimes(int k, const Vec& x) const {
    const Rows& r = rows_[k];
    Vec3 out = Vec3::Zero();
    for (const auto& [end, jac] : {std::pair{&endA_[k], &r.ja}, std::pair{&endB_[k], &r.jb}}) {
        if (end->dof < 0) continue;
        out += jac->col(0) * x[end->dof] + jac->col(1) * x[end->dof + 1];
        if (end->turns) out += jac->col(2) * x[end->dof + 2];
    }
    return out;
}

}  // namespace phasebox
