// Pathological piles (issue 15), at the format's defaults (dt 1/60, one sub-step, symplectic
// Euler): thousands of disks started at one point must cost a bounded number of contacts and
// come apart along finite, reproducible normals; a column must cost the broad phase what a
// row costs. Wall-time ratios are bench_piles' business; here the work is counted.

#include "physics/contacts/BroadPhase.h"
#include "physics/contacts/ContactStage.h"
#include "physics/scene/BuildWorld.h"
#include "physics/scene/SceneDesc.h"
#include "physics/world/World.h"

#include "../bench/AllocationCounter.h"

#include <QTest>

#include <cmath>
#include <ctime>
#include <utility>
#include <vector>

using namespace phasebox;

namespace {

// `count` disks of the default radius (5 cm) all at the origin, particle collisions on, no
// gravity, nothing else.
SceneDesc pileAtPoint(int count) {
    SceneDesc s;
    s.effects.particleCollisions = ParticleCollisionsDesc{};
    for (int i = 0; i < count; ++i) s.particles.push_back(ParticleDesc{});
    return s;
}

// `count` disks 0.12 m apart along y (a column) or x (a row): only the broad phase's grown
// boxes (5 cm radius + 2 cm speculative distance) reach the neighbours.
SceneDesc line(int count, bool vertical) {
    SceneDesc s;
    s.effects.particleCollisions = ParticleCollisionsDesc{};
    for (int i = 0; i < count; ++i) {
        ParticleDesc p;
        p.position = vertical ? Point2{0.0, 0.12 * i} : Point2{0.12 * i, 0.0};
        s.particles.push_back(p);
    }
    return s;
}

using Pairs = std::vector<std::pair<int, int>>;

// The CPU time this thread has used: the cost of the code, not of whatever else the machine
// runs (CI runs two suites at once; a wall-clock bound failed there on load alone).
double threadCpuSeconds() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

Pairs bruteForce(const std::vector<Aabb>& boxes) {
    Pairs pairs;
    for (int i = 0; i < static_cast<int>(boxes.size()); ++i)
        for (int j = i + 1; j < static_cast<int>(boxes.size()); ++j)
            if (boxes[i].overlaps(boxes[j])) pairs.emplace_back(i, j);
    return pairs;
}

}  // namespace

class TestPiles : public QObject {
    Q_OBJECT

private slots:
    void pileAtOnePointIsBounded();
    void boxPileAtOnePointComesApart_data();
    void boxPileAtOnePointComesApart();
    void coincidentCentresGiveReproducibleNormals();
    void columnCostsWhatARowCosts();
    void sweepAxisFollowsTheSpread();
    void cappedPairsAllocateNothingOnceWarm();
};

void TestPiles::pileAtOnePointIsBounded() {
    // 3,000 disks at one point. Before the cap each step made all 4.5 million pairs
    // (22–35 s and 3.3 GB per simulated second on this machine).
    constexpr int kCount = 3000;
    // Issue 15's bound: one simulated second in under 5 s on this two-core machine, counted
    // in this thread's CPU time (CI runs two suites at once; a wall-clock bound failed there on
    // load alone). History: 1.3 s when issue 15 was resolved; the elastic bounces of the
    // overlapping disks later cycled through all 32 passes every sub-step (8.7 s); inelastic
    // passes after four bounces brought it to 4.0–4.4 s idle and 5.4–5.6 s inside CI runs, over
    // the bound. Then a pair's speculative margin became what the two can close on each other
    // (relative velocity and turns), not the sum of their speeds, so a spreading pile's
    // neighbours stop making contacts, and the bounce passes read a compact array: 3.0–3.3 s
    // idle, 3.8 s while another build ran. The quadratic code took 22–35 s.
    constexpr double kSecondsBound = 5.0;
    auto world = buildWorld(pileAtPoint(kCount)).world;
    QVERIFY(world->contacts() != nullptr);
    const long long pairBound =
        (ContactStage::kOverlappingPairCap + ContactStage::kNearPairCap) * kCount / 2;
    long long mostPoints = 0;
    const double started = threadCpuSeconds();
    for (int step = 0; step < 60; ++step) {
        QVERIFY2(world->step(), "the world reported divergence");
        const ContactStage& stage = *world->contacts();
        // Equal disks: each pair counts against both disks' caps (overlapping or near).
        QVERIFY2(
            static_cast<long long>(stage.contacts().size()) <= pairBound,
            qPrintable(
                QStringLiteral("step %1: %2 constraints").arg(step).arg(stage.contacts().size())));
        QVERIFY(stage.pointCount() <= pairBound);
        mostPoints = std::max<long long>(mostPoints, stage.pointCount());
    }
    const double seconds = threadCpuSeconds() - started;

    const Vec& q = world->positions();
    const Vec& u = world->velocities();
    QVERIFY(q.allFinite());
    QVERIFY(u.allFinite());
    double fastest = 0.0, farthest = 0.0;
    for (int i = 0; i < kCount; ++i) {
        fastest = std::max(fastest, world->particleVelocity(i).norm());
        farthest = std::max(farthest, world->particlePosition(i).norm());
    }
    qInfo(
        "3,000 disks at one point, 60 steps: %.2f s of CPU, at most %lld contact points (bound "
        "%lld), "
        "fastest %.2f m/s, farthest %.2f m",
        seconds, mostPoints, pairBound, fastest, farthest);
    QVERIFY2(seconds < kSecondsBound, qPrintable(QString::number(seconds)));
    // The pile comes apart (it does not stay a point, nor a line along one shared normal),
    // and no disk is flung off with the energy of thousands of overlaps: deep overlap is pushed
    // out in positions and the push-out speed is a body's, not each contact's (17.5 m/s before
    // that, 2.2 m/s since; issue 15 asks nothing faster than 5 m/s from rest).
    QVERIFY2(farthest > 0.2, qPrintable(QString::number(farthest)));
    QVERIFY2(fastest < 5.0, qPrintable(QString::number(fastest)));
}

void TestPiles::boxPileAtOnePointComesApart_data() {
    QTest::addColumn<QString>("integrator");
    for (const char* name : {"symplectic_euler", "velocity_verlet", "rk4", "implicit_euler"})
        QTest::newRow(name) << QString(name);
}

void TestPiles::boxPileAtOnePointComesApart() {
    QFETCH(QString, integrator);
    // 1,000 1 m boxes at one point on the ground. The overlap is a thousand square metres of
    // box in one: it must come apart into a mound, and nothing may be launched. Before the
    // pair caps, the deep push-out and the shared push-out speed, boxes left at 830 m/s and
    // were 7 km away after 10 s; the guard now also calls a correction past 10³·E₀ a
    // divergence, so this run must not diverge either.
    constexpr int kCount = 1000;
    SceneDesc s;
    PlaneDesc ground;
    ground.point = {0.0, 0.0};
    ground.normal = {0.0, 1.0};
    s.planes.push_back(ground);
    s.effects.gravity = GravityDesc{};
    s.simulation.integrator = integrator.toStdString();
    for (int i = 0; i < kCount; ++i) {
        BoxDesc b;
        b.position = {0.0, 0.5};
        s.boxes.push_back(b);
    }
    auto world = buildWorld(s).world;
    double rising = 0.0, highest = 0.0, fastest = 0.0;
    for (int step = 0; step < 360; ++step) {
        QVERIFY2(world->step(), "the world reported divergence");
        for (int i = 0; i < kCount; ++i) {
            rising = std::max(rising, world->bodyVelocity(i).y());
            highest = std::max(highest, world->bodyPosition(i).y());
            fastest = std::max(fastest, world->bodyVelocity(i).norm());
        }
    }
    double spread = 0.0;
    for (int i = 0; i < kCount; ++i)
        spread = std::max(spread, std::abs(world->bodyPosition(i).x()));
    const double fall = std::sqrt(2.0 * 9.81 * highest);
    qInfo(
        "%s: 1,000 boxes at one point, 6 s: spread %.1f m, highest %.1f m, fastest rising %.2f "
        "m/s, fastest %.2f m/s (a fall from the highest point: %.2f m/s)",
        qPrintable(integrator), spread, highest, rising, fastest, fall);
    // Apart: a thousand unit boxes cover a thousand square metres, a mound some 30 m high.
    QVERIFY2(spread > 10.0, qPrintable(QString::number(spread)));
    // Pushed apart, not launched: nothing rises faster than a few push-out speeds (3 m/s
    // each), and nothing moves faster than a fall from the top of the mound plus that.
    QVERIFY2(rising < 10.0, qPrintable(QString::number(rising)));
    QVERIFY2(fastest < fall + 10.0, qPrintable(QString::number(fastest)));
}

void TestPiles::coincidentCentresGiveReproducibleNormals() {
    // The narrow phase: a pair's fallback normal is a unit vector that depends only on the
    // pair, and different pairs point different ways (one shared fallback would stack a pile
    // up in a line along it).
    const Disk a{{1.0, 2.0}, 0.05}, b{{1.0, 2.0}, 0.05};
    Manifold first, second;
    QVERIFY(collideDisks(a, b, 0.0, first, coincidentNormal(3, 7)));
    QVERIFY(collideDisks(a, b, 0.0, second, coincidentNormal(3, 7)));
    QVERIFY(first.normal.allFinite() && first.points[0].position.allFinite());
    QCOMPARE(first.normal.norm(), 1.0);
    QCOMPARE(first.normal, second.normal);
    QCOMPARE(first.points[0].separation, -0.1);
    QVERIFY(coincident(a.center, b.center));
    QVERIFY((coincidentNormal(3, 7) - coincidentNormal(3, 8)).norm() > 1e-3);
    QVERIFY((coincidentNormal(3, 7) - coincidentNormal(7, 3)).norm() > 1e-3);

    // The whole step: two runs of a small pile at a point end in identical, finite states in
    // which no two disks share a centre.
    const auto run = [] {
        auto world = buildWorld(pileAtPoint(40)).world;
        for (int step = 0; step < 30; ++step) world->step();
        return std::make_pair(Vec(world->positions()), Vec(world->velocities()));
    };
    const auto [q1, u1] = run();
    const auto [q2, u2] = run();
    QVERIFY(q1.allFinite() && u1.allFinite());
    QVERIFY(q1 == q2);
    QVERIFY(u1 == u2);
    for (int i = 0; i < 40; ++i)
        for (int j = i + 1; j < 40; ++j)
            QVERIFY((q1.segment<2>(2 * i) - q1.segment<2>(2 * j)).norm() > 1e-3);
}

void TestPiles::columnCostsWhatARowCosts() {
    // The broad phase's work for 20,000 disks in a column against the same disks in a row:
    // the candidates it visits along its sweep axis. Sweeping a column along x visits every
    // pair (2·10⁸); along y, about one neighbour per disk, as a row along x.
    constexpr int kCount = 20000;
    long long visited[2] = {0, 0}, pairs[2] = {0, 0};
    int axis[2] = {-1, -1};
    for (const bool vertical : {false, true}) {
        auto world = buildWorld(line(kCount, vertical)).world;
        for (int step = 0; step < 2; ++step) QVERIFY(world->step());
        const BroadPhase& broadPhase = world->contacts()->broadPhase();
        visited[vertical] = broadPhase.candidatesVisited();
        axis[vertical] = broadPhase.axis();
        pairs[vertical] = static_cast<long long>(world->contacts()->contacts().size());
    }
    qInfo(
        "20,000 disks: row visits %lld candidates (axis %d), column %lld (axis %d); "
        "constraints %lld and %lld",
        visited[0], axis[0], visited[1], axis[1], pairs[0], pairs[1]);
    QCOMPARE(axis[0], 0);
    QCOMPARE(axis[1], 1);
    QVERIFY(visited[0] > 0);
    QVERIFY2(visited[1] <= 2 * visited[0], qPrintable(QString::number(visited[1])));
    QVERIFY(visited[1] <= 2LL * kCount);
}

void TestPiles::sweepAxisFollowsTheSpread() {
    // Exact on either axis, through a switch of axis and back (each a full re-sort), with and
    // without a cap large enough never to bind.
    std::vector<Aabb> boxes;
    for (int i = 0; i < 300; ++i) {
        const Vec2 c(0.01 * (i % 7), 0.3 * i);  // a column, a little wobbly
        boxes.push_back({c - Vec2(0.2, 0.2), c + Vec2(0.2, 0.2)});
    }
    std::vector<unsigned char> limited(boxes.size(), 1);
    std::vector<double> size(boxes.size(), 0.2);
    BroadPhase broadPhase;
    Pairs pairs;
    for (int round = 0; round < 4; ++round) {
        broadPhase.findPairs(boxes, pairs);
        QCOMPARE(pairs, bruteForce(boxes));
        QCOMPARE(broadPhase.axis(), round % 2 == 0 ? 1 : 0);
        broadPhase.findPairs(boxes, pairs, {&limited, &size, 100, 100});
        QCOMPARE(pairs, bruteForce(boxes));
        for (Aabb& b : boxes) {  // turn the column into a row and back
            b.lower = Vec2(b.lower.y(), b.lower.x());
            b.upper = Vec2(b.upper.y(), b.upper.x());
        }
    }

    // A cap that binds: identical boxes, every one overlapping every other; each box keeps at
    // most perBox partners, and the unlimited box (a static ground) keeps all of them.
    std::vector<Aabb> pile(200, Aabb{{0.0, 0.0}, {1.0, 1.0}});
    pile.push_back({{-5.0, -5.0}, {5.0, 0.5}});
    std::vector<unsigned char> pileLimited(pile.size(), 1);
    pileLimited.back() = 0;
    std::vector<double> pileSize(pile.size(), 0.5);
    pileSize.back() = 5.0;
    broadPhase.findPairs(pile, pairs, {&pileLimited, &pileSize, 8, 8});
    std::vector<int> partners(pile.size(), 0);
    for (const auto& [i, j] : pairs) {
        ++partners[i];
        ++partners[j];
    }
    QCOMPARE(partners.back(), 200);
    for (int i = 0; i < 200; ++i) QVERIFY(partners[i] >= 1 && partners[i] <= 8 + 8 + 1);
}

void TestPiles::cappedPairsAllocateNothingOnceWarm() {
    using namespace phasebox::bench;
    std::vector<Aabb> boxes(2000, Aabb{{0.0, 0.0}, {0.1, 0.1}});
    std::vector<unsigned char> limited(boxes.size(), 1);
    std::vector<double> size(boxes.size(), 0.05);
    BroadPhase broadPhase;
    Pairs pairs;
    const auto step = [&](int k) {
        for (int i = 0; i < static_cast<int>(boxes.size()); ++i) {  // spread out, then back
            const double shift = (k % 2 ? 0.0 : 0.001) * i;
            boxes[i] = {{shift, 0.5 * shift}, {shift + 0.1, 0.5 * shift + 0.1}};
        }
        broadPhase.findPairs(boxes, pairs, {&limited, &size, 16, 32});
    };
    step(0);  // the buffers grow to both states
    step(1);
    const std::size_t capped = pairs.size();
    startCountingAllocations();
    for (int k = 0; k < 10; ++k) step(k);
    const AllocationCounts counts = stopCountingAllocations();
    QVERIFY(capped <= (16 + 32) * boxes.size() / 2);
    if (!kCountsAllocations)
        qInfo("allocations are not counted under AddressSanitizer; the release build checks them");
    QCOMPARE(counts.total(), 0LL);
}

QTEST_APPLESS_MAIN(TestPiles)
#include "tst_piles.moc"
