#pragma once
// An effect is one source of smooth force (gravity, drag, springs, …). It works on whole
// arrays: the world makes one virtual call per effect per evaluation, never one per object.
//
// Energy bookkeeping (CONTRACT.md §2): a conservative force reports its potential energy;
// a non-conservative one reports its power F·v so that its work enters work_nc. An effect
// may be both (a damped spring: elastic potential plus damping power).

#include "physics/core/EffectNames.h"
#include "physics/core/Layout.h"
#include "physics/core/OdeSystem.h"
#include "physics/core/Types.h"

#include <string>
#include <string_view>
#include <vector>

namespace phasebox {

struct Particle;
struct RigidBody;

// What every effect may read of the world: the layout and the per-dof masses, and the objects
// themselves for the few effects that need a property the state does not hold (a disk's radius
// for buoyancy, a charge for Coulomb, a pinned particle's fixed position). Such an effect copies
// what it needs into arrays of its own in bind(), so the per-step loops stay on flat arrays.
class WorkerPool;

struct EffectWorldView {
    const StateLayout* layout = nullptr;
    const Vec* mass = nullptr;  // per dof: m, m for particles; m, m, I for rigid bodies
    const std::vector<Particle>* particles = nullptr;  // every particle, with its dof (−1: pinned)
    const std::vector<RigidBody>* rigidBodies = nullptr;  // every rigid body, its dof (−1: static)
    // The world's threads, for an effect's large loops (null: the calling thread alone); an
    // effect shares only loops whose results do not depend on the number of workers.
    WorkerPool* pool = nullptr;
};

class Effect {
public:
    explicit Effect(std::string_view name) : name_(name) {}
    virtual ~Effect() = default;
    Effect(const Effect&) = delete;
    Effect& operator=(const Effect&) = delete;

    const std::string& name() const { return name_; }

    // Adds F(q, u, t) into force (generalised: forces on x, y; torque on θ). Returns the power
    // of the non-conservative part of the force, F_nc·u (0 for a conservative effect).
    virtual double addForces(double t, const Vec& q, const Vec& u, Vec& force) = 0;

    // Power of the non-conservative part alone; only called when hasNonConservativePart().
    virtual double nonConservativePower(double t, const Vec& q, const Vec& u) {
        (void)t, (void)q, (void)u;
        return 0.0;
    }

    // A field effect's force is m·(an acceleration field), like uniform gravity. The world then
    // asks it for the acceleration directly, which skips the multiply by m and the divide by m
    // of the force path. With overwrite the effect assigns instead of adding (it is the first
    // writer of the evaluation), which saves zeroing the array first.
    virtual bool isAccelerationField() const { return false; }
    // A field that is one acceleration on every dynamic point's and body's (x, y), and nothing
    // on angles, says so here; the world then hands it to the integrator as a constant
    // (OdeSystem::accelerationSplit) instead of writing it into every lane.
    virtual bool uniformAcceleration(Vec2& a) const {
        (void)a;
        return false;
    }
    virtual void addAccelerations(double t, const Vec& q, const Vec& u, Vec& accel,
                                  bool overwrite) {
        (void)t, (void)q, (void)u, (void)accel, (void)overwrite;
    }

    // Adds K = ∂F/∂q and D = ∂F/∂u. An effect without Jacobians is treated explicitly by the
    // implicit integrators (its force enters the right-hand side only).
    virtual void addJacobians(double t, const Vec& q, const Vec& u, ForceJacobians& jacobians) {
        (void)t, (void)q, (void)u, (void)jacobians;
    }

    // Both at once, for the implicit methods: addForces then addJacobians unless the effect
    // can share the work (a spring's length and direction serve both).
    virtual double addForcesAndJacobians(double t, const Vec& q, const Vec& u, Vec& force,
                                         ForceJacobians& jacobians) {
        const double power = addForces(t, q, u, force);
        addJacobians(t, q, u, jacobians);
        return power;
    }

    virtual double potentialEnergy(const Vec& q) const {
        (void)q;
        return 0.0;
    }

    // An effect whose potential depends on the state only through the mass moment Σm·x
    // (uniform gravity: −g·Σm·x) may compute it from the moment, which the world already has
    // from its diagnostics pass; returns false when it cannot.
    virtual bool potentialFromMassMoment(const Vec2& massMoment, double& energy) const {
        (void)massMoment, (void)energy;
        return false;
    }

    virtual bool hasNonConservativePart() const { return false; }

    // Sleeping (simulation.sleep) freezes islands of bodies that touch or are held together.
    // An effect whose force on a body depends on where other bodies are (mutual gravity,
    // charges, a flock) ties every body it acts on into one island: a frozen body would stop
    // pulling the others.
    virtual bool couplesBodies() const { return false; }
    // The first state index of a body the effect drives by hand (the mouse spring's), which
    // may not fall asleep while it does; −1 for none.
    virtual int drivenDof() const { return -1; }

    // The world's topology changed (objects added or removed): re-read what is needed.
    virtual void bind(const EffectWorldView& view) { view_ = view; }

protected:
    EffectWorldView view_;

private:
    std::string name_;
};

}  // namespace phasebox
