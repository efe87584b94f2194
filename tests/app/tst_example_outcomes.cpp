// Issue 37: two built-in scenes end as their descriptions say. In the Galton board every ball
// ends in the bins, below the last row of pegs (none stays balanced on a peg); in the rolling
// race every body stays within the scene as it opens (the region its objects span at t = 0) for
// the whole race.

#include "app/io/SceneIO.h"
#include "physics/scene/BuildWorld.h"

#include <QTest>

#include <algorithm>
#include <cmath>
#include <limits>

using namespace phasebox;

namespace {

SceneDesc load(const QString& path) {
    const SceneLoadResult result = SceneIO::load(path);
    if (!result.ok()) qFatal("%s", qPrintable(result.errorText()));
    return *result.scene;
}

struct Bounds {
    double lo[2] = {std::numeric_limits<double>::infinity(),
                    std::numeric_limits<double>::infinity()};
    double hi[2] = {-std::numeric_limits<double>::infinity(),
                    -std::numeric_limits<double>::infinity()};
    void include(const Vec2& p, double reach) {
        for (int k = 0; k < 2; ++k) {
            lo[k] = std::min(lo[k], p[k] - reach);
            hi[k] = std::max(hi[k], p[k] + reach);
        }
    }
    bool holds(const Vec2& p, double reach) const {
        for (int k = 0; k < 2; ++k)
            if (p[k] - reach < lo[k] || p[k] + reach > hi[k]) return false;
        return true;
    }
};

// The reach of a rigid body from its centre, as the canvas frames it: half its diagonal.
double reachOf(const RigidBody& box) {
    return 0.5 * box.size.norm();
}

}  // namespace

class TestExampleOutcomes : public QObject {
    Q_OBJECT

private slots:
    // Sixty balls fall through nine rows of pegs; after the scene's duration each is below the
    // last row (its centre lower than the lowest peg's bottom less its own radius), between the
    // side walls, and at rest in a bin. A ball a peg held by friction would still be up there.
    void galtonBallsAllEndInTheBins() {
        const SceneDesc scene = load(
            QStringLiteral(PHASEBOX_SOURCE_DIR "/resources/scenes/galton-board.phasebox.json"));
        auto world = buildWorld(scene).world;
        double lowestPeg = std::numeric_limits<double>::infinity();
        for (const DiskDesc& peg : scene.disks)
            lowestPeg = std::min(lowestPeg, peg.position[1] - peg.radius);
        QVERIFY(std::isfinite(lowestPeg));
        while (world->time() < scene.simulation.duration - 1e-9) QVERIFY(world->step());
        int above = 0;
        for (int i = 0; i < static_cast<int>(world->particles().size()); ++i) {
            const Particle& ball = world->particles()[i];
            const Vec2 x = world->particlePosition(i);
            if (x.y() + ball.radius >= lowestPeg) {
                qInfo("%s rests at (%.3f, %.3f), above the last pegs", ball.id.c_str(), x.x(),
                      x.y());
                ++above;
            }
            QVERIFY(std::abs(x.x()) < 3.4);
            QVERIFY2(world->particleVelocity(i).norm() < 0.1, ball.id.c_str());
        }
        QCOMPARE(above, 0);
        QCOMPARE(static_cast<int>(world->particles().size()), 60);
    }

    // The race ends at 3 s with all three still on their ramps: every body stays inside the
    // region the scene's objects span at t = 0, the view it opens with.
    void rollingRaceStaysInTheScenesView() {
        const SceneDesc scene = load(
            QStringLiteral(PHASEBOX_SOURCE_DIR "/resources/lessons/rolling-race.phasebox.json"));
        auto world = buildWorld(scene).world;
        Bounds view;
        for (int i = 0; i < static_cast<int>(world->rigidBodies().size()); ++i)
            view.include(world->bodyPosition(i), reachOf(world->rigidBodies()[i]));
        QVERIFY(view.hi[0] - view.lo[0] < 20.0);  // still a view a class can read
        while (world->time() < scene.simulation.duration - 1e-9) {
            QVERIFY(world->step());
            for (int i = 0; i < static_cast<int>(world->rigidBodies().size()); ++i) {
                const RigidBody& body = world->rigidBodies()[i];
                if (body.isStatic) continue;
                QVERIFY2(view.holds(world->bodyPosition(i), reachOf(body)),
                         qPrintable(QStringLiteral("%1 leaves the view at t = %2")
                                        .arg(QString::fromStdString(body.id))
                                        .arg(world->time())));
            }
        }
    }
};

QTEST_GUILESS_MAIN(TestExampleOutcomes)
#include "tst_example_outcomes.moc"
