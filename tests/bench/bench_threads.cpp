// bench_threads: what sharing the step's loops among workers (World::setWorkers, WorkerPool)
// gains, measured on the scenes of issue 39:
//
// pyramid100: the 100-row pyramid (5,050 boxes), settled for a few steps first.
// pile3000: 3,000 disks started at one point with particle collisions on (its first second).
//
// For each scene, one world per worker count (1 and 2 unless --workers gives a list), stepped
// in turns: a block of steps on each world in turn, repeated, so that every count sees the
// same load from the rest of the machine. Reports the median over blocks of the collide stage
// and of the whole step (ms per step), and their ratio to one worker. It also checks that the
// worlds stay bit-identical, and measures the pool's own cost: a loop of two empty chunks.
//
//   bench_threads [--steps N] [--repeat N] [--workers 1,2,4] [--json]

#include "BenchCommon.h"

#include "physics/core/WorkerPool.h"
#include "physics/scene/BuildWorld.h"
#include "physics/scene/SceneDesc.h"
#include "physics/scene/SceneLibrary.h"
#include "physics/world/World.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

namespace {

using namespace phasebox;
using namespace phasebox::bench;

struct Timing {
    std::vector<double> collideMs, stepMs;
};

struct SceneResult {
    std::string name;
    std::vector<Timing> perCount;
    bool identical = true;
};

SceneResult measure(const std::string& name, const SceneDesc& scene, int warmup,
                    const std::vector<int>& counts, int steps, int repeat) {
    SceneResult r{name, std::vector<Timing>(counts.size()), true};
    std::vector<std::unique_ptr<World>> worlds;
    for (int n : counts) {
        worlds.push_back(buildWorld(scene).world);
        worlds.back()->setWorkers(n);
        for (int s = 0; s < warmup; ++s) worlds.back()->step();
    }
    const int collide = static_cast<int>(StepStage::Collide);
    for (int block = 0; block < repeat; ++block)
        for (std::size_t w = 0; w < worlds.size(); ++w) {
            World& world = *worlds[w];
            world.resetProfile();
            const auto start = Clock::now();
            for (int s = 0; s < steps; ++s) world.step();
            r.perCount[w].stepMs.push_back(1e3 * secondsBetween(start, Clock::now()) / steps);
            r.perCount[w].collideMs.push_back(world.stepProfile().msPerStep(collide));
        }
    for (const auto& world : worlds)
        r.identical = r.identical && world->positions() == worlds[0]->positions() &&
                      world->velocities() == worlds[0]->velocities();
    return r;
}

// Microseconds per parallelFor of two chunks of nothing, at this many workers.
double poolOverheadUs(int workers) {
    WorkerPool pool(workers);
    int sink[2] = {0, 0};
    const auto loop = [&](int begin, int, int) { sink[begin] += 1; };
    for (int k = 0; k < 1000; ++k) pool.parallelFor(2, 1, loop);
    std::vector<double> us;
    for (int r = 0; r < 5; ++r) {
        const auto start = Clock::now();
        for (int k = 0; k < 10000; ++k) pool.parallelFor(2, 1, loop);
        us.push_back(1e6 * secondsBetween(start, Clock::now()) / 10000);
    }
    clobber(sink);
    return median(us);
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<int> counts = {1, 2};
    // --workers LIST is taken out before the common options are parsed.
    std::vector<char*> rest;
    for (int i = 0; i < argc; ++i) {
        if (i + 1 < argc && std::strcmp(argv[i], "--workers") == 0) {
            counts.clear();
            for (const char* p = argv[++i]; *p;) {
                counts.push_back(std::atoi(p));
                while (*p && *p != ',') ++p;
                if (*p == ',') ++p;
            }
            continue;
        }
        rest.push_back(argv[i]);
    }
    const Options options = parseOptions(static_cast<int>(rest.size()), rest.data(),
                                         "[--steps N] [--repeat N] [--workers 1,2,4] [--json]");
    const int steps = options.steps ? options.steps : 5;
    const int repeat = options.repeat ? options.repeat : 7;

    std::vector<SceneResult> results;
    std::fprintf(stderr, "pyramid100...\n");
    results.push_back(measure("pyramid100", scenes::pyramid(100), 3, counts, steps, repeat));
    std::fprintf(stderr, "pile3000...\n");
    results.push_back(measure("pile3000", pileAtPoint(3000), 3, counts, steps, repeat));

    std::FILE* out = stdout;
    if (options.json) std::fprintf(out, "{\"scenes\": [");
    for (std::size_t s = 0; s < results.size(); ++s) {
        const SceneResult& r = results[s];
        const double collide1 = median(r.perCount[0].collideMs);
        const double step1 = median(r.perCount[0].stepMs);
        if (!options.json)
            std::fprintf(out, "%s (%d steps x %d blocks, median; worlds identical: %s)\n",
                         r.name.c_str(), steps, repeat, r.identical ? "yes" : "NO");
        else
            std::fprintf(out, "%s{\"name\": \"%s\", \"identical\": %s, \"workers\": [",
                         s ? ", " : "", r.name.c_str(), r.identical ? "true" : "false");
        for (std::size_t c = 0; c < counts.size(); ++c) {
            const double collide = median(r.perCount[c].collideMs);
            const double step = median(r.perCount[c].stepMs);
            if (!options.json)
                std::fprintf(out,
                             "  %2d workers: collide %8.3f ms (%.2fx)   step %8.3f ms (%.2fx)\n",
                             counts[c], collide, collide / collide1, step, step / step1);
            else
                std::fprintf(out, "%s{\"workers\": %d, \"collide_ms\": %.4f, \"step_ms\": %.4f}",
                             c ? ", " : "", counts[c], collide, step);
        }
        if (options.json) std::fprintf(out, "]}");
    }
    std::vector<double> overhead;
    for (int n : counts) overhead.push_back(poolOverheadUs(n));
    if (options.json) {
        std::fprintf(out, "], \"pool_overhead_us\": [");
        for (std::size_t c = 0; c < counts.size(); ++c)
            std::fprintf(out, "%s%.3f", c ? ", " : "", overhead[c]);
        std::fprintf(out, "]}\n");
    } else {
        std::fprintf(out, "a loop of two empty chunks:");
        for (std::size_t c = 0; c < counts.size(); ++c)
            std::fprintf(out, "  %d workers %.2f us", counts[c], overhead[c]);
        std::fprintf(out, "\n");
    }
    bool identical = true;
    for (const SceneResult& r : results) identical = identical && r.identical;
    return identical ? 0 : 1;
}
