// bench_contacts: what World::step() costs in contact-heavy scenes, and how much of it is the
// contact stage (broad phase, narrow phase, sequential impulses), in steady state.
//
// Scenes: the 20-, 40- and 100-row pyramids and the tower of 40 from the scene library (the
// scenes the stability suite checks and the app opens), 1,000 boxes of random sizes rained into a
// 30 m container, and 10,000 disks (radius 0.05 m, particle collisions on) piled up by gravity
// in a 10 m box. Each is stepped until it has settled (a fixed warm-up for the stacks, which
// also primes the warm start; "until nothing moves faster than a threshold" for the rain and
// the disks, whose peak step time while landing is reported too), then timed.
//
// Per scene: ms per step (median over repeats, and the slowest single timed step), contact
// constraints and points, the share of the step spent in the contact stage (the world's
// "contacts" profile entry over the wall time of the steps), the step's "collide" stage alone
// (broad phase, narrow phase, the contacts made and warm-started), and heap allocations per
// timed step (steady state must allocate nothing). The collide stage of the 100-row pyramid is
// printed on a line of its own.
//
//   bench_contacts [--steps N] [--repeat N] [--json] [--quick] [--scene KEY]...
//
// --scene runs only the named scenes (keys: pyramid20 pyramid40 pyramid100 tower40 rain1000
// disks10000), e.g. under a profiler. --quick shortens warm-up and timing and skips the 100-row
// pyramid and the 10,000 disks unless named. With --json the table goes to stderr and stdout
// carries one JSON object.

#include "AllocationCounter.h"
#include "BenchCommon.h"

#include "physics/contacts/ContactStage.h"
#include "physics/scene/BuildWorld.h"
#include "physics/scene/SceneDesc.h"
#include "physics/scene/SceneLibrary.h"
#include "physics/world/World.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <functional>
#include <random>
#include <string>
#include <vector>

namespace {

using namespace phasebox;
using namespace phasebox::bench;

constexpr std::uint32_t kSeed = 20240611;
constexpr int kDefaultSteps = 60;  // one simulated second per repeat
constexpr int kDefaultRepeat = 5;
constexpr int kStackWarmup = 300;  // 5 s: the stacks have settled, the warm start is primed

// ---- the scenes built here ----------------------------------------------------------------

PlaneDesc wall(const char* id, Point2 point, Point2 normal, double friction, double restitution) {
    PlaneDesc p;
    p.id = id;
    p.point = point;
    p.normal = normal;
    p.friction = friction;
    p.restitution = restitution;
    return p;
}

// 1,000 boxes of 0.5–1 m (random width and height, random tilt) on a grid 24 wide, 1.2 m
// apart, the lowest row 2 m above the floor, falling into a 30 m wide container of planes.
// The library's contact defaults (dt 1/60, 4 sub-steps) so it compares with the pyramids.
SceneDesc rain(int count) {
    SceneDesc s = scenes::pyramid(1);  // the library's contact-scene settings and ground
    s.name = "Rain of boxes";
    s.description = "Boxes of random sizes dropped into a container.";
    s.boxes.clear();
    s.planes.clear();
    s.planes.push_back(wall("floor", {0.0, 0.0}, {0.0, 1.0}, 0.6, 0.0));
    s.planes.push_back(wall("left", {-15.0, 0.0}, {1.0, 0.0}, 0.6, 0.0));
    s.planes.push_back(wall("right", {15.0, 0.0}, {-1.0, 0.0}, 0.6, 0.0));
    std::mt19937_64 rng(kSeed);
    std::uniform_real_distribution<double> side(0.5, 1.0);
    std::uniform_real_distribution<double> tilt(-0.3, 0.3);
    constexpr int kColumns = 24;      // the outermost boxes clear the walls
    constexpr double kSpacing = 1.2;  // wider than the largest box, so none starts touching
    for (int i = 0; i < count; ++i) {
        BoxDesc b;
        b.position = {(i % kColumns - 0.5 * (kColumns - 1)) * kSpacing,
                      2.0 + (i / kColumns) * kSpacing};
        b.size = {side(rng), side(rng)};
        b.angle = tilt(rng);
        s.boxes.push_back(b);
    }
    return s;
}

// `count` disks of radius 0.05 m in a 10 m wide box of four planes, on a grid 0.12 m apart
// (jittered so that the columns buckle), falling into a pile under gravity. No bounce, so that
// the pile comes to rest: with e = 0.1 (and the default 1 m/s restitution threshold) a pile
// this deep never settles; thousands of disks keep moving at up to 2–4 m/s after 15 s.
SceneDesc disks(int count) {
    SceneDesc s = scenes::pyramid(1);
    s.name = "Disks in a box";
    s.description = "Disks piling up under gravity.";
    s.boxes.clear();
    s.planes.clear();
    constexpr double kWidth = 10.0, kHeight = 30.0;
    s.planes.push_back(wall("floor", {0.0, 0.0}, {0.0, 1.0}, 0.5, 0.0));
    s.planes.push_back(wall("ceiling", {0.0, kHeight}, {0.0, -1.0}, 0.5, 0.0));
    s.planes.push_back(wall("left", {0.0, 0.0}, {1.0, 0.0}, 0.5, 0.0));
    s.planes.push_back(wall("right", {kWidth, 0.0}, {-1.0, 0.0}, 0.5, 0.0));
    s.effects.particleCollisions = ParticleCollisionsDesc{0.0};
    std::mt19937_64 rng(kSeed);
    std::uniform_real_distribution<double> jitter(-0.01, 0.01);
    constexpr double kSpacing = 0.12;
    const int perRow = static_cast<int>((kWidth - 0.2) / kSpacing);
    for (int i = 0; i < count; ++i) {
        ParticleDesc p;
        p.radius = 0.05;
        p.restitution = 0.0;
        p.position = {0.1 + kSpacing * (0.5 + i % perRow) + jitter(rng),
                      0.1 + kSpacing * (0.5 + i / perRow) + jitter(rng)};
        s.particles.push_back(p);
    }
    return s;
}

// ---- measuring ----------------------------------------------------------------------------

struct SceneSpec {
    const char* key;
    const char* label;
    std::function<SceneDesc()> make;
    // Warm-up: at least minWarmup steps, then on until no velocity component exceeds
    // settleSpeed (m/s or rad/s), at most maxWarmup steps in all.
    int minWarmup;
    int maxWarmup;
    double settleSpeed;
    bool big;  // skipped by --quick unless named
};

struct SceneResult {
    const SceneSpec* spec = nullptr;
    int bodies = 0;
    int warmupSteps = 0;
    double warmupPeakMs = 0.0, warmupPeakTime = 0.0;   // the slowest step while settling
    double settledSpeed = 0.0;                         // largest |u| component after warm-up
    double msPerStep = 0.0;                            // median over repeats
    double timedPeakMs = 0.0;                          // slowest single timed step
    double contactMsPerStep = 0.0;                     // median over repeats
    double contactShare = 0.0;                         // median over repeats
    double collideMsPerStep = 0.0;                     // the "collide" stage, median
    int workers = 1;                                   // the world's threads
    long long constraints = 0, points = 0;             // after the timed steps
    long long minConstraints = 0, maxConstraints = 0;  // over the timed repeats
    AllocationCounts allocations;                      // over all timed steps
    AllocationCounts warmupAllocations;                // while settling (buffers growing)
    long long timedSteps = 0;
    long long failedSteps = 0;
};

double largestSpeed(const World& world) {
    const Vec& u = world.velocities();
    return u.size() ? u.cwiseAbs().maxCoeff() : 0.0;
}

long long constraintCount(const World& world) {
    return world.contacts() ? static_cast<long long>(world.contacts()->contacts().size()) : 0;
}

double contactSeconds(const World& world) {
    for (const EffectCost& cost : world.effectCosts())
        if (cost.name == "contacts") return cost.seconds;
    return 0.0;
}

SceneResult measure(const SceneSpec& spec, int steps, int repeat, bool quick) {
    SceneResult result;
    result.spec = &spec;
    BuildResult built = buildWorld(spec.make());
    World& world = *built.world;
    result.bodies = static_cast<int>(world.rigidBodies().size() + world.particles().size());

    // Settle, timing each step for the peak (the landing of the rain is its worst moment).
    const int minWarmup = quick ? spec.minWarmup / 2 : spec.minWarmup;
    const int maxWarmup = quick ? spec.maxWarmup / 2 : spec.maxWarmup;
    int k = 0;
    startCountingAllocations();
    for (; k < maxWarmup; ++k) {
        if (k >= minWarmup && largestSpeed(world) <= spec.settleSpeed) break;
        const auto start = Clock::now();
        if (!world.step()) ++result.failedSteps;
        const double ms = 1e3 * secondsBetween(start, Clock::now());
        if (ms > result.warmupPeakMs) {
            result.warmupPeakMs = ms;
            result.warmupPeakTime = world.time();
        }
    }
    result.warmupAllocations = stopCountingAllocations();
    result.warmupSteps = k;
    result.settledSpeed = largestSpeed(world);

    // Timed repeats. Everything the loop touches is allocated before counting starts, and
    // effectCosts() (which builds a vector of names) is read after it stops.
    std::vector<double> stepMs(static_cast<std::size_t>(steps));
    std::vector<double> perStep, contactMs, share, collideMs;
    result.minConstraints = constraintCount(world);
    result.maxConstraints = result.minConstraints;
    for (int r = 0; r < repeat; ++r) {
        world.resetProfile();
        startCountingAllocations();
        const auto start = Clock::now();
        auto last = start;
        for (int s = 0; s < steps; ++s) {
            if (!world.step()) ++result.failedSteps;
            const auto now = Clock::now();
            stepMs[static_cast<std::size_t>(s)] = 1e3 * secondsBetween(last, now);
            last = now;
        }
        const AllocationCounts counts = stopCountingAllocations();
        const double wall = secondsBetween(start, last);
        result.allocations.operatorNew += counts.operatorNew;
        result.allocations.malloc += counts.malloc;
        result.timedSteps += steps;
        const double contacts = contactSeconds(world);
        perStep.push_back(1e3 * wall / steps);
        contactMs.push_back(1e3 * contacts / steps);
        share.push_back(contacts / wall);
        collideMs.push_back(world.stepProfile().msPerStep(static_cast<int>(StepStage::Collide)));
        result.timedPeakMs =
            std::max(result.timedPeakMs, *std::max_element(stepMs.begin(), stepMs.end()));
        const long long n = constraintCount(world);
        result.minConstraints = std::min(result.minConstraints, n);
        result.maxConstraints = std::max(result.maxConstraints, n);
    }
    result.msPerStep = median(perStep);
    result.contactMsPerStep = median(contactMs);
    result.contactShare = median(share);
    result.collideMsPerStep = median(collideMs);
    result.workers = world.workers();
    result.constraints = constraintCount(world);
    result.points = world.contacts() ? world.contacts()->pointCount() : 0;
    return result;
}

// ---- reporting ----------------------------------------------------------------------------

void printTable(std::FILE* out, const std::vector<SceneResult>& results, int steps, int repeat) {
    const ContactSettings solver;  // the defaults the library scenes use
    std::fprintf(out,
                 "bench_contacts: World::step() after settling, dt = 1/60, 4 sub-steps, "
                 "%d + %d iterations;\n%d steps x %d repeats (median)\n\n",
                 solver.iterations, solver.relaxIterations, steps, repeat);
    std::fprintf(out, "%-38s", "");
    for (const SceneResult& r : results) std::fprintf(out, "%12s", r.spec->key);
    std::fprintf(out, "\n");
    const auto row = [&](const char* label, auto get, const char* format) {
        std::fprintf(out, "%-38s", label);
        for (const SceneResult& r : results) std::fprintf(out, format, get(r));
        std::fprintf(out, "\n");
    };
    row(
        "bodies", [](const SceneResult& r) { return r.bodies; }, "%12d");
    row(
        "warm-up steps (until settled)", [](const SceneResult& r) { return r.warmupSteps; },
        "%12d");
    row(
        "  largest |u| after warm-up", [](const SceneResult& r) { return r.settledSpeed; },
        "%12.3f");
    row(
        "  slowest warm-up step, ms", [](const SceneResult& r) { return r.warmupPeakMs; },
        "%12.2f");
    row(
        "    at simulated time, s", [](const SceneResult& r) { return r.warmupPeakTime; },
        "%12.2f");
    row(
        "ms per step (median)", [](const SceneResult& r) { return r.msPerStep; }, "%12.3f");
    row(
        "  slowest timed step, ms", [](const SceneResult& r) { return r.timedPeakMs; }, "%12.3f");
    row(
        "  of which contacts, ms", [](const SceneResult& r) { return r.contactMsPerStep; },
        "%12.3f");
    row(
        "  of which the collide stage, ms", [](const SceneResult& r) { return r.collideMsPerStep; },
        "%12.3f");
    row(
        "  contact share of the step", [](const SceneResult& r) { return 100.0 * r.contactShare; },
        "%11.1f%%");
    row(
        "contact constraints (pairs)", [](const SceneResult& r) { return r.constraints; },
        "%12lld");
    row(
        "  min..max over repeats: min", [](const SceneResult& r) { return r.minConstraints; },
        "%12lld");
    row(
        "                         max", [](const SceneResult& r) { return r.maxConstraints; },
        "%12lld");
    row(
        "contact points", [](const SceneResult& r) { return r.points; }, "%12lld");
    row(
        "heap allocations per timed step",
        [](const SceneResult& r) { return double(r.allocations.total()) / r.timedSteps; },
        "%12.2f");
    row(
        "  operator new, total", [](const SceneResult& r) { return r.allocations.operatorNew; },
        "%12lld");
    row(
        "  malloc/calloc/realloc, total", [](const SceneResult& r) { return r.allocations.malloc; },
        "%12lld");
    row(
        "heap allocations during warm-up",
        [](const SceneResult& r) { return r.warmupAllocations.total(); }, "%12lld");
    row(
        "steps that reported divergence", [](const SceneResult& r) { return r.failedSteps; },
        "%12lld");
    if (!kCountsMalloc)
        std::fprintf(out, "(malloc not watched on this platform: Eigen allocations unseen)\n");
    std::fprintf(out,
                 "\nThe contact share is the world's \"contacts\" profile entry (collide once per "
                 "step, solve per sub-step,\nincluding the energy ledger's two energy sums around "
                 "each solve) over the wall time of the steps.\n");
}

std::string toJson(const std::vector<SceneResult>& results, int steps, int repeat) {
    Json json;
    json.beginObject();
    json.value("benchmark", "contacts");
    json.value("steps", steps);
    json.value("repeat", repeat);
    json.value("statistic", "median");
    json.value("unit", "ms_per_step");
    json.value("counts_malloc", kCountsMalloc);
    json.beginArray("scenes");
    for (const SceneResult& r : results) {
        json.beginObject();
        json.value("scene", r.spec->key);
        json.value("label", r.spec->label);
        json.value("bodies", r.bodies);
        json.value("warmup_steps", r.warmupSteps);
        json.value("settled_largest_speed", r.settledSpeed);
        json.value("warmup_peak_ms", r.warmupPeakMs);
        json.value("warmup_peak_time", r.warmupPeakTime);
        json.value("ms_per_step", r.msPerStep);
        json.value("timed_peak_ms", r.timedPeakMs);
        json.value("contacts_ms_per_step", r.contactMsPerStep);
        json.value("contact_share", r.contactShare);
        json.value("collide_ms_per_step", r.collideMsPerStep);
        json.value("constraints", r.constraints);
        json.value("constraints_min", r.minConstraints);
        json.value("constraints_max", r.maxConstraints);
        json.value("points", r.points);
        json.value("allocations_per_step", double(r.allocations.total()) / r.timedSteps);
        json.value("allocations_operator_new", r.allocations.operatorNew);
        json.value("allocations_malloc", r.allocations.malloc);
        json.value("timed_steps", r.timedSteps);
        json.value("warmup_allocations", r.warmupAllocations.total());
        json.value("failed_steps", r.failedSteps);
        json.endObject();
    }
    json.endArray();
    json.endObject();
    return json.str();
}

}  // namespace

int main(int argc, char** argv) {
    // --scene KEY is this program's own option; the rest goes to the shared parser.
    std::vector<std::string> only;
    std::vector<char*> rest{argv[0]};
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--scene") == 0 && i + 1 < argc)
            only.emplace_back(argv[++i]);
        else
            rest.push_back(argv[i]);
    }
    const Options options =
        parseOptions(static_cast<int>(rest.size()), rest.data(),
                     "[--steps N] [--repeat N] [--json] [--quick] [--scene KEY]...", {"--quick"});
    const int steps = options.steps ? options.steps : (options.quick ? 30 : kDefaultSteps);
    const int repeat = options.repeat ? options.repeat : (options.quick ? 3 : kDefaultRepeat);

    // The stacks start at rest and only need the warm-up; the rain lands in about 4 s and the
    // disks pile up in a few, then both are stepped until still (or the cap).
    const std::vector<SceneSpec> specs{
        {"pyramid20", "pyramid of 20 rows", [] { return scenes::pyramid(20); }, kStackWarmup,
         kStackWarmup, 0.0, false},
        {"pyramid40", "pyramid of 40 rows", [] { return scenes::pyramid(40); }, kStackWarmup,
         kStackWarmup, 0.0, false},
        {"pyramid100", "pyramid of 100 rows", [] { return scenes::pyramid(100); }, kStackWarmup,
         kStackWarmup, 0.0, true},
        {"tower40", "tower of 40", [] { return scenes::tower(40); }, kStackWarmup, kStackWarmup,
         0.0, false},
        {"rain1000", "1,000 boxes rained into a container", [] { return rain(1000); }, 360, 1200,
         0.05, false},
        {"disks10000", "10,000 disks piled in a box", [] { return disks(10000); }, 240, 600, 0.05,
         true},
    };
    for (const std::string& key : only) {
        const auto named = [&](const SceneSpec& s) { return key == s.key; };
        if (std::none_of(specs.begin(), specs.end(), named)) {
            std::fprintf(stderr, "unknown scene %s\n", key.c_str());
            return 2;
        }
    }

    std::vector<SceneResult> results;
    for (const SceneSpec& spec : specs) {
        const bool named = std::find(only.begin(), only.end(), spec.key) != only.end();
        if (!only.empty() && !named) continue;
        if (options.quick && spec.big && !named) continue;
        std::fprintf(stderr, "%s...\n", spec.key);
        results.push_back(measure(spec, steps, repeat, options.quick));
    }

    printTable(options.json ? stderr : stdout, results, steps, repeat);
    for (const SceneResult& r : results)
        if (std::strcmp(r.spec->key, "pyramid100") == 0)
            std::fprintf(options.json ? stderr : stdout,
                         "\ncollide stage of the 100-row pyramid: %.3f ms per step (%d workers)\n",
                         r.collideMsPerStep, r.workers);
    if (options.json) std::printf("%s\n", toJson(results, steps, repeat).c_str());
    return 0;
}
