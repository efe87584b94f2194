#pragma once
// Probes (CONTRACT §7): the one vocabulary of measured quantities that the app's instruments
// and `phasebox-cli run --probe` read. A probe's text is parsed once against a world into a
// small record (what to measure, of which objects by index); evaluating it is a switch and a
// few reads of the state, with no allocation, so it can run every step.
//
//   ID.x ID.y ID.vx ID.vy ID.speed ID.angle ID.omega    the object's state (angle, ω: rigid)
//   ID.kinetic ID.px ID.py ID.L                         its energy, momentum, angular momentum
//                                                       about the origin (spin I·ω included)
//   system.kinetic .potential .total .work_nc .drift .correction     the energy ledger
//   system.px .py .L .com_x .com_y        of the dynamic objects (pinned and static excluded)
//   distance(A,B) angle(A,B,C) force(JOINT) contact_force(ID)
//   JOINT.angle                           a pendulum's θ from straight down (hinge, rod, rope)
//
// The arguments of distance and angle are objects or fixed points `X:Y` in metres
// (`angle(0:0,0:1.5,bob)`); angle's vertex is the middle one, as in ∠ABC.
//
// An object is a particle (a cloth node too: `flag[2,0]`) or a rigid body (box, disk,
// polygon). Pinned and static objects are valid everywhere: they sit at their fixed place with
// zero velocity (and no momentum or kinetic energy).
//
// PeriodTracker keeps a probe's statistics over a run in bounded memory: min, max, mean, final
// and the period of its oscillation (see there for how exact that is).

#include "physics/core/Types.h"

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace phasebox {

class World;

enum class ProbeKind : unsigned char {
    // of one object
    X,
    Y,
    Vx,
    Vy,
    Speed,
    Angle,
    Omega,
    Kinetic,
    Px,
    Py,
    AngularMomentum,
    // of the system
    SystemKinetic,
    SystemPotential,
    SystemTotal,
    SystemWorkNc,
    SystemDrift,
    SystemCorrection,
    SystemPx,
    SystemPy,
    SystemAngularMomentum,
    SystemComX,
    SystemComY,
    // instruments
    Distance,      // objects[0], objects[1]
    AngleAt,       // the angle at objects[1] from objects[0] to objects[2]
    JointForce,    // joint
    ContactForce,  // objects[0]
    JointAngle,    // joint: a pendulum's θ (jointAngle())
};

// An object a probe measures, resolved to its record.
struct ProbeObject {
    bool rigid = false;  // a rigid body (World::rigidBodies()) or a particle (World::particles())
    int index = -1;
};

struct Probe {
    std::string text;  // as given: the CSV column and the JSON key
    ProbeKind kind = ProbeKind::X;
    ProbeObject objects[3];
    // distance and angle: argument k is the fixed point points[k] (`X:Y`) instead of objects[k].
    std::optional<Vec2> points[3];
    int joint = -1;
};

// A probe, or why the text is not one: the message names the text and lists the vocabulary,
// `unknown probe "ball.z"; known: ID.x, ID.y, …` (with the reason before "; known" when the
// form is known but not its object: `unknown probe "b9.x": no object "b9"; known: …`).
struct ProbeParse {
    std::optional<Probe> probe;
    std::string error;
    explicit operator bool() const { return probe.has_value(); }
};

// The pieces the probes are made of, for the instruments that measure between places that are
// not all objects (a ruler from a body to a fixed point) and for the free-body view.
//
// The object of this id (a particle, a cloth node, a rigid body), or nullopt.
std::optional<ProbeObject> findProbeObject(const World& world, std::string_view id);
// Where it is now (a fixed object at its fixed place).
Vec2 probeObjectPosition(const World& world, const ProbeObject& object);
// A fixed point `X:Y` in metres (`-1.5:2e-1`), or nullopt when the text is not one.
std::optional<Vec2> parseProbePoint(std::string_view text);
// The signed angle at vertex from a − vertex to c − vertex, counter-clockwise positive, in
// (−π, π] (angle(A,B,C)); 0 when an arm has no length.
double signedAngle(const Vec2& a, const Vec2& vertex, const Vec2& c);

// JOINT.angle (CONTRACT §7), a pendulum's θ: for a hinge, rod or rope held to the world, the
// angle of the line from the anchor to a's centre (a hinge) or a's point (a rod, a rope) from
// straight down (−y), counter-clockwise positive, in (−π, π]; between two bodies a hinge's joint
// angle θb − θa − its value at load (CONTRACT §6, not wrapped: a wheel may turn many times), and
// a rod's or rope's line from b's point to a's point from straight down. nullopt for the other
// joint types.
std::optional<double> jointAngle(const World& world, int joint);

// Σ over the dynamic objects (pinned and static excluded): system.px, .py, .L, .com_x, .com_y.
struct SystemMotion {
    Vec2 momentum{0.0, 0.0};
    Vec2 massMoment{0.0, 0.0};  // Σ m·x
    double angularMomentum = 0.0;
    double mass = 0.0;
    // The centre of mass; nullopt when nothing is dynamic.
    std::optional<Vec2> centreOfMass() const {
        if (!(mass > 0.0)) return std::nullopt;
        return Vec2(massMoment / mass);
    }
};
SystemMotion systemMotion(const World& world);

// The vocabulary's forms, comma-separated (for messages and help texts).
std::string_view probeVocabulary();

// Resolves text against the world's objects and joints. Surrounding spaces and spaces after
// the commas of an instrument's arguments are ignored; ids are matched exactly.
ProbeParse parseProbe(const World& world, std::string_view text);

// The probe's value in the world's current state (SI units). A probe of a world whose objects
// changed since it was parsed must be parsed again. force(JOINT) is the joint's constraint force
// at the last derivative evaluation; contact_force(ID) the magnitude of World::contactForce: the
// vector sum of the contact impulses on the body over the last step divided by dt (0 when
// nothing touched it) as the impulse solver (SolverBody::stepImpulse) and the kinematic response
// book them, the penalty force at the current state under penalty. At a recorded frame shown
// (WorldSnapshot::show) both read the frame's forces (World::contactForce, World::jointForce).
double evaluateProbe(const World& world, const Probe& probe);

// The probe texts that parse against this world, for pickers that offer only valid probes: the
// system's, each particle's and rigid body's fields (angle and omega of rigid bodies only),
// force(JOINT) of each joint, JOINT.angle of each hinge, rod and rope, and contact_force(ID) of
// each moving body. Cloth nodes are left
// out (a cloth has hundreds): objectProbes() lists one node's.
std::vector<std::string> listProbes(const World& world);
// The fields of one object (`ID.x`, …, `contact_force(ID)` when it moves); empty when the world
// has no object of that id.
std::vector<std::string> objectProbes(const World& world, std::string_view id);
// The probes of one joint (`force(J)`, `J.angle` for a hinge, rod or rope); empty when the world
// has no joint of that id.
std::vector<std::string> jointProbes(const World& world, std::string_view id);

// The statistics of a probe's samples over a run (CONTRACT §7 `--probe` in `--json`).
struct ProbeSummary {
    long long samples = 0;
    double final = 0.0;
    double min = 0.0;
    double max = 0.0;
    double mean = 0.0;
    std::optional<double> period;
};

// The upward crossings of level by the series (times[i], values[i]), each crossing time
// interpolated linearly within its step, as PeriodTracker counts them: from below the level to
// at or above it. Pairs with a non-finite value are skipped.
std::vector<double> upwardCrossings(std::span<const double> times, std::span<const double> values,
                                    double level);

// Accumulates samples (t, value), t increasing, and reports ProbeSummary.
//
// mean: the plain mean of the samples added (the CLI adds one per step, all steps equal, so it
// is the time average by the rectangle rule). Non-finite samples are skipped.
//
// period: the mean interval between successive upward crossings of (min + max)/2 of the whole
// run, each crossing time interpolated linearly within its step. The mean of successive
// intervals telescopes to (last crossing − first crossing)/(crossings − 1), so only the number
// of crossings and the first and last crossing times matter. The level is known only at the
// end, so the samples are kept: every one up to `capacity`; then every other one is dropped and
// the stride doubles (memory stays below 16·capacity bytes however long the run). A decimated
// series alone would lose crossings once fewer than a few samples per period are left, so at
// the first decimation the tracker freezes the level of that moment, counts its crossings
// exactly from the still complete series, and from then on counts each new step exactly as it
// comes. At the end the frozen level is used when it lies within kLevelTolerance of the range
// from (min + max)/2: an oscillation whose extremes were all reached before that moment (or
// crept by less) gets its period from every sample, however long the run. Otherwise (the range
// kept growing: an unstable method, a drive) the level is frozen anew from the decimated series
// (at most once per capacity/4 samples, so the cost stays O(1) per sample), and the period
// there is as exact as the decimated series, which keeps at least capacity/2 samples.
class PeriodTracker {
public:
    static constexpr std::size_t kDefaultCapacity = 4096;
    // Relative to max − min: how far the frozen level may sit from the final mid-level. For a
    // steady oscillation the level's offset shifts the first and the last crossing alike and
    // cancels; it matters only for a swing whose extreme lies that close to the level.
    static constexpr double kLevelTolerance = 1e-3;

    explicit PeriodTracker(std::size_t capacity = kDefaultCapacity);
    void add(double t, double value);
    ProbeSummary summary() const;
    // Samples held now (≤ capacity), and whether they are all that was added.
    std::size_t storedSamples() const { return series_.size(); }
    bool complete() const { return !frozen_; }

private:
    struct Sample {
        double t, value;
    };
    // Upward crossings of one level.
    struct Crossings {
        long long count = 0;
        double first = 0.0, last = 0.0;
        void add(const Sample& a, const Sample& b, double level);
    };
    Crossings crossingsOfSeries(double level) const;
    void freeze();
    void decimate();

    std::size_t capacity_;
    std::vector<Sample> series_;
    long long stride_ = 1;  // series_ holds every stride_-th sample
    long long added_ = 0;   // finite samples added
    Sample last_{0.0, 0.0};
    double min_ = 0.0, max_ = 0.0;
    double sum_ = 0.0, compensation_ = 0.0;  // Neumaier summation of the values
    // The frozen level and its crossings, counted exactly from when it was frozen on.
    bool frozen_ = false;
    double level_ = 0.0;
    Crossings crossings_;
    long long sinceFreeze_ = 0;
};

}  // namespace phasebox
