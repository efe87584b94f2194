#pragma once
// Sequential impulses on contact constraints, after the smooth step of every sub-step.
//
// The scheme is Box2D v3's soft step, adapted to a solver that runs after the integrator:
// per sub-step of length h, with s the separation at the sub-step's start,
//   warm start → bounce → soft solve → move positions by h·Δv → relax.
// - Soft solve: a penetrating contact (s < 0) is a spring-damper of `hertz` and
//   `dampingRatio` whose push-out speed is capped at `pushOut`; a speculative one (s > 0) only
//   forbids closing more than the gap in this sub-step (v_n ≥ −s/h), which also catches fast
//   bodies before they pass through thin walls. The two points of a manifold are solved
//   together (a 2×2 block), which keeps tall stacks from tipping.
// - Relax: the same constraints without the push-out bias, on velocities only, so that the
//   position correction leaves no velocity behind (no energy is added by removing overlap).
// - Restitution first, on the current velocities, in passes until no contact that meets
//   within the sub-step approaches faster than the threshold: v_n ← −e·v_n (exactly
//   energy-conserving for e = 1, and the passes let a Newton's cradle hand its momentum down
//   the row ball by ball). An isolated pair is also moved to where it would be had it bounced
//   at its time of impact, so that a rebound's height is right.
// - Friction: Coulomb, each point's tangent impulse clamped to μ times its normal impulse.
// - Warm starting: accumulated impulses carry over from step to step when a contact's
//   pair and feature ids persist.
// - Order: the constraints are graph-coloured each step (no two in a colour share a dynamic
//   body) and swept colour by colour, eight at a time with AVX-512 where the CPU has it, four
//   at a time with AVX2, one by one in the same order otherwise (bit-identical every way).

#include "physics/contacts/Geometry.h"
#include "physics/core/LargeBuffer.h"
#include "physics/core/Types.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace phasebox {

class WorkerPool;

struct ContactSettings {
    int substeps = 0;         // inner sub-steps per step; 0 = the solver's choice (deep
                              // stacks get more: ContactSolver::stackSubsteps)
    int iterations = 3;       // soft solve iterations per inner sub-step (doubled across mass
                              // ratios of 10 or more)
    int relaxIterations = 1;  // bias-free iterations per inner sub-step
    double hertz = 60.0;      // contact stiffness (raised with extra sub-steps; capped at a
                              // quarter of the inner sub-step rate)
    double dampingRatio = 10.0;
    double pushOut = 3.0;               // m/s: the fastest overlap is removed
    double restitutionThreshold = 1.0;  // m/s, times 1 − e: slower impacts do not bounce
    double speculativeDistance = 0.02;  // m: contacts are made this far ahead of touching
    // A pair of colliders neither of which has moved since its contact was found keeps that
    // contact instead of a narrow phase (ContactStage's frames); off: every pair found anew
    // (tests and benchmarks compare the two).
    bool keepStillContacts = true;
};

// A body as the solver sees it during one step: what the stage sets (dof, rotates, masses,
// where the contacts were found) and the step's bookkeeping, touched a few times per inner
// sub-step. The velocities the iterations read and write live apart (ContactSolver::BodyState).
struct SolverBody {
    int dof = -1;  // first state index
    bool rotates = false;
    // A disk: its surface turns into itself, so its turn moves none of its contact points'
    // separations (a rolling wheel's contact point is always the one below its centre).
    bool round = false;
    bool jointed = false;  // a joint holds it (refreshHeld())
    double invMass = 0.0;
    double invInertia = 0.0;
    double mass = 0.0;  // 1 / invMass, once a step (prepare(): a body has several contacts)
    Vec2 collidePosition = Vec2::Zero();  // where its contacts are measured from (its frame)
    double collideAngle = 0.0;
    // The step: velocity at its start, the smooth step's velocity change, and the start's
    // offset from where the contacts were found.
    Vec2 v0 = Vec2::Zero(), smoothDv = Vec2::Zero(), startOffset = Vec2::Zero();
    double w0 = 0.0, smoothDw = 0.0, startAngle = 0.0;
    // Of the smooth step's change, the held contact forces' share (solveStep's holding): the
    // rest presses the body into its contacts (which body rests on which, restitution).
    Vec2 heldDv = Vec2::Zero();
    double heldDw = 0.0;
    // The solver's own path through the inner sub-steps (Σ h·v), where separations are measured.
    Vec2 path = Vec2::Zero();
    double anglePath = 0.0;
    Vec2 bounceDv = Vec2::Zero();  // the bounces' velocity change so far (instant, at impact)
    double bounceDw = 0.0;
    Vec2 shift = Vec2::Zero();  // displacement by the contact impulses so far
    double angleShift = 0.0;
    Vec2 timeShift = Vec2::Zero();  // a bounce's time-of-impact correction
    double angleTimeShift = 0.0;
    Vec2 pushV = Vec2::Zero();  // velocity before the bounces, then before relax
    double pushW = 0.0;
    Vec2 pushOut = Vec2::Zero();  // the position correction (push-out) of this step
    double pushOutAngle = 0.0;
    // What relax's impulses at closing points changed in this sub-step (bookClosings()).
    Vec2 impactDv = Vec2::Zero();
    double impactDw = 0.0;
    int contactCount = 0;  // constraints this step
    // The vector sum of the contact impulses the body received this step (N·s): warm start,
    // bounces, soft solve and relax of every inner sub-step, over the world's sub-steps and the
    // joints' interleaved relax. Divided by the step it is the mean contact force (probes).
    Vec2 stepImpulse = Vec2::Zero();
};

struct ContactPoint {
    Vec2 anchorA = Vec2::Zero();  // from each body's centre to the contact point, at collide
    Vec2 anchorB = Vec2::Zero();
    double baseSeparation = 0.0;  // separation when found
    double normalMass = 0.0;
    double tangentMass = 0.0;
    double normalImpulse = 0.0;  // accumulated
    double tangentImpulse = 0.0;
    // Of those, what the last inner sub-step's solve and relax gave (per inner sub-step: the
    // next step's warm start); the rest came from relaxJoined() after the step, once for the
    // whole step.
    double solvedNormal = 0.0, solvedTangent = 0.0;
    // The force the impulses of the step before the last stood for (a bound for the held force:
    // single precision is enough), and the force held over the next step (refreshHeld()), each
    // along the normal and the tangent.
    float lastNormal = 0.0f, lastTangent = 0.0f;
    double heldNormal = 0.0, heldTangent = 0.0;
    std::uint32_t id = 0;
};

struct ContactConstraint {
    std::uint64_t key = 0;       // the shape pair, for matching across steps
    int bodyA = -1, bodyB = -1;  // solver body indices, −1 = static
    Vec2 normal = Vec2::Zero();  // from A to B
    double friction = 0.0;
    double restitution = 0.0;
    double stiffness = 1.0;  // multiplier of the contact hertz (see prepare())
    // Overlap beyond this is pathological (bodies spawned into each other, a pile started at
    // one point): it is pushed out in positions only, never by a velocity (deepPushOut()).
    // ContactStage sets it to kDeepOverlapFraction of the smaller body's least half extent (a
    // disk's radius).
    static constexpr double kDeepOverlapFraction = 0.1;
    double deepOverlap = std::numeric_limits<double>::infinity();
    int pointCount = 0;
    // Last frame's, kept as it was (ContactStage's frames): its masses and stiffness stand.
    bool kept = false;
    // Its bodies' relative speed at collide could make an impact (above the restitution
    // threshold): without restitution too, the bounce passes look at it (bounce()).
    bool fast = false;
    ContactPoint points[2];
};

// A step's contacts (tens of megabytes in a dense pile: LargeBuffer.h).
using ConstraintList = LargeVector<ContactConstraint>;

// The joints as relaxJoined() sees them: x ← x − W·Jᵀ·(J·W·Jᵀ)⁻¹·J·x, a velocity change
// projected onto their tangent in the mass metric (JointSolver::projectChange).
class TangentProjection {
public:
    virtual void project(Vec& x) const = 0;

protected:
    ~TangentProjection() = default;
};

class ContactSolver {
public:
    // Room for bodies and contact constraints up front, so that a scene's first steps do not
    // grow the buffers one doubling at a time (ContactStage::bind).
    void reserve(std::size_t bodies, std::size_t constraints);
    // The threads the solver's passes share (null: the calling thread alone); the results are
    // bit-identical either way (forChunks()).
    void setPool(WorkerPool* pool) { pool_ = pool; }
    std::vector<SolverBody>& bodies() { return bodies_; }
    const std::vector<SolverBody>& bodies() const { return bodies_; }
    ConstraintList& constraints() { return constraints_; }
    const ConstraintList& constraints() const { return constraints_; }

    // Computes effective masses; call after the constraints and bodies are set for a step.
    void prepare();

    // One step of h: (q0, u0) is the state at its start, (q, u) after the smooth step; on
    // return (q, u) satisfy the contacts. The solver takes its own inner sub-steps
    // (innerSubsteps()): per inner sub-step the smooth velocity change, warm start, soft solve,
    // positions, relax.
    // positionWeight: the integrator's IntegratorInfo::positionWeight.
    // holding: the smooth step held the constraints' forces (addHeldForces() of these very
    // constraints): that share of the warm start has already acted in every inner sub-step, so
    // only the rest is applied, and the accumulated impulses start from the whole.
    void solveStep(double h, const Vec& q0, const Vec& u0, Vec& q, Vec& u,
                   const ContactSettings& settings, double positionWeight, bool holding);
    // After solveStep, where contacts touch jointed bodies: the last sub-step's bias-free rows
    // solved once more, from and to the world's velocities u, in the joints' tangent space, so
    // that a body both touching and jointed (a car's wheel, a ragdoll's foot) is held by both at
    // once. Each contact row's impulse moves the bodies by W'·gᵀ, W' = W − W·Jᵀ(J·W·Jᵀ)⁻¹·J·W
    // the inverse mass with the joints held (the Schur complement of the joint rows): one
    // projected Gauss-Seidel over the contact rows in which the joints hold exactly at every
    // update, instead of the two solvers taking turns. u must satisfy the joints on entry (it
    // does on return, to round-off). The accumulated impulses carry on from the step.
    void relaxJoined(Vec& u, const TangentProjection& joints);
    // Keeps the rows' accumulated impulses in the constraints, for the next step's warm start
    // and held forces (solveStep does; call after relaxJoined).
    void keepImpulses() { keepStep(false); }
    bool empty() const { return constraints_.empty(); }
    // The contact forces the kept impulses stand for, held over the next step (Box2D's warm
    // start, taken into the method's step as a force): per state index, each point's held force
    // (refreshHeld()) with its torque about the body's centre. Adds them to force; false when
    // no point holds one.
    bool addHeldForces(Vec& force) const;
    // After a trial solve of a first step (World::primeContactForces): each point's force is
    // held over the next step as it is, with no step before it to bound it.
    void primeHeld();
    // The strength of the uniform field (m/s², gravity's |g|; 0 without one) that bounds the
    // force held on a contact between two jointed bodies (refreshHeld()). The world sets it
    // at each collide().
    void setWeightField(double strength) { weightField_ = strength; }
    // That bound: this many times the two bodies' weight in the field.
    static constexpr double kJointedHoldWeights = 4.0;
    // A point of a jointed body found open at the frame's collide by more than this share of
    // the contact's deep overlap (1% of the smaller body's half-size) holds no force over the
    // next method step (refreshHeld()).
    static constexpr double kHeldOpenShare = 0.1;
    // Adds scale times the last step's position correction (push-out) to q.
    void addPushOut(Vec& q, double scale) const;
    // A body jammed into static geometry: one the deep push-out has moved out of it in each of
    // the last kJammedSolves solveStep() calls (a limb the joints press into a stair's corner,
    // under the weight of the body they hold it to). Where there is one, out becomes weights
    // (inverse masses, by state entry) with a jammed body's times factor, and the call returns
    // true (World::rejoin).
    static constexpr int kJammedSolves = 3;
    bool jammedWeights(const Vec& weights, double factor, Vec& out) const;

    // Inner sub-steps per step of h: at least kInnerRate per second (settings.substeps > 0
    // overrides).
    static constexpr double kInnerRate = 240.0;
    static constexpr int kMaxInnerSubsteps = 64;
    // The deepest sag a stack may take at the default stiffness before the solver adds inner
    // sub-steps (stiffer with each), and the passes that sum sag down support chains.
    static constexpr double kSagTarget = 0.04;
    // A taller stack may sag by this share of its height (its centre's height above the ground,
    // up its support chain): a 100 m pyramid sagging 10 cm looks to the class as a 40 m tower
    // sagging 4 cm. Below 40 m, kSagTarget.
    static constexpr double kSagHeightShare = 0.001;
    static double allowedSag(double height) {
        return std::max(kSagTarget, kSagHeightShare * height);
    }
    // The deepest a loaded contact may rest at the default stiffness, as a share of its
    // deep-overlap bound (a tenth of the smaller body's half-size): past that bound the push-out
    // moves positions only, so a stack of small bodies resting there is pushed apart and falls.
    static constexpr double kLoadedSinkShare = 0.25;
    static constexpr int kMaxSagPasses = 256;
    static constexpr int kStepsBeforeFewer = 120;
    static constexpr int kStepsBeforeMore = 30;
    static constexpr double kMassRatioForMoreIterations = 10.0;
    static constexpr int kDeepPushOutPasses = 4;
    static int innerSubsteps(double h, const ContactSettings& settings);
    // The inner sub-steps the last solveStep took (innerSubsteps() or more for a deep stack).
    int lastSubsteps() const { return lastSubsteps_; }
    // The sag the solver predicted for its deepest stack at innerSubsteps(), from the warm-start
    // impulses: each contact sinks by its force over its stiffness, summed down support chains.
    double predictedSag() const { return predictedSag_; }

    // The hot per-body state the iterations touch (40 bytes). Index bodies_.size() is the
    // static world: zero velocity and zero inverse masses, so a row needs no branch for it.
    struct BodyState {
        double vx, vy, w;
        double invMass, invInertia;
    };
    // kLanes rows of one graph colour side by side (no two share a dynamic body), lane by lane,
    // for the wide kernels (ContactWideLoop.inc). Unused lanes join the static world to itself
    // with zero masses. Eight lanes: each lane's solve is a long chain of dependent operations,
    // so more independent lanes per pass keep the processor's units busy (AVX-512 does eight at
    // once; AVX2 does them as two halves, one after the other).
    static constexpr int kLanes = 8;
    // What the solve sweeps read and write, and nothing else: over rows too many for the core's
    // own cache (the 100-row pyramid's) a sweep streams these lines and no others. A body's
    // inverse mass is not here: the sweep takes it with the body's velocities (its state's fourth
    // double). What the other passes read is in WideCold, at the same index.
    struct alignas(64) WideRow {
        int a[kLanes], b[kLanes];
        double nx[kLanes], ny[kLanes], friction[kLanes], iA[kLanes], iB[kLanes];
        double k11[kLanes], k12[kLanes], k22[kLanes];
        // The phase's block terms (RowSetup's blockTerms() where the phase solves the two points
        // as a block, else zeros: invA11 ≠ 0 says the lane's block is solved, and its a12 is k12).
        double i11[kLanes], i12[kLanes], i22[kLanes], invA11[kLanes], invA22[kLanes];
        struct Point {
            double rnA[kLanes], rnB[kLanes], rtA[kLanes], rtB[kLanes];  // RowPoint's
            double bias[kLanes];                                        // the phase's bias velocity
            double tangentMass[kLanes], normalImpulse[kLanes], tangentImpulse[kLanes];
            // The phase's soft terms: the sweep reads them only in a wide row where some lane's
            // block is not solved (effectiveMassOf() reads the mass too).
            double effectiveMass[kLanes], impulseScale[kLanes];
        } p[2];
    };
    // The rest of a wide row's lanes: the anchors, the held forces and the separations (the warm
    // start, the phase terms and the separations' passes).
    struct alignas(64) WideCold {
        struct Point {
            double rAx[kLanes], rAy[kLanes], rBx[kLanes], rBy[kLanes];
            double heldNormal[kLanes], heldTangent[kLanes];  // the held force per sub-step
            double baseSeparation[kLanes];
            double separation[kLanes];  // where the solver's path is now (separationOf())
        } p[2];
        int points[kLanes];  // each lane's point count (0: an unused lane)
    };
    // A wide row's points that close in an inner sub-step (speculative in its soft solve, touching
    // when relax measures them), and their impulses as relax finds them: what relax adds there
    // is the impact's (bookClosings()). Written only where some lane closes.
    struct alignas(64) WideClosing {
        long long mask[2][kLanes];  // −1 where the lane's point closes
        double normal[2][kLanes], tangent[2][kLanes];
    };
    // Box2D v3 takes 24 colours; a pile of disks started at one point gives a disk 30 to 40
    // contacts in its first steps, and with 24 colours 41% of its rows went to the overflow,
    // solved one by one after the lanes (none with 64). The sweeps pass only the colours in use.
    static constexpr int kColours = 64;
    // The instruction set of the wide kernels: 0 none (the rows one by one, in the same order), 1
    // AVX2, 2 AVX-512; the best the processor has unless set. Every level gives the same bits (the
    // tests run each). useInstructions() is false for a level the processor lacks; it is for tests
    // and benchmarks, between steps, on one thread.
    static int instructions();
    static bool useInstructions(int level);
    // Where a body is now relative to where its contacts were found: Δp and R(Δθ), once per
    // solver phase.
    struct BodyMotion {
        double dx, dy, cos, sin;
    };
    // What the phases are built from, per row (cold: read once per phase).
    struct RowSetup {
        double biasRate, massScale, impulseScale;
        double normalMass[2], compliance[2];
        double deepOverlap;
        double pushOutShare;
        bool blockable;  // two points whose K is well conditioned
    };
    // RowSetup lane by lane, beside the wide rows (read once per phase, with vector loads).
    struct alignas(64) WideSetup {
        double biasRate[kLanes], massScale[kLanes], impulseScale[kLanes];
        double normalMass[2][kLanes], compliance[2][kLanes];
        double deepOverlap[kLanes], pushOutShare[kLanes];
        long long blockable[kLanes];  // −1 where blockable, else 0
    };
    // A phase's constants: 1/h, the push-out speed, and whether it is a soft solve (else relax).
    struct PhaseTerms {
        double invH, maxPushOut;
        bool useBias;
    };

private:
    struct Softness {
        double biasRate, massScale, impulseScale;
    };
    // A contact point as the iterations see it. The phase terms (bias, effectiveMass,
    // impulseScale) depend only on the separation, which is fixed within a phase (a soft solve
    // or a relax): preparePhase() sets them once per phase, not once per iteration.
    struct RowPoint {
        double rAx, rAy, rBx, rBy;  // anchors (zero on the static side)
        // The anchors across the normal and the tangent, r × n and r × t (buildRow()): the
        // solve's relative velocity along n is n·(v_B − v_A) + ω_B·(r_B × n) − ω_A·(r_A × n), and
        // an impulse λ·n turns a body by I⁻¹·(r × n)·λ.
        double rnA, rnB, rtA, rtB;
        double bias;           // the phase's bias velocity
        double effectiveMass;  // normalMass times the phase's mass scale (0: inactive)
        double impulseScale;   // the phase's impulse scale
        double tangentMass;
        double normalImpulse, tangentImpulse;
        // Fixed for the step, read by the per-phase passes (updateSeparations, warmStart) with the
        // rest of the row, so that they do not walk the constraints: the separation when found,
        // and what the held force gives in one inner sub-step.
        double baseSeparation;
        double heldNormal, heldTangent;
        // Relax's: the point closes in this sub-step, and its impulses as relax found them
        // (WideClosing's, for the rows no lane took).
        bool closing;
        double relaxStartNormal, relaxStartTangent;
    };
    // A constraint as the iterations see it: built once per step from ContactConstraint with
    // everything that does not change within the step (masses, the block's K), and per phase
    // the block's inverse.
    struct Row {
        int a, b;  // BodyState indices
        int pointCount;
        bool block;  // the phase solves the two points as a block
        double nx, ny, friction;
        double k11, k12, k22;
        // The phase's block matrix A = K + diag(compliance): a12 and A⁻¹ (symmetric), and the
        // single-point fallbacks 1/a11, 1/a22.
        double a12, i11, i12, i22, invA11, invA22;
        RowPoint p[2];
    };

    // The passes over rows, bodies and each colour's wide rows run as chunks of a range
    // (fn(first, end)). Below the thresholds (kRowGrain rows, kBodyGrain bodies, kWideGrain wide
    // rows in a colour) a pass is a few tens of microseconds, not worth the hand-off to a worker
    // (about a microsecond while it spins, tens when it must be woken): it runs at once on the
    // calling thread, so that small and middling scenes stay on one thread. Above them a pass
    // goes by kBlocks blocks: equal parts of the bodies, or of the rows (which follow the
    // bodies' order), and in each colour the rows one of whose bodies is in a part (ordered so
    // by colourRows). A worker starts on the same blocks in every pass (WorkerPool), so a
    // body's state stays in its core's cache through the colours, the iterations and the
    // sub-steps; only rows across two workers' blocks move it. (Cut by count into chunks taken
    // in turn, a fifth of the bodies a colour's pass touched had last been written by the other
    // worker, and on a machine whose cores are 250 ns apart two workers took longer than one.)
    // The blocks depend on the counts only, never on the number of workers, and no two chunks
    // of a pass touch the same row or dynamic body (a colour's rows share none), so the results
    // are bit-identical however many workers take them. A loop ends when its last chunk does:
    // with 16 blocks the caller waited about 1.5 µs a loop for the other worker's last one on
    // the 100-row pyramid (about 290 loops a step), with 32 about 0.9 µs.
    static constexpr std::size_t kRowGrain = 4096;
    static constexpr std::size_t kBodyGrain = 4096;
    static constexpr std::size_t kWideGrain = 1024 / kLanes;  // 1,024 rows
    static constexpr int kBlocks = 32;
    // Where block `block` of [0, count) starts: item i is in block ⌊i·kBlocks/count⌋.
    static std::size_t blockStart(std::size_t count, int block) {
        return (count * static_cast<std::size_t>(block) + kBlocks - 1) / kBlocks;
    }
    // fn(first, end) over [0, count): at once up to `grain` items, else block by block.
    template <class F>
    void forChunks(std::size_t count, std::size_t grain, const F& fn);
    // fn(first, end) over a colour's wide rows: at once, or (above kWideGrain) block by block.
    template <class F>
    void forColour(int colour, const F& fn);
    // fn(first, end) over every colour's wide rows, for a pass whose rows are independent of one
    // another (each chunk writes its own rows only): in one loop, not colour by colour.
    template <class F>
    void forColours(const F& fn);
    // Whether a colour has more wide rows than kWideGrain (its sweep is shared with a pool).
    bool wideColour(int colour) const {
        return static_cast<std::size_t>(colourWide_[colour + 1] - colourWide_[colour]) > kWideGrain;
    }
    WorkerPool* pool_ = nullptr;

    void loadBodies(const Vec& q0, const Vec& u0, const Vec& u);
    bool holding_ = false;  // this solveStep's holding
    // Sub-steps for this step: `base`, or more when the stack the warm-start impulses carry
    // would sag further than its height allows (allowedSag()) at the base stiffness (after
    // loadBodies).
    int stackSubsteps(double h, int base, const ContactSettings& settings);
    // depth_ from supports_: how far each body sinks down its support chains, and height_ how
    // high its centre stands up them (0 on a cycle), in the supports'
    // topological order (Kahn's, left in supportReady_ with supportStart_ and supportOrder_,
    // the supports by lower body); false where they form a cycle (then by passes).
    bool sagDepths();
    // depth_ again in sagDepths()' order (after weightSinks() set the sinks).
    void depthsInOrder();
    // The first solve's sinks, from the weights pressed down the supports (in sagDepths()'
    // order, which it needs); returns the deepest over the most a contact may sink.
    double weightSinks(double h, double omega);
    // What a row is built from besides its constraint: the step's softness and warm start.
    struct BuildTerms {
        double hertz, zeta, h, warmScale;
    };
    void buildRows(double hertz, double zeta, double h, double warmScale);
    // Row i from its constraint, into row and setup: rows_[i] and setup_[i] for a row the scalar
    // passes read, a copy on the stack for one that goes straight into its lane (buildLanes()).
    // buildRow()'s last softness and push-out share, by the stiffness and the count they were
    // made from (one per chunk of rows).
    struct RowCache {
        double hertz = std::numeric_limits<double>::quiet_NaN();
        Softness soft{};
        int sharers = 0;
        double share = 0.0;
    };
    void buildRow(std::size_t i, Row& row, RowSetup& setup, const BuildTerms& terms,
                  RowCache& cache);
    // A row's softness this step, and its push-out share in cache.share.
    Softness stepSoftness(const ContactConstraint& c, const BuildTerms& terms, RowCache& cache);
    // Wide row r holds in every lane the kept contact it held last step (laneKey_), none
    // bouncing: refreshLanes() writes only what changes from step to step.
    bool sameLanes(std::size_t r) const;
    void refreshLanes(std::size_t r, const BuildTerms& terms, RowCache& cache);
    static constexpr std::uint64_t kNoLane = ~std::uint64_t{0};
    std::vector<std::uint64_t> laneKey_;  // per wide slot: the kept contact built there, or kNoLane
    // Row i's bounce terms (a row with restitution), from the row as buildRow() made it: where
    // it is built, so that a lane's row need not be kept in rows_ for bounce().
    void fillBounce(std::size_t i, const Row& row, const RowSetup& setup);
    void warmStart();
    void warmRow(std::size_t row);
    // Restitution in an inner sub-step of h, one of `substeps` of the step.
    bool bounce(double h, int substeps, const ContactSettings& settings);
    double smoothNormalChange(const Row& c, const RowPoint& p) const;
    static Softness makeSoft(double hertz, double zeta, double h);
    // The phase's per-row terms from the current separations (useBias: soft solve, else relax).
    // measure: the bodies moved since the separations were taken: each row's are taken anew in
    // the same pass (from motion_: updateMotion() first). The coloured rows' terms go straight into
    // their lanes (ContactWideLoop.inc), the others' into rows_ (prepareRow()).
    void preparePhase(double h, bool useBias, const ContactSettings& settings, bool measure);
    void prepareRow(std::size_t i, const PhaseTerms& terms, bool measure);
    // After relax: the velocity its impulses gave at points that closed in the sub-step (an
    // approach stopped, an impact), per body into SolverBody::impactDv, which the push-out
    // then leaves out: the soft solve's approach moved the body for real.
    void bookClosings();
    void bookClosing(int a, int b, double nx, double ny, const double (&arm)[4], double normal,
                     double tangent);
    // Row i's point k's separation where the solver's path is now: in its lane for a coloured
    // row (with the wide sweep), else in separation_.
    double separationOf(std::size_t i, int k) const {
        const int at = slot_[i];
        return at >= 0 && lanesHold_ ? wideCold_[at / kLanes].p[k].separation[at % kLanes]
                                     : separation_[2 * i + k];
    }
    // Row i's point k's effective mass in the last phase (0: inactive), likewise.
    double effectiveMassOf(std::size_t i, int k) const {
        const int at = slot_[i];
        return at >= 0 && lanesHold_ ? wide_[at / kLanes].p[k].effectiveMass[at % kLanes]
                                     : rows_[i].p[k].effectiveMass;
    }
    bool lanesHold_ = false;  // the wide sweep is there: the lanes hold the coloured rows
    void solve();
    void solveRow(Row& c);
    // Graph colours, from the constraints' bodies alone (before the rows are built;
    // ContactColours.cpp).
    void colourRows();
    // The coloured rows built straight into their lanes with what is fixed for the step: rows_
    // holds only the rows the scalar passes read (the overflow's, built by buildRows()) until
    // unpackRows() unpacks every lane for relaxJoined(); a row with restitution leaves its
    // bounce terms (fillBounce()).
    void buildLanes(const BuildTerms& terms);
    // The lanes hold the coloured rows, and their accumulated impulses, from buildLanes() to the
    // end of the step (warm start, solve and relax read and write them there); rows_ has them
    // only after unpackRows() (relaxJoined() does it; solveStep's store reads the lanes).
    void unpackRows();
    // A point's terms in a phase, from its separation s (the same arithmetic for a row and a
    // lane).
    struct PointTerms {
        double bias, effectiveMass, impulseScale, compliance;
        bool active;
    };
    static PointTerms pointTerms(double s, const RowSetup& setup, int k, const PhaseTerms& terms) {
        PointTerms t{0.0, 0.0, 0.0, 0.0, true};
        double massScale = 1.0, impulseScale = 0.0;
        if (s > 0.0) {
            // Speculative: close at most the gap. Only while solving: relaxing a gap would
            // brake an approaching body a sub-step early (the next solve sees the gap anew).
            t.bias = s * terms.invH;
            t.active = terms.useBias;
        } else if (terms.useBias) {
            // The push of an overlap deeper than deepOverlap is that of deepOverlap: the rest is
            // pushed out in positions (deepPushOut). In a pile each contact's push velocity adds
            // up along chains of bodies (20 boxes started at one point left at 40 m/s).
            const double depth = std::max(s, -setup.deepOverlap);
            t.bias = std::max(setup.biasRate * depth, -setup.pushOutShare * terms.maxPushOut);
            massScale = setup.massScale;
            impulseScale = setup.impulseScale;
            t.compliance = setup.compliance[k];
        }
        t.effectiveMass = t.active ? setup.normalMass[k] * massScale : 0.0;
        t.impulseScale = t.active ? impulseScale : 0.0;
        return t;
    }
    // The block's A = K + diag(compliance): a12, A⁻¹ and the single-point fallbacks 1/a11, 1/a22.
    struct BlockTerms {
        double a12, i11, i12, i22, invA11, invA22;
    };
    static BlockTerms blockTerms(double k11, double k12, double k22, const double compliance[2]) {
        const double a11 = k11 + compliance[0], a22 = k22 + compliance[1], a12 = k12;
        const double invDet = 1.0 / (a11 * a22 - a12 * a12);
        return {a12, a22 * invDet, -a12 * invDet, a11 * invDet, 1.0 / a11, 1.0 / a22};
    }
    // Separations with the bodies where the solver's path has taken them.
    void updateSeparations();
    // The end of a sub-step's solve: its length h and how far through the step it ends (f).
    struct SolveEnd {
        double h, f;
    };
    // Per body: motion_ from the solver's path; with `end`, the path first moved by the solve's
    // velocities (endSolve()).
    void updateMotion(const SolveEnd* end);
    // A body's sub-step of motion at the solve's velocities: its path, the displacement by the
    // contacts beyond the smooth path (shift), and the velocities relax starts from (pushV).
    static void endSolve(SolverBody& b, const BodyState& s, const SolveEnd& end);
    void rowSeparations(std::size_t row);  // per row point: separation_ from motion_
    // Removes overlap beyond each row's deepOverlap by moving the bodies apart along the
    // normal (no velocity), at most settings.pushOut·h per row and pass.
    void deepPushOut(double h, const ContactSettings& settings);

    std::vector<SolverBody> bodies_;
    ConstraintList constraints_;
    std::vector<BodyState> state_;    // bodies_.size() + 1 (the static world last)
    std::vector<BodyMotion> motion_;  // likewise
    // Per constraint, in constraints_'s order; only the rows a scalar pass reads are written
    // (buildLanes()), and the others' pages are never touched (a pile's 26 MB).
    UninitializedLargeVector<Row> rows_;
    UninitializedLargeVector<RowSetup> setup_;  // likewise
    LargeVector<WideSetup> wideSetup_;          // per wide row, its lanes' rows'
    std::vector<double> separation_;            // per row point (2 per row), where the path is now
    LargeVector<WideRow> wide_;                 // the coloured rows, colour by colour
    LargeVector<WideCold> wideCold_;            // likewise, their cold lanes
    LargeVector<WideClosing> wideClosing_;      // likewise, where relax's closing flags say
    std::vector<unsigned char> closingWide_;    // per wide row: some lane closes (relax)
    std::vector<unsigned char> singleWide_;     // per wide row: no lane has a second point
    std::vector<int> slot_;  // per row: kLanes·wide row + lane, or −1 (solved alone)
    std::vector<std::pair<int, int>> colouredPairs_;  // per row: its bodies at the last colouring
    std::vector<int> order_;     // per wide slot: its row, or −1 (the sweep order)
    std::vector<int> overflow_;  // rows no colour could take, solved after the wide ones
    std::vector<std::uint64_t> colourMask_;  // per body (+ the world): a bit per colour taken
    int colours_ = 0;                        // the colours in use: the highest taken + 1
    std::vector<int> colourWide_;            // per colour its first wide row, then the end
    std::vector<int> blockCount_;            // per colour and block its rows, then the next slot
    std::vector<int> blockWide_;  // per colour kBlocks + 1 wide rows: where each block starts
    // A row as the bounce passes read it (one with restitution, or one a bounce is handed on
    // through): the later passes' skip test reads only BounceRow (16 bytes a row), a look at the
    // row its BounceTerms (what the row holds, fixed for the step, side by side: a Row is 384
    // bytes, a pile's rows megabytes), the separations and the body states, and a row's K only
    // where a manifold lands flat.
    struct BounceRow {
        int row;
        int a, b;                 // the row's bodies
        std::uint32_t checkedAt;  // bounce()'s clock when last looked at
    };
    struct BounceTerms {
        int pointCount;
        bool isolated;   // neither body touches anything else (see bounce())
        bool blockable;  // RowSetup's
        double restitution;
        double nx, ny;
        double arm[2][4];        // per point rAx, rAy, rBx, rBy
        double smoothChange[2];  // smoothNormalChange of each point, over the whole step
        double normalMass[2];    // RowSetup's
        double k11, k12, k22;    // Row's (the two points' block)
    };
    LargeVector<BounceRow> bouncing_;                    // rows with restitution > 0
    UninitializedLargeVector<BounceTerms> bounceTerms_;  // likewise (filled by fillBounce())
    std::vector<int> bounceAt_;                          // per row: its place in bouncing_, or −1
    // The rows without restitution, where bouncing_ has some or one of them is fast: an impact
    // is handed on through them, inelastically, to the bodies it reaches (bounce()), and a fast
    // one is looked at from the first pass. Their terms are made the first time a pass looks at
    // one in the step (handedMade_).
    LargeVector<BounceRow> handedOn_;
    UninitializedLargeVector<BounceTerms> handedTerms_;
    std::vector<unsigned char> handedMade_;
    std::vector<int> fastHanded_;  // the fast ones (ContactConstraint::fast), by handedOn_ entry
    // Per body (+ the world), in a bounce() that hands an impact on: the direction of the push
    // of the support it was stopped against (zero: none).
    std::vector<Vec2> support_;
    // A row's terms with one body held (its inverse masses zero in a and b).
    static void oneSidedTerms(BounceTerms& t, const BodyState& a, const BodyState& b);
    // Whether the step's rows can bounce (bounce() has something to look at).
    bool bounces() const { return !bouncing_.empty() || !handedOn_.empty(); }
    void fillBounceTerms(BounceTerms& t, double restitution, const Row& row,
                         const RowSetup& setup) const;
    // Row i's bounce terms from its lane (or from rows_ where it has none), once the step's
    // rows are built: a row without restitution that a bounce reaches (handedOn_).
    void laneBounceTerms(std::size_t i, BounceTerms& t) const;
    std::vector<unsigned char> shifted_;  // per row point (2 per row): moved to its time of impact
    std::vector<unsigned char> bounces_;  // per row point: bounces in this inner sub-step
    std::vector<std::uint32_t> changedAt_;  // per body (+ the world): clock of its last impulse
    // stackSubsteps: per body (+ the static world) the predicted sag, and per contact which body
    // rests on which and how far the upper one sinks into the lower (upper −1: it carries no
    // load).
    std::vector<double> depth_, height_;
    struct Support {
        int upper, lower;
        double sink;
        double rise;  // from the lower centre up to the upper one (sagDepths()' heights)
    };
    std::vector<Support> supports_;
    // sagDepths: the supports by lower body (supportOrder_ from supportStart_[lower]), per body
    // how many supports under it are not done yet, and the bodies in the order they are done.
    std::vector<int> supportStart_, supportOrder_, supportsUnder_, supportReady_;
    std::vector<double> load_;     // weightSinks: per body (+ the world), the weight it carries
    std::vector<Vec2> deepShift_;  // per body (+ the static world): deepPushOut's displacement
    // Per state entry of a body's x: the solves running in which the deep push-out moved it out
    // of static geometry, and the last of them (pushOuts_ then). Keyed by the state, not by the
    // solver's bodies: those are numbered anew at each collide.
    struct Jammed {
        int solves = 0;
        std::uint64_t at = 0;
    };
    std::vector<Jammed> jammed_;
    std::uint64_t pushOuts_ = 0;  // deepPushOut() calls
    // What deepPushOut's passes read of a row: its bodies, normal, deepest point's separation
    // (a move along the normal shifts every point alike, and rounding keeps their order) and
    // deep overlap, side by side (a pass over the rows themselves streams 384 bytes a row).
    struct DeepRow {
        int a, b;
        double nx, ny, separation, deepOverlap;
    };
    LargeVector<DeepRow> deep_;
    // Every row point's separationOf() (2 per row), gathered in one pass over the lanes in their
    // order: looking each up from its row jumps through the lanes, megabytes of them in a pile.
    // Returns them (separation_ itself where no lanes hold the rows).
    const double* gatherSeparations();
    std::vector<double> gathered_;
    // The force a point's kept impulses stand for, along its normal and tangent.
    // (perSubstep and perStep: 1 over the last step's inner sub-step and step).
    static Vec2 forceOf(const ContactPoint& p, double perSubstep, double perStep);
    // Each point's force held over the next step (ContactPoint), from the kept impulses: per
    // constraint in keepStep() (the end of solveStep, and after relaxJoined), whole after a
    // trial solve (primeHeld()).
    void refreshHeld();
    // refreshHeld() for constraint i (perSubstep, perStep as forceOf()'s).
    void holdConstraint(std::size_t i, double perSubstep, double perStep);

    // relaxJoined(): one scalar row of a contact point (its normal or its tangent), g·u its
    // bodies' relative velocity along dir at the point. column: its W'·gᵀ over the whole state
    // in joinedColumns_ (from the first non-zero entry `from` to `to`), −1 where it is W·gᵀ
    // (neither body jointed: the joints do not reach it) or is projected at each update (past
    // kJoinedCacheEntries).
    struct JoinedRow {
        int row, point;
        bool normal;
        int dofA, dofB;  // −1: static
        bool turnsA, turnsB;
        double ga[3], gb[3];
        double wa[3], wb[3];  // each body's inverse masses (x, y, θ)
        double inverseMass;   // g·W'·gᵀ; 0: the joints hold it still; −1: not worked out yet
        int column;
        int from, to;
        bool jointed;
        double applied;  // the impulse this solve added
    };
    // The largest W'·gᵀ cache, in state entries (64 MiB).
    static constexpr std::size_t kJoinedCacheEntries = std::size_t{1} << 23;
    static constexpr int kJoinedSweeps = 64;
    // A row whose inverse mass with the joints held is below this share of its free one.
    static constexpr double kJoinedRankFloor = 1e-8;
    static constexpr double kJoinedTolerance = 1e-9;  // m/s: a sweep that changes no less ends it
    // The rows' compliance, as a share of their inverse mass: supports that the joints make
    // redundant (a welded table's four leg corners) share their load in the least-norm way
    // instead of the solve handing it from corner to corner between steps, which the held forces
    // cannot follow (a welded table rocked and slid 0.9 mm in 18 s,
    // its books 19 mJ each way; at 1% it moves 0.25 mm and books 4 mJ, at 0.1% 11 mJ). A resting
    // body is left approaching its support at 1% of the relax's answer, which the next step's
    // soft solve takes up.
    static constexpr double kJoinedCompliance = 0.01;
    // The step's rows, their responses not yet worked out (readyJoined()); n: the state's size.
    void buildJoinedRows(int n);
    // Works out row r's response and inverse mass the first time it is needed; false where the
    // joints hold the row still (it takes no impulse).
    bool readyJoined(JoinedRow& r, const TangentProjection& joints);
    double joinedVelocity(const JoinedRow& r, const Vec& u) const;
    // u += dp·W'·gᵀ of row r.
    void applyJoined(const JoinedRow& r, double dp, Vec& u, const TangentProjection& joints);
    // g_r·W'·g_sᵀ.
    double joinedCoupling(const JoinedRow& r, const JoinedRow& s, const TangentProjection& joints);
    // W·gᵀ of row r, scaled, into x (x zero there before).
    void addFreeResponse(const JoinedRow& r, double scale, Vec& x) const;
    std::vector<JoinedRow> joined_;
    std::vector<int> joinedStart_;       // per contact row: its first joined row (rows_.size() + 1)
    std::vector<double> blockCoupling_;  // per contact row: its two normal rows' g₁·W'·g₂ᵀ
    Vec joinedColumns_, joinedScratch_;
    std::size_t joinedCached_ = 0;  // columns in joinedColumns_ this step

    // The accumulated impulses into the constraints, then refreshHeld(), in one walk.
    // solved: they are the solve's (ContactPoint::solvedNormal), not the joined relax's, and a
    // coloured row's are still in its lanes (solveStep); else all are in rows_.
    void keepStep(bool solved);
    // keepStep()'s store for constraint i (fromLanes: from the lanes where it has a slot).
    void storeConstraint(std::size_t i, bool fromLanes, bool solved);
    // Per body, the held forces' share of the smooth step's change (after loadBodies).
    void holdBodies(double h);
    double lastInnerH_ = 0.0;   // the last step's inner sub-step (its impulses are per one)
    double lastStepH_ = 0.0;    // and the step itself (relaxJoined()'s impulses are per one)
    double weightField_ = 0.0;  // setWeightField()
    int lastSubsteps_ = 0;
    int stepsWantingFewer_ = 0;
    int stepsWantingMore_ = 0;
    double leastDepthRatio_ = 0.0;   // the least depth over its bound while more were wanted
    double largestMassRatio_ = 1.0;  // over the contacts between two dynamic bodies (prepare)
    double predictedSag_ = 0.0;
};

}  // namespace phasebox
