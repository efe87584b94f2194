// Rigid convex polygons (CONTRACT §6, issue 16): mass and inertia from their vertices, the state
// at the centroid, and contacts by separating axes with clipped two-point manifolds, under
// symplectic Euler, RK4 and implicit Euler at the format's defaults.

#include "physics/scene/BuildWorld.h"

#include <QTest>

#include <cmath>
#include <numbers>

using namespace phasebox;

namespace {

void addIntegrators() {
    QTest::addColumn<QString>("integrator");
    for (const char* name : {"symplectic_euler", "rk4", "implicit_euler"})
        QTest::newRow(name) << QString(name);
}

SceneDesc onTheGround(const QString& integrator) {
    SceneDesc s;
    s.simulation.integrator = integrator.toStdString();
    s.effects.gravity = GravityDesc{};
    s.planes.push_back(PlaneDesc{});
    return s;
}

PolygonDesc regular(int sides, double radius, Point2 at, double turn = 0.0) {
    PolygonDesc p;
    p.position = at;
    for (int k = 0; k < sides; ++k) {
        const double a = turn + 2.0 * std::numbers::pi * k / sides;
        p.vertices.push_back({radius * std::cos(a), radius * std::sin(a)});
    }
    return p;
}

double largestDisplacement(const World& world) {
    double worst = 0.0;
    for (int i = 0; i < static_cast<int>(world.rigidBodies().size()); ++i)
        worst = std::max(worst, (world.bodyPosition(i) - world.rigidBodies()[i].position).norm());
    return worst;
}

}  // namespace

class TestPolygons : public QObject {
    Q_OBJECT

private slots:
    void massAndInertiaComeFromTheVertices() {
        // A 3-4-5 right triangle, written clockwise and off its centroid: area 6, centroid
        // (1, 4/3) from the right angle, I about the centroid m·(a² + b² + c²)/36.
        PolygonDesc t;
        t.position = {0.0, 0.0};
        t.density = 2.0;
        t.vertices = {{0.0, 0.0}, {0.0, 4.0}, {3.0, 0.0}};
        QCOMPARE(t.area(), 6.0);
        QVERIFY(std::abs(t.centroid()[0] - 1.0) < 1e-15);
        QVERIFY(std::abs(t.centroid()[1] - 4.0 / 3.0) < 1e-15);
        QCOMPARE(t.resolvedMass(), 12.0);
        QVERIFY(std::abs(t.momentOfInertia() - 12.0 * 50.0 / 36.0) < 1e-12);
        // A rectangle as a polygon: m·(w² + h²)/12, like a box.
        PolygonDesc r;
        r.vertices = {{-1.0, -0.25}, {1.0, -0.25}, {1.0, 0.25}, {-1.0, 0.25}};
        QVERIFY(std::abs(r.momentOfInertia() - 1.0 * (4.0 + 0.25) / 12.0) < 1e-15);
    }

    void spinsFreelyWithItsEnergy_data() { addIntegrators(); }
    void spinsFreelyWithItsEnergy() {
        // The state is the centroid's (CONTRACT §6): a triangle given spinning about the origin
        // of its vertices (its right angle), off its centroid c = (1, 4/3), starts with the
        // centroid moving at ω × c, and keeps ½·m·|ω × c|² + ½·I·ω² (I from its vertices) while
        // it spins freely, its centroid on a straight line.
        QFETCH(QString, integrator);
        SceneDesc s;
        s.simulation.integrator = integrator.toStdString();
        PolygonDesc t;
        t.position = {2.0, 1.0};
        t.vertices = {{0.0, 0.0}, {3.0, 0.0}, {0.0, 4.0}};
        t.angularVelocity = 3.0;
        s.polygons.push_back(t);
        auto world = buildWorld(s).world;
        const double mass = 6.0, inertia = mass * 50.0 / 36.0, omega = 3.0;
        const Vec2 c(1.0, 4.0 / 3.0), v0(-omega * c.y(), omega * c.x());
        const double energy = 0.5 * mass * v0.squaredNorm() + 0.5 * inertia * omega * omega;
        QVERIFY((world->bodyPosition(0) - (Vec2(2.0, 1.0) + c)).norm() < 1e-12);
        QVERIFY((world->bodyVelocity(0) - v0).norm() < 1e-12);
        QVERIFY(std::abs(world->energy().kinetic - energy) < 1e-12 * energy);
        for (int k = 0; k < 600; ++k) QVERIFY(world->step());
        QVERIFY(std::abs(world->energy().kinetic - energy) < 1e-12 * energy);
        QVERIFY(std::abs(world->bodyAngularVelocity(0) - omega) < 1e-12);
        const Vec2 expected = Vec2(2.0, 1.0) + c + world->time() * v0;
        QVERIFY((world->bodyPosition(0) - expected).norm() < 1e-9);
    }

    void aTriangleOnItsBaseStays_data() { addIntegrators(); }
    void aTriangleOnItsBaseStays() {
        QFETCH(QString, integrator);
        SceneDesc s = onTheGround(integrator);
        PolygonDesc t;
        t.position = {0.0, 0.0};
        t.vertices = {{-0.6, 0.0}, {0.6, 0.0}, {0.1, 0.9}};
        s.polygons.push_back(t);
        auto world = buildWorld(s).world;
        const double angle = world->bodyAngle(0);
        for (int k = 0; k < 600; ++k) QVERIFY(world->step());
        qInfo("%s: triangle moved %.2e m, turned %.2e rad", qPrintable(integrator),
              largestDisplacement(*world), std::abs(world->bodyAngle(0) - angle));
        QVERIFY(largestDisplacement(*world) < 1e-3);
        QVERIFY(std::abs(world->bodyAngle(0) - angle) < 1e-3);
    }

    void stacksOfBoxesAndPolygonsStand_data() { addIntegrators(); }
    void stacksOfBoxesAndPolygonsStand() {
        // Issue 16: boxes and polygons stacked with a disk on top, every body within 2 cm of
        // its start after 10 s.
        QFETCH(QString, integrator);
        SceneDesc s = onTheGround(integrator);
        BoxDesc box;
        box.position = {0.0, 0.5};
        s.boxes.push_back(box);
        // A hexagon with flat top and bottom on the box, a box on the hexagon, a disk on top.
        const double r = 0.5, flat = r * std::sqrt(3.0) / 2.0;
        s.polygons.push_back(regular(6, r, {0.0, 1.0 + flat}));
        BoxDesc top;
        top.position = {0.0, 1.0 + 2.0 * flat + 0.25};
        top.size = {1.0, 0.5};
        s.boxes.push_back(top);
        DiskDesc disk;
        disk.radius = 0.3;
        disk.position = {0.0, top.position[1] + 0.25 + 0.3};
        s.disks.push_back(disk);
        // And two squares as polygons, one on the other.
        s.polygons.push_back(regular(4, std::sqrt(0.5), {3.0, 0.5}, std::numbers::pi / 4.0));
        s.polygons.push_back(regular(4, std::sqrt(0.5), {3.0, 1.5}, std::numbers::pi / 4.0));
        auto world = buildWorld(s).world;
        for (int k = 0; k < 600; ++k) QVERIFY(world->step());
        const double moved = largestDisplacement(*world);
        qInfo("%s: largest displacement after 10 s %.4f m", qPrintable(integrator), moved);
        QVERIFY2(moved < 0.02, qPrintable(QString::number(moved)));
    }

    void aPolygonFallsOntoAnotherAndRests_data() { addIntegrators(); }
    void aPolygonFallsOntoAnotherAndRests() {
        // A pentagon dropped onto a static triangle's slope slides off and comes to rest on
        // the ground: no overlap left, nothing faster than the fall.
        QFETCH(QString, integrator);
        SceneDesc s = onTheGround(integrator);
        PolygonDesc ramp;
        ramp.position = {0.0, 0.0};
        ramp.vertices = {{-2.0, 0.0}, {2.0, 0.0}, {2.0, 1.0}};
        ramp.isStatic = true;
        ramp.friction = 0.1;
        s.polygons.push_back(ramp);
        PolygonDesc falling = regular(5, 0.3, {1.0, 2.0});
        falling.friction = 0.1;
        s.polygons.push_back(falling);
        auto world = buildWorld(s).world;
        double fastest = 0.0;
        for (int k = 0; k < 600; ++k) {
            QVERIFY(world->step());
            fastest = std::max(fastest, world->bodyVelocity(1).norm());
        }
        const Vec2 p = world->bodyPosition(1);
        qInfo("%s: pentagon at (%.3f, %.3f), fastest %.2f m/s", qPrintable(integrator), p.x(),
              p.y(), fastest);
        QVERIFY(fastest < std::sqrt(2.0 * 9.81 * 2.0) + 1.0);
        QVERIFY(world->bodyVelocity(1).norm() < 0.05);
        QVERIFY(p.x() < -2.0);  // off the ramp's low end
        QVERIFY(std::abs(p.y() - 0.3 * std::cos(std::numbers::pi / 5.0)) < 0.08);
    }

    void smallShapesRestFlatAtEverySize_data() {
        QTest::addColumn<QString>("shape");
        QTest::addColumn<double>("size");
        for (double size : {2e-6, 1e-5, 1e-4, 1e-3, 1e-2, 1.0}) {
            const QByteArray triangle = "right triangle " + QByteArray::number(size);
            QTest::newRow(triangle.constData()) << QString("right triangle") << size;
        }
        QTest::newRow("equilateral triangle 1.2e-6") << QString("equilateral") << 1.2e-6;
        QTest::newRow("box 1e-5") << QString("box") << 1e-5;
    }
    void smallShapesRestFlatAtEverySize() {
        // A rigid shape lying flat on the floor stays flat and at rest, whatever its size: the
        // contact's rest depth must be a share of the body's size, not an absolute depth (a
        // right triangle's corners carry 2 : 1, so equal-stiffness corners at an absolute
        // depth tilt it by the depths' difference over its width, 0.53 rad at 10 µm, and a
        // 1 µm triangle dropped 1 cm spun at 345 rad/s). Each is dropped 1 cm at the defaults.
        QFETCH(QString, shape);
        QFETCH(double, size);
        SceneDesc s = onTheGround(QString::fromStdString(SimulationDesc{}.integrator));
        double bottomToCentre = 0.0;
        if (shape == "box") {
            BoxDesc b;
            b.size = {size, size};
            bottomToCentre = size / 2.0;
            b.position = {0.0, 0.01 + bottomToCentre};
            s.boxes.push_back(b);
        } else {
            PolygonDesc t;
            if (shape == "equilateral") {
                t = regular(3, size / std::sqrt(3.0), {0.0, 0.0}, std::numbers::pi / 2.0);
                bottomToCentre = size / (2.0 * std::sqrt(3.0));
            } else {
                t.vertices = {
                    {-size / 2, -size / 3}, {size / 2, -size / 3}, {-size / 2, 2 * size / 3}};
                bottomToCentre = size / 3.0;
            }
            t.position = {0.0, 0.01 + bottomToCentre};
            s.polygons.push_back(t);
        }
        auto world = buildWorld(s).world;
        double fastestTurn = 0.0;
        for (int k = 0; k < 180; ++k) {
            QVERIFY(world->step());
            if (k >= 120)
                fastestTurn = std::max(fastestTurn, std::abs(world->bodyAngularVelocity(0)));
        }
        const double tilt = std::abs(world->bodyAngle(0));
        const double depth = bottomToCentre - world->bodyPosition(0).y();
        qInfo(
            "%s %g m: tilt %.2e rad, fastest turn in the last second %.2e rad/s, rest depth "
            "%.2e of its size",
            qPrintable(shape), size, tilt, fastestTurn, depth / size);
        QVERIFY2(tilt < 1e-3, qPrintable(QString::number(tilt)));
        QVERIFY2(fastestTurn < 1e-3, qPrintable(QString::number(fastestTurn)));
        QVERIFY2(std::abs(depth) < 5e-3 * size, qPrintable(QString::number(depth / size)));
        QVERIFY(world->bodyVelocity(0).norm() < 1e-3 * std::sqrt(9.81 * size) + 1e-12);
    }

    void fastSmallShapesDoNotTunnel_data() { addIntegrators(); }
    void fastSmallShapesDoNotTunnel() {
        // 200 m/s at dt = 1/60 is 3.3 m a step against a 0.1 m wall: a 5 cm disk and a 5 cm
        // triangle are stopped by the speculative contacts over the swept distance.
        QFETCH(QString, integrator);
        SceneDesc s;
        s.simulation.integrator = integrator.toStdString();
        BoxDesc wall;
        wall.position = {5.0, 0.0};
        wall.size = {0.1, 4.0};
        wall.isStatic = true;
        s.boxes.push_back(wall);
        DiskDesc disk;
        disk.position = {0.0, 1.0};
        disk.radius = 0.05;
        disk.velocity = {200.0, 0.0};
        s.disks.push_back(disk);
        PolygonDesc triangle = regular(3, 0.05, {0.0, -1.0});
        triangle.velocity = {200.0, 0.0};
        s.polygons.push_back(triangle);
        auto world = buildWorld(s).world;
        double furthest = -1e9;
        for (int k = 0; k < 60; ++k) {
            QVERIFY(world->step());
            for (int i = 1; i < 3; ++i) furthest = std::max(furthest, world->bodyPosition(i).x());
        }
        qInfo("%s: furthest centre %.4f m (wall face at 4.95 m)", qPrintable(integrator), furthest);
        QVERIFY(furthest < 4.95);
        QVERIFY(world->bodyVelocity(1).x() < 0.0 && world->bodyVelocity(2).x() <= 0.0);
    }
};

QTEST_APPLESS_MAIN(TestPolygons)
#include "tst_polygons.moc"
