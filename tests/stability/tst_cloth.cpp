// Cloth, where explicit integrators fail and implicit Euler earns its cost (issue #4). The engine
// alone: the command line's report of the blow-up is tests/cli/tst_cli.cpp (clothBlowUpIsReported).

#include "physics/diagnostics/StabilityAdvisor.h"
#include "physics/scene/BuildWorld.h"
#include "physics/scene/SceneLibrary.h"

#include <QTest>

#include <cmath>

using namespace phasebox;

namespace {
double mechanicalEnergy(const World& world) {
    return world.energy().kinetic + world.energy().potential;
}
}  // namespace

class TestCloth : public QObject {
    Q_OBJECT

private slots:
    void implicitEulerClothStaysBoundedAndNeverGainsEnergy() {
        // 40 × 40 nodes, 1 kg, structural stiffness 2·10⁴ at dt = 1/60: the stiffest mode has
        // ω·h ≈ 190, a hundred times past any explicit method's limit.
        auto world = buildWorld(scenes::cloth(40, 2e4)).world;
        QCOMPARE(world->settings().integrator, std::string("implicit_euler"));
        QCOMPARE(world->settings().dt, 1.0 / 60.0);
        const double e0 = mechanicalEnergy(*world);
        double highest = e0;
        for (int k = 0; k < 3600; ++k) {  // 60 s
            QVERIFY2(world->step(),
                     world->divergence() ? world->divergence()->message().c_str() : "");
            highest = std::max(highest, mechanicalEnergy(*world));
        }
        qInfo("40x40 cloth, 60 s of implicit Euler: E0 = %.6f J, highest %.6f J, final %.6f J", e0,
              highest, mechanicalEnergy(*world));
        QVERIFY(world->positions().allFinite() && world->velocities().allFinite());
        QVERIFY(highest <= e0 + 1e-9 * std::abs(e0) + 1e-12);
        // It hangs: every node below its pinned top edge, none fallen away.
        const Vec& q = world->positions();
        for (int i = 1; i < q.size(); i += 2) QVERIFY(q[i] < 1.0 + 1e-6 && q[i] > -1.0);
    }

    void explicitMethodsAreCaughtDiverging_data() {
        QTest::addColumn<QString>("integrator");
        QTest::newRow("explicit_euler") << "explicit_euler";
        QTest::newRow("symplectic_euler") << "symplectic_euler";
    }
    void explicitMethodsAreCaughtDiverging() {
        QFETCH(QString, integrator);
        SceneDesc scene = scenes::cloth(40, 2e4);
        scene.simulation.integrator = integrator.toStdString();
        auto world = buildWorld(scene).world;
        QVERIFY(!adviseStability(*world).currentStable);  // the advisor saw it coming
        bool diverged = false;
        for (int k = 0; k < 600 && !diverged; ++k) diverged = !world->step();
        QVERIFY(diverged);
        const Divergence& d = *world->divergence();
        qInfo("%s: %s", qPrintable(integrator), d.message().c_str());
        QVERIFY(d.objectId.rfind("cloth[", 0) == 0);
        QVERIFY(d.time > 0.0);
        QVERIFY(world->positions().allFinite() && world->velocities().allFinite());
        QVERIFY(std::isfinite(world->energy().drift));
    }

    void clothDrapesOverABoxAndLiesOnTheFloor() {
        // Cloth nodes are particles with a radius: gravity and contacts act on them. In a 2D
        // world a cloth laid over a table is a strip: 2 m of it dropped on a 0.6 m table rests on
        // the top and hangs down both sides, its ends lying on the floor.
        SceneDesc scene = scenes::cloth(2, 2e3);
        ClothDesc& strip = scene.cloths[0];
        strip.resolution = {41, 2};
        strip.size = {2.0, 0.05};
        strip.origin = {-1.0, 0.8};
        strip.pinned = std::string("none");
        strip.damping = 0.05;
        strip.radius = 0.02;
        scene.simulation.substeps = 4;
        PlaneDesc floor;
        floor.point = {0.0, 0.0};
        floor.normal = {0.0, 1.0};
        scene.planes.push_back(floor);
        BoxDesc table;
        table.id = "table";
        table.position = {0.0, 0.3};
        table.size = {0.6, 0.6};
        table.isStatic = true;
        scene.boxes.push_back(table);
        auto world = buildWorld(scene).world;
        for (int k = 0; k < 300; ++k) QVERIFY(world->step());
        int onTable = 0, onFloor = 0;
        for (int i = 0; i < static_cast<int>(world->particles().size()); ++i) {
            const Vec2 p = world->particlePosition(i);
            QVERIFY2(p.y() > -0.01, "a node fell through the floor");
            const bool insideTable = std::abs(p.x()) < 0.3 - 0.01 && p.y() < 0.6 - 0.01;
            QVERIFY2(!insideTable, "a node is inside the table");
            onTable += std::abs(p.x()) < 0.3 && std::abs(p.y() - 0.62) < 0.05;
            onFloor += p.y() < 0.05;
        }
        qInfo("draped strip: %d nodes on the table top, %d on the floor", onTable, onFloor);
        QVERIFY(onTable >= 10);
        QVERIFY(onFloor >= 2);
    }
};

QTEST_GUILESS_MAIN(TestCloth)
#include "tst_cloth.moc"
