// Invariants of the world as a whole: switching the integrator keeps the state exactly,
// sub-steps equal finer steps, forces are the gradient of the potential and the Jacobians the
// derivatives of the forces (the torque path of springs on boxes included), springs on boxes
// conserve energy and momentum, a circular orbit keeps its period, and only the effects a
// scene lists are constructed.

#include "PhysicsTestSupport.h"

#include "physics/world/DivergenceGuard.h"

#include <QTest>

#include <algorithm>
#include <cmath>

using namespace phasebox;
using namespace phasebox::testing;

namespace {

const char* const kAllIntegrators[] = {
    "explicit_euler",  "symplectic_euler", "midpoint",          "heun",           "rk4",
    "velocity_verlet", "implicit_euler",   "implicit_midpoint", "adaptive_euler", "rk45",
};
const char* const kFixedStepIntegrators[] = {
    "explicit_euler",  "symplectic_euler", "midpoint",          "heun", "rk4",
    "velocity_verlet", "implicit_euler",   "implicit_midpoint",
};

BoxDesc box(const std::string& id, Point2 position, Point2 size, double mass, double angle,
            Point2 velocity, double angularVelocity) {
    BoxDesc b;
    b.id = id;
    b.position = position;
    b.size = size;
    b.mass = mass;
    b.angle = angle;
    b.velocity = velocity;
    b.angularVelocity = angularVelocity;
    return b;
}

SpringDesc spring(const std::string& a, std::optional<std::string> b, std::optional<Point2> anchor,
                  Point2 aPoint, Point2 bPoint, double k, double c, std::optional<double> rest) {
    SpringDesc s;
    s.a = a;
    s.b = std::move(b);
    s.anchor = anchor;
    s.aPoint = aPoint;
    s.bPoint = bPoint;
    s.stiffness = k;
    s.damping = c;
    s.restLength = rest;
    return s;
}

// A box hanging from a fixed anchor by a spring fixed off its centre (so the spring exerts a
// torque), under gravity: it swings, stretches and spins.
SceneDesc hangingBoxScene(const std::string& integrator, double dt) {
    SceneDesc scene;
    scene.simulation = simulation(integrator, dt);
    scene.effects.gravity = GravityDesc{};
    scene.boxes.push_back(box("crate", {0.3, -1.5}, {1.0, 0.5}, 2.0, 0.3, {0.5, 0.0}, 1.0));
    scene.springs.push_back(
        spring("crate", std::nullopt, Point2{0.0, 0.0}, {0.4, 0.2}, {0.0, 0.0}, 50.0, 0.0, 1.0));
    return scene;
}

// Two free boxes joined by a spring between off-centre points, and a particle tied to one of
// them, with no external force: total momentum and angular momentum are conserved. The bodies
// are kept far enough apart never to touch (see clearance()), so contacts, which a world with
// two boxes runs, never act and these are tests of the smooth forces alone.
SceneDesc boxPairScene(const std::string& integrator, double dt, double damping) {
    SceneDesc scene;
    scene.simulation = simulation(integrator, dt);
    scene.boxes.push_back(box("left", {-1.6, 0.0}, {0.8, 0.4}, 1.5, 0.2, {0.0, 0.3}, -0.5));
    scene.boxes.push_back(box("right", {1.6, 0.2}, {0.5, 1.0}, 0.7, -0.4, {0.2, -0.1}, 1.5));
    ParticleDesc p;
    p.id = "bob";
    p.position = {1.6, 2.0};
    p.velocity = {-0.4, 0.0};
    p.mass = 0.3;
    p.radius = 0.0;
    scene.particles.push_back(p);
    scene.springs.push_back(
        spring("left", "right", std::nullopt, {0.3, 0.1}, {-0.2, 0.4}, 20.0, damping, 2.7));
    scene.springs.push_back(
        spring("bob", "right", std::nullopt, {0.0, 0.0}, {0.1, 0.4}, 8.0, damping, std::nullopt));
    return scene;
}

// The smallest gap between the bounding circles of the bodies of boxPairScene (box half
// diagonals √(0.4² + 0.2²) and √(0.25² + 0.5²); the particle is a point): positive means
// nothing can touch.
double clearance(const World& world) {
    const double rl = std::hypot(0.4, 0.2), rr = std::hypot(0.25, 0.5);
    const Eigen::Vector2d left = world.bodyPosition(0), right = world.bodyPosition(1);
    const Eigen::Vector2d bob = world.particlePosition(0);
    return std::min(
        {(right - left).norm() - rl - rr, (bob - left).norm() - rl, (bob - right).norm() - rr});
}

// Three particles attracting each other and a fixed attractor, with softening, so every
// branch of the Newtonian effect (attractor, mutual pairs, ε) is in play.
SceneDesc softenedClusterScene(const std::string& integrator, double dt) {
    SceneDesc scene;
    scene.simulation = simulation(integrator, dt);
    NewtonianGravityDesc ng;
    ng.G = 1.0;
    ng.attractors.push_back({{0.0, 0.0}, 2.0});
    ng.mutual = true;
    ng.softening = 0.3;
    scene.effects.newtonianGravity = ng;
    const Point2 positions[] = {{1.0, 0.0}, {-0.5, 0.9}, {-0.4, -1.1}};
    const Point2 velocities[] = {{0.0, 1.2}, {-1.0, -0.5}, {1.1, -0.4}};
    const double masses[] = {1.0, 0.5, 0.8};
    for (int i = 0; i < 3; ++i) {
        ParticleDesc p;
        p.position = positions[i];
        p.velocity = velocities[i];
        p.mass = masses[i];
        p.radius = 0.0;
        scene.particles.push_back(p);
    }
    return scene;
}

// Total linear momentum (x, y) and angular momentum about the origin of the dynamic state.
Eigen::Vector3d momenta(const World& world) {
    const Eigen::VectorXd& q = world.positions();
    const Eigen::VectorXd& u = world.velocities();
    const Eigen::VectorXd& m = world.mass();
    const StateLayout& layout = world.layout();
    Eigen::Vector3d result = Eigen::Vector3d::Zero();
    auto body = [&](int dof) {
        result.x() += m[dof] * u[dof];
        result.y() += m[dof] * u[dof + 1];
        result.z() += m[dof] * (q[dof] * u[dof + 1] - q[dof + 1] * u[dof]);
    };
    for (int p = 0; p < layout.dynamicParticles; ++p) body(layout.particleDof(p));
    for (int b = 0; b < layout.dynamicRigidBodies; ++b) {
        const int dof = layout.rigidDof(b);
        body(dof);
        result.z() += m[dof + 2] * u[dof + 2];
    }
    return result;
}

std::vector<std::string> effectNames(const World& world) {
    std::vector<std::string> names;
    for (const auto& e : world.effects()) names.push_back(e->name());
    std::sort(names.begin(), names.end());
    return names;
}

Eigen::MatrixXd dense(const std::vector<Triplet>& triplets, int n) {
    Eigen::MatrixXd m = Eigen::MatrixXd::Zero(n, n);
    for (const Triplet& t : triplets) m(t.row(), t.col()) += t.value();
    return m;
}

// Particles (ids p0, p1, …) and a spinning box under a slanted gravity, nothing else.
SceneDesc fallingParticlesAndBox(int particles) {
    SceneDesc scene;
    scene.simulation = simulation("symplectic_euler", 0.01);
    scene.effects.gravity = GravityDesc{{0.3, -9.81}};
    for (int i = 0; i < particles; ++i) {
        ParticleDesc p;
        p.id = "p" + std::to_string(i);
        p.position = {0.1 * i, 1.0 + i};
        p.velocity = {1.0 - 0.3 * i, 0.5 * i};
        p.mass = 1.0 + i;
        p.radius = 0.0;
        scene.particles.push_back(p);
    }
    BoxDesc box;
    box.position = {3.0, 4.0};
    box.angularVelocity = 2.0;
    box.velocity = {-1.0, 2.0};
    scene.boxes.push_back(box);
    return scene;
}

}  // namespace

class TestWorldInvariants : public QObject {
    Q_OBJECT

private slots:
    void switchingIntegratorKeepsState();
    void switchedIntegratorTakesTheNextStep();
    void substepsEqualFinerSteps_data();
    void substepsEqualFinerSteps();
    void forcesAreMinusPotentialGradient_data();
    void forcesAreMinusPotentialGradient();
    void jacobiansMatchFiniteDifferences_data();
    void jacobiansMatchFiniteDifferences();
    void springOnBoxConservesEnergy();
    void springsConserveMomenta_data();
    void springsConserveMomenta();
    void circularOrbitPeriod();
    void mutualGravityBinaryOrbit();
    void onlyListedEffectsAreConstructed();
    void gravityAloneMatchesTheForceChannel();
    void splitAccelerationAddsUpToTheWhole();
    void anOverflowRestoresTheLastGoodState();
    void runawayDriftDivergesAsTheContractSays();
    void runawayCorrectionDivergesAtItsFirstStep();
};

// Gravity alone is an acceleration field, written straight into the accelerations; with a drag of
// zero listed, the force channel runs too (forces summed, times 1/m). Neither changes a single
// acceleration, so both must compute exactly the same step.
void TestWorldInvariants::gravityAloneMatchesTheForceChannel() {
    SceneDesc scene = fallingParticlesAndBox(7);
    scene.simulation.substeps = 3;
    SceneDesc generic = scene;
    generic.effects.drag = DragDesc{0.0, 0.0, 0.0};
    auto fast = build(scene);
    auto slow = build(generic);
    for (int k = 0; k < 200; ++k) {
        QVERIFY(fast->step());
        QVERIFY(slow->step());
    }
    QVERIFY(fast->positions() == slow->positions());
    QVERIFY(fast->velocities() == slow->velocities());
    QCOMPARE(fast->time(), slow->time());
    const EnergyLedger& a = fast->energy();
    const EnergyLedger& b = slow->energy();
    QVERIFY(std::abs(a.kinetic - b.kinetic) <= 1e-12 * std::abs(b.kinetic));
    QVERIFY(std::abs(a.potential - b.potential) <= 1e-12 * std::abs(b.potential));
    QVERIFY(std::abs(a.drift - b.drift) <= 1e-9 * (std::abs(b.kinetic) + std::abs(b.potential)));
}

// OdeSystem::accelerationSplit: the uniform part (gravity) plus the rest is the whole
// acceleration, lane for lane; with gravity alone there is no rest to write.
void TestWorldInvariants::splitAccelerationAddsUpToTheWhole() {
    SceneDesc scene = fallingParticlesAndBox(3);
    auto alone = build(scene);
    const int n = static_cast<int>(alone->positions().size());
    Eigen::VectorXd rest = Eigen::VectorXd::Constant(n, 7.0), whole(n);
    const auto onlyGravity =
        alone->accelerationSplit(0.0, alone->positions(), alone->velocities(), rest);
    QVERIFY(!onlyGravity.hasRest);
    QVERIFY(rest == Eigen::VectorXd::Constant(n, 7.0));  // untouched
    QCOMPARE(onlyGravity.uniform, Vec2(0.3, -9.81));

    scene.effects.drag = DragDesc{0.4, 0.0, 0.0};
    SpringDesc spring;
    spring.a = "p0";
    spring.b = "p2";
    spring.stiffness = 50.0;
    spring.damping = 0.5;
    spring.restLength = 1.2;
    scene.springs.push_back(spring);
    auto mixed = build(scene);
    const Eigen::VectorXd q = mixed->positions(), u = mixed->velocities();
    const double power = mixed->acceleration(0.0, q, u, whole);
    const auto split = mixed->accelerationSplit(0.0, q, u, rest);
    QVERIFY(split.hasRest);
    QCOMPARE(split.power, power);
    QVERIFY(power < 0.0);  // drag takes energy
    for (int i = 0; i < n; ++i) {
        const bool angle = i >= n - 1;  // the box's θ: no uniform part
        const double uniform = angle ? 0.0 : split.uniform[i % 2];
        QCOMPARE(uniform + rest[i], whole[i]);
    }
}

// A state near the top of the double range must be stepped with the frame start kept, and an
// overflow must restore it, whatever ran before.
void TestWorldInvariants::anOverflowRestoresTheLastGoodState() {
    SceneDesc scene;
    scene.simulation = simulation("symplectic_euler", 0.01);
    scene.effects.gravity = GravityDesc{{0.0, -9.81}};
    for (int i = 0; i < 5; ++i) {
        ParticleDesc p;
        p.position = {1.0 * i, 2.0};
        p.radius = 0.0;
        scene.particles.push_back(p);
    }
    auto world = build(scene);
    for (int k = 0; k < 10; ++k) QVERIFY(world->step());
    Eigen::VectorXd q = world->positions(), u = world->velocities();
    u[3] = 1e200;  // kinetic energy ½·m·v² overflows to infinity in the next frame's sums
    world->setState(q, u);
    const double t = world->time();
    QVERIFY(!world->step());
    QVERIFY(world->divergence().has_value());
    QCOMPARE(world->divergence()->objectId, std::string("p1"));
    QVERIFY(world->positions() == q && world->velocities() == u);
    QCOMPARE(world->time(), t);
    // Back to ordinary values, the world steps on.
    u[3] = 1.0;
    world->setState(q, u);
    for (int k = 0; k < 10; ++k) QVERIFY(world->step());
    QVERIFY(world->positions().allFinite() && world->velocities().allFinite());
}

// Switching the integrator between two steps changes nothing in the state, the clock or the
// ledger, whatever the pair of methods.
void TestWorldInvariants::switchingIntegratorKeepsState() {
    auto world = build(hangingBoxScene("rk4", 0.01));
    for (int i = 0; i < 10; ++i) QVERIFY(world->step());
    for (const char* from : kAllIntegrators) {
        for (const char* to : kAllIntegrators) {
            world->setIntegrator(from);
            QVERIFY(world->step());
            const Eigen::VectorXd q = world->positions(), u = world->velocities();
            const double t = world->time();
            const EnergyLedger ledger = world->energy();
            world->setIntegrator(to);
            QCOMPARE(std::string(world->integrator().info().name), std::string(to));
            QVERIFY2(world->positions() == q && world->velocities() == u,
                     qPrintable(QString("%1 → %2 changed the state").arg(from, to)));
            QCOMPARE(world->time(), t);
            QCOMPARE(world->energy().drift, ledger.drift);
            QCOMPARE(world->energy().workNc, ledger.workNc);
        }
    }
    QVERIFY(world->positions().allFinite());
}

// After a switch the next step is the new method's: from any state, one explicit Euler step of
// the oscillator is x' = x + h·v, v' = v − h·x (k = m = 1, rest length 0).
void TestWorldInvariants::switchedIntegratorTakesTheNextStep() {
    const double h = 0.05;
    auto world = build(oscillatorScene("rk4", h, {1.0, 0.0}, {0.0, 0.5}));
    for (int i = 0; i < 7; ++i) QVERIFY(world->step());
    world->setIntegrator("explicit_euler");
    const Eigen::VectorXd q = world->positions(), u = world->velocities();
    QVERIFY(world->step());
    const Eigen::VectorXd expectedQ = q + h * u;
    const Eigen::VectorXd expectedU = u - h * q;
    QVERIFY(world->positions() == expectedQ);
    QVERIFY((world->velocities() - expectedU).lpNorm<Eigen::Infinity>() < 1e-15);
    // And back: one symplectic Euler step, v' = v − h·x, x' = x + h·v'.
    world->setIntegrator("symplectic_euler");
    const Eigen::VectorXd q1 = world->positions(), u1 = world->velocities();
    QVERIFY(world->step());
    const Eigen::VectorXd v2 = u1 - h * q1;
    QVERIFY((world->velocities() - v2).lpNorm<Eigen::Infinity>() < 1e-15);
    QVERIFY((world->positions() - (q1 + h * v2)).lpNorm<Eigen::Infinity>() < 1e-15);
}

void TestWorldInvariants::substepsEqualFinerSteps_data() {
    QTest::addColumn<QString>("integrator");
    for (const char* name : kFixedStepIntegrators) QTest::newRow(name) << QString(name);
}

// A frame of dt in 4 sub-steps is the same computation as 4 frames of dt/4 (dt/4 is exact in
// binary), so the states agree bit for bit.
void TestWorldInvariants::substepsEqualFinerSteps() {
    QFETCH(QString, integrator);
    SceneDesc coarse = boxPairScene(integrator.toStdString(), 0.1, 0.3);
    coarse.simulation.substeps = 4;
    SceneDesc fine = boxPairScene(integrator.toStdString(), 0.025, 0.3);
    auto a = build(coarse);
    auto b = build(fine);
    for (int frame = 0; frame < 50; ++frame) {
        QVERIFY(a->step());
        for (int s = 0; s < 4; ++s) QVERIFY(b->step());
        QVERIFY2(clearance(*a) > 0.0, "the bodies came close enough to touch");
    }
    QVERIFY(a->positions() == b->positions());
    QVERIFY(a->velocities() == b->velocities());
    QCOMPARE(a->energy().workNc, b->energy().workNc);
    QVERIFY(std::abs(a->time() - 5.0) < 1e-12);
}

void TestWorldInvariants::forcesAreMinusPotentialGradient_data() {
    QTest::addColumn<QString>("scene");
    QTest::newRow("hanging box") << QString("hanging box");
    QTest::newRow("box pair") << QString("box pair");
    QTest::newRow("kepler") << QString("kepler");
    QTest::newRow("softened cluster") << QString("softened cluster");
}

// A conservative force is −∇U: the world's generalised forces (forces on x, y and the torque on
// θ) at zero velocity against central differences of its own potential energy. A torque with
// the wrong sign or arm fails this even where total energy happens to look fine.
void TestWorldInvariants::forcesAreMinusPotentialGradient() {
    QFETCH(QString, scene);
    std::unique_ptr<World> world;
    if (scene == "hanging box")
        world = build(hangingBoxScene("rk4", 0.01));
    else if (scene == "box pair")
        world = build(boxPairScene("rk4", 0.01, 0.0));
    else if (scene == "kepler")
        world = build(keplerScene("rk4", 0.01, 0.5));
    else
        world = build(softenedClusterScene("rk4", 0.01));
    // Move off the set-up state so that nothing sits at a special point.
    for (int i = 0; i < 25; ++i) QVERIFY(world->step());
    const Eigen::VectorXd q = world->positions();
    const Eigen::VectorXd zero = Eigen::VectorXd::Zero(q.size());
    const int n = static_cast<int>(q.size());
    Eigen::VectorXd force(n);
    world->forces(world->time(), q, zero, force);
    for (int j = 0; j < n; ++j) {
        const double delta = 1e-6;
        Eigen::VectorXd qp = q, qm = q;
        qp[j] += delta;
        qm[j] -= delta;
        world->setState(qp, zero);
        const double up = world->potentialEnergy();
        world->setState(qm, zero);
        const double um = world->potentialEnergy();
        const double gradient = (up - um) / (2.0 * delta);
        QVERIFY2(std::abs(force[j] + gradient) <= 1e-6 * (1.0 + std::abs(force[j])),
                 qPrintable(QString("dof %1 (%2): force %3, −dU/dq %4")
                                .arg(j)
                                .arg(world->objectAtDof(j).c_str())
                                .arg(force[j], 0, 'g', 12)
                                .arg(-gradient, 0, 'g', 12)));
    }
}

void TestWorldInvariants::jacobiansMatchFiniteDifferences_data() {
    QTest::addColumn<QString>("scene");
    QTest::addColumn<bool>("checkStiffness");
    // With spring damping the stiffness matrix deliberately leaves out the damping force's
    // dependence on the spring direction (Baraff & Witkin; documented in SpringEffect.cpp), so
    // only the damping matrix is compared there.
    QTest::newRow("hanging box") << QString("hanging box") << true;
    QTest::newRow("box pair") << QString("box pair") << true;
    QTest::newRow("box pair damped") << QString("box pair damped") << false;
    QTest::newRow("kepler") << QString("kepler") << true;
    QTest::newRow("softened cluster") << QString("softened cluster") << true;
    QTest::newRow("drag") << QString("drag") << true;
}

// K = ∂F/∂q and D = ∂F/∂u, which the implicit methods rely on, against central differences of
// the forces.
void TestWorldInvariants::jacobiansMatchFiniteDifferences() {
    QFETCH(QString, scene);
    QFETCH(bool, checkStiffness);
    std::unique_ptr<World> world;
    if (scene == "hanging box") {
        world = build(hangingBoxScene("rk4", 0.01));
    } else if (scene == "box pair" || scene == "box pair damped") {
        world = build(boxPairScene("rk4", 0.01, scene == "box pair" ? 0.0 : 0.8));
    } else if (scene == "kepler") {
        world = build(keplerScene("rk4", 0.01, 0.5));
    } else if (scene == "softened cluster") {
        world = build(softenedClusterScene("rk4", 0.01));
    } else {
        SceneDesc desc = boxPairScene("rk4", 0.01, 0.0);
        desc.effects.gravity = GravityDesc{};
        desc.effects.drag = DragDesc{0.4, 0.25, 0.3};
        world = build(desc);
    }
    for (int i = 0; i < 25; ++i) QVERIFY(world->step());
    const Eigen::VectorXd q = world->positions(), u = world->velocities();
    const int n = static_cast<int>(q.size());
    const double t = world->time();
    ForceJacobians jac;
    Eigen::VectorXd force(n);
    world->forcesAndJacobians(t, q, u, force, jac);
    const Eigen::MatrixXd K = dense(jac.stiffnessTriplets(), n),
                          D = dense(jac.dampingTriplets(), n);
    Eigen::MatrixXd numK(n, n), numD(n, n);
    Eigen::VectorXd fp(n), fm(n);
    const double delta = 1e-6;
    for (int j = 0; j < n; ++j) {
        Eigen::VectorXd qp = q, qm = q, up = u, um = u;
        qp[j] += delta;
        qm[j] -= delta;
        world->forces(t, qp, u, fp);
        world->forces(t, qm, u, fm);
        numK.col(j) = (fp - fm) / (2.0 * delta);
        up[j] += delta;
        um[j] -= delta;
        world->forces(t, q, up, fp);
        world->forces(t, q, um, fm);
        numD.col(j) = (fp - fm) / (2.0 * delta);
    }
    const double tolK = 1e-6 * (1.0 + numK.lpNorm<Eigen::Infinity>());
    const double tolD = 1e-6 * (1.0 + numD.lpNorm<Eigen::Infinity>());
    if (checkStiffness) {
        const double dk = (K - numK).lpNorm<Eigen::Infinity>();
        QVERIFY2(dk <= tolK, qPrintable(QString("|K − ∂F/∂q| = %1").arg(dk)));
    }
    const double dd = (D - numD).lpNorm<Eigen::Infinity>();
    QVERIFY2(dd <= tolD, qPrintable(QString("|D − ∂F/∂u| = %1").arg(dd)));
    // Something was actually differentiated.
    QVERIFY(numK.lpNorm<Eigen::Infinity>() > 0.1 || numD.lpNorm<Eigen::Infinity>() > 0.1);
}

// A box on an off-centre spring under gravity, rk4 at a small step: kinetic energy (½m·v² and
// ½I·ω²) plus spring and gravity potential stays constant to rk4's tiny error, which needs the
// torque of the spring about the box centre to be right.
void TestWorldInvariants::springOnBoxConservesEnergy() {
    auto world = build(hangingBoxScene("rk4", 0.001));
    const double e0 = mechanicalEnergy(*world);
    const double inertia = world->mass()[2];
    QCOMPARE(inertia, 2.0 * (1.0 + 0.25) / 12.0);
    double scale = std::abs(world->energy().kinetic) + std::abs(world->energy().potential);
    double worst = 0.0, maxRotational = 0.0, minAngle = 1e9, maxAngle = -1e9;
    for (int n = 0; n < 5000; ++n) {
        QVERIFY(world->step());
        worst = std::max(worst, std::abs(mechanicalEnergy(*world) - e0));
        const double w = world->velocities()[2], angle = world->positions()[2];
        maxRotational = std::max(maxRotational, 0.5 * inertia * w * w);
        minAngle = std::min(minAngle, angle);
        maxAngle = std::max(maxAngle, angle);
        scale = std::max(scale, world->energy().kinetic);
    }
    // The torque path was exercised: the box turned through a large angle and a good share of
    // the kinetic energy was rotational.
    QVERIFY2(maxAngle - minAngle > 1.0,
             qPrintable(QString("angle range %1").arg(maxAngle - minAngle)));
    QVERIFY(maxRotational > 0.05 * scale);
    QVERIFY2(worst <= 1e-8 * scale,
             qPrintable(QString("max |E − E0| = %1 (scale %2)").arg(worst).arg(scale)));
    QVERIFY(std::abs(world->energy().drift) <= 1e-8 * scale);
}

void TestWorldInvariants::springsConserveMomenta_data() {
    QTest::addColumn<QString>("integrator");
    QTest::addColumn<double>("damping");
    for (const char* name : kFixedStepIntegrators) {
        QTest::newRow(name) << QString(name) << 0.0;
        QTest::newRow(qPrintable(QString("%1 damped").arg(name))) << QString(name) << 0.5;
    }
}

// Spring forces between bodies are equal and opposite, so total momentum is conserved. Every
// Runge–Kutta-type method preserves linear invariants exactly, and the implicit solves do too
// (the Newton correction is a linear solve whose momentum change is zero), so momentum must
// hold to round-off for every method, damped springs included.
// The forces are also central (along the line between the attachment points), so angular
// momentum Σ m·x×v + Σ I·ω is conserved. It is a quadratic invariant of the form qᵀ·S·u with a
// constant mass matrix: symplectic Euler (L' = Σ m·x×v' = L + h·(total torque) = L), velocity
// Verlet and the implicit midpoint rule keep it to round-off; rk4 at this step keeps it to its
// truncation error.
void TestWorldInvariants::springsConserveMomenta() {
    QFETCH(QString, integrator);
    QFETCH(double, damping);
    auto world = build(boxPairScene(integrator.toStdString(), 0.002, damping));
    const Eigen::Vector3d p0 = momenta(*world);
    const double gap0 = (world->bodyPosition(1) - world->bodyPosition(0)).norm();
    double gapChange = 0.0;
    for (int n = 0; n < 2000; ++n) {
        QVERIFY(world->step());
        QVERIFY2(clearance(*world) > 0.0, "the bodies came close enough to touch");
        gapChange = std::max(
            gapChange, std::abs((world->bodyPosition(1) - world->bodyPosition(0)).norm() - gap0));
    }
    const Eigen::Vector3d p = momenta(*world);
    QVERIFY2(
        (p - p0).head<2>().lpNorm<Eigen::Infinity>() <= 1e-12,
        qPrintable(QString("momentum moved by (%1, %2)").arg(p.x() - p0.x()).arg(p.y() - p0.y())));
    double angularTolerance = -1.0;
    if (integrator == "symplectic_euler" || integrator == "velocity_verlet" ||
        integrator == "implicit_midpoint")
        angularTolerance = 1e-12;
    else if (integrator == "rk4")
        angularTolerance = 1e-9;
    if (angularTolerance > 0.0)
        QVERIFY2(std::abs(p.z() - p0.z()) <= angularTolerance,
                 qPrintable(QString("angular momentum moved by %1").arg(p.z() - p0.z())));
    // The bodies did move relative to each other.
    QVERIFY2(gapChange > 0.05, qPrintable(QString("gap changed by %1 only").arg(gapChange)));
}

// A particle on a circle of radius 1 about G·M = 1 (here G = 2, M = 0.5, and a particle of
// mass 3, which must not matter) has speed 1 and period 2π.
void TestWorldInvariants::circularOrbitPeriod() {
    SceneDesc scene;
    scene.simulation = simulation("rk4", 2.0 * kPi / 1000.0);
    NewtonianGravityDesc ng;
    ng.G = 2.0;
    ng.attractors.push_back({{0.0, 0.0}, 0.5});
    scene.effects.newtonianGravity = ng;
    ParticleDesc p;
    p.id = "moon";
    p.position = {1.0, 0.0};
    p.velocity = {0.0, 1.0};
    p.mass = 3.0;
    p.radius = 0.0;
    scene.particles.push_back(p);
    auto world = build(scene);
    // Potential −G·M·m/r = −3 J, kinetic ½·3·1² = 1.5 J.
    QCOMPARE(world->energy().potential, -3.0);
    QCOMPARE(world->energy().kinetic, 1.5);
    for (int n = 1; n <= 1000; ++n) {
        QVERIFY(world->step());
        const double t = world->time();
        const Eigen::Vector2d x(world->positions()[0], world->positions()[1]);
        QVERIFY2(std::abs(x.norm() - 1.0) <= 1e-9,
                 qPrintable(QString("t=%1: r=%2").arg(t).arg(x.norm())));
        QVERIFY2((x - Eigen::Vector2d(std::cos(t), std::sin(t))).norm() <= 1e-9,
                 qPrintable(QString("t=%1: off the exact position by %2")
                                .arg(t)
                                .arg((x - Eigen::Vector2d(std::cos(t), std::sin(t))).norm())));
    }
    // One period later it is back where it started, moving the same way.
    QVERIFY(std::abs(world->time() - 2.0 * kPi) < 1e-12);
    QVERIFY(std::abs(world->positions()[0] - 1.0) < 1e-9 && std::abs(world->positions()[1]) < 1e-9);
    QVERIFY(std::abs(world->velocities()[0]) < 1e-9 &&
            std::abs(world->velocities()[1] - 1.0) < 1e-9);
}

// Two bodies under mutual gravity only (no attractor): G = 1, masses 1 and 3 at distance 1 on
// circular orbits about their centre of mass, which needs ω² = G·(m₁ + m₂)/d³ = 4. Each body
// turns rigidly about the origin at ω = 2 (period π), and the centre of mass stays put.
void TestWorldInvariants::mutualGravityBinaryOrbit() {
    SceneDesc scene;
    scene.simulation = simulation("rk4", kPi / 1000.0);
    NewtonianGravityDesc ng;
    ng.G = 1.0;
    ng.mutual = true;
    scene.effects.newtonianGravity = ng;
    ParticleDesc light, heavy;
    light.position = {-0.75, 0.0};
    light.velocity = {0.0, -1.5};
    light.mass = 1.0;
    light.radius = 0.0;
    heavy.position = {0.25, 0.0};
    heavy.velocity = {0.0, 0.5};
    heavy.mass = 3.0;
    heavy.radius = 0.0;
    scene.particles = {light, heavy};
    auto world = build(scene);
    QCOMPARE(world->energy().potential, -3.0);
    for (int n = 1; n <= 1000; ++n) {
        QVERIFY(world->step());
        const double angle = 2.0 * world->time();
        const Eigen::Vector2d dir(std::cos(angle), std::sin(angle));
        const Eigen::VectorXd& q = world->positions();
        const double e1 = (q.segment<2>(0) + 0.75 * dir).norm();
        const double e2 = (q.segment<2>(2) - 0.25 * dir).norm();
        QVERIFY2(std::max(e1, e2) <= 1e-9, qPrintable(QString("t=%1: off the exact orbit by %2")
                                                          .arg(world->time())
                                                          .arg(std::max(e1, e2))));
        const Eigen::Vector2d centre = (q.segment<2>(0) + 3.0 * q.segment<2>(2)) / 4.0;
        QVERIFY(centre.norm() <= 1e-13);
    }
}

// "Only what is listed is simulated": the world holds exactly the scene's effects, plus the
// spring effect exactly when there are springs (cloths bring springs of their own).
void TestWorldInvariants::onlyListedEffectsAreConstructed() {
    using Names = std::vector<std::string>;
    SceneDesc bare;
    bare.particles.push_back(ParticleDesc{});
    QCOMPARE(effectNames(*build(bare)), Names{});

    SceneDesc gravityOnly = bare;
    gravityOnly.effects.gravity = GravityDesc{};
    QCOMPARE(effectNames(*build(gravityOnly)), Names{"gravity"});

    SceneDesc springsOnly = oscillatorScene("rk4", 0.01, {1.0, 0.0}, {0.0, 0.0});
    QCOMPARE(effectNames(*build(springsOnly)), Names{"springs"});

    SceneDesc all = boxPairScene("rk4", 0.01, 0.1);
    all.effects.gravity = GravityDesc{};
    all.effects.drag = DragDesc{0.1, 0.0, 0.0};
    all.effects.newtonianGravity = NewtonianGravityDesc{};
    all.effects.wind = WindDesc{{1.0, 0.0}, 0.2};
    QCOMPARE(effectNames(*build(all)),
             (Names{"drag", "gravity", "newtonian_gravity", "springs", "wind"}));

    SceneDesc dragNoSprings = bare;
    dragNoSprings.effects.drag = DragDesc{0.1, 0.0, 0.0};
    auto world = build(dragNoSprings);
    QCOMPARE(effectNames(*world), Names{"drag"});
    QVERIFY(world->findEffect("gravity") == nullptr);
    QVERIFY(world->findEffect("springs") == nullptr);
    QVERIFY(world->findEffect("drag") != nullptr);

    SceneDesc cloth = bare;
    ClothDesc c;
    c.id = "flag";
    c.resolution = {3, 3};
    cloth.cloths.push_back(c);
    QCOMPARE(effectNames(*build(cloth)), Names{"springs"});
}

// CONTRACT §2: a step diverges when |drift| exceeds 10³·E₀, and the state goes back to the start
// of the last step at which it was still within E₀. Explicit Euler multiplies an oscillator's
// energy by exactly 1 + (ω·h)² per step, so both steps follow in closed form.
void TestWorldInvariants::runawayDriftDivergesAsTheContractSays() {
    const double h = 0.7;
    auto world = build(oscillatorScene("explicit_euler", h, {1.0, 0.0}, {0.0, 0.0}));
    const double energy = 0.5;        // ½·k·x², k = m = 1
    const double scale = 2 * energy;  // E₀: the energy plus ½·m·(1 m/s)²
    QCOMPARE(world->divergenceScale(), scale);
    const auto drift = [&](int n) { return energy * (std::pow(1.0 + h * h, n) - 1.0); };
    int diverges = 1, restored = 0;
    while (!(drift(diverges) > 1e3 * scale)) ++diverges;
    while (drift(restored + 1) <= scale) ++restored;
    QCOMPARE(diverges, 20);
    QCOMPARE(restored, 2);
    int accepted = 0;
    while (world->step()) QVERIFY(++accepted < 100);
    QCOMPARE(accepted, diverges - 1);
    QVERIFY(world->divergence().has_value());
    QVERIFY(std::abs(world->divergence()->time - diverges * h) < 1e-9);
    QVERIFY(std::abs(world->divergence()->restoredTime - restored * h) < 1e-9);
    QVERIFY(std::abs(world->time() - restored * h) < 1e-9);
    QVERIFY(std::abs(world->energy().drift - drift(restored)) <= 1e-12);
}

// Energy a solver creates runs away like an integrator's: correction above 10³·E₀ diverges at
// the first step that puts it there, back to the start of the last step within E₀.
void TestWorldInvariants::runawayCorrectionDivergesAtItsFirstStep() {
    DivergenceGuard guard;
    guard.setEnergyScale(2.0);
    const Eigen::VectorXd q = Eigen::VectorXd::Zero(2), u = Eigen::VectorXd::Zero(2);
    SimulationClock clock;
    EnergyLedger ledger;
    const auto frame = [&](double correction) {
        guard.beginFrame(clock, ledger, q, u, true);
        ++clock.stepCount;
        clock.time += 0.1;
        ledger.correction = correction;
        return guard.judge(ledger, q, u);
    };
    using Verdict = DivergenceGuard::Verdict;
    QCOMPARE(frame(1.0), Verdict::Good);  // within E₀
    QCOMPARE(frame(5.0), Verdict::Good);  // beyond E₀: this frame's start is the last good one
    QCOMPARE(guard.runawayStart().clock.stepCount, 1);
    QCOMPARE(frame(1500.0), Verdict::Good);                  // 750·E₀
    QCOMPARE(frame(-2500.0), Verdict::RestoreRunawayStart);  // |correction| counts
    QCOMPARE(guard.runawayStart().clock.stepCount, 1);
    guard.forgetGrowth();
    QCOMPARE(frame(-2.5e6), Verdict::RestoreRunawayStart);  // at once, from a good start
    QCOMPARE(guard.runawayStart().clock.stepCount, 4);
    // Physical work put in raises E₀: the wind's energy is not the method's.
    guard.setEnergyScale(2.0);
    ledger.workNc = 0.0;
    guard.beginFrame(clock, ledger, q, u, true);
    ledger.workNc = 1e4;
    ledger.correction = 5e6;
    QCOMPARE(guard.judge(ledger, q, u), Verdict::Good);
    QCOMPARE(guard.divergenceScale(), 2.0 + 1e4);
}

QTEST_APPLESS_MAIN(TestWorldInvariants)
#include "tst_world_invariants.moc"
