// A chain pulled straight between two fixed points (the bridge a class builds first: planks
// hinged end to end in a line, hinged to the world at both ends) cannot sag without stretching:
// under gravity its joints' system is singular there, and the forces that keep it straight grow
// without bound as soon as it moves. At the format's step velocity Verlet, RK4 and midpoint
// diverge on it (velocity Verlet at a quarter of that step too). The divergence then names the
// chain by its first and last joints and says first what removes the cause (a sag, or a free
// end); the same planks started with a sag run, and a divergence of something else names no
// chain.

#include "JointTestSupport.h"

#include "physics/world/DivergenceGuard.h"

#include <QTest>

#include <cmath>
#include <memory>
#include <string>

using namespace phasebox;
using namespace phasebox::testing;

namespace {

std::string numbered(char prefix, int i) {
    std::string id(1, prefix);
    id += std::to_string(i);
    return id;
}

// Ten 1 m planks hinged end to end from (0, 5), each half of the chain sloping down and up by
// `sag` radians (0: straight), hinged to the world at both ends: hinges h0 to h10. With
// pinnedBothEnds false, the last hinge is left out and the chain hangs from h0 alone.
SceneDesc bridge(const QString& integrator, double dt, double sag, bool pinnedBothEnds = true) {
    SceneDesc s = scene(integrator, dt);
    Point2 at{0.0, 5.0};
    for (int i = 0; i < 10; ++i) {
        const double slope = i < 5 ? -sag : sag;
        const Point2 next{at[0] + std::cos(slope), at[1] + std::sin(slope)};
        BoxDesc plank;
        plank.id = numbered('p', i);
        plank.position = {0.5 * (at[0] + next[0]), 0.5 * (at[1] + next[1])};
        plank.angle = slope;
        plank.size = {1.0, 0.2};
        plank.density = 10.0;
        s.boxes.push_back(plank);
        JointDesc hinge = joint(JointType::Hinge, plank.id,
                                i == 0 ? std::optional<std::string>{} : numbered('p', i - 1));
        hinge.id = numbered('h', i);
        hinge.anchor = at;
        s.joints.push_back(hinge);
        at = next;
    }
    if (pinnedBothEnds) {
        JointDesc last = joint(JointType::Hinge, "p9");
        last.id = "h10";
        last.anchor = at;
        s.joints.push_back(last);
    }
    return s;
}

// Steps until the world diverges or `seconds` pass; whether it diverged.
bool diverges(World& world, double seconds) {
    const int steps = static_cast<int>(std::lround(seconds / world.settings().dt));
    for (int k = 0; k < steps; ++k)
        if (!world.step()) return true;
    return false;
}

}  // namespace

class TestStraightChain : public QObject {
    Q_OBJECT

private slots:
    void theStraightChainIsNamed_data();
    void theStraightChainIsNamed();
    void aSaggingChainRuns_data();
    void aSaggingChainRuns();
    void anotherDivergenceNamesNoChain();
};

void TestStraightChain::theStraightChainIsNamed_data() {
    QTest::addColumn<QString>("integrator");
    QTest::addColumn<double>("dt");
    for (const char* method : {"velocity_verlet", "rk4", "midpoint"})
        QTest::addRow("%s dt 1/60", method) << QString::fromLatin1(method) << 1.0 / 60.0;
    QTest::newRow("velocity_verlet dt 1/240") << QStringLiteral("velocity_verlet") << 1.0 / 240.0;
}

void TestStraightChain::theStraightChainIsNamed() {
    QFETCH(QString, integrator);
    QFETCH(double, dt);
    const std::unique_ptr<World> world = build(bridge(integrator, dt, 0.0));
    QVERIFY(diverges(*world, 2.0));
    const Divergence& d = *world->divergence();
    QCOMPARE(d.straightFrom, std::string("h0"));
    QCOMPARE(d.straightTo, std::string("h10"));
    const std::string message = d.message();
    QVERIFY2(message.find("\"h0\" to \"h10\" hold a chain pulled straight") != std::string::npos &&
                 message.find("Start the chain with some sag or free one of its ends") !=
                     std::string::npos,
             message.c_str());
}

void TestStraightChain::aSaggingChainRuns_data() {
    QTest::addColumn<QString>("integrator");
    for (const char* method : {"velocity_verlet", "rk4", "midpoint", "symplectic_euler"})
        QTest::newRow(method) << QString::fromLatin1(method);
}

void TestStraightChain::aSaggingChainRuns() {
    // What the message advises: the same planks in a V of 0.15 rad a side (1.1% longer than
    // their span) swing and hold at the format's step.
    QFETCH(QString, integrator);
    const std::unique_ptr<World> world = build(bridge(integrator, 1.0 / 60.0, 0.15));
    QVERIFY(!diverges(*world, 5.0));
    QVERIFY(world->positions().allFinite());
    QVERIFY2(world->jointErrors().position < 1e-3,
             qPrintable(QString::number(world->jointErrors().position)));
}

void TestStraightChain::anotherDivergenceNamesNoChain() {
    // The straight planks hanging from one end (they swing freely), beside a particle on a spring
    // far beyond explicit Euler's bound at this step: the spring diverges, and the message gives
    // the usual advice.
    SceneDesc s = bridge(QStringLiteral("explicit_euler"), 1.0 / 60.0, 0.0, false);
    s.particles.push_back(particle("bob", {20.0, 0.0}));
    SpringDesc spring;
    spring.a = "bob";
    spring.anchor = Point2{20.0, 1.0};
    spring.stiffness = 1e6;
    spring.restLength = 1.0;
    s.springs.push_back(spring);
    const std::unique_ptr<World> world = build(s);
    QVERIFY(diverges(*world, 5.0));
    const Divergence& d = *world->divergence();
    QVERIFY(d.straightFrom.empty() && d.straightTo.empty());
    QVERIFY2(d.message().find("pulled straight") == std::string::npos &&
                 d.message().find("Try a smaller dt") != std::string::npos,
             d.message().c_str());
}

QTEST_MAIN(TestStraightChain)
#include "tst_straight_chain.moc"
