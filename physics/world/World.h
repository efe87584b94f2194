#pragma once
// The live simulation: the objects, the flat state, the effects, the integrator, and the step
// that advances them as a script of named stages (see step()), each timed into a StepProfile.
// The diagnostics live beside it, one concern a file: EnergyLedger, DivergenceGuard,
// LocalErrorEstimator.
//
// Hot data is the flat state (q, u) with per-dof masses; cold data (ids, radii, materials)
// lives in the object records (core/Bodies.h).

#include "physics/contacts/ContactModel.h"
#include "physics/contacts/ContactSolver.h"
#include "physics/core/Bodies.h"
#include "physics/core/Layout.h"
#include "physics/core/OdeSystem.h"
#include "physics/core/WorkUnits.h"
#include "physics/effects/Effect.h"
#include "physics/integrators/Integrator.h"
#include "physics/joints/JointSolver.h"
#include "physics/world/DivergenceGuard.h"
#include "physics/world/EnergyLedger.h"
#include "physics/world/ErrorEstimate.h"
#include "physics/world/Islands.h"
#include "physics/world/StepProfile.h"

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace phasebox {

class ContactStage;
class PenaltyContacts;
class SpringEffect;
class WorkerPool;

struct SimulationSettings {
    std::string integrator = "symplectic_euler";
    double dt = 1.0 / 60.0;
    int substeps = 1;
    double tolerance = 1e-6;
    int newtonIterations = 1;
    ContactSettings contacts;  // the scene's simulation.solver
    // simulation.contact_model, contact_stiffness (k per point; 0 = automatic: the lightest
    // dynamic body that can touch gets ω·h = 0.5) and contact_damping (CONTRACT §6).
    ContactModel contactModel = ContactModel::Impulse;
    double contactStiffness = 0.0;
    double contactDamping = 0.0;
    // simulation.sleep (CONTRACT §6): islands at rest leave the step until woken.
    bool sleep = false;
};

// The forces a recorded frame keeps besides the state, for the readouts that show them
// (WorldSnapshot.h FrameState): the contact force on each body that had one in the step
// (World::contactForce), by the body's first state index in increasing order, and each joint's
// force (World::jointForce, jointForceOn). Bodies without a contact force are left out, so a
// frame of a pile keeps a few numbers per touching body and none for the others.
struct FrameForces {
    std::vector<int> contactDofs;
    std::vector<double> contactXY;  // x, y of each contact force, parallel to contactDofs
    struct Joint {
        double magnitude = 0.0;
        Vec2 onA{0.0, 0.0}, onB{0.0, 0.0};
    };
    std::vector<Joint> joints;

    std::size_t bytes() const {
        return contactDofs.size() * sizeof(int) + contactXY.size() * sizeof(double) +
               joints.size() * sizeof(Joint);
    }
};

struct EffectCost {
    std::string name;
    double seconds = 0.0;  // accumulated since the last resetProfile()
};

class World final : public OdeSystem {
public:
    World();
    ~World() override;
    World(const World&) = delete;
    World& operator=(const World&) = delete;

    // ---- objects ----------------------------------------------------------------------
    // Adding or removing objects rebuilds the state layout; live state is carried over.
    int addParticle(const Particle& particle);
    int addRigidBody(const RigidBody& body);
    int addPlane(const Plane& plane);
    int addSpring(const Spring& spring);
    int addCloth(const Cloth& cloth);  // its particles and springs are added separately
    int addJoint(const Joint& joint);
    // Builds the state layout after objects were added; step() does it when needed, and the
    // state accessors need it done. Live state is carried over, the energy drift too.
    void commit();

    const Bodies& bodies() const { return bodies_; }
    const std::vector<Particle>& particles() const { return bodies_.particles; }
    const std::vector<RigidBody>& rigidBodies() const { return bodies_.rigidBodies; }
    const std::vector<Plane>& planes() const { return bodies_.planes; }
    const std::vector<Spring>& springs() const { return bodies_.springs; }
    const std::vector<Cloth>& cloths() const { return bodies_.cloths; }
    const std::vector<Joint>& joints() const { return bodies_.joints; }
    // The joints' solver, or nullptr when the scene has none.
    const JointSolver* jointSolver() const { return joints_.get(); }
    // Joint j's force (JointSolver::force) and its force on body a or b (forceOnA, forceOnB),
    // at the last derivative evaluation, or as recorded in the frame shown
    // (WorldSnapshot::show): what readouts and force arrows read. 0 without joints.
    double jointForce(int j) const;
    Vec2 jointForceOn(int j, bool onB) const;
    // Whether a recorded frame is shown (WorldSnapshot::show) and not stepped on or edited since.
    bool showsRecordedFrame() const { return showingFrame_; }
    // The joints' violation in the current state (zero without joints).
    JointErrors jointErrors() const;

    Vec2 particlePosition(int i) const;
    Vec2 particleVelocity(int i) const;
    // Rigid body i (an index into rigidBodies(), whatever its shape).
    Vec2 bodyPosition(int i) const;
    double bodyAngle(int i) const;
    Vec2 bodyVelocity(int i) const;
    double bodyAngularVelocity(int i) const;
    // World position of a spring end.
    Vec2 springEndPosition(const SpringEnd& end) const;
    // Signed tension of spring i (positive = stretched), for drawing.
    double springTension(int i) const;

    // ---- effects ----------------------------------------------------------------------
    // Scene-level effects, in the order added. The spring effect is managed by the world: it
    // exists exactly while there are springs.
    void addEffect(std::unique_ptr<Effect> effect);
    const std::vector<std::unique_ptr<Effect>>& effects() const { return effects_; }
    Effect* findEffect(const std::string& name) const;
    // Takes an effect out of the world (a released mouse spring, an effect switched off) and
    // hands it back; nullptr when it is not here. The spring effect is the world's own.
    std::unique_ptr<Effect> removeEffect(const Effect* effect);

    // Particle–particle contacts (the scene's particle_collisions), with their restitution.
    // Contacts between boxes, planes and disks run whenever two such things can touch.
    void setParticleCollisions(bool enabled, double restitution);
    bool particleCollisions() const { return particleCollisions_; }
    // The contact stage, or nullptr when nothing in the scene can touch.
    const ContactStage* contacts() const { return contacts_.get(); }
    // The penalty model's stiffness per contact point (N/m) as it runs: the scene's, or the
    // automatic choice when the scene gives none. 0 when nothing can touch.
    double penaltyStiffness() const;
    // The largest ω² a penalty contact can give one body resting on a plane with its points
    // (a disk one, a box or polygon two, with its rotation), over the bodies that can touch: the
    // advisor's bound for contacts that have not begun yet. 0 under the other models.
    double anticipatedContactOmegaSquared() const;
    // The vector sum of the contact forces on the body whose state begins at dof, over the last
    // step (CONTRACT §7): the impulses it received over dt under the impulse and kinematic
    // models, the penalty force at the current state under penalty. Zero without contacts.
    Vec2 contactForce(int dof) const;
    // Every body's nonzero contactForce (a -0.0 counts as nonzero), as a recorded frame keeps them.
    void contactForces(FrameForces& out) const;

    // ---- settings and stepping --------------------------------------------------------
    // Throws std::invalid_argument for an unknown integrator or an out-of-range number;
    // the world is unchanged then. Switching the integrator keeps the state exactly.
    void setSettings(const SimulationSettings& settings);
    const SimulationSettings& settings() const { return settings_; }
    void setIntegrator(const std::string& name);
    const Integrator& integrator() const { return *integrator_; }

    // Advances by settings().dt in settings().substeps sub-steps. Returns false when the step
    // diverged: the world is then back in its last good state and divergence() says what
    // happened where and when.
    bool step();
    const std::optional<Divergence>& divergence() const { return divergence_; }
    // E₀ of the divergence rule (CONTRACT §2): |drift| or |correction| above 10³ times this
    // diverges.
    double divergenceScale() const { return guard_.divergenceScale(); }

    // The threads a step's large loops share (the collide stage's narrow phase, the contact
    // solver): not part of the scene or the state, since every result is bit-identical for any
    // number (CONTRACT §4). Default every core; 0 means every core. Small scenes run on the
    // calling thread whatever the number (WorkerPool: a loop of one chunk is not shared).
    void setWorkers(int workers);
    int workers() const;
    WorkerPool& workerPool() const { return *pool_; }

    double time() const { return clock_.time; }
    // Sets the clock (a rebuilt world continuing a run); steps count on from here.
    void setTime(double t);
    long long stepCount() const { return clock_.stepCount; }
    long long forceEvaluations() const { return forceEvaluations_; }

    // ---- sleeping (simulation.sleep, CONTRACT §6; WorldSleep.cpp) ---------------------
    // An island of bodies tied by contacts, springs or joints whose every body has stayed below
    // kSleepSpeed and kSleepTurnRate for kSleepSeconds falls asleep: its bodies leave the state
    // (dof −1, Particle::asleep, RigidBody::asleep) with their positions and velocities kept in
    // their records, so nothing steps them, no effect or contact solve sees them, and their energy
    // is held as it was (the ledger books nothing for them). Contacts see them as static bodies.
    // The island wakes, exactly as it fell asleep, when an awake body comes within reach
    // (ContactStage::reachedSleepers), on an edit of the world (objects, effects) and when the
    // method or the contact model is switched. Joints tie their bodies into one island, which
    // sleeps with its joints (they leave the joint solver, JointSolver::bind, and come back with
    // what they held); an island a motor drives stays awake.
    static constexpr double kSleepSpeed = 0.01;                                     // m/s
    static constexpr double kSleepTurnRate = 2.0 * 3.14159265358979323846 / 180.0;  // rad/s
    static constexpr double kSleepSeconds = 0.5;
    // The bodies asleep now (0 with sleeping off).
    int sleepingBodies() const { return sleepingBodies_; }
    // Wakes every island asleep.
    void wakeAll();
    // Wakes the island of one body (rigid: a RigidBody record, else a particle); false when it was
    // awake.
    bool wakeBody(bool rigid, int index);
    // The bodies asleep now and what their records hold (nullptr when none sleeps): shared,
    // so that a recording keeps one for every frame of a stretch in which the same islands sleep.
    const std::shared_ptr<const Sleepers>& sleepers() const { return sleepers_; }

    // ---- diagnostics ------------------------------------------------------------------
    // Step doubling at the current state: one sub-step of h = dt/substeps against two of h/2
    // with the current method, smooth forces only (contacts are events, not a smooth error).
    // Returns the estimated local error of one sub-step, max over position coordinates (m,
    // or rad for a box angle): the difference of the two answers divided by (1 − 2^−p) for a
    // method of order p. The world, its clock, ledger, counters and profile are untouched, and
    // a separate integrator instance keeps the run's own (its adaptive step, its solver's warm
    // start) as it was, so estimating never changes the simulation. Costs about three steps.
    double estimateLocalError();
    // The forces and their Jacobians at the current state, for a diagnostic (the stability
    // advisor): not part of the run either. Its evaluation is not counted or timed, and the
    // joints keep what the run's evaluations left (their forces, cached rotations and the limits
    // the step holds), so asking between steps never changes the simulation.
    void diagnosticForcesAndJacobians(Vec& force, ForceJacobians& jacobians);
    const EnergyLedger& energy() const { return ledger_; }
    // Makes the current state the energy baseline (drift 0, work_nc 0).
    void resetEnergyBaseline();
    // Seconds spent in each effect (and in contacts) since resetProfile().
    std::vector<EffectCost> effectCosts() const;
    // Seconds per named stage of the step, and the steps they were summed over.
    const StepProfile& stepProfile() const { return profile_; }
    void resetProfile();
    // Seconds spent stepping (every stage) since resetProfile().
    double integratorSeconds() const { return profile_.total(); }

    // ---- the flat state (the ODE view) ------------------------------------------------
    const StateLayout& layout() const { return layout_; }
    const Vec& positions() const { return q_[current_]; }
    const Vec& velocities() const { return u_[current_]; }
    // Overwrites the state; sizes must match the layout.
    void setState(const Vec& q, const Vec& u);
    // Id of the object owning a state index.
    std::string objectAtDof(int dof) const;

    int dimension() const override { return layout_.dimension(); }
    const Vec& inverseMass() const override { return invMass_; }
    const Vec& mass() const override { return mass_; }
    int pointDofs() const override { return layout_.rigidBase(); }
    // The scene's units of work (core/WorkUnits.h), as the validation counts them.
    double workUnits() const override {
        return static_cast<double>(bodies_.particles.size() + bodies_.springs.size()) +
               static_cast<double>(kCostlyWorkUnits) *
                   static_cast<double>(bodies_.rigidBodies.size() + bodies_.joints.size());
    }
    double acceleration(double t, const Vec& q, const Vec& u, Vec& accel) override;
    SplitAcceleration accelerationSplit(double t, const Vec& q, const Vec& u, Vec& rest) override;
    // The sum of the uniform fields' accelerations (gravity's g).
    Vec2 uniformField() const;
    double nonConservativePower(double t, const Vec& q, const Vec& u) override;
    double forces(double t, const Vec& q, const Vec& u, Vec& force) override;
    double forcesAndJacobians(double t, const Vec& q, const Vec& u, Vec& force,
                              ForceJacobians& jacobians) override;
    bool activeSetChanged(const Vec& q0, const Vec& q1) override;

    double kineticEnergy() const;
    double potentialEnergy() const;

private:
    friend class WorldSnapshot;  // saves and restores the whole state (WorldSnapshot.h)

    // Sleeping (WorldSleep.cpp): the timers after a good step, islands that fall asleep, sleepers
    // reached; the state rebuilt around them with the ledger and the contacts carried over.
    void updateSleep();
    bool fallAsleep();
    bool wakeIsland(int island);
    void relayoutForSleep();
    void resetSleep();
    // The bodies s names asleep (their records set from it) and every other awake, the state
    // rebuilt around them when that changes which bodies sleep (WorldSnapshot). All of them
    // count as one island; the island ids and timers are the caller's to set.
    void putToSleep(const std::shared_ptr<const Sleepers>& s);
    // The layout rebuilt for the asleep flags of the records, the contacts and joints carried.
    void rebuildForSleep();
    void ensureLayout() {
        if (layoutDirty_) commit();
    }
    void storeStateInObjects();
    void rebuildSpringEffect();
    void sortEffectsByChannel();
    bool addAccelerations(double t, const Vec& q, const Vec& u, Vec& accel,
                          const std::vector<int>& fields, double& power);
    void bindEffects();
    // The joints' constraint forces (accelerations: M⁻¹ of them) into x, as the method takes
    // them (IntegratorInfo::constraintsAtEnd).
    void constrainJoints(const Vec& q, const Vec& u, Vec& x, bool accelerations);
    // The held contact forces into force while holding_ (their work: bookHeldWork()).
    void addHeldForces(Vec& force) const;

    // The stages of step(), in the order they run.
    void primeContactForces(StageTimer& timer);
    void holdContactForces();
    // The motors' torques of their last drive into heldMotor_, held over the method's step
    // (JointSolver::addHeldMotorTorques(); their work: bookHeldWork()).
    void holdMotorTorques();
    bool integrate(double t, double h, int next, StateSummary* summary);
    // After the method's step of h into buffer next: the joints, the contacts (found when
    // collideSubsteps > 0, the frame's first sub-step of that many), their booking.
    void solveConstraints(double h, int collideSubsteps, int next, StageTimer& timer);
    void bookHeldWork(double h, int next);
    // collided: collide() ran in this step (ContactStage::heldCarried() is of it).
    void releaseHeldForces(double h, int next, bool collided);
    void advanceClock();
    void collide(int next, int substeps);
    void findPenaltyPairs();
    void configureContactModel();
    double contactPotential(const Vec& q) const;
    void solveKinematic(int next);
    // before: the energy at the method's end, which the contacts' booking starts from; held:
    // the method's step held the contacts' forces (releaseHeldForces()).
    void solveContacts(double h, int next, double before, bool held);
    // How many sub-steps the joints need this frame.
    int jointSubstepsForFrame();
    void solveJoints(double h, int next);
    void rejoin(int next);
    StateSummary closeLedger(const StateSummary* summed);
    bool guard(const StateSummary& summary);
    bool failSubstep(double t, bool integratorFailed, int next);

    double mechanicalEnergy(const Vec& q, const Vec& u) const;
    void restore(const DivergenceGuard::Checkpoint& checkpoint, bool fromOtherBuffer);
    std::string firstNonFinite(const Vec& q, const Vec& u) const;
    std::string mostEnergeticObject() const;
    // A divergence's cause where it is a chain of hinges or rods pulled straight between two
    // fixed points at the current state (Divergence::straightFrom): such a chain cannot sag
    // without stretching, and the joints' system is singular there.
    void nameStraightChain(Divergence& d) const;
    void checkInvariants(StepStage after) const;

    Bodies bodies_;
    std::vector<int> dynamicParticles_;    // particle index of each dynamic particle
    std::vector<int> dynamicRigidBodies_;  // rigid body index of each dynamic one

    std::vector<std::unique_ptr<Effect>> effects_;
    SpringEffect* springEffect_ = nullptr;
    // Indices into effects_ by how the world calls them.
    std::vector<int> forceEffects_;      // the force channel
    std::vector<int> fieldEffects_;      // the acceleration-field channel
    std::vector<int> restFieldEffects_;  // of those, the ones that are not uniform
    std::vector<int> uniformEffects_;    // and the uniform ones (accelerationSplit)
    std::vector<int> nonConservative_;   // those with power to account
    std::vector<double> effectSeconds_;  // parallel to effects_

    std::unique_ptr<WorkerPool> pool_;
    std::unique_ptr<ContactStage> contacts_;
    std::unique_ptr<PenaltyContacts> penalty_;  // only under the penalty model
    Vec penaltyVelocity_;                       // u at the last pair search, for its sweep
    Vec kinematicImpulse_;  // per dof: the kinematic response's impulses in the last step
    // The impulse model's contact forces of the last solve, held over the method's step
    // (holdContactForces()): a force like any effect's while holding_, per state index.
    // heldValid_: the solver's bodies are of this layout (a collide since the last commit).
    Vec heldForce_;
    double heldWork_ = 0.0;  // their work in this sub-step's method (bookHeldWork())
    bool holding_ = false;
    // The joints' motors' torques, held likewise while motorsHeld_ (one sub-step's method).
    Vec heldMotor_;
    bool motorsHeld_ = false;
    bool heldValid_ = false;
    bool penaltyPairsStale_ = true;
    std::unique_ptr<JointSolver> joints_;
    Vec jointScratch_;
    Vec unappliedJointForce_;  // constrainJoints() under a method that takes them at the end
    Vec beforeContactsQ_, beforeContactsU_;  // the state the contacts start from (step)
    Vec rejoinWeights_;                      // rejoin(): the inverse masses, a jammed body's scaled
    // The first sub-step's velocities the trial of primeContactForces() collided with, when it
    // stopped at a deep overlap (trialSubsteps_ > 0: its contacts stand for the step's collide
    // while the step's inputs are the same to the bit).
    Vec trialNextU_;
    int trialSubsteps_ = 0;
    // The joints' sub-steps per frame (jointSubstepsForFrame()): for turning, held since when,
    // and for the pull of their forces, held since when, and the most needed since then.
    int jointSubsteps_ = 1;
    double jointSubstepsSince_ = 0.0;
    int pulledSubsteps_ = 1, pulledPeak_ = 1;
    double pulledSince_ = 0.0;
    bool particleCollisions_ = false;
    double particleRestitution_ = 1.0;

    SimulationSettings settings_;
    std::unique_ptr<Integrator> integrator_;
    LocalErrorEstimator errorEstimator_;

    StateLayout layout_;
    bool layoutDirty_ = true;
    bool committed_ = false;
    // Double-buffered state: the integrator writes the other buffer, so the start of the step
    // is kept without a copy and restored by flipping back.
    Vec q_[2], u_[2];
    int current_ = 0;
    Vec mass_, invMass_, force_;
    Vec withoutPushOut_;  // scratch: the state less the contacts' push-out, for the ledger

    SimulationClock clock_;
    long long forceEvaluations_ = 0;
    // Runs fn outside the run (estimateLocalError(), diagnosticForcesAndJacobians()): what its
    // evaluations change of the run's bookkeeping is put back after it.
    template <class Fn>
    auto outsideTheRun(Fn&& fn);
    JointSolver::EvaluationRecord keptJointEvaluation_;  // across outsideTheRun()
    EnergyLedger ledger_;
    DivergenceGuard guard_;
    std::optional<Divergence> divergence_;
    StepProfile profile_;

    // Sleeping, per body (particles, then rigid bodies): seconds below the thresholds, the island
    // it sleeps in (−1 awake); per island root in fallAsleep(): the least of those seconds, and
    // whether a joint holds it.
    std::vector<double> restingSeconds_;
    std::vector<int> sleepingIsland_;
    std::vector<double> islandRest_;
    std::vector<unsigned char> islandHeld_;
    std::vector<int> islandId_;
    Islands islands_;
    int sleepingBodies_ = 0;
    int nextIsland_ = 0;
    // What the bodies asleep hold of the ledger's kinetic and potential energy: constant while
    // they sleep, taken when the state was rebuilt around them.
    double sleepingKinetic_ = 0.0, sleepingPotential_ = 0.0;
    std::shared_ptr<const Sleepers> sleepers_;
    bool sleepRelayout_ = false;  // commit() rebuilds for a change of islands, not an edit
    std::vector<double> keptEffectSeconds_;
    // A recorded frame shown (WorldSnapshot::show): its forces answer contactForce and
    // jointForce until the world steps, is set or rebuilt.
    FrameForces shownForces_;
    bool showingFrame_ = false;
};

}  // namespace phasebox
