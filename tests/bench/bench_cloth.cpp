// bench_cloth: the price of stiffness. A cloth at dt = 1/60 under implicit Euler, against
// symplectic Euler with the sub-steps the stability advisor says it needs to survive the same
// stiffness, both as CPU seconds per simulated second, measured in the same run.
//
//   bench_cloth [--frames N] [--n N] [--stiffness K] [--json] [--implicit-only]
//
// Implicit Euler runs N frames from release (default 300, 5 simulated seconds); its mean is
// given over all of them and over the first second alone, where the falling cloth needs the
// most CG iterations. Symplectic Euler runs min(N, 60) frames (each costs a hundred sub-steps).
// --implicit-only skips the symplectic run (for profiling the implicit step alone).

#include "BenchCommon.h"

#include "physics/diagnostics/StabilityAdvisor.h"
#include "physics/scene/BuildWorld.h"
#include "physics/scene/SceneLibrary.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

using namespace phasebox;

namespace {

struct Measurement {
    double msPerFrame = 0.0;        // mean over the frames
    double medianMsPerFrame = 0.0;  // robust against another process taking the core a while
    double firstSecondMs = 0.0;     // mean over the first 60 frames
    int substeps = 1;
    bool diverged = false;
    double cgPerStep = 0.0;
};

Measurement measure(SceneDesc scene, int frames) {
    auto world = buildWorld(scene).world;
    for (int k = 0; k < 3; ++k) world->step();  // warm-up: patterns analysed, caches primed
    const long long cgBefore = world->integrator().stats().linearIterations;
    Measurement m;
    m.substeps = scene.simulation.substeps;
    std::vector<double> perFrame;
    perFrame.reserve(frames);
    double total = 0.0;
    for (int k = 0; k < frames; ++k) {
        const auto start = bench::Clock::now();
        const bool ok = world->step();
        perFrame.push_back(1000.0 * bench::secondsBetween(start, bench::Clock::now()));
        total += perFrame.back();
        if (!ok) {
            m.diverged = true;
            break;
        }
    }
    m.msPerFrame = total / static_cast<double>(perFrame.size());
    const std::size_t first = std::min<std::size_t>(60, perFrame.size());
    for (std::size_t k = 0; k < first; ++k)
        m.firstSecondMs += perFrame[k] / static_cast<double>(first);
    m.medianMsPerFrame = bench::median(perFrame);
    m.cgPerStep =
        static_cast<double>(world->integrator().stats().linearIterations - cgBefore) / frames;
    return m;
}

}  // namespace

int main(int argc, char** argv) {
    int frames = 300, n = 64;
    double stiffness = 2e4;
    bool json = false, implicitOnly = false;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--frames") && i + 1 < argc)
            frames = std::atoi(argv[++i]);
        else if (!std::strcmp(argv[i], "--n") && i + 1 < argc)
            n = std::atoi(argv[++i]);
        else if (!std::strcmp(argv[i], "--stiffness") && i + 1 < argc)
            stiffness = std::atof(argv[++i]);
        else if (!std::strcmp(argv[i], "--json"))
            json = true;
        else if (!std::strcmp(argv[i], "--implicit-only"))
            implicitOnly = true;
    }

    const SceneDesc implicitScene = scenes::cloth(n, stiffness);
    auto probe = buildWorld(implicitScene).world;
    const StabilityAdvice advice = adviseStability(*probe);
    // Symplectic Euler needs ω·h < 2: the sub-steps for that, with a 10% margin.
    SceneDesc explicitScene = implicitScene;
    explicitScene.simulation.integrator = "symplectic_euler";
    explicitScene.simulation.substeps =
        static_cast<int>(std::ceil(1.1 * implicitScene.simulation.dt * advice.omegaMax / 2.0));

    const Measurement imp = measure(implicitScene, frames);
    if (implicitOnly) explicitScene.simulation.substeps = 1;  // a token run, not reported
    const Measurement sym = measure(explicitScene, implicitOnly ? 1 : std::min(frames, 60));
    if (implicitOnly) {
        std::printf(
            "implicit_euler %d x %d, %d frames: %.2f ms per step (median %.2f, first second %.2f), "
            "%.1f CG iterations per step\n",
            n, n, frames, imp.msPerFrame, imp.medianMsPerFrame, imp.firstSecondMs, imp.cgPerStep);
        return 0;
    }
    const double framesPerSecond = 1.0 / implicitScene.simulation.dt;
    const double impCost = imp.msPerFrame * framesPerSecond / 1000.0;
    const double symCost = sym.msPerFrame * framesPerSecond / 1000.0;

    if (json) {
        std::printf(
            "{\"n\": %d, \"stiffness\": %g, \"omega_max\": %g, \"implicit_ms_per_step\": %g, "
            "\"implicit_median_ms_per_step\": %g, \"implicit_first_second_ms_per_step\": %g, "
            "\"implicit_cg_iterations_per_step\": %g, \"symplectic_substeps\": %d, "
            "\"symplectic_ms_per_frame\": %g, \"implicit_cpu_s_per_sim_s\": %g, "
            "\"symplectic_cpu_s_per_sim_s\": %g, \"symplectic_diverged\": %s}\n",
            n, stiffness, advice.omegaMax, imp.msPerFrame, imp.medianMsPerFrame, imp.firstSecondMs,
            imp.cgPerStep, sym.substeps, sym.msPerFrame, impCost, symCost,
            sym.diverged ? "true" : "false");
        return 0;
    }
    std::printf(
        "bench_cloth: %d x %d cloth, 1 kg, structural stiffness %g, dt = 1/60, %d frames "
        "(symplectic: %d)\n",
        n, n, stiffness, frames, std::min(frames, 60));
    std::printf("stiffest mode omega = %.4g rad/s (omega*dt = %.1f)\n\n", advice.omegaMax,
                advice.omegaMax * implicitScene.simulation.dt);
    std::printf("%-34s %12s %14s\n", "", "ms/frame", "CPU s per sim s");
    std::printf(
        "%-34s %12.2f %14.2f   (median %.2f ms, first second %.2f ms; %.1f CG iterations per "
        "step)\n",
        "implicit_euler, 1 step", imp.msPerFrame, impCost, imp.medianMsPerFrame, imp.firstSecondMs,
        imp.cgPerStep);
    std::printf("%-34s %12.2f %14.2f%s\n",
                ("symplectic_euler, " + std::to_string(sym.substeps) + " sub-steps").c_str(),
                sym.msPerFrame, symCost, sym.diverged ? "   (diverged!)" : "");
    std::printf("\nratio implicit / symplectic-with-sub-steps: %.2f\n", impCost / symCost);
    return 0;
}
