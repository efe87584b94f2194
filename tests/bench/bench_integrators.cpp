// bench_integrators: the cost of one World::step() for every integrator of the registry on the
// same scene, a 1,000-particle spring chain under gravity (first particle pinned), in two
// configurations:
//
//   stiff   dt = 1/60, 1 sub-step: beyond the stability limit of the explicit methods
//           (the chain's highest mode has ω·h ≈ 10). They are expected to diverge; the table
//           then says "diverged" with the step at which World::step() returned false. Each
//           method first runs up to kHorizonSteps steps (4 s simulated, within a wall-time
//           budget) so that a slow blow-up is seen too, not only an immediate one.
//   stable  dt = 1/4000, 1 sub-step: every method is stable, so every method has a figure.
//           (Explicit Euler on a damped spring chain is stable only for h < c/k = 1/2000,
//           whatever the mode, so 1/2000 itself would be marginal.)
//
// Per method: ms per step (median of the repeats), force evaluations per step (the world's
// counter), linear solves per step (implicit methods), internal steps per step (adaptive
// methods), heap allocations per step. The bench also watches the kinetic energy itself: when
// it passes 100× the most gravity can give the chain, it notes the step ("runaway at"), so
// the table shows how long the world's divergence check took to react.
//
//   bench_integrators [--steps N] [--repeat N] [--json]
//
// --steps sets the timed steps of the stable configuration (default 200); the stiff one times
// a twentieth as many (at least 5): each of its steps covers 66× the time, and its adaptive
// and Newton-iterated methods are slow there. A tenth of the steps (at least 3) is run first
// as a warm-up. With --json the table goes to stderr and stdout carries one JSON object.

#include "AllocationCounter.h"
#include "BenchCommon.h"

#include "physics/integrators/Integrator.h"
#include "physics/scene/BuildWorld.h"
#include "physics/scene/SceneDesc.h"
#include "physics/world/World.h"

#include <cstdio>
#include <optional>
#include <string>
#include <vector>

namespace {

using namespace phasebox;
using namespace phasebox::bench;

constexpr int kParticles = 1000;
constexpr double kSpacing = 0.1;     // m, also the rest length: the chain starts unstretched
constexpr double kMass = 0.01;       // kg per particle
constexpr double kStiffness = 1000;  // N/m
constexpr double kDamping = 0.5;     // N·s/m
constexpr int kDefaultSteps = 200;
constexpr int kDefaultRepeat = 5;
constexpr double kG = 9.81;
// Wall-time budgets per method and configuration (see runMethod): they keep the whole run
// under 30 s although the slowest method is ~1000× slower per step than the fastest.
constexpr double kHorizonBudgetSeconds = 2.0;
constexpr double kRepeatBudgetSeconds = 1.5;
constexpr int kMinRepeats = 3;
constexpr int kHorizonSteps = 240;  // stiff configuration: 4 s simulated
// The most kinetic energy the chain can get from gravity: all its mass falling its length.
constexpr double kEnergyBound = kParticles * kMass * kG * kParticles * kSpacing;

struct Config {
    const char* name;
    double dt;
    int substeps;
    int steps;         // timed steps per repeat
    int horizonSteps;  // steps of the first run, to see divergence (at least warm-up + steps)
};

// "p<i>". (Not "p" + std::to_string(i): GCC 12 raises a false -Wrestrict on that at -O3.)
std::string nodeId(int i) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "p%d", i);
    return buf;
}

SceneDesc chainScene(const std::string& integrator, const Config& config) {
    SceneDesc scene;
    scene.name = "bench_integrators chain";
    scene.simulation.integrator = integrator;
    scene.simulation.dt = config.dt;
    scene.simulation.substeps = config.substeps;
    scene.effects.gravity = GravityDesc{{0.0, -kG}};
    scene.particles.resize(kParticles);
    for (int i = 0; i < kParticles; ++i) {
        ParticleDesc& p = scene.particles[static_cast<std::size_t>(i)];
        p.id = nodeId(i);
        p.position = {i * kSpacing, 0.0};
        p.mass = kMass;
        p.pinned = i == 0;
    }
    for (int i = 0; i + 1 < kParticles; ++i) {
        SpringDesc s;
        s.a = nodeId(i);
        s.b = nodeId(i + 1);
        s.stiffness = kStiffness;
        s.damping = kDamping;
        s.restLength = kSpacing;
        scene.springs.push_back(s);
    }
    return scene;
}

// One method on one configuration, over all repeats.
struct MethodResult {
    std::string name;
    int order = 0;
    bool implicit = false;
    bool adaptive = false;
    std::string evaluationsPhrase;  // what the registry says, for comparison
    bool diverged = false;
    long long divergedAtStep = 0;  // 1-based, counting warm-up steps
    double divergedAtTime = 0.0;
    std::string divergence;       // World::divergence()->what
    long long runawayAtStep = 0;  // kinetic energy first above 100 × kEnergyBound; 0 = never
    long long stepsRun = 0;       // by the first (horizon) run
    int repeats = 0;              // repeats actually run (slow methods stop early)
    double msPerStep = 0.0;       // median over repeats
    double evaluationsPerStep = 0.0;
    double linearSolvesPerStep = 0.0;
    double internalStepsPerStep = 0.0;  // accepted + rejected
    double rejectedPerStep = 0.0;
    double allocationsPerStep = 0.0;
    // Implicit methods, at the last step: Newton iterations and the size of the last update.
    int lastNewtonIterations = 0;
    double lastNewtonCorrection = 0.0;
};

struct Counters {
    long long evaluations = 0, linearSolves = 0, accepted = 0, rejected = 0;
    static Counters of(const World& world) {
        const IntegratorStats& s = world.integrator().stats();
        return {world.forceEvaluations(), s.linearSolves, s.acceptedSteps, s.rejectedSteps};
    }
};

// One run of a fresh world: `steps` steps, of which those from `warmup` on are timed, counted
// and watched for allocations; stops early at a divergence or when the wall-time budget is
// spent (but never before the timed steps are done).
struct Run {
    double seconds = 0.0;  // the timed steps
    int timed = 0;
    Counters counts;  // over the timed steps
    AllocationCounts allocations;
    long long stepsRun = 0;
    bool diverged = false;
    long long divergedAtStep = 0;
    double divergedAtTime = 0.0;
    std::string divergence;
    long long runawayAtStep = 0;
    IntegratorStats lastStats;
};

Run runOnce(const std::string& method, const Config& config, int warmup, int steps,
            double budgetSeconds) {
    Run run;
    // Building is not timed: 1,000 particles and springs with their ids.
    BuildResult built = buildWorld(chainScene(method, config));
    World& world = *built.world;
    const int timedEnd = warmup + config.steps;
    Counters before{};
    const auto runStart = Clock::now();
    for (int s = 0; s < steps; ++s) {
        if (s >= timedEnd && secondsBetween(runStart, Clock::now()) > budgetSeconds) break;
        const bool timing = s >= warmup && s < timedEnd;
        if (s == warmup) before = Counters::of(world);
        if (timing) startCountingAllocations();
        const auto start = Clock::now();
        const bool ok = world.step();
        const auto end = Clock::now();
        if (timing) {
            const AllocationCounts a = stopCountingAllocations();
            run.allocations.operatorNew += a.operatorNew;
            run.allocations.malloc += a.malloc;
            run.seconds += secondsBetween(start, end);
            ++run.timed;
        }
        run.stepsRun = s + 1;
        if (!ok) {
            run.diverged = true;
            run.divergedAtStep = s + 1;
            if (const auto& d = world.divergence()) {
                run.divergedAtTime = d->time;
                run.divergence = d->what;
            }
            return run;
        }
        if (run.runawayAtStep == 0 && !(world.energy().kinetic <= 100.0 * kEnergyBound))
            run.runawayAtStep = s + 1;
        if (s + 1 == timedEnd) {
            const Counters after = Counters::of(world);
            run.counts = {after.evaluations - before.evaluations,
                          after.linearSolves - before.linearSolves,
                          after.accepted - before.accepted, after.rejected - before.rejected};
            run.lastStats = world.integrator().stats();
        }
    }
    return run;
}

MethodResult runMethod(const IntegratorInfo& info, const Config& config, int repeat) {
    MethodResult result;
    result.name = std::string(info.name);
    result.order = info.order;
    result.implicit = info.implicit;
    result.adaptive = info.adaptive;
    result.evaluationsPhrase = std::string(info.evaluations);
    // Warm-up: caches, and the implicit methods' first factorisation.
    const int warmup = std::max(3, config.steps / 10);
    const int timedEnd = warmup + config.steps;

    std::vector<double> ms;
    double spent = 0.0;
    for (int r = 0; r < repeat; ++r) {
        // The slowest methods (Newton to convergence, adaptive Euler on the stiff chain) would
        // take most of the run: after kMinRepeats they stop once over budget.
        if (r >= kMinRepeats && spent > kRepeatBudgetSeconds) break;
        // Every repeat integrates the same trajectory from a fresh world, so repeats differ
        // only by timing noise; the first also looks further ahead for a divergence.
        const auto start = Clock::now();
        const Run run =
            r == 0 ? runOnce(result.name, config, warmup, std::max(timedEnd, config.horizonSteps),
                             kHorizonBudgetSeconds)
                   : runOnce(result.name, config, warmup, timedEnd, 0.0);
        spent += secondsBetween(start, Clock::now());
        if (r == 0) {
            result.stepsRun = run.stepsRun;
            result.runawayAtStep = run.runawayAtStep;
        }
        if (run.diverged) {
            // A cost per step of a diverging run is not a figure anyone should use: the
            // method's cost is in the stable configuration's table.
            result.diverged = true;
            result.divergedAtStep = run.divergedAtStep;
            result.divergedAtTime = run.divergedAtTime;
            result.divergence = run.divergence;
            return result;
        }
        const double steps = run.timed;
        ms.push_back(run.seconds * 1e3 / steps);
        // The counts are the same in every repeat (same trajectory); the last one is kept.
        result.evaluationsPerStep = double(run.counts.evaluations) / steps;
        result.linearSolvesPerStep = double(run.counts.linearSolves) / steps;
        result.internalStepsPerStep = double(run.counts.accepted + run.counts.rejected) / steps;
        result.rejectedPerStep = double(run.counts.rejected) / steps;
        result.allocationsPerStep = double(run.allocations.total()) / steps;
        result.lastNewtonIterations = run.lastStats.lastNewtonIterations;
        result.lastNewtonCorrection = run.lastStats.lastNewtonCorrection;
    }
    result.repeats = static_cast<int>(ms.size());
    result.msPerStep = median(ms);
    return result;
}

// ---- reporting ----------------------------------------------------------------------------

void printConfig(std::FILE* out, const Config& config, const std::vector<MethodResult>& results,
                 int repeat) {
    std::fprintf(out,
                 "\n%s: %d-particle spring chain (k = %g N/m, c = %g N*s/m, m = %g kg), gravity, "
                 "dt = %g s (1/%g), %d sub-step(s); %d timed steps x %d repeats, median\n",
                 config.name, kParticles, kStiffness, kDamping, kMass, config.dt, 1.0 / config.dt,
                 config.substeps, config.steps, repeat);
    std::fprintf(out, "%-18s %5s %-4s %11s %11s %11s %11s %11s  %s\n", "integrator", "order",
                 "kind", "ms/step", "evals/step", "solves/step", "substeps/st", "allocs/step",
                 "status");
    for (const MethodResult& r : results) {
        const char* kind = r.implicit ? "impl" : r.adaptive ? "adap" : "expl";
        std::fprintf(out, "%-18s %5d %-4s ", r.name.c_str(), r.order, kind);
        if (r.diverged) {
            std::fprintf(out, "%11s %11s %11s %11s %11s  ", "-", "-", "-", "-", "-");
            std::fprintf(out, "diverged at step %lld (t = %.4g s): %s", r.divergedAtStep,
                         r.divergedAtTime, r.divergence.c_str());
        } else {
            std::fprintf(out, "%11.4f %11.2f ", r.msPerStep, r.evaluationsPerStep);
            if (r.implicit)
                std::fprintf(out, "%11.2f ", r.linearSolvesPerStep);
            else
                std::fprintf(out, "%11s ", "-");
            if (r.adaptive)
                std::fprintf(out, "%11.1f ", r.internalStepsPerStep);
            else
                std::fprintf(out, "%11s ", "-");
            std::fprintf(out, "%11.1f  ok for %lld steps", r.allocationsPerStep, r.stepsRun);
            if (r.repeats < repeat) std::fprintf(out, " (%d repeats)", r.repeats);
        }
        // The bench's own watch: a kinetic energy no falling chain can have.
        if (r.runawayAtStep > 0)
            std::fprintf(out, "%s; KE > 100x bound from step %lld", r.diverged ? "" : " BUT",
                         r.runawayAtStep);
        std::fprintf(out, "\n");
    }
}

void writeConfigJson(Json& json, const Config& config, const std::vector<MethodResult>& results) {
    json.beginObject();
    json.value("name", config.name);
    json.value("dt", config.dt);
    json.value("substeps", config.substeps);
    json.value("steps", config.steps);
    json.beginArray("integrators");
    for (const MethodResult& r : results) {
        const bool measured = !r.diverged;
        const double none = std::nan("");  // written as null
        json.beginObject();
        json.value("name", r.name);
        json.value("order", r.order);
        json.value("implicit", r.implicit);
        json.value("adaptive", r.adaptive);
        json.value("status", r.diverged ? "diverged" : "ok");
        json.value("ms_per_step", measured ? r.msPerStep : none);
        json.value("force_evaluations_per_step", measured ? r.evaluationsPerStep : none);
        json.value("linear_solves_per_step",
                   r.implicit && !r.diverged ? r.linearSolvesPerStep : none);
        json.value("internal_steps_per_step",
                   r.adaptive && !r.diverged ? r.internalStepsPerStep : none);
        json.value("rejected_steps_per_step", r.adaptive && !r.diverged ? r.rejectedPerStep : none);
        json.value("allocations_per_step", r.diverged ? none : r.allocationsPerStep);
        json.value("repeats", r.repeats);
        json.value("steps_run", r.stepsRun);
        if (r.runawayAtStep > 0) json.value("runaway_at_step", r.runawayAtStep);
        if (r.implicit && measured) {
            json.value("last_newton_iterations", r.lastNewtonIterations);
            json.value("last_newton_correction", r.lastNewtonCorrection);
        }
        json.value("registry_evaluations", r.evaluationsPhrase);
        if (r.diverged) {
            json.value("diverged_at_step", r.divergedAtStep);
            json.value("diverged_at_time", r.divergedAtTime);
            json.value("divergence", r.divergence);
        }
        json.endObject();
    }
    json.endArray();
    json.endObject();
}

}  // namespace

int main(int argc, char** argv) {
    const Options options = parseOptions(argc, argv, "[--steps N] [--repeat N] [--json]");
    const int steps = options.steps ? options.steps : kDefaultSteps;
    const int repeat = options.repeat ? options.repeat : kDefaultRepeat;
    const Config configs[] = {
        {"stiff", 1.0 / 60.0, 1, std::max(5, steps / 20), kHorizonSteps},
        {"stable", 1.0 / 4000.0, 1, steps, 0},
    };

    std::FILE* out = options.json ? stderr : stdout;
    std::fprintf(out, "bench_integrators: World::step() per integrator (ms per step)\n");
    std::fprintf(out,
                 "runaway watch: kinetic energy above 100x %g J (all mass falling the "
                 "chain's length)\n",
                 kEnergyBound);
    Json json;
    json.beginObject();
    json.value("benchmark", "integrators");
    json.value("particles", kParticles);
    json.value("springs", kParticles - 1);
    json.value("stiffness", kStiffness);
    json.value("damping", kDamping);
    json.value("mass", kMass);
    json.value("energy_bound", kEnergyBound);
    json.value("repeat", repeat);
    json.value("statistic", "median");
    json.value("counts_malloc", kCountsMalloc);
    json.beginArray("configs");
    for (const Config& config : configs) {
        std::vector<MethodResult> results;
        for (const IntegratorInfo& info : integratorRegistry())
            results.push_back(runMethod(info, config, repeat));
        printConfig(out, config, results, repeat);
        writeConfigJson(json, config, results);
    }
    json.endArray();
    json.endObject();
    if (!kCountsMalloc)
        std::fprintf(out, "(malloc not watched on this platform: Eigen allocations unseen)\n");
    if (options.json) std::printf("%s\n", json.str().c_str());
    return 0;
}
