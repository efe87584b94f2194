#pragma once
// Shared scenes and exact solutions for the physics suites. Everything here is built from the
// scene description (the public way in), so the suites exercise buildWorld, the effects and
// World::step exactly as the app and the command line do.

#include "physics/scene/BuildWorld.h"
#include "physics/scene/SceneDesc.h"
#include "physics/world/World.h"

#include <Eigen/Dense>

#include <cmath>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

namespace phasebox::testing {

inline constexpr double kPi = std::numbers::pi;

// Each fixed-step method's order of accuracy from numerical analysis (not from the registry).
struct Theory {
    const char* name;
    double order;
};
inline constexpr Theory kFixedStep[] = {
    {"explicit_euler", 1.0},
    {"symplectic_euler", 1.0},
    {"midpoint", 2.0},
    {"heun", 2.0},
    {"rk4", 4.0},
    {"velocity_verlet", 2.0},
    {"implicit_euler", 1.0},
    {"implicit_midpoint", 2.0},
};

inline SimulationDesc simulation(const std::string& integrator, double dt) {
    SimulationDesc sim;
    sim.integrator = integrator;
    sim.dt = dt;
    return sim;
}

// A particle of mass m on a spring of stiffness k and rest length 0 to a fixed anchor at the
// origin. With rest length 0 the spring force is exactly −k·x, so each coordinate is an
// independent harmonic oscillator of angular frequency √(k/m).
inline SceneDesc oscillatorScene(const std::string& integrator, double dt, Eigen::Vector2d x0,
                                 Eigen::Vector2d v0, double k = 1.0, double m = 1.0) {
    SceneDesc scene;
    scene.simulation = simulation(integrator, dt);
    ParticleDesc p;
    p.id = "ball";
    p.position = {x0.x(), x0.y()};
    p.velocity = {v0.x(), v0.y()};
    p.mass = m;
    p.radius = 0.0;
    scene.particles.push_back(p);
    SpringDesc s;
    s.a = "ball";
    s.anchor = Point2{0.0, 0.0};
    s.stiffness = k;
    s.restLength = 0.0;
    scene.springs.push_back(s);
    return scene;
}

// A Kepler orbit of semi-major axis 1 and eccentricity e around a fixed attractor at the origin
// with G·M = 1, perihelion on +x, period 2π. The particle starts at true anomaly nu: radius
// p/(1 + e·cos nu) with p = 1 − e², velocity √(1/p)·(−sin nu, e + cos nu).
//
// Why the start matters: at an apsis (nu = 0 or π) the velocity is perpendicular to the
// radius, and the O(h) error that a first-order symplectic method makes there leaves the
// energy (hence the period) unchanged to first order, so over a whole period it cancels and
// symplectic Euler appears second order. A generic start such as nu = π/2 shows its true order.
inline SceneDesc keplerScene(const std::string& integrator, double dt, double e,
                             double nu = kPi / 2.0) {
    SceneDesc scene;
    scene.simulation = simulation(integrator, dt);
    NewtonianGravityDesc ng;
    ng.G = 1.0;
    ng.attractors.push_back({{0.0, 0.0}, 1.0});
    scene.effects.newtonianGravity = ng;
    const double p = 1.0 - e * e;
    const double r = p / (1.0 + e * std::cos(nu));
    const double speed = std::sqrt(1.0 / p);
    ParticleDesc particle;
    particle.id = "planet";
    particle.position = {r * std::cos(nu), r * std::sin(nu)};
    particle.velocity = {-speed * std::sin(nu), speed * (e + std::cos(nu))};
    particle.mass = 1.0;
    particle.radius = 0.0;
    scene.particles.push_back(particle);
    return scene;
}

// Exact state (x, y, vx, vy) at time t of the orbit of keplerScene(…, e, nu0), from Kepler's
// equation E − e·sin E = M solved by Newton's method (a = 1, mean motion 1).
inline Eigen::Vector4d keplerState(double e, double nu0, double t) {
    const double E0 = 2.0 * std::atan(std::sqrt((1.0 - e) / (1.0 + e)) * std::tan(nu0 / 2.0));
    const double M = E0 - e * std::sin(E0) + t;
    double E = M;
    for (int i = 0; i < 50; ++i) {
        const double dE = (E - e * std::sin(E) - M) / (1.0 - e * std::cos(E));
        E -= dE;
        if (std::abs(dE) < 1e-16) break;
    }
    const double b = std::sqrt(1.0 - e * e);
    const double rate = 1.0 / (1.0 - e * std::cos(E));  // dE/dt
    return {std::cos(E) - e, b * std::sin(E), -std::sin(E) * rate, b * std::cos(E) * rate};
}

// The scene under `integrator` at the format's defaults for the contact solver: one step per
// frame, no solver keys (the hard contact cases must hold there).
inline SceneDesc atDefaults(SceneDesc scene, const std::string& integrator) {
    scene.simulation.substeps = 1;
    scene.simulation.solver.clear();
    scene.simulation.integrator = integrator;
    return scene;
}

inline std::unique_ptr<World> build(const SceneDesc& scene) {
    return buildWorld(scene).world;
}

// Largest absolute difference over all positions and velocities of the world's state.
inline double stateError(const World& world, const Eigen::VectorXd& q, const Eigen::VectorXd& u) {
    return std::max((world.positions() - q).lpNorm<Eigen::Infinity>(),
                    (world.velocities() - u).lpNorm<Eigen::Infinity>());
}

// Least-squares slope of log(error) against log(h): the observed order of convergence.
inline double fittedOrder(const std::vector<double>& h, const std::vector<double>& error) {
    const auto n = static_cast<double>(h.size());
    double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
    for (std::size_t i = 0; i < h.size(); ++i) {
        const double x = std::log(h[i]), y = std::log(error[i]);
        sx += x;
        sy += y;
        sxx += x * x;
        sxy += x * y;
    }
    return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

// Total mechanical energy as the world's ledger reports it.
inline double mechanicalEnergy(const World& world) {
    return world.energy().kinetic + world.energy().potential;
}

// Gravity and a floor through the origin under `integrator`, at the format's defaults otherwise
// (dt 1/60, one sub-step, impulse contacts): the resting scenes' ground.
inline SceneDesc floorScene(const std::string& integrator) {
    SceneDesc s;
    s.simulation.integrator = integrator;
    s.effects.gravity = GravityDesc{};
    PlaneDesc floor;
    floor.point = {0.0, 0.0};
    floor.normal = {0.0, 1.0};
    s.planes.push_back(floor);
    return s;
}

// The mass of the world's moving particles and bodies (what CONTRACT §6's rest bound is per).
inline double dynamicMass(const World& world) {
    double mass = 0.0;
    for (const Particle& p : world.particles())
        if (!p.pinned) mass += p.mass;
    for (const RigidBody& b : world.rigidBodies())
        if (!b.isStatic) mass += b.mass;
    return mass;
}

}  // namespace phasebox::testing
