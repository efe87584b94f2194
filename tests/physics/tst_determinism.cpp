// Determinism: the same scene and settings give bit-identical results, run after run, for a
// contact scene and a spring/cloth scene under several integrators. Checked four ways:
//   - two worlds built from one SceneDesc and stepped side by side;
//   - a fresh world built later in the process (after other worlds have run and freed memory,
//     so that nothing may depend on addresses, allocation order or leftover scratch state);
//   - stepping in chunks, with every read-only query of the app in between (energies, the
//     local-error estimate, the stability advisor, costs, profile reset, state reads), against
//     stepping at once;
//   - a hash pinned in this file, so that a change of the bits between builds or commits is
//     seen too (tst_contacts' runsAreBitIdentical only compares two runs of one process);
//   - at 1, 2 and 4 workers (World::setWorkers, CONTRACT §4), and the 100-row pyramid, whose
//     loops are large enough to be shared, a few steps at each;
//   - with each instruction set of the contact rows this processor has (rows one by one, AVX2,
//     AVX-512: ContactSolver::useInstructions), the 100-row pyramid among them.
//
// A pinned hash changes whenever the physics changes on purpose (a new contact rule, another
// order of force accumulation): the failure message prints the new value to paste in. A change
// that nobody meant is exactly what this test is for.

#include "physics/contacts/ContactSolver.h"
#include "physics/core/WorkerPool.h"
#include "physics/diagnostics/StabilityAdvisor.h"
#include "physics/scene/BuildWorld.h"
#include "physics/scene/SceneLibrary.h"
#include "physics/world/World.h"

#include "tests/support/StateBits.h"

#include <QTest>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <memory>
#include <string>

using namespace phasebox;

namespace {

// FNV-1a over the bit patterns (not the values: 0.0 and -0.0, or two NaNs, differ here).
class StateHash {
public:
    void add(double v) {
        const auto bits = std::bit_cast<std::uint64_t>(v);
        for (int i = 0; i < 8; ++i) {
            hash_ ^= (bits >> (8 * i)) & 0xFF;
            hash_ *= 0x100000001B3ull;
        }
    }
    void add(const Vec& v) {
        for (Eigen::Index i = 0; i < v.size(); ++i) add(v[i]);
    }
    std::uint64_t value() const { return hash_; }

private:
    std::uint64_t hash_ = 0xCBF29CE484222325ull;
};

std::uint64_t hashOf(const World& world) {
    StateHash h;
    h.add(world.positions());
    h.add(world.velocities());
    h.add(world.time());
    const EnergyLedger& e = world.energy();
    for (double v : {e.kinetic, e.potential, e.workNc, e.drift, e.maxAbsDrift}) h.add(v);
    return h.value();
}

QString hex(std::uint64_t v) {
    return QStringLiteral("0x%1").arg(v, 16, 16, QLatin1Char('0'));
}

// Ten planks hinged end to end in a shallow V between two hinges to the world (a straight one
// would have to be pulled infinitely taut), and a crate dropped on them: joints and contacts at
// once, as in the chain-bridge example, where the joints' forces of one step's evaluations feed
// the next (the sub-steps a pulled joint needs, the contacts' joined relax).
SceneDesc bridge() {
    SceneDesc s;
    s.effects.gravity = GravityDesc{};
    constexpr double kSag = 0.15;  // each half's slope, rad
    Point2 at{0.0, 5.0};           // the next hinge
    const auto hinge = [&](const std::string& a, const std::string& b) {
        JointDesc j;
        j.type = JointType::Hinge;
        j.a = a;
        if (!b.empty()) j.b = b;  // absent: the world
        j.anchor = at;
        s.joints.push_back(j);
    };
    for (int i = 0; i < 10; ++i) {
        const double angle = i < 5 ? -kSag : kSag;
        const Point2 next{at[0] + std::cos(angle), at[1] + std::sin(angle)};
        BoxDesc plank;
        plank.id = "plank" + std::to_string(i);
        plank.position = {0.5 * (at[0] + next[0]), 0.5 * (at[1] + next[1])};
        plank.angle = angle;
        plank.size = {1.0, 0.2};
        plank.density = 10.0;
        s.boxes.push_back(plank);
        hinge(plank.id, i == 0 ? std::string() : "plank" + std::to_string(i - 1));
        at = next;
    }
    hinge("plank9", {});
    BoxDesc crate;
    crate.id = "crate";
    crate.position = {4.3, 5.0};
    crate.size = {0.8, 0.8};
    crate.density = 10.0;
    s.boxes.push_back(crate);
    return s;
}

SceneDesc sceneFor(const QString& name, const QString& integrator) {
    SceneDesc s;
    if (name == "pyramid")
        s = scenes::pyramid(8);
    else if (name == "gas")
        s = scenes::elasticGas(60);
    else if (name == "chain100")
        s = scenes::hingedChain(100);
    else if (name == "bridge")
        s = bridge();
    else
        s = scenes::cloth(6, 200.0);
    s.simulation.integrator = integrator.toStdString();
    // The cloth at a step every method keeps stable, so that each is compared on a real run
    // rather than on a restored blow-up.
    if (name == "cloth") s.simulation.dt = 1.0 / 240.0;
    return s;
}

std::unique_ptr<World> build(const SceneDesc& s) {
    return buildWorld(s).world;
}

constexpr int kSteps = 240;

}  // namespace

class TestDeterminism : public QObject {
    Q_OBJECT

private slots:
    void bitIdentical_data() {
        QTest::addColumn<QString>("scene");
        QTest::addColumn<QString>("integrator");
        QTest::addColumn<quint64>("pinned");
        // Pinned on x86-64 Linux, g++ 12, Release and RelWithDebInfo alike (no -ffast-math,
        // no FMA contraction: the bits do not depend on the optimisation level).
        QTest::newRow("pyramid symplectic_euler")
            << "pyramid"
            << "symplectic_euler" << quint64(0x8d9d609602f45bdcull);
        QTest::newRow("pyramid velocity_verlet")
            << "pyramid"
            << "velocity_verlet" << quint64(0x1c14449ae346aa6aull);
        QTest::newRow("pyramid rk4") << "pyramid"
                                     << "rk4" << quint64(0x72faaf26cca4f709ull);
        QTest::newRow("gas symplectic_euler")
            << "gas"
            << "symplectic_euler" << quint64(0x8c86375eb28eb6daull);
        QTest::newRow("cloth symplectic_euler")
            << "cloth"
            << "symplectic_euler" << quint64(0x11952b28e17ae1b1ull);
        QTest::newRow("cloth rk4") << "cloth"
                                   << "rk4" << quint64(0xd25c9118bf6737dbull);
        QTest::newRow("cloth implicit_euler") << "cloth"
                                              << "implicit_euler" << quint64(0x2d0fd9c4c0126da3ull);
        QTest::newRow("cloth implicit_midpoint")
            << "cloth"
            << "implicit_midpoint" << quint64(0x1837a4a821be8d59ull);
        QTest::newRow("cloth rk45") << "cloth"
                                    << "rk45" << quint64(0x57f29acd06b16250ull);
        // Joints: the app's local-error estimate between steps evaluates them on trial steps.
        QTest::newRow("chain100 velocity_verlet")
            << "chain100"
            << "velocity_verlet" << quint64(0x1e49b59e72fd8175ull);
        // Joints and contacts: the Parameters panel's stability advisor evaluates the forces
        // between steps.
        QTest::newRow("bridge velocity_verlet")
            << "bridge"
            << "velocity_verlet" << quint64(0x208037292d074cf5ull);
        QTest::newRow("bridge symplectic_euler")
            << "bridge"
            << "symplectic_euler" << quint64(0xedee993d58798f89ull);
    }

    void bitIdentical() {
        QFETCH(QString, scene);
        QFETCH(QString, integrator);
        QFETCH(quint64, pinned);
        const SceneDesc desc = sceneFor(scene, integrator);

        // Two worlds side by side.
        auto first = build(desc);
        auto second = build(desc);
        for (int k = 0; k < kSteps; ++k) {
            QVERIFY2(first->step(), "the reference run diverged");
            QVERIFY(second->step());
        }
        const std::uint64_t reference = hashOf(*first);
        QCOMPARE(hex(hashOf(*second)), hex(reference));
        QVERIFY(first->positions() == second->positions());
        QVERIFY(first->velocities() == second->velocities());
        first.reset();
        second.reset();

        // A fresh world, built after the others ran and were freed, from the same description.
        auto fresh = build(desc);
        for (int k = 0; k < kSteps; ++k) QVERIFY(fresh->step());
        QCOMPARE(hex(hashOf(*fresh)), hex(reference));

        // In chunks of 1, 7 and 50 steps with the app's read-only queries in between.
        auto chunked = build(desc);
        int done = 0;
        for (int chunk : {1, 7, 50, 50, 50, 50, 32}) {
            for (int k = 0; k < chunk; ++k) {
                QVERIFY(chunked->step());
                (void)chunked->estimateLocalError();  // the status bar's, once a frame
                (void)adviseStability(*chunked, 20);  // the Parameters panel's, on a refresh
            }
            done += chunk;
            (void)chunked->energy();
            (void)chunked->effectCosts();
            (void)chunked->kineticEnergy();
            (void)chunked->potentialEnergy();
            for (int i = 0; i < static_cast<int>(chunked->particles().size()); ++i)
                (void)chunked->particlePosition(i);
            chunked->resetProfile();
        }
        QCOMPARE(done, kSteps);
        QCOMPARE(hex(hashOf(*chunked)), hex(reference));

        // At 1, 2 and 4 workers.
        for (int workers : {1, 2, 4}) {
            auto shared = build(desc);
            shared->setWorkers(workers);
            QCOMPARE(shared->workers(), workers);
            for (int k = 0; k < kSteps; ++k) QVERIFY(shared->step());
            QCOMPARE(hex(hashOf(*shared)), hex(reference));
        }

        // With each instruction set of the contact rows.
        forEachInstructionSet([&](int level) {
            auto world = build(desc);
            for (int k = 0; k < kSteps; ++k) QVERIFY(world->step());
            QVERIFY2(
                hashOf(*world) == reference,
                qPrintable(QStringLiteral("contact instructions %1: another state").arg(level)));
        });

        // And the bits this build gives are the bits every build gave.
        if (std::uint64_t(pinned) != reference)
            QFAIL(qPrintable(QStringLiteral("%1 with %2 after %3 steps: state hash %4, pinned %5. "
                                            "If the physics changed on purpose, pin the new value; "
                                            "otherwise the step is no longer deterministic.")
                                 .arg(scene, integrator)
                                 .arg(kSteps)
                                 .arg(hex(reference), hex(pinned))));
    }

    void largePyramidIsTheSameForAnyNumberOfWorkers() {
        // 5,050 boxes: the contact stage's loops run in many chunks, shared when there are
        // workers to share them.
        sameForAnyNumberOfWorkers(scenes::pyramid(100), 6);
    }

    void largePyramidIsTheSameOnEveryInstructionSet() {
        // The wide rows of 5,050 boxes, on two workers, with each instruction set against the
        // rows one by one.
        std::vector<std::uint64_t> reference;
        int sets = 0;
        forEachInstructionSet([&](int level) {
            auto world = build(scenes::pyramid(100));
            world->setWorkers(2);
            for (int k = 0; k < 6; ++k) QVERIFY(world->step());
            const std::vector<std::uint64_t> bits = testing::stateBits(*world);
            ++sets;
            if (reference.empty())
                reference = bits;
            else
                QVERIFY2(bits == reference,
                         qPrintable(
                             QStringLiteral("contact instructions %1: another state").arg(level)));
        });
        // Every x86-64 processor this is built for since 2015 has AVX2: the rows one by one and
        // at least one wide set were compared.
#if defined(__x86_64__)
        QVERIFY(sets >= 2);
#endif
    }

    void treeGravityIsTheSameForAnyNumberOfWorkers() {
        // 2,000 bodies in clusters: mutual gravity by the Barnes–Hut tree, whose walks the
        // workers share in chunks of bodies.
        sameForAnyNumberOfWorkers(scenes::clusteredBodies(2000), 5);
    }

private:
    // fn(level) with the contact rows on each instruction set this processor has, from none up;
    // then back to the best.
    template <class F>
    static void forEachInstructionSet(const F& fn) {
        const int best = ContactSolver::instructions();
        for (int level = 0; ContactSolver::useInstructions(level); ++level) {
            fn(level);
            if (QTest::currentTestFailed()) break;
        }
        ContactSolver::useInstructions(best);
    }

    // The state after `steps` steps at 1, 2 and 4 workers, to the bit; the loops are shared
    // whenever there is more than one worker.
    static void sameForAnyNumberOfWorkers(const SceneDesc& desc, int steps) {
        std::vector<std::uint64_t> reference;
        for (int workers : {1, 2, 4}) {
            auto world = build(desc);
            world->setWorkers(workers);
            for (int k = 0; k < steps; ++k) QVERIFY(world->step());
            QCOMPARE(world->workerPool().sharedLoops() > 0, workers > 1);
            const std::vector<std::uint64_t> bits = testing::stateBits(*world);
            if (reference.empty())
                reference = bits;
            else
                QVERIFY2(bits == reference,
                         qPrintable(QStringLiteral("%1 workers: another state").arg(workers)));
        }
    }
};

QTEST_APPLESS_MAIN(TestDeterminism)
#include "tst_determinism.moc"
