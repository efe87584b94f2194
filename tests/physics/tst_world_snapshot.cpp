// A snapshot of the world's whole state (WorldSnapshot) restored and stepped on gives the same
// bits as the run that was never interrupted: what a recording's keyframes promise (CONTRACT
// §8). Each scene runs a while, is saved, runs on (the reference), is put back and runs the same
// steps again, every state compared bit for bit. The scenes exercise what carries state from
// step to step: contact warm starts and broad-phase order (a pyramid), the joints' solver and
// its sub-step choice (a hinged chain of boxes), springs under an implicit method (cloth), an
// adaptive method's step size (rk45) and penalty contacts.

#include "JointTestSupport.h"
#include "physics/scene/BuildWorld.h"
#include "physics/scene/SceneLibrary.h"
#include "physics/world/World.h"
#include "physics/world/WorldSnapshot.h"
#include "tests/support/StateBits.h"

#include <QTest>

#include <bit>
#include <cstdint>
#include <vector>

using namespace phasebox;

namespace {

// The state as bits (testing::stateBits) and the step count.
std::vector<std::uint64_t> bitsOf(const World& world) {
    std::vector<std::uint64_t> bits = testing::stateBits(world);
    bits.push_back(static_cast<std::uint64_t>(world.stepCount()));
    return bits;
}

SceneDesc hingedChain() {
    SceneDesc s = testing::scene("symplectic_euler", 1.0 / 60.0);
    for (int i = 0; i < 6; ++i) {
        BoxDesc b;
        b.id = "link" + std::to_string(i);
        b.position = {0.5 + i * 1.0, 3.0};
        b.size = {1.0, 0.2};
        s.boxes.push_back(b);
        JointDesc j = testing::joint(JointType::Hinge, b.id);
        if (i > 0) j.b = "link" + std::to_string(i - 1);
        j.anchor = Point2{i * 1.0, 3.0};
        s.joints.push_back(j);
    }
    PlaneDesc ground;
    s.planes.push_back(ground);
    return s;
}

SceneDesc sceneNamed(const QString& name) {
    if (name == "pyramid") return scenes::pyramid(10);
    if (name == "chain") return hingedChain();
    SceneDesc s;
    if (name == "cloth implicit") {
        s = scenes::cloth(8, 400.0);
        s.simulation.integrator = "implicit_euler";
    } else if (name == "rk45 pyramid") {
        s = scenes::pyramid(4);
        s.simulation.integrator = "rk45";
    } else if (name == "rk45 cloth") {
        s = scenes::cloth(6, 200.0);
        s.simulation.integrator = "rk45";
    } else if (name == "penalty") {
        s = scenes::pyramid(5);
        s.simulation.contactModel = ContactModel::Penalty;
        s.simulation.dt = 1.0 / 240.0;
    } else if (name == "kinematic") {
        s = scenes::elasticGas(40);
        s.simulation.contactModel = ContactModel::Kinematic;
    }
    return s;
}

}  // namespace

class TestWorldSnapshot : public QObject {
    Q_OBJECT

private slots:
    void restoredRunIsBitIdentical_data() {
        QTest::addColumn<QString>("scene");
        for (const char* name : {"pyramid", "chain", "cloth implicit", "rk45 pyramid", "rk45 cloth",
                                 "penalty", "kinematic"})
            QTest::newRow(name) << QString::fromLatin1(name);
    }

    void restoredRunIsBitIdentical() {
        QFETCH(QString, scene);
        auto world = buildWorld(sceneNamed(scene)).world;
        QVERIFY(world);
        for (int i = 0; i < 45; ++i) world->step();
        const WorldSnapshot snapshot = WorldSnapshot::take(*world);
        QCOMPARE(snapshot.stepCount(), world->stepCount());
        QVERIFY(snapshot.bytes() > 0);

        std::vector<std::vector<std::uint64_t>> reference;
        for (int i = 0; i < 60; ++i) {
            world->step();
            reference.push_back(bitsOf(*world));
        }
        QVERIFY(snapshot.restoreInto(*world));
        QCOMPARE(world->stepCount(), snapshot.stepCount());
        for (int i = 0; i < 60; ++i) {
            world->step();
            QVERIFY2(bitsOf(*world) == reference[static_cast<std::size_t>(i)],
                     qPrintable(QStringLiteral("step %1 after the restore differs").arg(i + 1)));
        }
    }

    // A frame shown gives back the forces the readouts read at that step (each body's contact
    // force, each joint's force on its bodies), bit for bit, under every contact model; stepping
    // on reads the live ones again.
    void shownFrameGivesBackItsForces_data() {
        QTest::addColumn<QString>("scene");
        for (const char* name : {"pyramid", "chain", "rk45 pyramid", "penalty", "kinematic"})
            QTest::newRow(name) << QString::fromLatin1(name);
    }

    void shownFrameGivesBackItsForces() {
        QFETCH(QString, scene);
        auto world = buildWorld(sceneNamed(scene)).world;
        QVERIFY(world);
        const auto forcesOf = [](const World& w) {
            std::vector<std::uint64_t> bits;
            const auto add = [&](double v) { bits.push_back(std::bit_cast<std::uint64_t>(v)); };
            for (const Particle& p : w.particles())
                for (double v : w.contactForce(p.dof)) add(v);
            for (const RigidBody& b : w.rigidBodies())
                for (double v : w.contactForce(b.dof)) add(v);
            for (int j = 0; j < static_cast<int>(w.joints().size()); ++j) {
                add(w.jointForce(j));
                for (bool onB : {false, true})
                    for (double v : w.jointForceOn(j, onB)) add(v);
            }
            return bits;
        };
        std::vector<FrameState> frames;
        std::vector<std::vector<std::uint64_t>> live;
        bool touched = false, pulled = false;
        for (int i = 0; i < 90; ++i) {
            world->step();
            frames.push_back(FrameState::of(*world));
            live.push_back(forcesOf(*world));
            for (const RigidBody& b : world->rigidBodies())
                touched = touched || world->contactForce(b.dof) != Vec2::Zero();
            for (const Particle& p : world->particles())
                touched = touched || world->contactForce(p.dof) != Vec2::Zero();
            pulled = pulled || (!world->joints().empty() && world->jointForce(0) != 0.0);
        }
        QVERIFY(touched || pulled);  // the scene has forces to give back
        for (int i : {0, 44, 13, 89, 70}) {
            QVERIFY(WorldSnapshot::show(*world, frames[static_cast<std::size_t>(i)]));
            QVERIFY(world->showsRecordedFrame());
            QVERIFY2(forcesOf(*world) == live[static_cast<std::size_t>(i)],
                     qPrintable(QStringLiteral("frame %1").arg(i)));
        }
        // A frame of a pile keeps the touching bodies' forces only.
        const FrameState& last = frames.back();
        QVERIFY(last.forces.contactDofs.size() <=
                world->particles().size() + world->rigidBodies().size());
        QVERIFY(last.bytes() >= sizeof(FrameState) + last.forces.bytes());
        // Stepping on from the frame shown reads the live forces of the new step again.
        world->step();
        QVERIFY(!world->showsRecordedFrame());
    }

    // Restoring twice from one snapshot, with other steps between, gives one answer: the
    // snapshot is not consumed or changed by a restore.
    void restoreIsRepeatable() {
        auto world = buildWorld(scenes::pyramid(6)).world;
        for (int i = 0; i < 30; ++i) world->step();
        const WorldSnapshot snapshot = WorldSnapshot::take(*world);
        for (int i = 0; i < 20; ++i) world->step();
        const auto first = bitsOf(*world);
        for (int round = 0; round < 2; ++round) {
            QVERIFY(snapshot.restoreInto(*world));
            for (int i = 0; i < 20; ++i) world->step();
            QVERIFY(bitsOf(*world) == first);
        }
    }

    // The settings are part of the state: a run that switched its method after the snapshot
    // goes back to the saved method, and steps on as the run from the snapshot did.
    void restoreBringsBackTheSettings() {
        auto world = buildWorld(scenes::pyramid(4)).world;
        for (int i = 0; i < 10; ++i) world->step();
        const WorldSnapshot snapshot = WorldSnapshot::take(*world);
        for (int i = 0; i < 10; ++i) world->step();
        const auto reference = bitsOf(*world);
        world->setIntegrator("rk4");
        world->step();
        QVERIFY(snapshot.restoreInto(*world));
        QCOMPARE(QString::fromStdString(world->settings().integrator),
                 QStringLiteral("symplectic_euler"));
        for (int i = 0; i < 10; ++i) world->step();
        QVERIFY(bitsOf(*world) == reference);
    }

    // A snapshot of other objects is refused and leaves the world as it was.
    void otherObjectsAreRefused() {
        auto world = buildWorld(scenes::pyramid(3)).world;
        world->step();
        const WorldSnapshot snapshot = WorldSnapshot::take(*world);
        auto other = buildWorld(scenes::pyramid(4)).world;
        other->step();
        const auto before = bitsOf(*other);
        QVERIFY(!snapshot.restoreInto(*other));
        QVERIFY(bitsOf(*other) == before);
    }
};

QTEST_GUILESS_MAIN(TestWorldSnapshot)
#include "tst_world_snapshot.moc"
