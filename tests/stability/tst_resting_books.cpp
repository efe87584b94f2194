// What rests is at rest in every book (CONTRACT §6, the energy ledger): contacts and joints act
// inside the method's step, so a body resting on its support, or held at rest by a joint on
// one, books no drift and no correction under any method, and does not move. At the format's
// defaults (impulse contacts, dt 1/60, one sub-step), from 2 s after load to 20 s, drift,
// correction and the total each stay within 1 mJ per kg of dynamic mass per simulated second of
// their value at 2 s; no body moves 1 mm; no wheel or table top sinks 5 mm below where it was
// put. And a box left resting for two hours of simulated time runs to the end.

#include "../physics/PhysicsTestSupport.h"

#include "physics/world/World.h"

#include <QTest>

#include <algorithm>
#include <cmath>
#include <map>

using namespace phasebox;
using namespace phasebox::testing;

namespace {

BoxDesc box(const std::string& id, Point2 position, Point2 size) {
    BoxDesc b;
    b.id = id;
    b.position = position;
    b.size = size;
    return b;
}

DiskDesc disk(const std::string& id, Point2 position, double radius) {
    DiskDesc d;
    d.id = id;
    d.position = position;
    d.radius = radius;
    return d;
}

JointDesc joint(JointType type, const std::string& a, const std::string& b,
                std::optional<Point2> anchor = {}) {
    JointDesc j;
    j.type = type;
    j.a = a;
    j.b = b;
    j.anchor = anchor;
    return j;
}

// The resting scenes, each with the bodies whose sinking is bounded (wheels, table tops).
struct RestingScene {
    SceneDesc scene;
    std::vector<std::string> mustNotSink;
};

RestingScene restingScene(const QString& name, const char* integrator) {
    RestingScene r{floorScene(integrator), {}};
    SceneDesc& s = r.scene;
    if (name == "box") {
        s.boxes.push_back(box("b", {0.0, 0.5}, {1.0, 1.0}));
    } else if (name == "tower") {
        for (int i = 0; i < 10; ++i)
            s.boxes.push_back(box("b" + std::to_string(i), {0.0, 0.5 + i}, {1.0, 1.0}));
    } else if (name == "disks and a hexagon") {
        s.disks.push_back(disk("d0", {0.0, 0.3}, 0.3));
        s.disks.push_back(disk("d1", {1.0, 0.5}, 0.5));
        PolygonDesc hexagon;
        hexagon.id = "hexagon";
        hexagon.position = {3.0, 0.5 * std::sqrt(3.0) * 0.5};
        for (int k = 0; k < 6; ++k)
            hexagon.vertices.push_back(
                {0.5 * std::cos(k * M_PI / 3.0), 0.5 * std::sin(k * M_PI / 3.0)});
        s.polygons.push_back(hexagon);
    } else if (name == "cart on hinged wheels") {
        BoxDesc body = box("body", {0.0, 0.6}, {2.0, 0.3});
        body.mass = 20.0;
        s.boxes.push_back(body);
        for (const auto& [id, x] : {std::pair{"w0", -0.7}, std::pair{"w1", 0.7}}) {
            DiskDesc wheel = disk(id, {x, 0.3}, 0.3);
            wheel.mass = 2.0;
            s.disks.push_back(wheel);
            s.joints.push_back(joint(JointType::Hinge, "body", id, Point2{x, 0.3}));
            r.mustNotSink.push_back(id);
        }
        r.mustNotSink.push_back("body");
    } else if (name == "hinged planks") {
        for (int i = 0; i < 5; ++i)
            s.boxes.push_back(box("p" + std::to_string(i), {1.0 * i, 0.05}, {1.0, 0.1}));
        for (int i = 0; i < 4; ++i)
            s.joints.push_back(joint(JointType::Hinge, "p" + std::to_string(i),
                                     "p" + std::to_string(i + 1), Point2{i + 0.5, 0.05}));
    } else if (name == "welded table") {
        s.boxes.push_back(box("top", {0.0, 1.05}, {2.0, 0.1}));
        s.boxes.push_back(box("leg0", {-0.9, 0.5}, {0.1, 1.0}));
        s.boxes.push_back(box("leg1", {0.9, 0.5}, {0.1, 1.0}));
        s.joints.push_back(joint(JointType::Weld, "top", "leg0"));
        s.joints.push_back(joint(JointType::Weld, "top", "leg1"));
        r.mustNotSink.push_back("top");
    }
    return r;
}

// Every dynamic body's centre, by id.
std::map<std::string, Vec2> centres(const World& world) {
    std::map<std::string, Vec2> out;
    for (int i = 0; i < static_cast<int>(world.particles().size()); ++i)
        out[world.particles()[i].id] = world.particlePosition(i);
    for (int i = 0; i < static_cast<int>(world.rigidBodies().size()); ++i)
        if (!world.rigidBodies()[i].isStatic)
            out[world.rigidBodies()[i].id] = world.bodyPosition(i);
    return out;
}

}  // namespace

class TestRestingBooks : public QObject {
    Q_OBJECT
private slots:
    void restingBodiesBookNothing_data() {
        QTest::addColumn<QString>("scene");
        QTest::addColumn<QString>("integrator");
        for (const char* scene : {"box", "tower", "disks and a hexagon", "cart on hinged wheels",
                                  "hinged planks", "welded table"})
            for (const char* method : {"symplectic_euler", "velocity_verlet", "rk4",
                                       "implicit_euler", "implicit_midpoint"})
                QTest::newRow(qPrintable(QString("%1, %2").arg(scene, method)))
                    << QString(scene) << QString(method);
    }
    void restingBodiesBookNothing() {
        QFETCH(QString, scene);
        QFETCH(QString, integrator);
        const RestingScene resting = restingScene(scene, qPrintable(integrator));
        auto world = build(resting.scene);
        const auto placed = centres(*world);
        const double dt = world->settings().dt;
        while (world->time() < 2.0 - 0.5 * dt) QVERIFY(world->step());
        const auto settled = centres(*world);
        const EnergyLedger at2 = world->energy();
        double drift = 0.0, correction = 0.0, total = 0.0, moved = 0.0, sunk = 0.0;
        while (world->time() < 20.0 - 0.5 * dt) {
            QVERIFY(world->step());
            const EnergyLedger& e = world->energy();
            drift = std::max(drift, std::abs(e.drift - at2.drift));
            correction = std::max(correction, std::abs(e.correction - at2.correction));
            total =
                std::max(total, std::abs(e.kinetic + e.potential - at2.kinetic - at2.potential));
            for (const auto& [id, p] : centres(*world)) {
                moved = std::max(moved, (p - settled.at(id)).norm());
                if (std::count(resting.mustNotSink.begin(), resting.mustNotSink.end(), id))
                    sunk = std::max(sunk, placed.at(id).y() - p.y());
            }
        }
        // 1 mJ per kg of dynamic mass per simulated second, over the 18 s watched.
        const double bound = 1e-3 * dynamicMass(*world) * 18.0;
        qInfo(
            "%s, %s: |drift| %.2e J, |correction| %.2e J, |total| %.2e J (bound %.2e J); "
            "moved %.2e m, sunk %.2e m",
            qPrintable(scene), qPrintable(integrator), drift, correction, total, bound, moved,
            sunk);
        QVERIFY2(drift <= bound, "drift");
        QVERIFY2(correction <= bound, "correction");
        QVERIFY2(total <= bound, "total");
        QVERIFY2(moved < 1e-3, "a resting body moved");
        QVERIFY2(sunk < 5e-3, "a wheel or a table top sank");
    }

    // Left on the floor for two hours of simulated time, a box is still where it settled and
    // nothing has been booked against it since: the divergence guard never trips. (Its first
    // step, before any contact is known, is a free fall of the method's, booked as such.)
    void boxRestsForTwoHours() {
        auto world = build(restingScene("box", "symplectic_euler").scene);
        const double dt = world->settings().dt;
        EnergyLedger settled;
        Vec2 start = Vec2::Zero();
        while (world->time() < 7200.0 - 0.5 * dt) {
            if (std::abs(world->time() - 2.0) < 0.5 * dt) {
                settled = world->energy();
                start = centres(*world).at("b");
            }
            if (world->step()) continue;
            QFAIL(qPrintable(QString("diverged at %1 s: %2")
                                 .arg(world->divergence()->time)
                                 .arg(QString::fromStdString(world->divergence()->what))));
        }
        const EnergyLedger& e = world->energy();
        const double moved = (centres(*world).at("b") - start).norm();
        qInfo("from 2 s to 7200 s: drift %.2e J, correction %.2e J, moved %.2e m",
              e.drift - settled.drift, e.correction - settled.correction, moved);
        QVERIFY(std::abs(e.drift - settled.drift) < 1e-6);
        QVERIFY(std::abs(e.correction - settled.correction) < 1e-6);
        QVERIFY(moved < 1e-6);
    }
};

QTEST_APPLESS_MAIN(TestRestingBooks)
#include "tst_resting_books.moc"
