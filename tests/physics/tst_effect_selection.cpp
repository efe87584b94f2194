// "Only what the scene calls for runs" (DESIGN.md, CONTRACT.md §1): a gravity-only scene holds
// exactly one effect and no contact stage; the first spring switches the spring effect on and
// the first box the contacts, and a world built without them has neither; each effect of
// issue #7 exists exactly when the scene calls for it; an effect that is not in the world is
// never called, and the cost table lists only what is there. And the new effects step without
// touching the heap once warmed up.

#include "PhysicsTestSupport.h"

#include "../bench/AllocationCounter.h"
#include "physics/contacts/ContactStage.h"
#include "physics/effects/NewtonianGravityEffect.h"

#include <QTest>

#include <algorithm>

using namespace phasebox;
using namespace phasebox::testing;

namespace {

using Names = std::vector<std::string>;

Names effectNames(const World& world) {
    Names names;
    for (const auto& e : world.effects()) names.push_back(e->name());
    return names;
}

Names costNames(const World& world) {
    Names names;
    for (const EffectCost& c : world.effectCosts()) names.push_back(c.name);
    return names;
}

ParticleDesc particle(Point2 position, double radius = 0.0, double charge = 0.0) {
    ParticleDesc p;
    p.position = position;
    p.radius = radius;
    p.charge = charge;
    return p;
}

SceneDesc gravityOnly() {
    SceneDesc scene;
    scene.effects.gravity = GravityDesc{};
    for (int i = 0; i < 3; ++i) scene.particles.push_back(particle({1.0 * i, 0.0}, 0.05));
    return scene;
}

// An effect that counts how often the world calls it.
class CountingEffect final : public Effect {
public:
    CountingEffect() : Effect("counting") {}
    double addForces(double, const Vec&, const Vec&, Vec&) override {
        ++calls;
        return 0.0;
    }
    double potentialEnergy(const Vec&) const override {
        ++calls;
        return 0.0;
    }
    mutable int calls = 0;
};

}  // namespace

class TestEffectSelection : public QObject {
    Q_OBJECT

private slots:
    void gravityOnlySceneHasOneEffectAndNoContacts();
    void firstSpringSwitchesSpringsOnAndRebuildingWithoutSwitchesThemOff();
    void firstBoxSwitchesContactsOnAndRebuildingWithoutSwitchesThemOff();
    void newEffectsExistExactlyWhenCalledFor();
    void buoyancyWithoutGravityIsRefused();
    void absentEffectIsNeverCalled();
    void newEffectsStepWithoutAllocating_data();
    void newEffectsStepWithoutAllocating();
};

void TestEffectSelection::gravityOnlySceneHasOneEffectAndNoContacts() {
    auto world = build(gravityOnly());
    QCOMPARE(world->effects().size(), std::size_t(1));
    QCOMPARE(effectNames(*world), Names{"gravity"});
    // Disks alone, without particle_collisions, planes or boxes, have nothing to touch.
    QVERIFY(world->contacts() == nullptr);
    for (int n = 0; n < 10; ++n) QVERIFY(world->step());
    QCOMPARE(costNames(*world), Names{"gravity"});
}

void TestEffectSelection::firstSpringSwitchesSpringsOnAndRebuildingWithoutSwitchesThemOff() {
    const SceneDesc scene = gravityOnly();
    auto world = build(scene);
    QVERIFY(world->findEffect("springs") == nullptr);
    Spring s;
    s.a = {SpringEnd::Kind::Particle, 0, Eigen::Vector2d::Zero()};
    s.b = {SpringEnd::Kind::Particle, 1, Eigen::Vector2d::Zero()};
    s.stiffness = 10.0;
    s.restLength = 1.0;
    world->addSpring(s);
    world->commit();
    QCOMPARE(effectNames(*world), (Names{"gravity", "springs"}));
    QVERIFY(world->step());
    QCOMPARE(costNames(*world), (Names{"gravity", "springs"}));
    // The scene without the spring: the world built from it has no spring effect.
    auto rebuilt = build(scene);
    QCOMPARE(effectNames(*rebuilt), Names{"gravity"});
}

void TestEffectSelection::firstBoxSwitchesContactsOnAndRebuildingWithoutSwitchesThemOff() {
    SceneDesc scene = gravityOnly();
    PlaneDesc ground;
    ground.point = {0.0, -2.0};
    for (ParticleDesc& p : scene.particles) p.radius = 0.0;  // points never touch anything
    scene.planes.push_back(ground);
    auto world = build(scene);
    QVERIFY(world->contacts() == nullptr);
    RigidBody box;
    box.id = "crate";
    box.position = {0.0, 0.0};
    world->addRigidBody(box);
    world->commit();
    QVERIFY(world->contacts() != nullptr);
    for (int n = 0; n < 5; ++n) QVERIFY(world->step());
    QCOMPARE(costNames(*world).back(), std::string("contacts"));
    // Rebuilt from the scene (no box): the contact stage is gone, and costs nothing.
    auto rebuilt = build(scene);
    QVERIFY(rebuilt->contacts() == nullptr);
    QVERIFY(rebuilt->step());
    QCOMPARE(costNames(*rebuilt), Names{"gravity"});
}

// Buoyancy and flocking exist when listed; Coulomb's law when two particles carry a charge and
// one of them can move, whether or not effects.coulomb sets its constants.
void TestEffectSelection::newEffectsExistExactlyWhenCalledFor() {
    SceneDesc scene = gravityOnly();
    scene.effects.buoyancy = BuoyancyDesc{};
    scene.effects.flocking = FlockingDesc{};
    scene.effects.wind = WindDesc{{1.0, 0.0}, 0.1};
    const BuildResult built = buildWorld(scene);
    QVERIFY(built.unsupported.empty());
    QCOMPARE(effectNames(*built.world), (Names{"gravity", "buoyancy", "wind", "flocking"}));

    SceneDesc charged = gravityOnly();
    QVERIFY(build(charged)->findEffect("coulomb") == nullptr);
    charged.effects.coulomb = CoulombDesc{};  // constants alone call for nothing
    QVERIFY(build(charged)->findEffect("coulomb") == nullptr);
    charged.particles[0].charge = 1e-6;
    QVERIFY(build(charged)->findEffect("coulomb") == nullptr);  // one charge feels nothing
    charged.particles[1].charge = -1e-6;
    QCOMPARE(effectNames(*build(charged)), (Names{"gravity", "coulomb"}));
    charged.particles[0].pinned = charged.particles[1].pinned = true;
    QVERIFY(build(charged)->findEffect("coulomb") == nullptr);  // nothing that can move
    charged.particles[1].pinned = false;
    charged.effects.coulomb.reset();
    QVERIFY(build(charged)->findEffect("coulomb") != nullptr);  // a free charge near a fixed one
}

void TestEffectSelection::buoyancyWithoutGravityIsRefused() {
    SceneDesc scene;
    scene.effects.buoyancy = BuoyancyDesc{};
    const std::vector<SceneIssue> issues = validateScene(scene);
    QCOMPARE(issues.size(), std::size_t(1));
    QCOMPARE(issues[0].path, std::string("effects.buoyancy"));
    QVERIFY(issues[0].message.find("gravity") != std::string::npos);
    QVERIFY_THROWS_EXCEPTION(SceneError, buildWorld(scene));
}

// An effect taken out of the world is not called again, by any path: forces, the ledger's
// potential, the implicit methods' Jacobians. And the cost table lists only what is there.
void TestEffectSelection::absentEffectIsNeverCalled() {
    for (const char* integrator : {"symplectic_euler", "rk4", "implicit_euler"}) {
        SceneDesc scene = gravityOnly();
        scene.simulation.integrator = integrator;
        auto world = build(scene);
        auto owned = std::make_unique<CountingEffect>();
        CountingEffect* counting = owned.get();
        world->addEffect(std::move(owned));
        for (int n = 0; n < 3; ++n) QVERIFY(world->step());
        QVERIFY(counting->calls > 0);
        QCOMPARE(costNames(*world), (Names{"gravity", "counting"}));
        std::unique_ptr<Effect> removed = world->removeEffect(counting);
        QVERIFY(removed.get() == counting);
        const int before = counting->calls;
        for (int n = 0; n < 10; ++n) QVERIFY(world->step());
        QCOMPARE(counting->calls, before);
        QCOMPARE(costNames(*world), Names{"gravity"});
    }
}

void TestEffectSelection::newEffectsStepWithoutAllocating_data() {
    QTest::addColumn<QString>("effect");
    QTest::addColumn<QString>("integrator");
    // "jacobians" evaluates the forces and Jacobians as the implicit methods do, without their
    // linear solve (which is not an effect's, and allocates on its own: 5 times per step).
    for (const char* effect : {"buoyancy", "flocking", "coulomb", "barnes_hut"})
        for (const char* integrator : {"symplectic_euler", "rk4", "jacobians"})
            QTest::newRow(qPrintable(QString("%1 %2").arg(effect, integrator)))
                << QString(effect) << QString(integrator);
}

// After warm-up steps (buffers grow to the scene's size once) a step allocates nothing.
void TestEffectSelection::newEffectsStepWithoutAllocating() {
    QFETCH(QString, effect);
    QFETCH(QString, integrator);
    const bool jacobians = integrator == "jacobians";
    SceneDesc scene;
    scene.simulation = simulation(jacobians ? "rk4" : integrator.toStdString(), 0.01);
    const int count = effect == "barnes_hut" ? 1200 : 60;
    for (int i = 0; i < count; ++i)
        scene.particles.push_back(particle({0.3 * (i % 30), 0.3 * (i / 30) - 0.5}, 0.1,
                                           effect == "coulomb" ? 1e-7 * (i % 2 ? 1 : -1) : 0.0));
    if (effect == "buoyancy") {
        scene.effects.gravity = GravityDesc{};
        scene.effects.buoyancy = BuoyancyDesc{1000.0, 0.0, 5.0};
        BoxDesc box;
        box.position = {2.0, 0.0};
        box.size = {1.0, 0.5};
        box.density = 500.0;
        box.angle = 0.3;
        scene.boxes.push_back(box);
        for (ParticleDesc& p : scene.particles) p.mass = 20.0;
    } else if (effect == "flocking") {
        scene.effects.flocking = FlockingDesc{};
    } else if (effect == "barnes_hut") {
        NewtonianGravityDesc ng;
        ng.G = 1e-3;
        ng.mutual = true;
        ng.softening = 0.1;
        scene.effects.newtonianGravity = ng;
    }
    auto world = build(scene);
    const Eigen::VectorXd q = world->positions(), u = world->velocities();
    Eigen::VectorXd force(q.size());
    ForceJacobians jac;
    const auto run = [&] {
        if (!jacobians) return world->step();
        jac.clear();
        world->forcesAndJacobians(0.0, q, u, force, jac);
        return true;
    };
    // Warm-up: the buoyancy scene starts with particles inside the floating box, and deep
    // overlap is pushed out a little each step (ContactSolver::deepPushOut), so its contact
    // set keeps growing for about 25 steps before the buffers have their size.
    for (int n = 0; n < 30; ++n) QVERIFY(run());
    bench::startCountingAllocations();
    bool ok = true;
    for (int n = 0; n < 10; ++n) ok = run() && ok;
    const bench::AllocationCounts counts = bench::stopCountingAllocations();
    QVERIFY(ok);
    if (effect == "barnes_hut")
        QVERIFY(static_cast<const NewtonianGravityEffect*>(world->findEffect("newtonian_gravity"))
                    ->usesTree());
    QVERIFY2(counts.total() == 0,
             qPrintable(QString("%1 allocations (%2 new, %3 malloc) in 10 steps")
                            .arg(counts.total())
                            .arg(counts.operatorNew)
                            .arg(counts.malloc)));
}

QTEST_APPLESS_MAIN(TestEffectSelection)
#include "tst_effect_selection.moc"
