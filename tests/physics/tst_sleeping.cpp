// Sleeping (simulation.sleep, CONTRACT §6): an island at rest for 0.5 s leaves the step until
// something reaches it, an edit or a switch of method or contact model wakes it.
//   - a settled 20-row pyramid falls asleep whole, and asleep a step costs a fifth of an awake
//     one at most;
//   - a box sliding into its apex after it fell asleep wakes it, pushes the apex as far as with
//     sleeping off (within 2 cm, and more than 5 cm), and the pyramid falls asleep again;
//   - nothing jumps when islands fall asleep or wake, and the ledger books nothing for them;
//   - a pendulum that slows at its turning points but passes its lowest point fast stays awake;
//   - switching the method or the contact model wakes every island;
//   - the same scene gives the same bits, and sleeping off changes nothing.

#include "../bench/AllocationCounter.h"
#include "../bench/SleepScenes.h"
#include "physics/scene/BuildWorld.h"
#include "physics/scene/SceneLibrary.h"
#include "physics/world/World.h"

#include <QTest>

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

using namespace phasebox;

namespace {

constexpr int kPyramidBoxes = 210;

std::unique_ptr<World> build(const SceneDesc& desc) {
    return buildWorld(desc).world;
}

using sleep_scenes::pyramid;
using sleep_scenes::pyramidAndSlider;

int boxIndex(const World& w, const std::string& id) {
    for (int i = 0; i < static_cast<int>(w.rigidBodies().size()); ++i)
        if (w.rigidBodies()[i].id == id) return i;
    return -1;
}

int asleepAmong(const World& w, int count) {
    int n = 0;
    for (int i = 0; i < count; ++i) n += w.rigidBodies()[i].asleep;
    return n;
}

// Steps until the first count boxes are asleep; the time, or -1 when not within limit seconds.
double stepUntilAsleep(World& w, int count, double limit) {
    while (w.time() < limit) {
        if (!w.step()) return -1.0;
        if (asleepAmong(w, count) == count) return w.time();
    }
    return -1.0;
}

double medianStepMs(World& w, int steps) {
    std::vector<double> ms;
    for (int k = 0; k < steps; ++k) {
        const auto start = std::chrono::steady_clock::now();
        w.step();
        ms.push_back(
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count());
    }
    std::nth_element(ms.begin(), ms.begin() + steps / 2, ms.end());
    return ms[steps / 2];
}

std::uint64_t hashOf(const World& w) {
    std::uint64_t h = 0xCBF29CE484222325ull;
    const auto add = [&](double v) {
        const auto bits = std::bit_cast<std::uint64_t>(v);
        for (int i = 0; i < 8; ++i) {
            h ^= (bits >> (8 * i)) & 0xFF;
            h *= 0x100000001B3ull;
        }
    };
    for (int i = 0; i < static_cast<int>(w.rigidBodies().size()); ++i) {
        add(w.bodyPosition(i).x());
        add(w.bodyPosition(i).y());
        add(w.bodyAngle(i));
        add(w.bodyVelocity(i).x());
    }
    add(w.energy().drift);
    add(w.energy().correction);
    return h;
}

}  // namespace

class TestSleeping : public QObject {
    Q_OBJECT

private slots:
    void offByDefault() {
        QVERIFY(!SceneDesc{}.simulation.sleep);
        auto w = build(scenes::pyramid(20));
        for (int k = 0; k < 300; ++k) QVERIFY(w->step());
        QCOMPARE(w->sleepingBodies(), 0);
    }

    void pyramidFallsAsleepAndCostsLittle() {
        auto asleep = build(pyramid(true));
        const double t = stepUntilAsleep(*asleep, kPyramidBoxes, 10.0);
        qInfo("20-row pyramid asleep at t = %.3f s", t);
        QVERIFY2(t > 0.0, "the pyramid did not fall asleep in 10 s");
        QCOMPARE(asleep->sleepingBodies(), kPyramidBoxes);
        QCOMPARE(asleep->layout().dimension(), 0);
        // The same pyramid awake at the same time, then a second of steps of each.
        auto awake = build(pyramid(false));
        while (awake->time() < asleep->time() - 1e-9) QVERIFY(awake->step());
        const double awakeMs = medianStepMs(*awake, 60);
        const double asleepMs = medianStepMs(*asleep, 60);
        qInfo("median step: awake %.4f ms, asleep %.4f ms (ratio %.4f)", awakeMs, asleepMs,
              asleepMs / awakeMs);
        QVERIFY2(asleepMs <= 0.2 * awakeMs,
                 qPrintable(QString("asleep %1 ms, awake %2 ms").arg(asleepMs).arg(awakeMs)));
        QCOMPARE(asleep->sleepingBodies(), kPyramidBoxes);
        // Asleep, and awake with the sleep timers running, a step allocates nothing.
        auto timing = build(pyramid(true));
        for (int k = 0; k < 30; ++k) QVERIFY(timing->step());
        QCOMPARE(timing->sleepingBodies(), 0);
        bench::startCountingAllocations();
        for (int k = 0; k < 10; ++k) QVERIFY(timing->step());
        const long long awakeAllocations = bench::stopCountingAllocations().total();
        bench::startCountingAllocations();
        for (int k = 0; k < 60; ++k) QVERIFY(asleep->step());
        const long long asleepAllocations = bench::stopCountingAllocations().total();
        if (bench::kCountsAllocations) {
            QCOMPARE(awakeAllocations, 0LL);
            QCOMPARE(asleepAllocations, 0LL);
        }
    }

    void ledgerBooksNothingForSleepers() {
        auto w = build(pyramid(true));
        QVERIFY(stepUntilAsleep(*w, kPyramidBoxes, 10.0) > 0.0);
        const EnergyLedger e = w->energy();
        for (int k = 0; k < 120; ++k) QVERIFY(w->step());
        // Bit for bit: a sleeping body's energy is constant, and nothing is booked for it.
        QCOMPARE(w->energy().kinetic, e.kinetic);
        QCOMPARE(w->energy().potential, e.potential);
        QCOMPARE(w->energy().drift, e.drift);
        QCOMPARE(w->energy().correction, e.correction);
        QCOMPARE(w->energy().workNc, e.workNc);
        // Across the change of layout the total stays where it was.
        auto fresh = build(pyramid(true));
        double before = 0.0;
        while (fresh->sleepingBodies() == 0) {
            before = fresh->energy().kinetic + fresh->energy().potential;
            QVERIFY(fresh->step());
        }
        const double after = fresh->energy().kinetic + fresh->energy().potential;
        QVERIFY2(std::abs(after - before) < 1e-6 * std::abs(before),
                 qPrintable(QString("total %1 -> %2").arg(before).arg(after)));
    }

    void nothingJumps() {
        // Every step from 1 s on, through falling asleep and waking (by a switch of method and
        // back), no box moves more than 0.1 mm, and asleep none moves at all.
        auto w = build(pyramid(true));
        for (int k = 0; k < 60; ++k) QVERIFY(w->step());
        const int n = kPyramidBoxes;
        std::vector<Vec2> last(n);
        std::vector<char> wasAsleep(n, 0);
        for (int i = 0; i < n; ++i) last[i] = w->bodyPosition(i);
        double largest = 0.0;
        bool woke = false;
        int asleepSteps = 0;
        while (w->time() < 12.0) {
            QVERIFY(w->step());
            for (int i = 0; i < n; ++i) {
                const double moved = (w->bodyPosition(i) - last[i]).norm();
                largest = std::max(largest, moved);
                if (wasAsleep[i] && w->rigidBodies()[i].asleep) {
                    QCOMPARE(moved, 0.0);
                    ++asleepSteps;
                }
                wasAsleep[i] = w->rigidBodies()[i].asleep;
                last[i] = w->bodyPosition(i);
            }
            if (!woke && w->sleepingBodies() == n) {
                woke = true;
                w->setIntegrator("velocity_verlet");
                QCOMPARE(w->sleepingBodies(), 0);
                w->setIntegrator("symplectic_euler");
            }
        }
        qInfo("largest move of a box in one step: %.3g m", largest);
        QVERIFY(woke);
        QVERIFY(asleepSteps > 0);
        QCOMPARE(w->sleepingBodies(), n);  // and asleep again
        QVERIFY2(largest < 1e-4, qPrintable(QString("a box moved %1 m in one step").arg(largest)));
    }

    void sliderWakesApex() {
        auto run = [](bool sleep, double& asleepAt, double& apexBefore, double& apexAfter,
                      int& sleepingAtEnd) {
            auto w = build(pyramidAndSlider(sleep));
            const int apex = boxIndex(*w, "r19c0");
            asleepAt = -1.0;
            apexBefore = 0.0;
            while (w->time() < 7.0) {
                if (!w->step()) return false;
                if (asleepAt < 0.0 && asleepAmong(*w, kPyramidBoxes) == kPyramidBoxes)
                    asleepAt = w->time();
            }
            apexBefore = w->bodyPosition(apex).x();
            while (w->time() < 16.0)
                if (!w->step()) return false;
            apexAfter = w->bodyPosition(apex).x();
            sleepingAtEnd = asleepAmong(*w, kPyramidBoxes);
            return true;
        };
        double asleepAt = 0.0, before = 0.0, after = 0.0, offAt = 0.0, offBefore = 0.0,
               offAfter = 0.0;
        int sleepingAtEnd = 0, offSleeping = 0;
        QVERIFY(run(true, asleepAt, before, after, sleepingAtEnd));
        QVERIFY(run(false, offAt, offBefore, offAfter, offSleeping));
        qInfo(
            "pyramid asleep at %.3f s; apex pushed %.4f m with sleeping, %.4f m without "
            "(difference %.4f m); pyramid bodies asleep at the end: %d",
            asleepAt, before - after, offBefore - offAfter,
            std::abs((after - before) - (offAfter - offBefore)), sleepingAtEnd);
        QVERIFY2(asleepAt > 0.0 && asleepAt < 7.0, "the pyramid was not asleep before the slider");
        QVERIFY2(before - after > 0.05,
                 qPrintable(QString("apex pushed %1 m").arg(before - after)));
        QVERIFY(std::abs((after - before) - (offAfter - offBefore)) < 0.02);
        QCOMPARE(offSleeping, 0);
        QCOMPARE(sleepingAtEnd, kPyramidBoxes);
    }

    void swingingPendulumStaysAwake() {
        // A bob on a stiff spring 1 m below its anchor, swinging 5 cm to each side: it slows
        // below 0.01 m/s at each turning point for a fraction of a second and passes the
        // lowest point at 0.16 m/s, so it never rests 0.5 s.
        SceneDesc s;
        s.simulation.dt = 1.0 / 60.0;
        s.simulation.sleep = true;
        s.effects.gravity = GravityDesc{};
        ParticleDesc bob;
        bob.id = "bob";
        bob.position = {0.05, -1.0 + 0.00125};
        bob.radius = 0.0;
        s.particles.push_back(bob);
        SpringDesc rope;
        rope.a = "bob";
        rope.anchor = Point2{0.0, 0.0};
        rope.stiffness = 1e4;
        rope.restLength = 1.0 - 9.81 / 1e4;
        s.springs.push_back(rope);
        auto w = build(s);
        double slowest = 1e9, fastest = 0.0;
        while (w->time() < 20.0) {
            QVERIFY(w->step());
            QCOMPARE(w->sleepingBodies(), 0);
            const double v = w->particleVelocity(0).norm();
            slowest = std::min(slowest, v);
            fastest = std::max(fastest, v);
        }
        QVERIFY(slowest < World::kSleepSpeed);  // it does slow below the threshold
        QVERIFY(fastest > 0.1);
        // Left alone at the bottom, the same bob falls asleep.
        s.particles[0].position = {0.0, -1.0};
        auto resting = build(s);
        while (resting->time() < 2.0) QVERIFY(resting->step());
        QCOMPARE(resting->sleepingBodies(), 1);
    }

    void switchingWakesEveryIsland() {
        auto w = build(pyramid(true));
        QVERIFY(stepUntilAsleep(*w, kPyramidBoxes, 10.0) > 0.0);
        w->setIntegrator("rk4");
        QCOMPARE(w->sleepingBodies(), 0);
        QCOMPARE(w->layout().dimension(), 3 * kPyramidBoxes);
        QVERIFY(stepUntilAsleep(*w, kPyramidBoxes, w->time() + 10.0) > 0.0);
        SimulationSettings settings = w->settings();
        settings.contactModel = ContactModel::Kinematic;
        w->setSettings(settings);
        QCOMPARE(w->sleepingBodies(), 0);
        settings.contactModel = ContactModel::Impulse;
        w->setSettings(settings);
        QVERIFY(stepUntilAsleep(*w, kPyramidBoxes, w->time() + 10.0) > 0.0);
        // Switching sleeping off wakes them too; a change of dt alone does not.
        settings.dt = 1.0 / 120.0;
        w->setSettings(settings);
        QCOMPARE(w->sleepingBodies(), kPyramidBoxes);
        settings.sleep = false;
        w->setSettings(settings);
        QCOMPARE(w->sleepingBodies(), 0);
    }

    void islandsSleepApart() {
        // Two stacks on one floor and a box sliding on it far away: the floor ties nothing, so
        // each stack sleeps on its own while the slider moves, and waking one body wakes its
        // island only.
        SceneDesc s;
        s.simulation.sleep = true;
        s.effects.gravity = GravityDesc{};
        PlaneDesc floor;
        floor.id = "floor";
        s.planes.push_back(floor);
        const auto box = [&](const char* id, double x, double y, double vx, double friction) {
            BoxDesc b;
            b.id = id;
            b.position = {x, y};
            b.velocity = {vx, 0.0};
            b.friction = friction;
            s.boxes.push_back(b);
        };
        box("a0", 0.0, 0.5, 0.0, 0.6);
        box("a1", 0.0, 1.5, 0.0, 0.6);
        box("b0", 5.0, 0.5, 0.0, 0.6);
        box("b1", 5.0, 1.5, 0.0, 0.6);
        box("slider", 20.0, 0.5, 1.0, 0.0);
        auto w = build(s);
        while (w->time() < 2.0) QVERIFY(w->step());
        QCOMPARE(w->sleepingBodies(), 4);
        QVERIFY(!w->rigidBodies()[4].asleep);
        QVERIFY(w->wakeBody(true, 1));  // a1: the a stack wakes, the b stack sleeps on
        QCOMPARE(w->sleepingBodies(), 2);
        QVERIFY(!w->rigidBodies()[0].asleep && !w->rigidBodies()[1].asleep);
        QVERIFY(w->rigidBodies()[2].asleep && w->rigidBodies()[3].asleep);
        QVERIFY(!w->wakeBody(true, 4));  // the slider is awake already
        while (w->time() < 3.0) QVERIFY(w->step());
        QCOMPARE(w->sleepingBodies(), 4);
    }

    void aHingedSignSleeps() {
        // A box hanging at rest from a hinge: one island with its joint, which falls asleep
        // (tst_sleeping_joints has chains, a bridge and motors).
        SceneDesc s;
        s.simulation.sleep = true;
        s.effects.gravity = GravityDesc{};
        BoxDesc b;
        b.id = "sign";
        b.position = {0.0, -1.0};
        s.boxes.push_back(b);
        JointDesc hinge;
        hinge.a = "sign";
        hinge.anchor = Point2{0.0, 0.0};
        s.joints.push_back(hinge);
        auto w = build(s);
        while (w->time() < 3.0) QVERIFY(w->step());
        QCOMPARE(w->sleepingBodies(), 1);
        QCOMPARE(w->jointSolver()->jointCount(), 0);
    }

    void sameBitsEveryRun() {
        std::uint64_t first = 0;
        for (int run = 0; run < 2; ++run) {
            auto w = build(pyramidAndSlider(true));
            while (w->time() < 12.0) QVERIFY(w->step());
            const std::uint64_t h = hashOf(*w);
            if (run == 0) first = h;
            QCOMPARE(h, first);
        }
    }
};

QTEST_APPLESS_MAIN(TestSleeping)
#include "tst_sleeping.moc"
