#pragma once
// Closed-form solutions for the scenes whose motion Phasebox knows exactly, used as the
// reference of the accuracy study: linear oscillators (particles on springs to fixed points,
// undamped or damped, in 2D when the force is linear and along the spring's axis otherwise),
// free fall (with linear drag and wind, or none), Kepler orbits around one fixed attractor,
// simple pendulums (a particle on a rod to a fixed point, or a bead on a hoop) swinging under
// gravity, at any amplitude below the top, and physical pendulums (a rigid body on a hinge to a
// fixed point; on a rod or taut rope at its centre it swings as a simple pendulum and spins
// freely).
//
// Exactness is claimed only when the world's equations of motion are exactly those of the
// closed form: anything else (a coupling spring, quadratic drag, a contact, a spring with a
// rest length swinging sideways) makes findExactReference() answer nullopt and the study falls
// back to a tight rk45 run.

#include "physics/core/Types.h"

#include <Eigen/Dense>

#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace phasebox {

class World;
struct SceneDesc;

// x'' + γ·x' + ω²·x = f with x(0) = x0, x'(0) = v0: one coordinate of a damped oscillator
// (ω² > 0) or of free motion under a constant force and linear drag (ω² = 0).
struct LinearMotion {
    double omega2 = 0.0;
    double gamma = 0.0;
    double force = 0.0;
    double x0 = 0.0;
    double v0 = 0.0;

    double at(double t) const;
    // A lower bound of x(t) over [0, T] (exact for the undamped oscillator and for the
    // over-damped and critical cases, the envelope for the under-damped one).
    double lowerBound(double T) const;
};

// A Kepler orbit (elliptic or hyperbolic) of a body around a fixed centre, from its elements.
struct KeplerMotion {
    Vec2 centre{0.0, 0.0};
    Vec2 periapsis{1.0, 0.0};  // unit vector towards the periapsis (P)
    Vec2 normal{0.0, 1.0};     // P turned by 90° in the direction of motion (Q)
    double a = 1.0;            // semi-major axis, |a| for a hyperbola
    double b = 1.0;            // semi-minor axis (ellipse) or a·√(e² − 1) (hyperbola)
    double e = 0.0;
    double meanMotion = 1.0;  // √(μ/|a|³)
    double meanAnomaly0 = 0.0;
    bool hyperbolic = false;

    // Elements from the position relative to the centre and the velocity; nullopt for the
    // cases not handled here (radial and near-parabolic orbits, a body at the centre).
    static std::optional<KeplerMotion> fromState(const Vec2& centre, const Vec2& position,
                                                 const Vec2& velocity, double mu);
    Vec2 at(double t) const;
};

// A simple pendulum of length L about a fixed centre under gravity (down the unit vector
// `down`), swinging below the top (libration): sin(θ/2) = k·sn(ω₀·t + φ, k), ω₀ = √(g/L),
// θ counted from `down` toward `side` (down turned by +90°).
struct PendulumMotion {
    Vec2 centre{0.0, 0.0}, down{0.0, -1.0}, side{1.0, 0.0};
    double length = 1.0, omega0 = 1.0, k = 0.0, phase = 0.0;

    double startAngle = 0.0;  // θ at t = 0

    // From the state; nullopt when it goes over the top (k ≥ 1) or sits at the centre. The
    // point swings at `length` from the centre; equivalentLength sets ω₀ = √(g/L) when it
    // differs (a physical pendulum: L = I_pivot/(m·d), with d = length; 0 = length).
    static std::optional<PendulumMotion> fromState(const Vec2& centre, double length, const Vec2& g,
                                                   const Vec2& position, const Vec2& velocity,
                                                   double equivalentLength = 0.0);
    // θ(t), from `down` toward `side`.
    double angle(double t) const;
    Vec2 at(double t) const;
};
// A ball moving straight along a plane's normal under gravity and penalty contact (CONTRACT §6):
// flights with s'' = −g and contacts in which the overlap
// d = r − s obeys m·d'' = m·g − k·d − c·d' (F = k·d + c·ḋ, not clamped while d > 0), each phase
// a LinearMotion of the height s of the centre above the plane, joined where s crosses r. A
// contact lasts π·√(m/k)/√(1 − ζ²) without gravity; with it, slightly longer.
struct PenaltyBounceMotion {
    struct Phase {
        double start = 0.0;
        LinearMotion s;
        bool contact = false;
    };
    std::vector<Phase> phases;

    static PenaltyBounceMotion fromState(double s0, double v0, double g, double radius, double k,
                                         double c, double m, double endTime);
    // The same ball under impulse contacts (no overlap: flights joined where v ← −e·v, at rest
    // once an impact is slower than threshold·(1 − e)).
    static PenaltyBounceMotion impulse(double s0, double v0, double g, double radius,
                                       double restitution, double threshold, double endTime);
    double height(double t) const;
};

class ExactReference {
public:
    // The motions a closed form is made of, each giving some coordinates of the world's state.
    // A recogniser (findExactReference and the others below) fills a Parts and hands it over
    // whole; nothing reaches into an ExactReference afterwards, so no recogniser needs its
    // privates.
    struct Coordinate {
        int dof;
        LinearMotion motion;
    };
    // A particle moving on a fixed line through the anchor of its spring: x = anchor + s·axis.
    struct AxisMotion {
        int dof;
        Vec2 anchor, axis;
        LinearMotion s;
    };
    struct Orbit {
        int dof;
        KeplerMotion orbit;
    };
    struct Pendulum {
        int dof;
        PendulumMotion motion;
    };
    // A rigid body whose centre swings as `motion` does: on a hinge it turns with the line from
    // the pivot (angle = angle0 + θ(t) − θ(0)); on a rod or rope at its centre it spins freely
    // (angle = angle0 + spin·t).
    struct RigidPendulum {
        int dof;
        PendulumMotion motion;
        double angle0 = 0.0;
        bool hinged = true;
        double spin = 0.0;
        double angle(double t) const {
            return hinged ? angle0 + motion.angle(t) - motion.startAngle : angle0 + spin * t;
        }
    };
    // x = plane point + s·n + the start's offset along the plane (which stays).
    struct Bounce {
        int dof;
        Vec2 base, normal;
        PenaltyBounceMotion motion;
    };
    // Particles on a line joined by springs to each other and to fixed points: x_i = origin +
    // s_i·axis with M·s'' = −K·s + f, so s(t) = s* + Σ_k φ_k·(a_k·cos ω_k t + b_k·sin ω_k t/ω_k)
    // over the normal modes K·φ = ω²·M·φ (φᵀ·M·φ = 1).
    struct Modes {
        std::vector<int> dofs;
        Vec2 origin{0.0, 0.0}, axis{1.0, 0.0};
        Eigen::VectorXd equilibrium, omega, a, b;
        Eigen::MatrixXd shapes;  // column k: φ_k
        double along(std::size_t i, double t) const;
    };
    // A free body (no force but uniform gravity) moving in flights joined where an impulse
    // changes its velocity and spin: x = x_k + v_k·τ + ½·g·τ², angle = θ_k + ω_k·τ, τ = t − t_k.
    struct Flight {
        int dof;
        bool rigid;  // the angle is the state's third coordinate
        Vec2 g{0.0, 0.0};
        struct Phase {
            double start;
            Vec2 x, v;
            double angle, omega;
        };
        std::vector<Phase> phases;
        const Phase& at(double t) const;
        Vec2 position(double t) const;
        double angle(double t) const;
    };
    struct Parts {
        std::string kind;
        double validUntil = std::numeric_limits<double>::infinity();
        int dimension = 0;
        std::vector<Coordinate> coordinates;
        std::vector<AxisMotion> axes;
        std::vector<Orbit> orbits;
        std::vector<Pendulum> pendulums;
        std::vector<RigidPendulum> rigidPendulums;
        std::vector<Bounce> bounces;
        std::vector<Modes> modes;
        std::vector<Flight> flights;
    };
    // Implicit, so that a recogniser returns its Parts as an std::optional<ExactReference>.
    ExactReference(Parts parts)
        : parts_(std::move(parts)) {}  // NOLINT(google-explicit-constructor)
    const Parts& parts() const { return parts_; }

    // What the reference is, for people: "harmonic oscillator", "Kepler orbit", ….
    const std::string& kind() const { return parts_.kind; }
    // Every position coordinate of the world's state (its layout) at time t.
    Vec positions(double t) const;
    // One position coordinate at time t, without the others (the phase plot's one curve).
    double position(int dof, double t) const;
    // Its rate, by a central difference of the closed form (relative error about 1e-10).
    double velocity(int dof, double t) const;
    // Whether the closed form gives this coordinate (findBodyReferences covers only some).
    bool covers(int dof) const;
    // The periods of the periodic motions in it (undamped oscillators, pendulums, elliptic
    // orbits); empty when nothing repeats.
    std::vector<double> periods() const;
    // The closed form holds up to this time (the first contact that can happen along it);
    // +∞ when it holds throughout (findDisplayReference alone answers shorter ones).
    double validUntil() const { return parts_.validUntil; }

private:
    Parts parts_;
};

// The closed form of the scene's motion up to endTime, or nullopt when there is none that is
// exact for this world. `world` is the scene built by buildWorld(scene), at t = 0.
std::optional<ExactReference> findExactReference(const SceneDesc& scene, const World& world,
                                                 double endTime);

// Closed forms for single bodies of a scene that has none as a whole: today a ball bouncing
// straight on a plane under penalty contact (the lesson "Three ways to collide"), with nothing
// else within reach of its path at the start and nothing attached to it. nullopt when no body
// qualifies; covers() tells which coordinates the answer gives.
std::optional<ExactReference> findBodyReferences(const SceneDesc& scene, const World& world,
                                                 double endTime);

// Boxes and disks lying on a face of a static rectangle (a ramp, a table) under gravity alone
// with impulse contacts: a box slides with Coulomb friction μ = √(μ_body·μ_support) (stopping
// where friction wins), a disk from rest rolls without slipping at g_t/(1 + I/(m·r²)) when
// friction can hold it, else slides and spins up. Each until it leaves its face; a body with
// anything else within reach of its path is left out. nullopt when no body qualifies.
std::optional<ExactReference> findSupportedReferences(const SceneDesc& scene, const World& world,
                                                      double endTime);

// Particles joined by undamped springs to each other and to fixed points, all on one line and
// moving along it, with no other force: the normal modes (kind "coupled oscillators"), while no
// spring's ends pass each other. findExactReference tries it when springs couple particles.
std::optional<ExactReference> coupledOnALine(const World& world, double endTime);

// Two free bodies (a particle or disk against a disk or a box that does not spin before it is
// hit) that meet once under impulse contacts, with nothing but uniform gravity acting and
// nothing else within reach: each body flies until the impact, where one impulse
// j = −(1 + e)·v_n/(1/m₁ + 1/m₂ + (r₁×n)²/I₁ + (r₂×n)²/I₂) along the normal changes both
// momenta and spins, and flies on (kind "impact"). Holds for the whole run when they do not
// meet again; frictionless pairs only, unless the impact has no sliding to resist. nullopt
// otherwise. The lesson "Impulse and spin".
std::optional<ExactReference> findImpactReference(const SceneDesc& scene, const World& world,
                                                  double endTime);

// What View → Exact Solution draws: findExactReference's answer (for the whole run), else
// single bodies' closed forms (findBodyReferences and findSupportedReferences together: they go
// on through their bodies' contacts), else the scene's closed form up to the first contact that
// can happen along it (validUntil(); an Atwood machine until a weight lands). Not for the
// accuracy study, which needs the whole run.
std::optional<ExactReference> findDisplayReference(const SceneDesc& scene, const World& world,
                                                   double endTime);

}  // namespace phasebox
