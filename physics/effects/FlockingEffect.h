#pragma once
// Flocking (Reynolds 1987, "Flocks, herds and schools"): every dynamic particle is a boid that
// steers by its neighbours closer than `radius`. As accelerations (the force is m·a, so a
// heavy boid steers like a light one):
//   separation  w_s·Σ_j û_ij·(R_s/r_ij − 1)  away from each neighbour closer than R_s = R/2
//   alignment   w_a·Σ_j w_ij·(v_j − v_i)/max(Σ_j w_ij, 1)   toward the neighbours' velocity
//   cohesion    w_c·Σ_j w_ij·(p_j − p_i)/max(Σ_j w_ij, 1)   toward the neighbours' centre
//   max speed   −k·(‖v‖ − v_max)·v̂ when ‖v‖ > v_max, with k = 2·v_max/R
// with r_ij = ‖p_i − p_j‖, û_ij = (p_i − p_j)/r_ij, R the radius and w_ij = 1 − r_ij/R.
//
// Why these forms: every term fades to zero as a neighbour reaches its radius, so the force is
// continuous while boids come and go (a plain average jumps from nothing to a full pull when
// the first neighbour enters, a kink that adaptive and high-order methods pay for at every
// crossing). Dividing by max(Σw, 1) gives the plain weighted average in a crowd and fades a
// lone distant neighbour in. Separation grows like 1/r, so boids never collapse onto each
// other, and it reaches only half as far as cohesion (Reynolds' innermost zone): between R/2
// and R neighbours only attract, which holds a flock together at a spacing somewhat below R/2.
// (With separation out to R as well, pushing and pulling cancel near the radius and a flock
// slowly evaporates into single boids.) The speed limit is a force, not a clamp: the integrators
// own the state, and a clamp would change velocities behind their back (and behind the energy
// ledger). Its rate lets a boid shed excess speed in about the time it needs to cross half its
// neighbourhood.
//
// Neighbours come from a uniform grid of cells of size R, rebuilt at every evaluation into
// arrays sized once per layout: a boid's neighbours lie in its own cell and the eight around it.
// Cells are hashed into a table of about twice as many slots as boids, so a flock spread over
// a large area costs no more memory than a tight one.
//
// Energy: steering is not conservative; its power Σ F·v enters work_nc. No Jacobians: the
// implicit methods treat flocking explicitly.

#include "physics/effects/Effect.h"

#include <cstdint>
#include <vector>

namespace phasebox {

struct FlockingParameters {
    double radius = 1.0;
    double separation = 1.0;
    double alignment = 1.0;
    double cohesion = 1.0;
    double maxSpeed = 2.0;
};

class FlockingEffect final : public Effect {
public:
    explicit FlockingEffect(const FlockingParameters& parameters)
        : Effect(effectName::flocking), parameters_(parameters) {}

    double addForces(double t, const Vec& q, const Vec& u, Vec& force) override;
    double nonConservativePower(double t, const Vec& q, const Vec& u) override;
    bool hasNonConservativePart() const override { return true; }
    bool couplesBodies() const override { return true; }
    void bind(const EffectWorldView& view) override;

    const FlockingParameters& parameters() const { return parameters_; }
    // The separation radius as a fraction of the neighbourhood radius.
    static constexpr double kSeparationFraction = 0.5;

private:
    // Sorts the boids into the hashed grid for positions q.
    void buildGrid(const Vec& q);
    std::uint32_t slotOf(std::int64_t cellX, std::int64_t cellY) const;
    // Adds m·a of every boid to force; returns Σ F·v.
    double steer(const Vec& q, const Vec& u, Vec& force);

    FlockingParameters parameters_;
    // The grid, sized by bind(): slotStart_[s] .. slotStart_[s + 1] index boidsBySlot_.
    std::vector<std::uint32_t> slotOfBoid_;
    std::vector<std::uint32_t> slotStart_;
    std::vector<int> boidsBySlot_;
    std::uint32_t slotMask_ = 0;
    Vec scratch_;  // forces for nonConservativePower()
};

}  // namespace phasebox
