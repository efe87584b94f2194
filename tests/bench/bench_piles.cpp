// bench_piles: the pathological piles of issue 15, at the format's defaults (dt 1/60, one
// sub-step, symplectic Euler, no gravity).
//
// pile3000: 3,000 disks of radius 0.05 m started at one point with particle collisions on,
//   stepped for one simulated second (60 steps, once: the old quadratic code takes half a
//   minute). Reports seconds per simulated second, the most contact constraints any step
//   made, whether every value stayed finite, and the peak resident memory of the process
//   (VmHWM from /proc/self/status; the pile runs first, so the peak is its own).
// column/row: 20,000 disks 0.12 m apart (5 cm radius, so only the broad phase's grown boxes
//   touch) in a vertical column and in a horizontal row. Reports ms per step of each (median
//   over repeats) and their ratio: a broad phase that sweeps along a fixed axis makes the one
//   lying along the other axis quadratic.
//
//   bench_piles [--steps N] [--repeat N] [--json]     (--steps: timed steps of column and row)
//
// Uses only the scene description and World, so the same file builds against older trees.

#include "BenchCommon.h"

#if __has_include("physics/world/World.h")
#include "physics/world/World.h"
#else
#include "physics/core/World.h"
#endif
#include "physics/contacts/ContactStage.h"
#include "physics/scene/BuildWorld.h"
#include "physics/scene/SceneDesc.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace {

using namespace phasebox;
using namespace phasebox::bench;

// kB, or −1 where /proc is not there.
long long statusKilobytes(const char* field) {
    std::FILE* f = std::fopen("/proc/self/status", "r");
    if (!f) return -1;
    char line[256];
    long long value = -1;
    const std::size_t length = std::strlen(field);
    while (std::fgets(line, sizeof line, f)) {
        if (std::strncmp(line, field, length) == 0 && line[length] == ':') {
            value = std::atoll(line + length + 1);
            break;
        }
    }
    std::fclose(f);
    return value;
}

SceneDesc line(int count, bool vertical) {
    SceneDesc s;
    s.name = vertical ? "Column" : "Row";
    s.effects.particleCollisions = ParticleCollisionsDesc{};
    for (int i = 0; i < count; ++i) {
        ParticleDesc p;
        p.position = vertical ? Point2{0.0, 0.12 * i} : Point2{0.12 * i, 0.0};
        s.particles.push_back(p);
    }
    return s;
}

long long constraintCount(const World& world) {
    return world.contacts() ? static_cast<long long>(world.contacts()->contacts().size()) : 0;
}

struct PileResult {
    double secondsPerSimulatedSecond = 0.0;
    long long peakConstraints = 0;
    bool finite = true;
    long long rssBeforeKb = 0, peakRssKb = 0;
};

PileResult measurePile(int count, int steps) {
    PileResult r;
    r.rssBeforeKb = statusKilobytes("VmHWM");
    BuildResult built = buildWorld(pileAtPoint(count));
    World& world = *built.world;
    world.setWorkers(1);  // one thread (bench_threads measures the shared step)
    const auto start = Clock::now();
    for (int s = 0; s < steps; ++s) {
        world.step();
        r.peakConstraints = std::max(r.peakConstraints, constraintCount(world));
    }
    const double wall = secondsBetween(start, Clock::now());
    r.secondsPerSimulatedSecond = wall / (steps * world.settings().dt);
    r.finite = world.positions().allFinite() && world.velocities().allFinite();
    r.peakRssKb = statusKilobytes("VmHWM");
    return r;
}

double msPerStep(const SceneDesc& scene, int steps, int repeat) {
    BuildResult built = buildWorld(scene);
    World& world = *built.world;
    world.setWorkers(1);
    for (int s = 0; s < 3; ++s) world.step();  // buffers grown, the sweep order settled
    std::vector<double> perStep;
    for (int r = 0; r < repeat; ++r) {
        const auto start = Clock::now();
        for (int s = 0; s < steps; ++s) world.step();
        perStep.push_back(1e3 * secondsBetween(start, Clock::now()) / steps);
    }
    return median(perStep);
}

}  // namespace

int main(int argc, char** argv) {
    const Options options = parseOptions(argc, argv, "[--steps N] [--repeat N] [--json]");
    const int steps = options.steps ? options.steps : 30;
    const int repeat = options.repeat ? options.repeat : 3;
    std::FILE* out = options.json ? stderr : stdout;

    constexpr int kPile = 3000, kLine = 20000;
    std::fprintf(stderr, "pile3000...\n");
    const PileResult pile = measurePile(kPile, 60);
    std::fprintf(stderr, "column and row...\n");
    const double rowMs = msPerStep(line(kLine, false), steps, repeat);
    const double columnMs = msPerStep(line(kLine, true), steps, repeat);

    std::fprintf(out, "bench_piles: dt 1/60, 1 sub-step, symplectic Euler, no gravity\n\n");
    std::fprintf(out, "%d disks at one point, 1 simulated second (60 steps):\n", kPile);
    std::fprintf(out, "  seconds per simulated second   %10.3f\n", pile.secondsPerSimulatedSecond);
    std::fprintf(out, "  most contact constraints       %10lld\n", pile.peakConstraints);
    std::fprintf(out, "  state finite after             %10s\n", pile.finite ? "yes" : "NO");
    std::fprintf(out, "  peak RSS (VmHWM), MB           %10.1f   (%.1f before the scene)\n",
                 pile.peakRssKb / 1024.0, pile.rssBeforeKb / 1024.0);
    std::fprintf(out, "%d disks 0.12 m apart, %d steps x %d repeats (median):\n", kLine, steps,
                 repeat);
    std::fprintf(out, "  row, ms per step               %10.3f\n", rowMs);
    std::fprintf(out, "  column, ms per step            %10.3f\n", columnMs);
    std::fprintf(out, "  column / row                   %10.2f\n", columnMs / rowMs);

    if (options.json) {
        Json json;
        json.beginObject();
        json.value("benchmark", "piles");
        json.value("pile_bodies", kPile);
        json.value("pile_seconds_per_simulated_second", pile.secondsPerSimulatedSecond);
        json.value("pile_peak_constraints", pile.peakConstraints);
        json.value("pile_finite", pile.finite);
        json.value("pile_peak_rss_mb", pile.peakRssKb / 1024.0);
        json.value("line_bodies", kLine);
        json.value("row_ms_per_step", rowMs);
        json.value("column_ms_per_step", columnMs);
        json.value("column_row_ratio", columnMs / rowMs);
        json.endObject();
        std::printf("%s\n", json.str().c_str());
    }
    return 0;
}
