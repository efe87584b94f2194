// bench_sleeping: what sleeping (simulation.sleep) saves and what it changes, on the library's
// 20-row pyramid at the format's defaults (dt = 1/60, one step per frame).
//
// Cost: the pyramid is stepped with sleeping off and on from the same setup until the one with
// sleeping on is asleep, then both are timed step by step in turns (median over the repeats of
// the median step), with the allocations of the timed steps.
//
// Waking: a 1 m box slides at 2 m/s on a frictionless static ledge at the apex's base into the
// apex, arriving after the pyramid fell asleep. Reported: when it fell asleep, how far the apex
// moves with sleeping on and off, how far the two runs' apexes end apart, when the pyramid is
// all asleep again, and the largest displacement of any pyramid box from its setup.
//
//   bench_sleeping [--steps N] [--repeat N] [--json]

#include "AllocationCounter.h"
#include "BenchCommon.h"
#include "SleepScenes.h"

#include "physics/scene/BuildWorld.h"
#include "physics/scene/SceneLibrary.h"
#include "physics/world/World.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

namespace {

using namespace phasebox;
using namespace phasebox::bench;

constexpr int kRows = sleep_scenes::kRows;
constexpr int kBoxes = kRows * (kRows + 1) / 2;
constexpr int kDefaultSteps = 120;
constexpr int kDefaultRepeat = 7;

using sleep_scenes::pyramid;

int asleep(const World& w) {
    int n = 0;
    for (int i = 0; i < kBoxes; ++i) n += w.rigidBodies()[i].asleep;
    return n;
}

struct Cost {
    double asleepAt = -1.0;
    double awakeMs = 0.0, asleepMs = 0.0;
    double awakeAllocations = 0.0, asleepAllocations = 0.0;  // per step
};

double timeSteps(World& w, int steps, long long& allocations) {
    std::vector<double> ms;
    ms.reserve(static_cast<std::size_t>(steps));
    startCountingAllocations();
    for (int s = 0; s < steps; ++s) {
        const auto start = Clock::now();
        w.step();
        ms.push_back(1e3 * secondsBetween(start, Clock::now()));
    }
    allocations += stopCountingAllocations().total();
    return median(ms);
}

Cost measureCost(int steps, int repeat) {
    Cost c;
    auto awake = buildWorld(pyramid(false)).world;
    auto sleeping = buildWorld(pyramid(true)).world;
    while (sleeping->time() < 10.0 && asleep(*sleeping) < kBoxes) {
        sleeping->step();
        awake->step();
    }
    if (asleep(*sleeping) == kBoxes) c.asleepAt = sleeping->time();
    std::vector<double> awakeMs, asleepMs;
    long long awakeAllocations = 0, asleepAllocations = 0;
    for (int r = 0; r < repeat; ++r) {
        awakeMs.push_back(timeSteps(*awake, steps, awakeAllocations));
        asleepMs.push_back(timeSteps(*sleeping, steps, asleepAllocations));
    }
    c.awakeMs = median(awakeMs);
    c.asleepMs = median(asleepMs);
    c.awakeAllocations = double(awakeAllocations) / (steps * repeat);
    c.asleepAllocations = double(asleepAllocations) / (steps * repeat);
    return c;
}

struct Wake {
    double asleepAt = -1.0, asleepAgainAt = -1.0;
    double apexBefore = 0.0, apexAfter = 0.0;
    double largestDisplacement = 0.0;  // any pyramid box from its setup, over the run
};

Wake runSlider(bool sleep) {
    Wake r;
    auto w = buildWorld(sleep_scenes::pyramidAndSlider(sleep)).world;
    int apex = -1;
    for (int i = 0; i < static_cast<int>(w->rigidBodies().size()); ++i)
        if (w->rigidBodies()[i].id == "r19c0") apex = i;
    std::vector<Vec2> setup(kBoxes);
    for (int i = 0; i < kBoxes; ++i) setup[i] = w->bodyPosition(i);
    bool woke = false;
    while (w->time() < 16.0) {
        w->step();
        for (int i = 0; i < kBoxes; ++i)
            r.largestDisplacement =
                std::max(r.largestDisplacement, (w->bodyPosition(i) - setup[i]).norm());
        const int n = asleep(*w);
        if (r.asleepAt < 0.0 && n == kBoxes) r.asleepAt = w->time();
        if (r.asleepAt > 0.0 && n < kBoxes) woke = true;
        if (woke && r.asleepAgainAt < 0.0 && n == kBoxes) r.asleepAgainAt = w->time();
        if (w->time() < 7.0) r.apexBefore = w->bodyPosition(apex).x();
    }
    r.apexAfter = w->bodyPosition(apex).x();
    return r;
}

}  // namespace

int main(int argc, char** argv) {
    const Options options = parseOptions(argc, argv, "[--steps N] [--repeat N] [--json]");
    const int steps = options.steps ? options.steps : kDefaultSteps;
    const int repeat = options.repeat ? options.repeat : kDefaultRepeat;
    const Cost cost = measureCost(steps, repeat);
    const Wake on = runSlider(true), off = runSlider(false);
    const double pushedOn = on.apexBefore - on.apexAfter,
                 pushedOff = off.apexBefore - off.apexAfter;

    std::FILE* out = options.json ? stderr : stdout;
    std::fprintf(out,
                 "bench_sleeping: scenes::pyramid(%d), dt = 1/60; %d steps x %d repeats "
                 "(median)\n\n",
                 kRows, steps, repeat);
    std::fprintf(out, "  asleep (all %d boxes) at t = %.3f s\n", kBoxes, cost.asleepAt);
    std::fprintf(out, "  median step, sleeping off   %10.4f ms   %6.2f allocations/step\n",
                 cost.awakeMs, cost.awakeAllocations);
    std::fprintf(out, "  median step, asleep         %10.4f ms   %6.2f allocations/step\n",
                 cost.asleepMs, cost.asleepAllocations);
    std::fprintf(out, "  ratio asleep / awake        %10.4f\n\n", cost.asleepMs / cost.awakeMs);
    std::fprintf(out, "  a box sliding at 2 m/s into the apex (arrives at about t = 8 s):\n");
    std::fprintf(out,
                 "    apex pushed, sleeping on  %8.4f m (pyramid asleep at %.3f s, again "
                 "at %.3f s)\n",
                 pushedOn, on.asleepAt, on.asleepAgainAt);
    std::fprintf(out, "    apex pushed, sleeping off %8.4f m\n", pushedOff);
    std::fprintf(out, "    the two apexes end apart  %8.4f m\n",
                 std::abs(on.apexAfter - off.apexAfter));
    std::fprintf(out, "    largest box displacement  %8.4f m on, %.4f m off\n",
                 on.largestDisplacement, off.largestDisplacement);

    if (options.json) {
        Json json;
        json.beginObject();
        json.value("benchmark", "sleeping");
        json.value("rows", kRows);
        json.value("steps", steps);
        json.value("repeat", repeat);
        json.value("asleep_at", cost.asleepAt);
        json.value("awake_ms_per_step", cost.awakeMs);
        json.value("asleep_ms_per_step", cost.asleepMs);
        json.value("ratio_asleep_awake", cost.asleepMs / cost.awakeMs);
        json.value("asleep_allocations_per_step", cost.asleepAllocations);
        json.value("apex_pushed_sleeping_on", pushedOn);
        json.value("apex_pushed_sleeping_off", pushedOff);
        json.value("apex_end_difference", std::abs(on.apexAfter - off.apexAfter));
        json.value("asleep_again_at", on.asleepAgainAt);
        json.value("largest_displacement_on", on.largestDisplacement);
        json.value("largest_displacement_off", off.largestDisplacement);
        json.endObject();
        std::printf("%s\n", json.str().c_str());
    }
    return 0;
}
