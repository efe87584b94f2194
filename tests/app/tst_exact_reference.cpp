// The closed forms found for a scene with contacts (app/accuracy/ExactReference): exact only
// while no contact can happen along them. A ball dropped from 10 m above a floor falls freely
// for √(2·9.9/g) = 1.42 s before its 10 cm radius touches; a hoop's bead never reaches a floor
// below the hoop; a ball that lands has none.

#include "app/accuracy/ExactReference.h"
#include "physics/scene/BuildWorld.h"
#include "physics/scene/SceneDesc.h"
#include "physics/world/World.h"

#include <QTest>

#include <cmath>

using namespace phasebox;

namespace {

SceneDesc dropOverFloor(double duration) {
    SceneDesc s;
    s.simulation.duration = duration;
    s.effects.gravity = GravityDesc{};
    ParticleDesc ball;
    ball.id = "ball";
    ball.position = {0.0, 10.0};
    ball.radius = 0.1;
    s.particles.push_back(ball);
    PlaneDesc floor;
    floor.id = "floor";
    s.planes.push_back(floor);
    return s;
}

std::optional<ExactReference> find(const SceneDesc& s) {
    auto world = buildWorld(s).world;
    return findExactReference(s, *world, s.simulation.duration);
}

}  // namespace

class TestExactReference : public QObject {
    Q_OBJECT

private slots:
    void fallAboveAFloorIsExactUntilItLands() {
        QVERIFY(buildWorld(dropOverFloor(1.0)).world->contacts() != nullptr);
        const auto early = find(dropOverFloor(1.0));  // falls 4.9 m of 9.9
        QVERIFY(early.has_value());
        QCOMPARE(early->kind(), std::string("free fall"));
        QVERIFY(std::abs(early->position(1, 1.0) - (10.0 - 0.5 * 9.81)) < 1e-12);
        QVERIFY(!find(dropOverFloor(1.5)).has_value());  // lands at 1.42 s
        QVERIFY(!find(dropOverFloor(10.0)).has_value());
    }

    void beadOnAHoopNeverReachesTheFloorBelow() {
        SceneDesc s;
        s.simulation.duration = 10.0;
        s.effects.gravity = GravityDesc{};
        ParticleDesc bead;
        bead.id = "bead";
        bead.position = {1.0, 0.0};
        bead.radius = 0.08;
        s.particles.push_back(bead);
        PlaneDesc floor;
        floor.point = {0.0, -1.4};
        s.planes.push_back(floor);
        JointDesc wire;
        wire.id = "wire";
        wire.type = JointType::Track;
        wire.a = "bead";
        wire.circle = TrackCircleDesc{{0.0, 0.0}, 1.0};
        s.joints.push_back(wire);
        const auto ref = find(s);
        QVERIFY(ref.has_value());
        QCOMPARE(ref->kind(), std::string("simple pendulum"));
        // The floor raised to within the bead's reach of the hoop's bottom: no closed form.
        s.planes.front().point = {0.0, -1.09};
        QVERIFY(!find(s).has_value());
    }
};

QTEST_GUILESS_MAIN(TestExactReference)
#include "tst_exact_reference.moc"
