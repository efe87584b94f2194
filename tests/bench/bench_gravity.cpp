// bench_gravity: what World::step() costs per particle under gravity alone, against the loop a
// programmer would write by hand over the same arrays, in the same run.
//
// The engine step includes its diagnostics (energy ledger, divergence check), so there are two
// baselines: the bare hand loop (v += h·g; x += h·v), and the same loop that also computes the
// kinetic energy ½Σm·v², the gravity potential −Σm·g·x and a finiteness check, in one pass.
// The target is engine ≤ 2× the bare hand loop.
//
//   bench_gravity [--steps N] [--repeat N] [--json] [--breakdown] [--quick]
//
// --breakdown adds hand-written models of the engine's step, one pass at a time, to show where
// the time beyond the hand loop goes. --quick runs only the smaller size (for profilers).
// With --json the table goes to stderr and stdout carries one JSON object.

#include "AllocationCounter.h"
#include "BenchCommon.h"

#include "physics/scene/BuildWorld.h"
#include "physics/scene/SceneDesc.h"
#include "physics/world/World.h"

#include <cstdint>
#include <cstdio>
#include <functional>
#include <random>
#include <string>
#include <vector>

namespace {

using namespace phasebox;
using namespace phasebox::bench;

constexpr double kDt = 1.0 / 60.0;
constexpr double kGx = 0.0, kGy = -9.81;
constexpr std::uint32_t kSeed = 20240611;
constexpr int kDefaultSteps = 200;
constexpr int kDefaultRepeat = 7;

// Written by every baseline so that the compiler must compute what they compute.
volatile double g_sink = 0.0;

SceneDesc gravityScene(int particles) {
    SceneDesc scene;
    scene.name = "bench_gravity";
    scene.simulation.integrator = "symplectic_euler";
    scene.simulation.dt = kDt;
    scene.effects.gravity = GravityDesc{{kGx, kGy}};
    std::mt19937_64 rng(kSeed);
    std::uniform_real_distribution<double> position(-100.0, 100.0);
    std::uniform_real_distribution<double> velocity(-10.0, 10.0);
    // Masses vary so that the diagnostics' m·v² is a real multiply, as in a real scene.
    std::uniform_real_distribution<double> mass(0.5, 2.0);
    scene.particles.resize(static_cast<std::size_t>(particles));
    for (ParticleDesc& p : scene.particles) {
        p.position = {position(rng), position(rng)};
        p.velocity = {velocity(rng), velocity(rng)};
        p.mass = mass(rng);
    }
    return scene;
}

// The hand-written state: the same layout as the engine's (x0, y0, x1, y1, …), per-dof masses.
struct HandState {
    std::vector<double> x, v, m;
    // Second buffers and an acceleration array, used only by the --breakdown models.
    std::vector<double> x1, v1, a;

    explicit HandState(const World& world)
        : x(world.positions().begin(), world.positions().end()),
          v(world.velocities().begin(), world.velocities().end()),
          m(world.mass().begin(), world.mass().end()),
          x1(x.size()),
          v1(v.size()),
          a(x.size()) {}
};

// ---- the two baselines --------------------------------------------------------------------
// Written as a programmer would: v += h·g, x += h·v, particle by particle over the interleaved
// arrays. The new velocity is held in a local before the stores: GCC 12 then packs each
// particle's (x, y) into one SSE register, whereas the literal `v[i] += …; x[i] += h·v[i]`
// form gets shuffles and is ~1.5× slower (kept as handStepLiteral for --breakdown). Results
// are bit-identical either way; the faster form is the stricter baseline.

void handStep(double* __restrict x, double* __restrict v, std::size_t n, double h) {
    const double dvx = h * kGx, dvy = h * kGy;
    for (std::size_t i = 0; i < n; i += 2) {
        const double vx = v[i] + dvx, vy = v[i + 1] + dvy;
        v[i] = vx;
        v[i + 1] = vy;
        x[i] += h * vx;
        x[i + 1] += h * vy;
    }
}

void handStepLiteral(double* __restrict x, double* __restrict v, std::size_t n, double h) {
    for (std::size_t i = 0; i < n; i += 2) {
        v[i] += h * kGx;
        v[i + 1] += h * kGy;
        x[i] += h * v[i];
        x[i + 1] += h * v[i + 1];
    }
}

// The same loop computing, in the same pass, what the engine's diagnostics compute: ½Σm·v²,
// the gravity potential −Σm·g·x and a finiteness check of x. Plain sums, as a programmer
// would write them. Returns a value depending on all three so none can be dropped.
double handStepWithDiagnostics(double* __restrict x, double* __restrict v,
                               const double* __restrict m, std::size_t n, double h) {
    const double dvx = h * kGx, dvy = h * kGy;
    double twiceKinetic = 0.0, potential = 0.0, check = 0.0;
    for (std::size_t i = 0; i < n; i += 2) {
        const double vx = v[i] + dvx, vy = v[i + 1] + dvy;
        const double px = x[i] + h * vx, py = x[i + 1] + h * vy;
        v[i] = vx;
        v[i + 1] = vy;
        x[i] = px;
        x[i + 1] = py;
        twiceKinetic += m[i] * vx * vx + m[i + 1] * vy * vy;
        potential -= m[i] * (kGx * px + kGy * py);
        check += px * 0.0 + py * 0.0;  // NaN exactly when x is not finite
    }
    const bool finite = std::isfinite(twiceKinetic) && std::isfinite(check);
    return finite ? 0.5 * twiceKinetic + potential : std::nan("");
}

// ---- models of the engine's step, for --breakdown -----------------------------------------
// Each pass below copies the loop of the engine code named in its comment, so that adding
// them one at a time attributes the engine's time to passes over memory. The "proposed"
// passes are what the report suggests changing in physics/.

using Lanes = Eigen::Array2d;  // one SSE register: accumulates x and y dofs side by side

// SymplecticEuler::step without an acceleration array: from buffer 0 into buffer 1.
void passDoubleBuffered(HandState& s, double h) {
    const std::size_t n = s.x.size();
    const double* __restrict q0 = s.x.data();
    const double* __restrict u0 = s.v.data();
    double* __restrict q = s.x1.data();
    double* __restrict u = s.v1.data();
    const double dvx = h * kGx, dvy = h * kGy;
    for (std::size_t i = 0; i < n; i += 2) {
        const double vx = u0[i] + dvx, vy = u0[i + 1] + dvy;
        u[i] = vx;
        u[i + 1] = vy;
        q[i] = q0[i] + h * vx;
        q[i + 1] = q0[i + 1] + h * vy;
    }
}

// GravityEffect::addAccelerations (overwrite) then SymplecticEuler::step: the smooth step.
void passAccelerationAndUpdate(HandState& s, double h) {
    const std::size_t n = s.x.size();
    double* __restrict a = s.a.data();
    for (std::size_t i = 0; i < n; i += 2) {
        a[i] = kGx;
        a[i + 1] = kGy;
    }
    clobber(a);  // the engine calls through a virtual function: no fusion across it
    const double* __restrict q0 = s.x.data();
    const double* __restrict u0 = s.v.data();
    double* __restrict q = s.x1.data();
    double* __restrict u = s.v1.data();
    for (std::size_t i = 0; i < n; ++i) {
        const double v = u0[i] + h * a[i];
        u[i] = v;
        q[i] = q0[i] + h * v;
    }
}

// World::kineticEnergyChecked on the new state (x1, v1 before the swap).
double passKineticChecked(const HandState& s) {
    const std::size_t n = s.x.size();
    const double* __restrict m = s.m.data();
    const double* __restrict q = s.x1.data();
    const double* __restrict u = s.v1.data();
    double twiceKinetic = 0.0, check = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        twiceKinetic += m[i] * u[i] * u[i];
        check += q[i] * 0.0;
    }
    return std::isfinite(twiceKinetic) && std::isfinite(check) ? 0.5 * twiceKinetic : std::nan("");
}

// GravityEffect::potentialEnergy on the new state.
double passPotential(const HandState& s) {
    const std::size_t n = s.x.size();
    const double* m = s.m.data();
    const double* q = s.x1.data();
    double sum = 0.0;
    for (std::size_t i = 0; i < n; i += 2) sum += m[i] * (kGx * q[i] + kGy * q[i + 1]);
    return -sum;
}

// Proposed World::kineticEnergyChecked: the same sums, kept in two-lane registers with two
// independent accumulators, so the compiler may vectorise them (a serial scalar sum may not
// be reordered without -ffast-math) and consecutive adds do not wait on each other.
double passKineticCheckedLanes(const HandState& s) {
    const Eigen::Index n = static_cast<Eigen::Index>(s.x.size());
    const double* m = s.m.data();
    const double* q = s.x1.data();
    const double* u = s.v1.data();
    Lanes k0 = Lanes::Zero(), k1 = Lanes::Zero(), c0 = Lanes::Zero(), c1 = Lanes::Zero();
    Eigen::Index i = 0;
    for (; i + 4 <= n; i += 4) {
        const Lanes u0 = Lanes::Map(u + i), u1 = Lanes::Map(u + i + 2);
        k0 += Lanes::Map(m + i) * u0 * u0;
        k1 += Lanes::Map(m + i + 2) * u1 * u1;
        c0 += Lanes::Map(q + i) * 0.0;
        c1 += Lanes::Map(q + i + 2) * 0.0;
    }
    for (; i < n; i += 2) {
        const Lanes u0 = Lanes::Map(u + i);
        k0 += Lanes::Map(m + i) * u0 * u0;
        c0 += Lanes::Map(q + i) * 0.0;
    }
    const double twiceKinetic = (k0 + k1).sum(), check = (c0 + c1).sum();
    return std::isfinite(twiceKinetic) && std::isfinite(check) ? 0.5 * twiceKinetic : std::nan("");
}

// Proposed GravityEffect::potentialEnergy: the mass moments Σm·x and Σm·y in the two lanes,
// then −(gx·Σm·x + gy·Σm·y).
double passPotentialLanes(const HandState& s) {
    const Eigen::Index n = static_cast<Eigen::Index>(s.x.size());
    const double* m = s.m.data();
    const double* q = s.x1.data();
    Lanes s0 = Lanes::Zero(), s1 = Lanes::Zero();
    Eigen::Index i = 0;
    for (; i + 4 <= n; i += 4) {
        s0 += Lanes::Map(m + i) * Lanes::Map(q + i);
        s1 += Lanes::Map(m + i + 2) * Lanes::Map(q + i + 2);
    }
    for (; i < n; i += 2) s0 += Lanes::Map(m + i) * Lanes::Map(q + i);
    const Lanes moment = s0 + s1;
    return -(kGx * moment[0] + kGy * moment[1]);
}

// Proposed, further: one diagnostics pass (kinetic energy and mass moments together; the
// moments are NaN or ∞ exactly when a position is, so they double as the finiteness check).
double passDiagnosticsFused(const HandState& s) {
    const Eigen::Index n = static_cast<Eigen::Index>(s.x.size());
    const double* m = s.m.data();
    const double* q = s.x1.data();
    const double* u = s.v1.data();
    Lanes k0 = Lanes::Zero(), k1 = Lanes::Zero(), s0 = Lanes::Zero(), s1 = Lanes::Zero();
    Eigen::Index i = 0;
    for (; i + 4 <= n; i += 4) {
        const Lanes m0 = Lanes::Map(m + i), m1 = Lanes::Map(m + i + 2);
        const Lanes u0 = Lanes::Map(u + i), u1 = Lanes::Map(u + i + 2);
        k0 += m0 * u0 * u0;
        k1 += m1 * u1 * u1;
        s0 += m0 * Lanes::Map(q + i);
        s1 += m1 * Lanes::Map(q + i + 2);
    }
    for (; i < n; i += 2) {
        const Lanes m0 = Lanes::Map(m + i), u0 = Lanes::Map(u + i);
        k0 += m0 * u0 * u0;
        s0 += m0 * Lanes::Map(q + i);
    }
    const double twiceKinetic = (k0 + k1).sum();
    const Lanes moment = s0 + s1;
    if (!std::isfinite(twiceKinetic) || !moment.allFinite()) return std::nan("");
    return 0.5 * twiceKinetic - (kGx * moment[0] + kGy * moment[1]);
}

// The update with all diagnostics in the same pass, in two-lane sums: kinetic energy, and
// the mass moments Σm·x, Σm·y (which give the gravity potential and are NaN or ∞ exactly when
// a position is). In place (from == to), it is the best a hand-written loop with diagnostics
// does; double-buffered, the least a double-buffered engine step with diagnostics can cost.
double fusedUpdateWithDiagnostics(const double* q0, const double* u0, double* q, double* u,
                                  const double* m, Eigen::Index n, double h) {
    const Lanes dv(h * kGx, h * kGy);
    Lanes k0 = Lanes::Zero(), k1 = Lanes::Zero(), s0 = Lanes::Zero(), s1 = Lanes::Zero();
    Eigen::Index i = 0;
    for (; i + 4 <= n; i += 4) {  // two particles per iteration: two independent sums each
        const Lanes v0 = Lanes::Map(u0 + i) + dv, v1 = Lanes::Map(u0 + i + 2) + dv;
        const Lanes x0 = Lanes::Map(q0 + i) + h * v0, x1 = Lanes::Map(q0 + i + 2) + h * v1;
        Lanes::Map(u + i) = v0;
        Lanes::Map(u + i + 2) = v1;
        Lanes::Map(q + i) = x0;
        Lanes::Map(q + i + 2) = x1;
        const Lanes m0 = Lanes::Map(m + i), m1 = Lanes::Map(m + i + 2);
        k0 += m0 * v0 * v0;
        k1 += m1 * v1 * v1;
        s0 += m0 * x0;
        s1 += m1 * x1;
    }
    for (; i < n; i += 2) {
        const Lanes v0 = Lanes::Map(u0 + i) + dv;
        const Lanes x0 = Lanes::Map(q0 + i) + h * v0;
        Lanes::Map(u + i) = v0;
        Lanes::Map(q + i) = x0;
        k0 += Lanes::Map(m + i) * v0 * v0;
        s0 += Lanes::Map(m + i) * x0;
    }
    const double twiceKinetic = (k0 + k1).sum();
    const Lanes moment = s0 + s1;
    if (!std::isfinite(twiceKinetic) || !moment.allFinite()) return std::nan("");
    return 0.5 * twiceKinetic - (kGx * moment[0] + kGy * moment[1]);
}

enum class Model {
    DoubleBuffered,  // the fused update, double-buffered, no acceleration array
    SmoothStep,      // + the acceleration pass: the engine's smooth step
    PlusKinetic,     // + World::kineticEnergyChecked
    EngineModel,     // + GravityEffect::potentialEnergy: all passes of World::step
    LanesPatch,      // smooth step + both diagnostics passes with two-lane sums
    FusedPatch,      // smooth step + one fused diagnostics pass with two-lane sums
    HandLanes,       // in place, diagnostics in the update pass, two-lane sums
    Floor,           // double-buffered, diagnostics in the update pass, no acceleration array
};

// One step of a model; swaps the buffers like the world's double-buffered state.
double modelStep(Model model, HandState& s, double h) {
    const auto n = static_cast<Eigen::Index>(s.x.size());
    if (model == Model::HandLanes)
        return fusedUpdateWithDiagnostics(s.x.data(), s.v.data(), s.x.data(), s.v.data(),
                                          s.m.data(), n, h);
    if (model == Model::Floor) {
        const double result = fusedUpdateWithDiagnostics(s.x.data(), s.v.data(), s.x1.data(),
                                                         s.v1.data(), s.m.data(), n, h);
        s.x.swap(s.x1);
        s.v.swap(s.v1);
        return result;
    }
    double result = 0.0;
    if (model == Model::DoubleBuffered)
        passDoubleBuffered(s, h);
    else
        passAccelerationAndUpdate(s, h);
    clobber(s.x1.data());
    clobber(s.v1.data());
    switch (model) {
        case Model::DoubleBuffered:
        case Model::SmoothStep:
        case Model::HandLanes:
        case Model::Floor:
            break;
        case Model::PlusKinetic:
            result = passKineticChecked(s);
            break;
        case Model::EngineModel:
            result = passKineticChecked(s) + passPotential(s);
            break;
        case Model::LanesPatch:
            result = passKineticCheckedLanes(s) + passPotentialLanes(s);
            break;
        case Model::FusedPatch:
            result = passDiagnosticsFused(s);
            break;
    }
    s.x.swap(s.x1);
    s.v.swap(s.v1);
    return result;
}

struct ModelInfo {
    Model model;
    const char* label;
    const char* key;
};
constexpr ModelInfo kModels[] = {
    {Model::DoubleBuffered, "double-buffered update, no accel array", "double_buffered"},
    {Model::SmoothStep, "+ acceleration pass (= smooth step)", "smooth_step"},
    {Model::PlusKinetic, "+ kinetic/finite pass (serial sums)", "plus_kinetic_pass"},
    {Model::EngineModel, "+ potential pass (= engine model)", "engine_model"},
    {Model::LanesPatch, "patch A: both diag passes, 2-lane sums", "patch_lanes"},
    {Model::FusedPatch, "patch B: one fused diag pass, 2-lane", "patch_fused"},
    {Model::HandLanes, "hand + diagnostics, 2-lane sums, 1 pass", "hand_diagnostics_lanes"},
    {Model::Floor, "floor: double-buffered, diag in update pass", "floor_double_buffered"},
};

// ---- measuring ----------------------------------------------------------------------------

struct SizeResult {
    int particles = 0;
    double engineNs = 0, handNs = 0, handDiagNs = 0;  // medians, ns per step per particle
    double engineSmoothNs = 0;  // of engineNs: the smooth step (World::integratorSeconds())
    double handLiteralNs = 0;   // --breakdown only
    double modelNs[std::size(kModels)] = {};
    long long failedSteps = 0;
    AllocationCounts allocations;  // over all timed engine steps of all repeats
    long long timedEngineSteps = 0;
    double checksum = 0;  // of the hand state, printed so the loops' results are used
};

SizeResult measure(int particles, int steps, int repeat, bool breakdown) {
    SizeResult result;
    result.particles = particles;
    BuildResult built = buildWorld(gravityScene(particles));
    World& world = *built.world;
    HandState hand(world);
    const std::size_t n = hand.x.size();

    // Every candidate runs `steps` steps per call. They take turns inside each repeat, so a
    // disturbance from another process (others build on the same cores) hits all of them
    // alike instead of one candidate's whole series; the median then drops it.
    std::vector<std::function<void(int)>> candidates;
    candidates.push_back([&](int count) {
        world.resetProfile();
        startCountingAllocations();
        for (int s = 0; s < count; ++s)
            if (!world.step()) ++result.failedSteps;
        const AllocationCounts counts = stopCountingAllocations();
        result.allocations.operatorNew += counts.operatorNew;
        result.allocations.malloc += counts.malloc;
        result.timedEngineSteps += count;
    });
    candidates.push_back([&](int count) {
        for (int s = 0; s < count; ++s) {
            handStep(hand.x.data(), hand.v.data(), n, kDt);
            clobber(hand.x.data());  // each step's stores must happen before the next step
            clobber(hand.v.data());
        }
    });
    candidates.push_back([&](int count) {
        double sum = 0.0;
        for (int s = 0; s < count; ++s) {
            sum += handStepWithDiagnostics(hand.x.data(), hand.v.data(), hand.m.data(), n, kDt);
            clobber(hand.x.data());
            clobber(hand.v.data());
        }
        g_sink = g_sink + sum;
    });
    if (breakdown) {
        candidates.push_back([&](int count) {
            for (int s = 0; s < count; ++s) {
                handStepLiteral(hand.x.data(), hand.v.data(), n, kDt);
                clobber(hand.x.data());
                clobber(hand.v.data());
            }
        });
        for (const ModelInfo& info : kModels) {
            candidates.push_back([&hand, model = info.model](int count) {
                double sum = 0.0;
                for (int s = 0; s < count; ++s) sum += modelStep(model, hand, kDt);
                g_sink = g_sink + sum;
            });
        }
    }

    // Warm-up: page faults, caches, branch predictors; also the engine's first-step work.
    const int warmup = std::max(10, steps / 4);
    for (auto& run : candidates) run(warmup);
    result.failedSteps = 0;
    result.allocations = {};
    result.timedEngineSteps = 0;

    const double perStepParticle = 1e9 / (double(steps) * particles);
    std::vector<std::vector<double>> ns(candidates.size());
    std::vector<double> smooth;
    for (int r = 0; r < repeat; ++r) {
        for (std::size_t c = 0; c < candidates.size(); ++c) {
            const auto start = Clock::now();
            candidates[c](steps);
            const auto end = Clock::now();
            ns[c].push_back(secondsBetween(start, end) * perStepParticle);
            if (c == 0) smooth.push_back(world.integratorSeconds() * perStepParticle);
        }
    }
    result.engineNs = median(ns[0]);
    result.engineSmoothNs = median(smooth);
    result.handNs = median(ns[1]);
    result.handDiagNs = median(ns[2]);
    if (breakdown) {
        result.handLiteralNs = median(ns[3]);
        for (std::size_t k = 0; k < std::size(kModels); ++k) result.modelNs[k] = median(ns[4 + k]);
    }

    double checksum = 0.0;
    for (std::size_t i = 0; i < n; ++i) checksum += hand.x[i] + hand.v[i];
    result.checksum = checksum;
    return result;
}

// ---- reporting ----------------------------------------------------------------------------

void printTable(std::FILE* out, const std::vector<SizeResult>& results, int steps, int repeat,
                bool breakdown) {
    std::fprintf(out,
                 "bench_gravity: gravity only, symplectic_euler, dt = 1/60, %d steps x %d "
                 "repeats (median), ns per step per particle\n\n",
                 steps, repeat);
    std::fprintf(out, "%-48s", "");
    for (const SizeResult& r : results) std::fprintf(out, "%14d", r.particles);
    std::fprintf(out, "\n");
    const auto row = [&](const char* label, auto get, const char* format) {
        std::fprintf(out, "%-48s", label);
        for (const SizeResult& r : results) std::fprintf(out, format, get(r));
        std::fprintf(out, "\n");
    };
    row(
        "engine  World::step()", [](const SizeResult& r) { return r.engineNs; }, "%14.3f");
    row(
        "  of which smooth step (integrator+effects)",
        [](const SizeResult& r) { return r.engineSmoothNs; }, "%14.3f");
    row(
        "  of which diagnostics and the rest",
        [](const SizeResult& r) { return r.engineNs - r.engineSmoothNs; }, "%14.3f");
    row(
        "hand loop", [](const SizeResult& r) { return r.handNs; }, "%14.3f");
    row(
        "hand loop + diagnostics (same pass)", [](const SizeResult& r) { return r.handDiagNs; },
        "%14.3f");
    row(
        "ratio engine / hand   (target <= 2)",
        [](const SizeResult& r) { return r.engineNs / r.handNs; }, "%13.2fx");
    row(
        "ratio engine / (hand + diagnostics)",
        [](const SizeResult& r) { return r.engineNs / r.handDiagNs; }, "%13.2fx");
    row(
        "engine heap allocations, timed steps",
        [](const SizeResult& r) { return r.allocations.total(); }, "%14lld");
    row(
        "  (timed engine steps)", [](const SizeResult& r) { return r.timedEngineSteps; }, "%14lld");
    row(
        "engine steps that reported divergence", [](const SizeResult& r) { return r.failedSteps; },
        "%14lld");
    if (!kCountsMalloc)
        std::fprintf(out, "(malloc not watched on this platform: Eigen allocations unseen)\n");
    if (breakdown) {
        std::fprintf(out, "\nbreakdown: hand-written models of the engine's passes\n");
        row(
            "hand loop, in place (the baseline)", [](const SizeResult& r) { return r.handNs; },
            "%14.3f");
        row(
            "hand loop, literal v[i] += h*g; x[i] += h*v[i]",
            [](const SizeResult& r) { return r.handLiteralNs; }, "%14.3f");
        for (std::size_t k = 0; k < std::size(kModels); ++k) {
            std::fprintf(out, "%-48s", kModels[k].label);
            for (const SizeResult& r : results) std::fprintf(out, "%14.3f", r.modelNs[k]);
            std::fprintf(out, "\n");
        }
        row(
            "engine World::step() (measured above)", [](const SizeResult& r) { return r.engineNs; },
            "%14.3f");
    }
    std::fprintf(out, "\n(checksums:");
    for (const SizeResult& r : results) std::fprintf(out, " %.6g", r.checksum);
    std::fprintf(out, ")\n");
}

std::string toJson(const std::vector<SizeResult>& results, int steps, int repeat, bool breakdown) {
    Json json;
    json.beginObject();
    json.value("benchmark", "gravity");
    json.value("integrator", "symplectic_euler");
    json.value("dt", kDt);
    json.value("steps", steps);
    json.value("repeat", repeat);
    json.value("statistic", "median");
    json.value("unit", "ns_per_step_per_particle");
    json.value("target_ratio_engine_hand", 2.0);
    json.value("counts_malloc", kCountsMalloc);
    json.beginArray("sizes");
    for (const SizeResult& r : results) {
        json.beginObject();
        json.value("particles", r.particles);
        json.value("engine", r.engineNs);
        json.value("engine_smooth_step", r.engineSmoothNs);
        json.value("engine_diagnostics_and_rest", r.engineNs - r.engineSmoothNs);
        json.value("hand", r.handNs);
        json.value("hand_with_diagnostics", r.handDiagNs);
        json.value("ratio_engine_hand", r.engineNs / r.handNs);
        json.value("ratio_engine_hand_with_diagnostics", r.engineNs / r.handDiagNs);
        json.value("within_target", r.engineNs / r.handNs <= 2.0);
        json.value("allocations", r.allocations.total());
        json.value("allocations_operator_new", r.allocations.operatorNew);
        json.value("allocations_malloc", r.allocations.malloc);
        json.value("timed_engine_steps", r.timedEngineSteps);
        json.value("failed_steps", r.failedSteps);
        if (breakdown) {
            json.beginObject("breakdown");
            json.value("hand_literal_form", r.handLiteralNs);
            for (std::size_t k = 0; k < std::size(kModels); ++k)
                json.value(kModels[k].key, r.modelNs[k]);
            json.endObject();
        }
        json.value("checksum", r.checksum);
        json.endObject();
    }
    json.endArray();
    json.endObject();
    return json.str();
}

}  // namespace

int main(int argc, char** argv) {
    const Options options =
        parseOptions(argc, argv, "[--steps N] [--repeat N] [--json] [--breakdown] [--quick]",
                     {"--breakdown", "--quick"});
    const int steps = options.steps ? options.steps : kDefaultSteps;
    const int repeat = options.repeat ? options.repeat : kDefaultRepeat;
    std::vector<int> sizes{20000, 100000};
    if (options.quick) sizes.resize(1);

    std::vector<SizeResult> results;
    for (const int particles : sizes)
        results.push_back(measure(particles, steps, repeat, options.breakdown));

    // With --json stdout carries only the JSON object; the table still goes to a person.
    printTable(options.json ? stderr : stdout, results, steps, repeat, options.breakdown);
    if (options.json)
        std::printf("%s\n", toJson(results, steps, repeat, options.breakdown).c_str());
    return 0;
}
