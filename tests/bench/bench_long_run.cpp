// Long runs: an hour of simulated time of the elastic gas and of the pyramid (the library's
// default sizes, the scenes the app opens), checking that memory stays flat and every value
// stays finite. Resident memory is read from /proc/self/statm once per simulated minute.
//
// usage: bench_long_run [--seconds S] [--scene gas|pyramid|all]
// Exit status 0 when both runs stay finite, never diverge and grow resident memory by less
// than 1 MiB between the first and the last simulated minute; 1 otherwise.

#include "physics/scene/BuildWorld.h"
#include "physics/scene/SceneLibrary.h"
#include "physics/world/World.h"
#include "tests/bench/BenchCommon.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

using namespace phasebox;

namespace {

// Resident set size in bytes (the second field of /proc/self/statm, in pages).
long long residentBytes() {
    std::FILE* file = std::fopen("/proc/self/statm", "r");
    if (!file) return -1;
    long long size = 0, resident = 0;
    const int read = std::fscanf(file, "%lld %lld", &size, &resident);
    std::fclose(file);
    return read == 2 ? resident * static_cast<long long>(::sysconf(_SC_PAGESIZE)) : -1;
}

double mib(long long bytes) {
    return static_cast<double>(bytes) / (1024.0 * 1024.0);
}

struct RunFigures {
    long long steps = 0;
    double wallSeconds = 0.0;
    long long rssFirstMinute = 0, rssLastMinute = 0, rssPeak = 0;
    bool finite = true, diverged = false;
    double maxSpeed = 0.0, drift = 0.0, maxAbsDrift = 0.0, initialEnergy = 0.0, kinetic = 0.0,
           workNc = 0.0;
};

RunFigures run(const std::string& name, SceneDesc scene, double simulatedSeconds) {
    RunFigures f;
    BuildResult built = buildWorld(scene);
    World& world = *built.world;
    const double dt = world.settings().dt;
    const long long steps = static_cast<long long>(std::ceil(simulatedSeconds / dt - 1e-9));
    const long long stepsPerMinute = static_cast<long long>(std::llround(60.0 / dt));
    std::printf("%s: %zu particles, %zu boxes, dt = %.6g s, %d sub-steps, %lld steps\n",
                name.c_str(), world.particles().size(), world.rigidBodies().size(), dt,
                world.settings().substeps, steps);
    f.initialEnergy = world.energy().initial;
    const auto start = bench::Clock::now();
    for (long long k = 1; k <= steps; ++k) {
        if (!world.step()) {
            f.diverged = true;
            std::printf("  diverged: %s\n", world.divergence()->message().c_str());
            break;
        }
        f.steps = k;
        const bool minute = k % stepsPerMinute == 0 || k == steps;
        if (!minute) continue;
        // Finite everywhere: the state, and the energies computed from it.
        const EnergyLedger& e = world.energy();
        f.finite = f.finite && world.positions().allFinite() && world.velocities().allFinite() &&
                   std::isfinite(e.kinetic) && std::isfinite(e.potential) && std::isfinite(e.drift);
        for (int i = 0; i < static_cast<int>(world.particles().size()); ++i)
            f.maxSpeed = std::max(f.maxSpeed, world.particleVelocity(i).norm());
        for (int i = 0; i < static_cast<int>(world.rigidBodies().size()); ++i)
            f.maxSpeed = std::max(f.maxSpeed, world.bodyVelocity(i).norm());
        const long long rss = residentBytes();
        if (k == stepsPerMinute) f.rssFirstMinute = rss;
        f.rssLastMinute = rss;
        f.rssPeak = std::max(f.rssPeak, rss);
        const long long minuteIndex = (k + stepsPerMinute - 1) / stepsPerMinute;
        if (minuteIndex % 10 == 0 || k == steps)
            std::printf("  t = %7.1f s  rss %7.2f MiB  kinetic %.6g J  drift %.3g J  wall %.1f s\n",
                        world.time(), mib(rss), e.kinetic, e.drift,
                        bench::secondsBetween(start, bench::Clock::now()));
        std::fflush(stdout);
    }
    f.wallSeconds = bench::secondsBetween(start, bench::Clock::now());
    f.drift = world.energy().drift;
    f.maxAbsDrift = world.energy().maxAbsDrift;
    f.kinetic = world.energy().kinetic;
    f.workNc = world.energy().workNc;
    return f;
}

}  // namespace

int main(int argc, char** argv) {
    double seconds = 3600.0;
    std::string which = "all";
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--seconds") && i + 1 < argc)
            seconds = std::atof(argv[++i]);
        else if (!std::strcmp(argv[i], "--scene") && i + 1 < argc)
            which = argv[++i];
        else {
            std::fprintf(stderr, "usage: %s [--seconds S] [--scene gas|pyramid|all]\n", argv[0]);
            return 2;
        }
    }
    if (!(seconds >= 60.0)) {
        std::fprintf(stderr, "--seconds: at least 60 (one memory sample per simulated minute)\n");
        return 2;
    }
    struct Named {
        std::string name;
        SceneDesc scene;
    };
    std::vector<Named> runs;
    // The library's default sizes: what `phasebox-cli scene gas` and the app's examples hold.
    if (which == "all" || which == "gas")
        runs.push_back({"elastic gas (200 disks)", scenes::elasticGas(200)});
    if (which == "all" || which == "pyramid")
        runs.push_back({"pyramid (20 rows, 210 boxes)", scenes::pyramid(20)});

    bool good = true;
    for (const Named& r : runs) {
        const RunFigures f = run(r.name, r.scene, seconds);
        const double growth = mib(f.rssLastMinute - f.rssFirstMinute);
        const bool flat = growth < 1.0;
        std::printf(
            "%s: %lld steps to t = %.0f s in %.1f s wall (%.3f ms/step)\n"
            "  resident memory: %.2f MiB after 1 min, %.2f MiB after %.0f min (%+.3f MiB), peak "
            "%.2f MiB\n"
            "  values finite: %s; diverged: %s; fastest object %.4g m/s\n"
            "  energy: initial %.10g J, kinetic now %.10g J, work_nc %.4g J, drift %.3g J, "
            "largest |drift| %.3g J\n\n",
            r.name.c_str(), f.steps, seconds, f.wallSeconds,
            1000.0 * f.wallSeconds / std::max<long long>(1, f.steps), mib(f.rssFirstMinute),
            mib(f.rssLastMinute), seconds / 60.0, growth, mib(f.rssPeak), f.finite ? "yes" : "NO",
            f.diverged ? "YES" : "no", f.maxSpeed, f.initialEnergy, f.kinetic, f.workNc, f.drift,
            f.maxAbsDrift);
        good = good && f.finite && !f.diverged && flat;
    }
    return good ? 0 : 1;
}
