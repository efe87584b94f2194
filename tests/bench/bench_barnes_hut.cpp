// bench_barnes_hut: mutual gravity by the Barnes–Hut tree against direct summation, through the
// world's own force evaluation (World::forces), on clustered bodies: the time of one force
// evaluation each way, the speed-up, and the tree's error against the direct sum (relative
// force error per body: median, 99th percentile, maximum; relative potential energy error).
//
//   bench_barnes_hut [--repeat N] [--json] [--quick]
//
// --quick measures 5,000 bodies only (the direct sum of 20,000 takes about a second).
// With --json the table goes to stderr and stdout carries one JSON object.

#include "BenchCommon.h"

#include "physics/effects/NewtonianGravityEffect.h"
#include "physics/scene/BuildWorld.h"
#include "physics/scene/SceneLibrary.h"
#include "physics/world/World.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <vector>

namespace {

using namespace phasebox;
using namespace phasebox::bench;

constexpr int kDefaultRepeat = 5;

// Median seconds of one World::forces() call over `repeat` calls.
double timeForces(World& world, int repeat, Eigen::VectorXd& force) {
    const Eigen::VectorXd q = world.positions(), u = world.velocities();
    std::vector<double> seconds;
    for (int r = 0; r < repeat; ++r) {
        const auto start = Clock::now();
        world.forces(0.0, q, u, force);
        clobber(force.data());
        seconds.push_back(secondsBetween(start, Clock::now()));
    }
    return median(seconds);
}

struct Row {
    int bodies = 0;
    double theta = 0.0;
    double treeSeconds = 0.0, directSeconds = 0.0;
    double median = 0.0, p99 = 0.0, max = 0.0, potential = 0.0;
};

}  // namespace

int main(int argc, char** argv) {
    const Options options =
        parseOptions(argc, argv, "[--repeat N] [--json] [--quick]", {"--quick"});
    const int repeat = options.repeat > 0 ? options.repeat : kDefaultRepeat;
    std::vector<int> sizes = {5000, 20000};
    if (options.quick) sizes.resize(1);
    std::vector<Row> rows;
    struct WorkerRow {
        int bodies;
        double one, two;
        bool same;
    };
    std::vector<WorkerRow> workerRows;
    for (const int n : sizes) {
        auto world = buildWorld(scenes::clusteredBodies(n)).world;
        auto& gravity =
            static_cast<NewtonianGravityEffect&>(*world->findEffect("newtonian_gravity"));
        Eigen::VectorXd direct(world->dimension()), tree(world->dimension());
        gravity.setTreeThreshold(1 << 30);
        // The direct sum is O(N²): one call is enough at 20,000 bodies.
        const double directSeconds = timeForces(*world, n > 10000 ? 1 : repeat, direct);
        const double directPotential = world->potentialEnergy();
        gravity.setTreeThreshold(NewtonianGravityEffect::kDefaultTreeThreshold);
        for (const double theta : {0.3, 0.5, 0.7}) {
            gravity.setOpeningAngle(theta);
            Row row;
            row.bodies = n;
            row.theta = theta;
            row.directSeconds = directSeconds;
            row.treeSeconds = timeForces(*world, repeat, tree);
            std::vector<double> errors;
            for (int i = 0; i < n; ++i)
                errors.push_back((tree.segment<2>(2 * i) - direct.segment<2>(2 * i)).norm() /
                                 direct.segment<2>(2 * i).norm());
            std::sort(errors.begin(), errors.end());
            row.median = errors[errors.size() / 2];
            row.p99 = errors[static_cast<std::size_t>(0.99 * static_cast<double>(n - 1))];
            row.max = errors.back();
            row.potential = std::abs(world->potentialEnergy() / directPotential - 1.0);
            rows.push_back(row);
        }
        // The tree's walks shared by two workers (the same bits as one: BarnesHutTree::addForces).
        gravity.setOpeningAngle(0.5);
        Eigen::VectorXd one(world->dimension()), two(world->dimension());
        world->setWorkers(1);
        const double oneSeconds = timeForces(*world, repeat, one);
        world->setWorkers(2);
        const double twoSeconds = timeForces(*world, repeat, two);
        const bool same = std::memcmp(one.data(), two.data(), sizeof(double) * one.size()) == 0;
        workerRows.push_back({n, oneSeconds, twoSeconds, same});
    }
    FILE* table = options.json ? stderr : stdout;
    std::fprintf(table, "%7s %5s %12s %12s %9s %10s %10s %10s %10s\n", "bodies", "theta", "tree ms",
                 "direct ms", "speed-up", "median", "99%", "max", "potential");
    for (const Row& r : rows)
        std::fprintf(table, "%7d %5.1f %12.2f %12.2f %9.1f %10.2e %10.2e %10.2e %10.2e\n", r.bodies,
                     r.theta, 1e3 * r.treeSeconds, 1e3 * r.directSeconds,
                     r.directSeconds / r.treeSeconds, r.median, r.p99, r.max, r.potential);
    for (const WorkerRow& w : workerRows)
        std::fprintf(table,
                     "%7d bodies, theta 0.5: tree forces %.2f ms on 1 worker, %.2f ms on 2 "
                     "(%.2fx), the same bits: %s\n",
                     w.bodies, 1e3 * w.one, 1e3 * w.two, w.two / w.one, w.same ? "yes" : "NO");
    if (options.json) {
        Json json;
        json.beginObject();
        json.value("benchmark", "barnes_hut");
        json.beginArray("rows");
        for (const Row& r : rows) {
            json.beginObject();
            json.value("bodies", r.bodies);
            json.value("theta", r.theta);
            json.value("tree_ms", 1e3 * r.treeSeconds);
            json.value("direct_ms", 1e3 * r.directSeconds);
            json.value("speedup", r.directSeconds / r.treeSeconds);
            json.value("median_relative_error", r.median);
            json.value("p99_relative_error", r.p99);
            json.value("max_relative_error", r.max);
            json.value("potential_relative_error", r.potential);
            json.endObject();
        }
        json.endArray();
        json.endObject();
        std::printf("%s\n", json.str().c_str());
    }
    return 0;
}
