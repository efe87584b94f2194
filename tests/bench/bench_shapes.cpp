// bench_shapes: what a polygon costs against a box, on the same pyramid in the same run
// (issue 16: a 20-row pyramid of hexagons within 1.5x the same pyramid of boxes). Both are
// stepped at the format's defaults after a warm-up, in turns within each repeat, and the
// ratio of the medians is printed with how far each pyramid settled.
//
//   bench_shapes [--steps N] [--repeat N] [--json]

#include "BenchCommon.h"

#include "physics/contacts/ContactStage.h"
#include "physics/scene/BuildWorld.h"
#include "physics/scene/SceneLibrary.h"
#include "physics/world/World.h"

#include <cstdio>
#include <memory>

namespace {

using namespace phasebox;
using namespace phasebox::bench;

constexpr int kRows = 20;
constexpr int kWarmup = 300;
constexpr int kDefaultSteps = 60;
constexpr int kDefaultRepeat = 7;

double largestDisplacement(const World& world) {
    double worst = 0.0;
    for (int i = 0; i < static_cast<int>(world.rigidBodies().size()); ++i)
        worst = std::max(worst, (world.bodyPosition(i) - world.rigidBodies()[i].position).norm());
    return worst;
}

}  // namespace

int main(int argc, char** argv) {
    const Options options = parseOptions(argc, argv, "[--steps N] [--repeat N] [--json]");
    const int steps = options.steps > 0 ? options.steps : kDefaultSteps;
    const int repeat = options.repeat > 0 ? options.repeat : kDefaultRepeat;
    const char* labels[2] = {"boxes (scenes::pyramid)", "hexagons (scenes::hexagonPyramid)"};
    std::unique_ptr<World> worlds[2] = {buildWorld(scenes::pyramid(kRows)).world,
                                        buildWorld(scenes::hexagonPyramid(kRows)).world};
    long long failed = 0;
    for (auto& w : worlds)
        for (int k = 0; k < kWarmup; ++k) failed += !w->step();
    std::vector<double> ms[2];
    for (int r = 0; r < repeat; ++r)
        for (int c = 0; c < 2; ++c) {
            const auto start = Clock::now();
            for (int s = 0; s < steps; ++s) failed += !worlds[c]->step();
            ms[c].push_back(1e3 * secondsBetween(start, Clock::now()) / steps);
        }
    const double box = median(ms[0]), hexagon = median(ms[1]);
    if (options.json) {
        std::printf(
            "{\"benchmark\": \"shapes\", \"rows\": %d, \"boxes_ms_per_step\": %.6g, "
            "\"hexagons_ms_per_step\": %.6g, \"ratio\": %.4g, \"failed_steps\": %lld}\n",
            kRows, box, hexagon, hexagon / box, failed);
        return failed ? 1 : 0;
    }
    std::printf(
        "bench_shapes: %d-row pyramids at the format's defaults, after %d warm-up steps; "
        "%d steps x %d repeats (median)\n\n",
        kRows, kWarmup, steps, repeat);
    for (int c = 0; c < 2; ++c)
        std::printf("  %-40s%8.3f ms/step  %5zu contacts  |dp|max %.4f m\n", labels[c],
                    c == 0 ? box : hexagon, worlds[c]->contacts()->contacts().size(),
                    largestDisplacement(*worlds[c]));
    std::printf("\n  ratio hexagons / boxes (target <= 1.5)   %8.2fx\n", hexagon / box);
    if (failed) std::printf("  steps that diverged: %lld\n", failed);
    return failed ? 1 : 0;
}
