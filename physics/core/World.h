#pragma once
// The live simulation: objects, the flat state, the effects, the integrator, and the
// diagnostics (energy ledger, divergence detection, per-effect cost).
//
// Hot data is the flat state (q, u) with per-dof masses; cold data (ids, radii, materials)
// lives in the object vectors. For a dynamic object the state is authoritative and the
// object's own position/velocity fields are only its setup values; for a pinned particle or
// a static box the object's fields are the truth.

#include "physics/contacts/ContactSolver.h"
#include "physics/core/Layout.h"
#include "physics/core/OdeSystem.h"
#include "physics/effects/Effect.h"
#include "physics/integrators/Integrator.h"

#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace phasebox {

class ContactStage;
class SpringEffect;

struct Particle {
    std::string id;
    Vec2 position{0.0, 0.0};  // setup value; live value in the state unless pinned
    Vec2 velocity{0.0, 0.0};
    double mass = 1.0;
    double radius = 0.05;
    bool pinned = false;
    double restitution = 0.5;
    double friction = 0.2;
    double charge = 0.0;
    int cloth = -1;  // index of the cloth this node belongs to, or −1
    int dof = -1;    // first state index, −1 when pinned
};

struct Box {
    std::string id;
    Vec2 position{0.0, 0.0};  // setup value; live value in the state unless static
    double angle = 0.0;
    Vec2 velocity{0.0, 0.0};
    double angularVelocity = 0.0;
    Vec2 size{1.0, 1.0};
    double mass = 1.0;
    double inertia = 1.0 / 6.0;
    bool isStatic = false;
    double friction = 0.6;
    double restitution = 0.0;
    int dof = -1;  // first state index, −1 when static
};

struct Plane {
    std::string id;
    Vec2 point{0.0, 0.0};
    Vec2 normal{0.0, 1.0};  // unit; solid on the side opposite the normal
    double friction = 0.5;
    double restitution = 0.5;
};

// One end of a spring, by object index (resolved to a BodyPoint when the layout is built).
struct SpringEnd {
    enum class Kind { Particle, Box, Anchor };
    Kind kind = Kind::Anchor;
    int index = -1;           // particle or box index
    Vec2 point{0.0, 0.0};     // box: attachment in the box frame; anchor: world point
};

struct Spring {
    std::string id;
    SpringEnd a, b;
    double stiffness = 0.0;
    double damping = 0.0;
    double restLength = 0.0;
    int cloth = -1;
};

struct Cloth {
    std::string id;
    int nx = 0, ny = 0;
    int firstParticle = 0;  // node (i, j) is particle firstParticle + j·nx + i
    int firstSpring = 0;
    int springCount = 0;
};

struct SimulationSettings {
    std::string integrator = "symplectic_euler";
    double dt = 1.0 / 60.0;
    int substeps = 1;
    double tolerance = 1e-6;
    int newtonIterations = 1;
    ContactSettings contacts;  // the scene's simulation.solver
};

// CONTRACT.md §2.
struct EnergyLedger {
    double kinetic = 0.0;
    double potential = 0.0;
    double workNc = 0.0;
    double drift = 0.0;
    double maxAbsDrift = 0.0;
    double initial = 0.0;  // kinetic + potential at the baseline (t = 0)
};

struct Divergence {
    double time = 0.0;         // when the bad value appeared
    std::string objectId;      // the first object where it appeared
    std::string what;          // "non-finite velocity", "energy growing without bound", …
    double restoredTime = 0.0; // the state was restored to this time
    std::string message() const;
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
    int addBox(const Box& box);
    int addPlane(const Plane& plane);
    int addSpring(const Spring& spring);
    int addCloth(const Cloth& cloth);  // its particles and springs are added separately
    // Builds the state layout after objects were added; step() does it when needed, and the
    // state accessors need it done. Live state is carried over, the energy drift too.
    void commit();

    const std::vector<Particle>& particles() const { return particles_; }
    const std::vector<Box>& boxes() const { return boxes_; }
    const std::vector<Plane>& planes() const { return planes_; }
    const std::vector<Spring>& springs() const { return springs_; }
    const std::vector<Cloth>& cloths() const { return cloths_; }

    Vec2 particlePosition(int i) const;
    Vec2 particleVelocity(int i) const;
    Vec2 boxPosition(int i) const;
    double boxAngle(int i) const;
    Vec2 boxVelocity(int i) const;
    double boxAngularVelocity(int i) const;
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

    double time() const { return time_; }
    // Sets the clock (a rebuilt world continuing a run); steps count on from here.
    void setTime(double t);
    long long stepCount() const { return stepCount_; }
    long long forceEvaluations() const { return forceEvaluations_; }

    // ---- diagnostics ------------------------------------------------------------------
    // Step doubling at the current state: one sub-step of h = dt/substeps against two of h/2
    // with the current method, smooth forces only (contacts are events, not a smooth error).
    // Returns the estimated local error of one sub-step, max over position coordinates (m,
    // or rad for a box angle): the difference of the two answers divided by (1 − 2^−p) for a
    // method of order p. The world, its clock, ledger, counters and profile are untouched, and
    // a separate integrator instance keeps the run's own (its adaptive step, its solver's warm
    // start) as it was, so estimating never changes the simulation. Costs about three steps.
    double estimateLocalError();
    const EnergyLedger& energy() const { return ledger_; }
    // Makes the current state the energy baseline (drift 0, work_nc 0).
    void resetEnergyBaseline();
    // Seconds spent in each effect (and the world's own stages) since resetProfile().
    std::vector<EffectCost> effectCosts() const;
    void resetProfile();
    // Seconds spent stepping (integrator, effects and contacts) since resetProfile().
    double integratorSeconds() const { return integratorSeconds_; }

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
    int pairedDofs() const override { return layout_.boxBase(); }
    double acceleration(double t, const Vec& q, const Vec& u, Vec& accel) override;
    double nonConservativePower(double t, const Vec& q, const Vec& u) override;
    double forces(double t, const Vec& q, const Vec& u, Vec& force) override;
    double forcesAndJacobians(double t, const Vec& q, const Vec& u, Vec& force,
                              ForceJacobians& jacobians) override;

    double kineticEnergy() const;
    double potentialEnergy() const;

private:
    using Clock = std::chrono::steady_clock;

    void ensureLayout() {
        if (layoutDirty_) commit();
    }
    void storeStateInObjects();
    void rebuildSpringEffect();
    void sortEffectsByChannel();
    void bindEffects();
    struct StateSummary {
        double kinetic = 0.0;
        Vec2 massMoment = Vec2::Zero();  // Σ m·(x, y) over particles and boxes
        bool finite = true;               // every coordinate and velocity is finite
        // Largest |coordinate| and |velocity| component; only the free-fall pass fills them.
        double maxAbsPosition = 0.0, maxAbsVelocity = 0.0;
    };
    StateSummary summarizeState(const Vec& q, const Vec& u) const;
    double potentialEnergy(const Vec& q, const Vec2& massMoment) const;
    double mechanicalEnergy(const Vec& q, const Vec& u) const;
    bool solveContacts(double h, const Vec& q0, Vec& q, Vec& u);
    void updateLedger(const Vec2& massMoment);
    bool checkSubstep(double t, int substep);
    bool checkEnergy(const StateSummary* precomputed);
    bool fusedFreeFall() const;
    bool freeFallCannotDiverge() const;
    void freeFallStep(double h, const Vec& q0, const Vec& u0, Vec& q, Vec& u, StateSummary* summary);

    // What a failed step goes back to: the start of the frame, or of a blow-up's first frame.
    struct Checkpoint {
        Vec q, u;  // valid when hasState
        bool hasState = false;
        bool inPlace = false;  // the frame was stepped in place: there is no state to go back to
        double time = 0.0, timeBase = 0.0;
        long long stepsSinceTimeBase = 0, stepCount = 0;
        EnergyLedger ledger;
    };
    void saveFrameStart(bool inPlace);
    void restoreFrameStart();
    void restoreScalars(const Checkpoint& c);
    std::string firstNonFinite(const Vec& q, const Vec& u) const;
    std::string mostEnergeticObject() const;

    std::vector<Particle> particles_;
    std::vector<Box> boxes_;
    std::vector<Plane> planes_;
    std::vector<Spring> springs_;
    std::vector<Cloth> cloths_;
    std::vector<int> dynamicParticles_;  // particle index of each dynamic particle
    std::vector<int> dynamicBoxes_;      // box index of each dynamic box

    std::vector<std::unique_ptr<Effect>> effects_;
    SpringEffect* springEffect_ = nullptr;
    // Indices into effects_ by how the world calls them.
    std::vector<int> forceEffects_;     // the force channel
    std::vector<int> fieldEffects_;     // the acceleration-field channel
    std::vector<int> nonConservative_;  // those with power to account
    std::vector<double> effectSeconds_; // parallel to effects_
    double integratorSeconds_ = 0.0;    // whole steps: smooth steps, effects and contacts

    std::unique_ptr<ContactStage> contacts_;
    bool particleCollisions_ = false;
    double particleRestitution_ = 1.0;
    double contactSeconds_ = 0.0;

    SimulationSettings settings_;
    std::unique_ptr<Integrator> integrator_;
    // For estimateLocalError(): its own instance of the method and scratch state.
    std::unique_ptr<Integrator> errorIntegrator_;
    Vec errorQ_[3], errorU_[3];
    std::vector<double> errorSavedSeconds_;

    StateLayout layout_;
    bool layoutDirty_ = true;
    bool committed_ = false;
    // Double-buffered state: the integrator writes the other buffer, so the start of the step
    // is kept without a copy and restored by flipping back.
    Vec q_[2], u_[2];
    int current_ = 0;
    Vec mass_, invMass_, force_;
    Vec particleMass_;  // per dynamic particle (the fused free-fall pass reads half the bytes)
    double totalDofMass_ = 0.0;  // Σ of mass_, for the free-fall overflow bound
    // Maxima of the state after the last free-fall frame, valid until anything else touches it.
    std::optional<StateSummary> freeFallBound_;

    double time_ = 0.0;
    double timeBase_ = 0.0;  // time_ = timeBase_ + stepsSinceTimeBase_·dt
    long long stepsSinceTimeBase_ = 0;
    long long stepCount_ = 0;
    long long forceEvaluations_ = 0;
    EnergyLedger ledger_;
    double energyScale_ = 0.0;
    double previousDrift_ = 0.0;
    int growthStreak_ = 0;
    Checkpoint frameStart_, streakStart_;
    std::optional<Divergence> divergence_;
};

}  // namespace phasebox
