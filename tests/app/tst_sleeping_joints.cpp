// Sleeping islands that joints hold (CONTRACT §6): joints tie their bodies into one island,
// which falls asleep whole; its joints then leave the joint solver (it steps none of them),
// and come back with what they held when something wakes the island.
//   - a chain hanging at rest falls asleep after kSleepSeconds, and asleep nothing moves and the
//     ledger books nothing;
//   - nothing jumps when it falls asleep or wakes: in those steps no body moves farther than a
//     body at rest can (kSleepSpeed·dt);
//   - waking one link wakes the whole chain, a switch of method wakes it, and it sleeps again;
//   - a bridge that has come to rest sleeps with its load, a box dropped onto it wakes it, and
//     where the bridge ends is where it ends with sleeping off; a ragdoll at rest sleeps;
//   - an island a motor drives stays awake.

#include "app/io/SceneIO.h"
#include "physics/scene/BuildWorld.h"
#include "physics/world/World.h"

#include <QTest>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

using namespace phasebox;

namespace {

constexpr int kLinks = 10;
constexpr double kLinkLength = 0.5;  // m
const QString kSceneDir = QStringLiteral(PHASEBOX_SOURCE_DIR "/resources/scenes");

// A chain of kLinks boxes hinged end to end, hanging straight down from a hinge to the world at
// (0, 6): at rest where it starts.
SceneDesc hangingChain() {
    SceneDesc s;
    s.simulation.sleep = true;
    s.effects.gravity = GravityDesc{};
    for (int i = 0; i < kLinks; ++i) {
        BoxDesc b;
        b.id = "link" + std::to_string(i);
        b.position = {0.0, 6.0 - (i + 0.5) * kLinkLength};
        b.size = {0.1, kLinkLength};
        s.boxes.push_back(b);
        JointDesc j;
        j.a = b.id;
        if (i > 0) j.b = "link" + std::to_string(i - 1);
        j.anchor = Point2{0.0, 6.0 - i * kLinkLength};
        s.joints.push_back(j);
    }
    return s;
}

SceneDesc load(const QString& name) {
    const SceneLoadResult result = SceneIO::load(kSceneDir + QLatin1Char('/') + name);
    if (!result.ok()) qFatal("%s", qPrintable(result.errorText()));
    return *result.scene;
}

std::unique_ptr<World> build(const SceneDesc& desc) {
    auto w = buildWorld(desc).world;
    w->commit();
    return w;
}

int dynamicBodies(const World& w) {
    int n = 0;
    for (const RigidBody& b : w.rigidBodies()) n += !b.isStatic;
    return n;
}

double fastest(const World& w) {
    double v = 0.0;
    for (int i = 0; i < static_cast<int>(w.rigidBodies().size()); ++i)
        v = std::max(v, w.bodyVelocity(i).norm());
    return v;
}

std::vector<Vec2> positions(const World& w) {
    std::vector<Vec2> p;
    for (int i = 0; i < static_cast<int>(w.rigidBodies().size()); ++i)
        p.push_back(w.bodyPosition(i));
    return p;
}

double largestMove(const std::vector<Vec2>& a, const std::vector<Vec2>& b) {
    double m = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) m = std::max(m, (a[i] - b[i]).norm());
    return m;
}

// The chain-bridge example with air drag (so that it comes to rest within seconds) and its
// crate raised to 8 m: the bridge starts at rest in its catenary and falls asleep before the
// crate lands on it.
// A library example with air drag that brings it to rest within seconds, sleeping or not.
SceneDesc withAirDrag(const QString& name, bool sleep) {
    SceneDesc s = load(name);
    s.simulation.sleep = sleep;
    DragDesc drag;
    drag.linear = 2.0;
    drag.angular = 0.5;
    s.effects.drag = drag;
    return s;
}

SceneDesc dampedBridge(bool sleep) {
    SceneDesc s = withAirDrag(QStringLiteral("chain-bridge.phasebox.json"), sleep);
    for (BoxDesc& b : s.boxes)
        if (b.id == "crate") b.position = {0.4, 8.0};
    return s;
}

int index(const World& w, const std::string& id) {
    for (int i = 0; i < static_cast<int>(w.rigidBodies().size()); ++i)
        if (w.rigidBodies()[i].id == id) return i;
    return -1;
}

}  // namespace

class TestSleepingJoints : public QObject {
    Q_OBJECT

private slots:
    void hangingChainFallsAsleep() {
        auto w = build(hangingChain());
        const double dt = w->settings().dt;
        QCOMPARE(w->jointSolver()->jointCount(), kLinks);
        while (w->sleepingBodies() < kLinks && w->time() < 2.0) QVERIFY(w->step());
        qInfo("the chain fell asleep at %.4f s", w->time());
        // At rest from the start: asleep as soon as it has rested kSleepSeconds.
        QVERIFY(w->time() <= World::kSleepSeconds + 2.0 * dt + 1e-12);
        QCOMPARE(w->sleepingBodies(), kLinks);
        QCOMPARE(w->layout().dimension(), 0);
        QCOMPARE(w->jointSolver()->jointCount(), 0);  // its joints left the solver
        // Asleep, nothing moves and the ledger books nothing.
        const std::vector<Vec2> p = positions(*w);
        const EnergyLedger e = w->energy();
        for (int k = 0; k < 120; ++k) QVERIFY(w->step());
        QCOMPARE(largestMove(p, positions(*w)), 0.0);
        QCOMPARE(w->energy().kinetic, e.kinetic);
        QCOMPARE(w->energy().potential, e.potential);
        QCOMPARE(w->energy().drift, e.drift);
        QCOMPARE(w->energy().correction, e.correction);
        QCOMPARE(w->energy().workNc, e.workNc);
        // The joints still draw where they were and report the forces they held.
        const double weight = kLinks * 1.0 * 0.1 * kLinkLength * 9.81;
        QVERIFY(std::abs(w->jointSolver()->force(0) - weight) < 1e-6 * weight);
        QVERIFY((w->jointSolver()->pointA(0, w->positions()) - Vec2(0.0, 6.0)).norm() < 1e-6);
    }

    // Waking one link wakes the chain; a switch of method wakes it too; it sleeps again each
    // time. No body ever moves farther in a step than a body at rest can, and neither falling
    // asleep nor waking books energy.
    void nothingJumpsWhenTheChainWakes() {
        auto w = build(hangingChain());
        const double dt = w->settings().dt;
        const double atRest = World::kSleepSpeed * dt;  // the farthest a resting body moves
        std::vector<Vec2> last = positions(*w);
        double largest = 0.0;
        const auto stepAndMeasure = [&] {
            if (!w->step()) return false;
            const std::vector<Vec2> now = positions(*w);
            largest = std::max(largest, largestMove(last, now));
            last = now;
            return true;
        };
        while (w->sleepingBodies() < kLinks) QVERIFY(stepAndMeasure());
        QVERIFY(w->wakeBody(true, kLinks - 1));  // the lowest link
        QCOMPARE(w->sleepingBodies(), 0);
        QCOMPARE(w->jointSolver()->jointCount(), kLinks);
        QCOMPARE(w->layout().dimension(), 3 * kLinks);
        for (int k = 0; k < 5; ++k) QVERIFY(stepAndMeasure());
        while (w->sleepingBodies() < kLinks && w->time() < 5.0) QVERIFY(stepAndMeasure());
        QCOMPARE(w->sleepingBodies(), kLinks);
        const EnergyLedger before = w->energy();
        w->setIntegrator("velocity_verlet");  // wakes every island
        QCOMPARE(w->sleepingBodies(), 0);
        QCOMPARE(w->energy().kinetic + w->energy().potential, before.kinetic + before.potential);
        QCOMPARE(w->energy().correction, before.correction);
        QCOMPARE(w->energy().drift, before.drift);
        while (w->sleepingBodies() < kLinks && w->time() < 8.0) QVERIFY(stepAndMeasure());
        QCOMPARE(w->sleepingBodies(), kLinks);
        qInfo("largest move of a link in one step: %.3g m (a body at rest: %.3g m)", largest,
              atRest);
        QVERIFY(largest <= atRest);
    }

    // A bridge at rest sleeps with its joints; the crate landing on it wakes it; the bridge and
    // its load come to rest and sleep again, where they come to rest with sleeping off.
    void droppedBoxWakesTheBridge() {
        auto on = build(dampedBridge(true));
        auto off = build(dampedBridge(false));
        const int crate = index(*on, "crate");
        QVERIFY(crate >= 0);
        const int planks = dynamicBodies(*on) - 1;
        QCOMPARE(planks, 10);
        double bridgeAsleep = -1.0, woken = -1.0, allAsleep = -1.0;
        while (on->time() < 12.0) {
            QVERIFY(on->step());
            QVERIFY(off->step());
            const int n = on->sleepingBodies();
            if (bridgeAsleep < 0.0 && n == planks && !on->rigidBodies()[crate].asleep)
                bridgeAsleep = on->time();
            if (bridgeAsleep > 0.0 && woken < 0.0 && n == 0) woken = on->time();
            if (woken > 0.0 && allAsleep < 0.0 && n == planks + 1) allAsleep = on->time();
        }
        qInfo("bridge asleep at %.3f s, woken by the crate at %.3f s, all asleep at %.3f s",
              bridgeAsleep, woken, allAsleep);
        QVERIFY(bridgeAsleep > 0.0 && bridgeAsleep < 1.0);
        QVERIFY(woken > bridgeAsleep);
        QVERIFY(allAsleep > woken);
        QCOMPARE(on->sleepingBodies(), planks + 1);
        QCOMPARE(on->jointSolver()->jointCount(), 0);
        QCOMPARE(off->sleepingBodies(), 0);
        // The crate fell 5 m onto the bridge and pushed it down by centimetres: where it all
        // rests is within 5 mm of where it rests with sleeping off (what it would still creep
        // at below 1 cm/s, damped within a second).
        const double apart = largestMove(positions(*on), positions(*off));
        qInfo("largest distance of a body from the sleeping-off run: %.3g m", apart);
        QVERIFY(apart < 0.005);
    }

    // The ragdoll example with the bridge's air drag: tumbled down the stairs, it comes to rest
    // at the wall and falls asleep whole, its nine hinges (with limits) out of the solver.
    void ragdollAtTheWallSleeps() {
        auto w = build(withAirDrag(QStringLiteral("ragdoll.phasebox.json"), true));
        const int limbs = dynamicBodies(*w);
        QCOMPARE(limbs, 10);
        while (w->sleepingBodies() < limbs && w->time() < 30.0) QVERIFY(w->step());
        qInfo("the ragdoll fell asleep at %.3f s", w->time());
        QCOMPARE(w->sleepingBodies(), limbs);
        QCOMPARE(w->jointSolver()->jointCount(), 0);
        QVERIFY(fastest(*w) < World::kSleepSpeed);
    }

    // A motor drives its island: an arm hanging at rest that a motor holds at speed 0 stays
    // awake (without the motor it is the hinged sign of tst_sleeping, which sleeps).
    void aMotorKeepsItsIslandAwake() {
        SceneDesc s;
        s.simulation.sleep = true;
        s.effects.gravity = GravityDesc{};
        BoxDesc arm;
        arm.id = "arm";
        arm.position = {0.0, -0.5};
        arm.size = {0.1, 1.0};
        s.boxes.push_back(arm);
        JointDesc hinge;
        hinge.a = "arm";
        hinge.anchor = Point2{0.0, 0.0};
        hinge.motor = JointMotorDesc{0.0, 100.0};
        s.joints.push_back(hinge);
        auto w = build(s);
        while (w->time() < 2.0) QVERIFY(w->step());
        QVERIFY(w->bodyVelocity(0).norm() < World::kSleepSpeed);
        QCOMPARE(w->sleepingBodies(), 0);
    }
};
QTEST_GUILESS_MAIN(TestSleepingJoints)
#include "tst_sleeping_joints.moc"
