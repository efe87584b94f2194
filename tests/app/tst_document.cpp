// The document and its commands: every kind of edit reaches the setup and the live world,
// undo and redo restore the setup byte for byte (as SceneIO writes it), drags and property
// edits merge, invalid edits are refused with validateScene's words, effects switch off and
// on with their parameters, and files load and save safely. (Edits during a run are in
// tst_controller, next to the controller that runs it.)

#include "app/document/Commands.h"
#include "app/document/Document.h"
#include "app/document/ObjectClipboard.h"
#include "app/document/PropertyTable.h"
#include "app/io/SceneIO.h"
#include "physics/world/World.h"
#include "tests/support/SceneBuilders.h"

#include <QFile>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <numbers>

#include <cmath>

using namespace phasebox;
using testing::anchorSpring;
using testing::bodySpring;

namespace {

QByteArray bytes(const Document& doc) {
    return SceneIO::serialize(doc.setup());
}

ParticleDesc particle(double x, double y, const std::string& id = {}) {
    ParticleDesc p;
    p.id = id;
    p.position = {x, y};
    return p;
}

// Two particles on springs under gravity: something that moves.
SceneDesc pendulumScene() {
    SceneDesc s;
    s.name = "two pendulums";
    s.simulation.dt = 0.01;
    s.effects.gravity = GravityDesc{};
    s.particles = {particle(1.0, 0.0, "a"), particle(-1.0, 0.5, "b")};
    s.particles[1].velocity = {0.3, 0.0};
    s.springs = {anchorSpring("a", {0.0, 0.0}, 50.0), anchorSpring("b", {0.0, 0.0}, 30.0)};
    return s;
}

void run(Document& doc, int steps) {
    for (int i = 0; i < steps; ++i) QVERIFY(doc.world().step());
}

int particleIndex(const World& world, const std::string& id) {
    for (int i = 0; i < static_cast<int>(world.particles().size()); ++i)
        if (world.particles()[i].id == id) return i;
    return -1;
}

}  // namespace

class TestDocument : public QObject {
    Q_OBJECT

private slots:
    void addEveryKindOfObject();
    void generatedIdsSkipUsedOnes();
    void undoRedoRestoresTheExactSetup();
    void consecutiveMovesMergeIntoOneStep();
    void deletingAParticleDeletesItsSprings();
    void deletingAClothDeletesSpringsToItsNodes();
    void setPropertyRefusesInvalidValues();
    void setPropertyMergesAndReachesTheWorld();
    void setPinnedTogglesParticleAndBox();
    void propertyTableDescribesEachKind();
    void simulationEditsMergePerField();
    void effectOffRemovesItAndOnRestoresParameters();
    void loadingABadFileChangesNothing();
    void saveThenLoadRoundTrips();
    void modifiedFollowsTheUndoStack();
    void defaultIdsAreWrittenOnLoad();
    void selectionIsPrunedByDeletes();
    void disksAreEditedLikeBoxes();
    void copiesKeepTheirSpringsAndPasteUnderFreshIds();
};

void TestDocument::addEveryKindOfObject() {
    Document doc;
    QVERIFY(doc.loadFromDesc(SceneDesc{}));
    QSignalSpy edited(&doc, &Document::sceneEdited);

    QString id;
    QVERIFY(doc.addObject(particle(1.0, 0.0), nullptr, &id));
    QCOMPARE(id, QStringLiteral("p0"));
    QCOMPARE(doc.setup().particles.size(), std::size_t(1));
    QCOMPARE(doc.world().particles().size(), std::size_t(1));
    QCOMPARE(doc.world().particles()[0].id, std::string("p0"));

    QVERIFY(doc.addObject(anchorSpring("p0", {0.0, 0.0}, 10.0), nullptr, &id));
    QCOMPARE(id, QStringLiteral("s0"));
    QCOMPARE(doc.world().springs().size(), std::size_t(1));
    QVERIFY(doc.world().findEffect("springs") != nullptr);

    BoxDesc box;
    box.position = {0.0, 2.0};
    box.size = {0.5, 0.25};
    QVERIFY(doc.addObject(box, nullptr, &id));
    QCOMPARE(id, QStringLiteral("b0"));
    QCOMPARE(doc.world().rigidBodies().size(), std::size_t(1));

    PlaneDesc floor;
    floor.point = {0.0, -1.0};
    QVERIFY(doc.addObject(floor, nullptr, &id));
    QCOMPARE(id, QStringLiteral("plane0"));
    QCOMPARE(doc.world().planes().size(), std::size_t(1));

    ClothDesc cloth;
    cloth.resolution = {3, 4};
    cloth.origin = {2.0, 2.0};
    QVERIFY(doc.addObject(cloth, nullptr, &id));
    QCOMPARE(id, QStringLiteral("cloth0"));
    QCOMPARE(doc.world().cloths().size(), std::size_t(1));
    QCOMPARE(doc.world().particles().size(), std::size_t(1 + 12));
    QVERIFY(particleIndex(doc.world(), "cloth0[2,3]") >= 0);

    QCOMPARE(edited.count(), 5);
    QCOMPARE(doc.undoStack()->count(), 5);
    QCOMPARE(doc.undoStack()->text(0), QStringLiteral("Add particle p0"));

    // A spring to an unknown body is refused with the validator's message.
    QString error;
    QVERIFY(!doc.addObject(anchorSpring("q7", {0.0, 0.0}, 1.0), &error));
    QVERIFY2(error.contains(QStringLiteral("unknown object id \"q7\"")), qPrintable(error));
    QCOMPARE(doc.undoStack()->count(), 5);
}

void TestDocument::generatedIdsSkipUsedOnes() {
    Document doc;
    SceneDesc s;
    s.particles = {particle(0, 0, "p0"), particle(1, 0, "p1"), particle(2, 0, "p3")};
    QVERIFY(doc.loadFromDesc(s));
    QString id;
    QVERIFY(doc.addObject(particle(0, 1), nullptr, &id));
    QCOMPARE(id, QStringLiteral("p2"));
    QVERIFY(doc.addObject(particle(0, 2), nullptr, &id));
    QCOMPARE(id, QStringLiteral("p4"));
    // An explicit id that is taken is refused.
    QString error;
    QVERIFY(!doc.addObject(particle(0, 3, "p1"), &error));
    QVERIFY2(error.contains(QStringLiteral("duplicate id \"p1\"")), qPrintable(error));
}

void TestDocument::undoRedoRestoresTheExactSetup() {
    Document doc;
    QVERIFY(doc.loadFromDesc(pendulumScene()));
    QList<QByteArray> states{bytes(doc)};
    auto step = [&](bool ok) {
        QVERIFY(ok);
        states << bytes(doc);
    };
    step(doc.addObject(particle(0.5, 0.5)));
    step(doc.addObject(bodySpring("a", "p0", 20.0)));
    step(doc.moveObject(QStringLiteral("b"), {-2.0, 1.0}));
    step(doc.setProperty(QStringLiteral("a"), QStringLiteral("mass"), 2.5));
    step(doc.setPinned(QStringLiteral("p0"), true));
    step(doc.deleteObjects({QStringLiteral("a")}));
    SimulationDesc sim = doc.setup().simulation;
    sim.integrator = "rk4";
    step(doc.applySimulationSettings(sim));
    step(doc.setEffectEnabled(QStringLiteral("gravity"), false));
    QCOMPARE(doc.undoStack()->count(), states.size() - 1);

    for (int i = states.size() - 2; i >= 0; --i) {
        doc.undoStack()->undo();
        QCOMPARE(bytes(doc), states[i]);
    }
    for (int i = 1; i < states.size(); ++i) {
        doc.undoStack()->redo();
        QCOMPARE(bytes(doc), states[i]);
    }
    // The world follows the setup: "a" was deleted, the integrator is rk4, no gravity.
    QCOMPARE(particleIndex(doc.world(), "a"), -1);
    QCOMPARE(doc.world().settings().integrator, std::string("rk4"));
    QVERIFY(doc.world().findEffect("gravity") == nullptr);
}

void TestDocument::consecutiveMovesMergeIntoOneStep() {
    Document doc;
    QVERIFY(doc.loadFromDesc(pendulumScene()));
    const QByteArray before = bytes(doc);
    for (int i = 1; i <= 10; ++i)
        QVERIFY(doc.moveObject(QStringLiteral("a"), {1.0 + 0.1 * i, 0.0}));
    QCOMPARE(doc.undoStack()->count(), 1);
    QCOMPARE(doc.setup().particles[0].position, (Point2{2.0, 0.0}));
    QCOMPARE(doc.world().particlePosition(0), Vec2(2.0, 0.0));

    // Another object, or a new drag of the same one, is a new step.
    QVERIFY(doc.moveObject(QStringLiteral("b"), {0.0, 3.0}));
    QCOMPARE(doc.undoStack()->count(), 2);
    doc.finishInteraction();
    QVERIFY(doc.moveObject(QStringLiteral("b"), {0.0, 4.0}));
    QCOMPARE(doc.undoStack()->count(), 3);

    doc.undoStack()->undo();
    doc.undoStack()->undo();
    QCOMPARE(doc.setup().particles[1].position, (Point2{-1.0, 0.5}));
    doc.undoStack()->undo();
    QCOMPARE(bytes(doc), before);

    // A drag that ends where it began leaves no step at all.
    doc.finishInteraction();
    QVERIFY(doc.moveObject(QStringLiteral("a"), {5.0, 5.0}));
    QVERIFY(doc.moveObject(QStringLiteral("a"), {1.0, 0.0}));
    QCOMPARE(doc.undoStack()->index(), 0);
    QCOMPARE(bytes(doc), before);

    QString error;
    QVERIFY(!doc.moveObject(QStringLiteral("nobody"), {0.0, 0.0}, &error));
    QVERIFY(error.contains(QStringLiteral("unknown object id")));
    QVERIFY(!doc.moveObject(QStringLiteral("a"), {std::nan(""), 0.0}, &error));
}

void TestDocument::deletingAParticleDeletesItsSprings() {
    Document doc;
    SceneDesc s = pendulumScene();
    s.particles.push_back(particle(0.0, -1.0, "c"));
    s.springs.push_back(bodySpring("a", "c", 10.0));  // s2: attached to a
    s.springs.push_back(bodySpring("c", "b", 10.0));  // s3: not
    s.springs[0].id = "sa";
    QVERIFY(doc.loadFromDesc(s));
    const QByteArray before = bytes(doc);

    QVERIFY(doc.deleteObjects({QStringLiteral("a")}));
    QCOMPARE(doc.setup().particles.size(), std::size_t(2));
    QCOMPARE(doc.setup().springs.size(), std::size_t(2));
    QCOMPARE(doc.setup().springs[0].a, std::string("b"));
    QCOMPARE(doc.setup().springs[1].a, std::string("c"));
    QCOMPARE(doc.world().springs().size(), std::size_t(2));
    QCOMPARE(doc.undoStack()->text(0), QStringLiteral("Delete a"));

    doc.undoStack()->undo();
    QCOMPARE(bytes(doc), before);  // springs back at their original indices, ids as they were
    QCOMPARE(doc.setup().springs[0].id, std::string("sa"));
    QCOMPARE(doc.setup().springs[2].a, std::string("a"));

    QString error;
    QVERIFY(!doc.deleteObjects({QStringLiteral("ghost")}, &error));
    QVERIFY(error.contains(QStringLiteral("nothing to delete")));
}

void TestDocument::deletingAClothDeletesSpringsToItsNodes() {
    Document doc;
    SceneDesc s;
    ClothDesc cloth;
    cloth.id = "flag";
    cloth.resolution = {3, 3};
    s.cloths = {cloth};
    s.particles = {particle(3.0, 3.0, "weight")};
    s.springs = {bodySpring("weight", "flag[2,2]", 10.0)};
    QVERIFY(doc.loadFromDesc(s));
    const QByteArray before = bytes(doc);
    // A node's id names its cloth.
    QVERIFY(doc.deleteObjects({QStringLiteral("flag[1,1]")}));
    QVERIFY(doc.setup().cloths.empty());
    QVERIFY(doc.setup().springs.empty());
    QCOMPARE(doc.world().particles().size(), std::size_t(1));
    doc.undoStack()->undo();
    QCOMPARE(bytes(doc), before);
}

void TestDocument::setPropertyRefusesInvalidValues() {
    Document doc;
    QVERIFY(doc.loadFromDesc(pendulumScene()));
    const QByteArray before = bytes(doc);
    QSignalSpy edited(&doc, &Document::sceneEdited);
    QString error;
    QVERIFY(!doc.setProperty(QStringLiteral("a"), QStringLiteral("mass"), -1.0, &error));
    QCOMPARE(error, QStringLiteral("particles[0].mass: must be > 0 (got -1)"));
    QVERIFY(!doc.setProperty(QStringLiteral("a"), QStringLiteral("restitution"), 1.5, &error));
    QVERIFY(error.contains(QStringLiteral("must be between 0 and 1")));
    QVERIFY(!doc.setProperty(QStringLiteral("a"), QStringLiteral("colour"), 1.0, &error));
    QVERIFY(error.contains(QStringLiteral("no property \"colour\"")));
    QVERIFY(!doc.setProperty(QStringLiteral("zz"), QStringLiteral("mass"), 1.0, &error));
    QCOMPARE(bytes(doc), before);
    QCOMPARE(doc.undoStack()->count(), 0);
    QCOMPARE(edited.count(), 0);

    // A refused command pushed directly does nothing and is dropped by the stack.
    auto* command = new SetPropertyCommand(doc, QStringLiteral("a"), QStringLiteral("mass"), 0.0);
    QVERIFY(!command->isValid());
    doc.undoStack()->push(command);
    QCOMPARE(doc.undoStack()->count(), 0);
    QCOMPARE(bytes(doc), before);
}

void TestDocument::setPropertyMergesAndReachesTheWorld() {
    Document doc;
    SceneDesc s = pendulumScene();
    BoxDesc box;
    box.id = "crate";
    box.position = {0.0, 3.0};
    s.boxes = {box};  // mass from density 1
    QVERIFY(doc.loadFromDesc(s));
    const QByteArray before = bytes(doc);
    for (double m : {1.5, 2.0, 2.5})
        QVERIFY(doc.setProperty(QStringLiteral("a"), QStringLiteral("mass"), m));
    QCOMPARE(doc.undoStack()->count(), 1);
    QCOMPARE(doc.world().particles()[0].mass, 2.5);
    QVERIFY(doc.setProperty(QStringLiteral("a"), QStringLiteral("radius"), 0.2));
    QCOMPARE(doc.undoStack()->count(), 2);

    QVERIFY(doc.setProperty(QStringLiteral("crate"), QStringLiteral("size.w"), 2.0));
    QVERIFY(doc.setProperty(QStringLiteral("crate"), QStringLiteral("mass"), 4.0));
    QCOMPARE(doc.world().rigidBodies()[0].size.x(), 2.0);
    QCOMPARE(doc.world().rigidBodies()[0].mass, 4.0);
    QVERIFY(doc.setProperty(QStringLiteral("s0"), QStringLiteral("stiffness"), 75.0));
    QCOMPARE(doc.world().springs()[0].stiffness, 75.0);

    while (doc.undoStack()->canUndo()) doc.undoStack()->undo();
    QCOMPARE(bytes(doc), before);  // the box's mass is implicit (density) again
    QVERIFY(!doc.setup().boxes[0].mass.has_value());
}

void TestDocument::setPinnedTogglesParticleAndBox() {
    Document doc;
    SceneDesc s = pendulumScene();
    BoxDesc box;
    box.id = "crate";
    s.boxes = {box};
    QVERIFY(doc.loadFromDesc(s));
    QVERIFY(doc.setPinned(QStringLiteral("a"), true));
    QVERIFY(doc.world().particles()[0].pinned);
    QCOMPARE(doc.world().particles()[0].dof, -1);
    QVERIFY(doc.setPinned(QStringLiteral("crate"), true));
    QVERIFY(doc.world().rigidBodies()[0].isStatic);
    doc.undoStack()->undo();
    doc.undoStack()->undo();
    QVERIFY(!doc.setup().particles[0].pinned);
    QVERIFY(!doc.setup().boxes[0].isStatic);
    QString error;
    QVERIFY(!doc.setPinned(QStringLiteral("s0"), true, &error));
    QVERIFY(error.contains(QStringLiteral("only particles and rigid bodies")));
}

void TestDocument::propertyTableDescribesEachKind() {
    SceneDesc s = pendulumScene();
    s.springs[0].b.reset();
    BoxDesc box;
    box.id = "crate";
    box.size = {2.0, 0.5};
    box.density = 3.0;
    s.boxes = {box};
    ClothDesc cloth;
    cloth.id = "flag";
    s.cloths = {cloth};

    auto row = [&](const QString& id, const QString& key) -> PropertyRow {
        for (const PropertyRow& r : propertiesOf(s, id))
            if (r.key == key) return r;
        return {};
    };
    const PropertyRow mass = row(QStringLiteral("a"), QStringLiteral("mass"));
    QCOMPARE(mass.unit, QStringLiteral("kg"));
    QCOMPARE(mass.value, 1.0);
    QVERIFY(mass.minimum > 0.0);
    QVERIFY(row(QStringLiteral("a"), QStringLiteral("pinned")).isBool);
    QCOMPARE(row(QStringLiteral("a"), QStringLiteral("restitution")).maximum, 1.0);
    QCOMPARE(row(QStringLiteral("crate"), QStringLiteral("size.w")).value, 2.0);
    QCOMPARE(row(QStringLiteral("crate"), QStringLiteral("mass")).value, 3.0);  // ρ·w·h
    QCOMPARE(row(QStringLiteral("crate"), QStringLiteral("angular_velocity")).unit,
             QStringLiteral("rad/s"));
    // No rest length in the scene: the initial distance is shown.
    QCOMPARE(row(QStringLiteral("s0"), QStringLiteral("rest_length")).value, 1.0);
    QCOMPARE(row(QStringLiteral("s0"), QStringLiteral("stiffness")).unit, QStringLiteral("N/m"));
    QCOMPARE(row(QStringLiteral("s0"), QStringLiteral("anchor.x")).key, QStringLiteral("anchor.x"));
    QCOMPARE(row(QStringLiteral("flag"), QStringLiteral("stiffness.shear")).value, 100.0);
    QCOMPARE(row(QStringLiteral("flag[1,1]"), QStringLiteral("resolution.x")).decimals, 0);
    QVERIFY(propertiesOf(s, QStringLiteral("nobody")).empty());
    QCOMPARE(propertyValue(s, QStringLiteral("b"), QStringLiteral("velocity.x")),
             std::optional<double>(0.3));
}

void TestDocument::simulationEditsMergePerField() {
    Document doc;
    QVERIFY(doc.loadFromDesc(pendulumScene()));
    SimulationDesc sim = doc.setup().simulation;
    for (double dt : {0.02, 0.03, 0.04}) {
        sim.dt = dt;
        QVERIFY(doc.applySimulationSettings(sim));
    }
    QCOMPARE(doc.undoStack()->count(), 1);
    QCOMPARE(doc.world().settings().dt, 0.04);
    sim.substeps = 4;
    QVERIFY(doc.applySimulationSettings(sim));
    QCOMPARE(doc.undoStack()->count(), 2);
    QCOMPARE(doc.world().settings().substeps, 4);

    QString error;
    sim.integrator = "rk5";
    QVERIFY(!doc.applySimulationSettings(sim, &error));
    QVERIFY2(error.contains(QStringLiteral("unknown integrator \"rk5\"")), qPrintable(error));
    sim.integrator = "rk4";
    sim.dt = 0.0;
    QVERIFY(!doc.applySimulationSettings(sim, &error));
    QVERIFY(error.contains(QStringLiteral("simulation.dt")));
    QCOMPARE(doc.undoStack()->count(), 2);
}

void TestDocument::effectOffRemovesItAndOnRestoresParameters() {
    Document doc;
    SceneDesc s = pendulumScene();
    s.effects.drag = DragDesc{0.3, 0.05, 0.0};
    QVERIFY(doc.loadFromDesc(s));
    QVERIFY(doc.world().findEffect("drag") != nullptr);
    QVERIFY(doc.isEffectEnabled(QStringLiteral("drag")));

    QVERIFY(doc.setEffectEnabled(QStringLiteral("drag"), false));
    QVERIFY(!doc.setup().effects.drag.has_value());
    QVERIFY(doc.world().findEffect("drag") == nullptr);
    for (const EffectCost& cost : doc.world().effectCosts()) QVERIFY(cost.name != "drag");
    QVERIFY(!doc.isEffectEnabled(QStringLiteral("drag")));

    QVERIFY(doc.setEffectEnabled(QStringLiteral("drag"), true));
    QVERIFY(doc.world().findEffect("drag") != nullptr);
    QCOMPARE(doc.setup().effects.drag->linear, 0.3);
    QCOMPARE(doc.setup().effects.drag->quadratic, 0.05);
    QCOMPARE(doc.undoStack()->count(), 2);
    QVERIFY(doc.setEffectEnabled(QStringLiteral("drag"), true));  // already on: no step
    QCOMPARE(doc.undoStack()->count(), 2);

    // addEffect: defaults, whatever was remembered.
    QVERIFY(doc.setEffectEnabled(QStringLiteral("drag"), false));
    QVERIFY(doc.addEffect(QStringLiteral("drag")));
    QCOMPARE(doc.setup().effects.drag->linear, 0.0);
    QVERIFY(doc.addEffect(QStringLiteral("wind")));
    QVERIFY(doc.world().findEffect("wind") != nullptr);

    // Parameter edits with one merge key are one step.
    EffectsDesc fx = doc.setup().effects;
    const int steps = doc.undoStack()->count();
    for (double g : {-5.0, -3.0, -1.62}) {
        fx.gravity->g = {0.0, g};
        QVERIFY(doc.setEffects(fx, QStringLiteral("gravity.g")));
    }
    QCOMPARE(doc.undoStack()->count(), steps + 1);
    QCOMPARE(doc.setup().effects.gravity->g[1], -1.62);

    QString error;
    QVERIFY(!doc.setEffectEnabled(QStringLiteral("magnetism"), true, &error));
    QVERIFY(error.contains(QStringLiteral("unknown effect")));
    fx.drag = DragDesc{-1.0, 0.0, 0.0};
    QVERIFY(!doc.setEffects(fx, {}, &error));
    QVERIFY(error.contains(QStringLiteral("effects.drag.linear")));
}

void TestDocument::loadingABadFileChangesNothing() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString good = dir.filePath(QStringLiteral("good.json"));
    const QString bad = dir.filePath(QStringLiteral("bad.json"));
    QVERIFY(SceneIO::save(pendulumScene(), good, nullptr));
    QFile file(bad);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(
        R"({"format": "phasebox-scene", "version": 1, "particles": [{"position": [0, 0], "mass": -1}]})");
    file.close();

    Document doc;
    QString error;
    QVERIFY2(doc.load(good, &error), qPrintable(error));
    QVERIFY(doc.addObject(particle(0.0, 0.0)));
    run(doc, 5);
    const QByteArray before = bytes(doc);
    const double t = doc.world().time();
    QSignalSpy reset(&doc, &Document::sceneReset);
    QSignalSpy path(&doc, &Document::filePathChanged);

    QVERIFY(!doc.load(bad, &error));
    QVERIFY2(error.contains(QStringLiteral("bad.json")) &&
                 error.contains(QStringLiteral("particles[0].mass")),
             qPrintable(error));
    QVERIFY(!doc.load(dir.filePath(QStringLiteral("missing.json")), &error));
    QCOMPARE(bytes(doc), before);
    QCOMPARE(doc.filePath(), good);
    QCOMPARE(doc.world().time(), t);
    QCOMPARE(doc.undoStack()->count(), 1);
    QCOMPARE(reset.count(), 0);
    QCOMPARE(path.count(), 0);
}

void TestDocument::saveThenLoadRoundTrips() {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("scene.phasebox.json"));
    Document doc;
    QVERIFY(doc.loadFromDesc(pendulumScene()));
    ClothDesc cloth;
    cloth.resolution = {4, 3};
    QVERIFY(doc.addObject(cloth));
    QVERIFY(doc.setProperty(QStringLiteral("a"), QStringLiteral("mass"), 1.0 / 3.0));
    QSignalSpy pathChanged(&doc, &Document::filePathChanged);
    QString error;
    QVERIFY2(doc.save(path, &error), qPrintable(error));
    QVERIFY(!doc.isModified());
    QCOMPARE(doc.filePath(), path);
    QCOMPARE(pathChanged.count(), 1);

    Document other;
    QVERIFY2(other.load(path, &error), qPrintable(error));
    QCOMPARE(bytes(other), bytes(doc));
    QCOMPARE(other.filePath(), path);
    QVERIFY(!other.isModified());

    // A failed save leaves the old file and the document's path as they were.
    const QString blocked = dir.filePath(QStringLiteral("no/such/dir/x.json"));
    QVERIFY(!doc.save(blocked, &error));
    QVERIFY(!error.isEmpty());
    QCOMPARE(doc.filePath(), path);
}

void TestDocument::modifiedFollowsTheUndoStack() {
    QTemporaryDir dir;
    Document doc;
    QVERIFY(doc.loadFromDesc(pendulumScene()));
    QSignalSpy modified(&doc, &Document::modifiedChanged);
    QVERIFY(!doc.isModified());
    QVERIFY(doc.addObject(particle(0.0, 0.0)));
    QVERIFY(doc.isModified());
    QCOMPARE(modified.count(), 1);
    QCOMPARE(modified.last().at(0).toBool(), true);
    doc.undoStack()->undo();
    QVERIFY(!doc.isModified());
    QCOMPARE(modified.last().at(0).toBool(), false);
    doc.undoStack()->redo();
    QVERIFY(doc.isModified());
    QVERIFY(doc.save(dir.filePath(QStringLiteral("s.json")), nullptr));
    QVERIFY(!doc.isModified());
    doc.undoStack()->undo();
    QVERIFY(doc.isModified());
    // Running the simulation is not an edit.
    doc.undoStack()->redo();
    run(doc, 10);
    QVERIFY(!doc.isModified());
    doc.newScene();
    QVERIFY(!doc.isModified());
    QVERIFY(doc.filePath().isEmpty());
    QCOMPARE(doc.undoStack()->count(), 0);
}

void TestDocument::defaultIdsAreWrittenOnLoad() {
    SceneDesc s;
    s.particles = {particle(0, 0), particle(1, 0), particle(2, 0)};
    s.springs = {bodySpring("p1", "p2", 5.0)};
    Document doc;
    QVERIFY(doc.loadFromDesc(s));
    QCOMPARE(doc.setup().particles[2].id, std::string("p2"));
    QCOMPARE(doc.setup().springs[0].id, std::string("s0"));
    // Deleting p0 must not turn p1 into "p0" and break the spring.
    QVERIFY(doc.deleteObjects({QStringLiteral("p0")}));
    QCOMPARE(doc.setup().particles[0].id, std::string("p1"));
    QCOMPARE(doc.world().springs().size(), std::size_t(1));
}

void TestDocument::selectionIsPrunedByDeletes() {
    Document doc;
    QVERIFY(doc.loadFromDesc(pendulumScene()));
    QSignalSpy selection(&doc, &Document::selectionChanged);
    doc.setSelection({QStringLiteral("a"), QStringLiteral("b")});
    QCOMPARE(selection.count(), 1);
    QVERIFY(doc.deleteObjects({QStringLiteral("a")}));
    QCOMPARE(doc.selection(), QStringList{QStringLiteral("b")});
    QCOMPARE(selection.count(), 2);
}

// A disk is added, edited (radius, static), moved and deleted with undo and redo like a box;
// the world holds it as a turning rigid body of that radius.
void TestDocument::disksAreEditedLikeBoxes() {
    Document doc;
    QVERIFY(doc.loadFromDesc(SceneDesc{}));
    DiskDesc disk;
    disk.position = {1.0, 2.0};
    disk.radius = 0.4;
    QString id;
    QVERIFY(doc.addObject(disk, nullptr, &id));
    QCOMPARE(id, QStringLiteral("d0"));
    QCOMPARE(doc.world().rigidBodies().size(), std::size_t(1));
    QVERIFY(doc.world().rigidBodies()[0].shape == RigidShape::Disk);
    QCOMPARE(doc.world().rigidBodies()[0].radius, 0.4);
    QCOMPARE(doc.world().rigidBodies()[0].inertia, 0.5 * (std::numbers::pi * 0.16) * 0.16);

    QVERIFY(doc.setProperty(id, QStringLiteral("radius"), 0.6));
    QCOMPARE(doc.setup().disks[0].radius, 0.6);
    QCOMPARE(doc.world().rigidBodies()[0].radius, 0.6);
    QVERIFY(doc.setPinned(id, true));
    QVERIFY(doc.world().rigidBodies()[0].isStatic);
    QVERIFY(doc.moveObject(id, {3.0, 4.0}));
    QCOMPARE(doc.world().bodyPosition(0), Vec2(3.0, 4.0));
    QVERIFY(doc.deleteObjects({id}));
    QVERIFY(doc.setup().disks.empty());
    QVERIFY(doc.world().rigidBodies().empty());

    doc.undoStack()->undo();  // the delete
    QCOMPARE(doc.setup().disks.size(), std::size_t(1));
    doc.undoStack()->undo();  // the move
    doc.undoStack()->undo();  // static
    doc.undoStack()->undo();  // the radius
    QCOMPARE(doc.setup().disks[0].radius, 0.4);
    QVERIFY(!doc.setup().disks[0].isStatic);
    QCOMPARE(doc.setup().disks[0].position, (Point2{1.0, 2.0}));
    doc.undoStack()->redo();
    QCOMPARE(doc.world().rigidBodies()[0].radius, 0.6);
    QCOMPARE(propertyValue(doc.setup(), id, QStringLiteral("mass")).value_or(0.0),
             std::numbers::pi * 0.36);
}

QTEST_GUILESS_MAIN(TestDocument)
#include "tst_document.moc"

// A copy takes the chosen bodies (a node id its cloth), the springs between them or to fixed
// anchors, and leaves a spring to a body left behind; the paste renames everything to free
// ids (cloth node ends included) and shifts every position, anchor and origin.
void TestDocument::copiesKeepTheirSpringsAndPasteUnderFreshIds() {
    SceneDesc s;
    ClothDesc cloth;
    cloth.id = "flag";
    cloth.resolution = {3, 3};
    s.cloths = {cloth};
    s.particles = {particle(3.0, 3.0, "weight"), particle(5.0, 3.0, "other")};
    SpringDesc anchored;
    anchored.id = "hook";
    anchored.a = "weight";
    anchored.anchor = Point2{3.0, 5.0};
    anchored.stiffness = 10.0;
    s.springs = {bodySpring("weight", "flag[2,2]", 10.0), bodySpring("weight", "other", 10.0),
                 anchored};
    s.planes = {PlaneDesc{}};
    s.planes[0].id = "floor";

    const SceneDesc copy = copyObjects(s, {QStringLiteral("flag[1,1]"), QStringLiteral("weight")});
    QCOMPARE(copy.cloths.size(), std::size_t(1));
    QCOMPARE(copy.particles.size(), std::size_t(1));
    QVERIFY(copy.planes.empty());
    QCOMPARE(copy.springs.size(), std::size_t(2));  // to the cloth node and to the anchor
    QVERIFY(validateScene(copy).empty());
    // A spring alone, without its ends, is not copied.
    QVERIFY(copyObjects(s, {QStringLiteral("s1")}).springs.empty());

    const std::vector<ObjectDesc> pasted = pastedObjects(s, copy, {1.0, -2.0});
    QCOMPARE(pasted.size(), std::size_t(4));
    const auto& p = std::get<ParticleDesc>(pasted[0]);
    const auto& c = std::get<ClothDesc>(pasted[1]);
    const auto& toNode = std::get<SpringDesc>(pasted[2]);
    const auto& toAnchor = std::get<SpringDesc>(pasted[3]);
    QCOMPARE(p.id, std::string("p0"));
    QCOMPARE(p.position, (Point2{4.0, 1.0}));
    QCOMPARE(c.id, std::string("cloth0"));
    QCOMPARE(c.origin, (Point2{cloth.origin[0] + 1.0, cloth.origin[1] - 2.0}));
    QCOMPARE(toNode.a, std::string("p0"));
    QCOMPARE(*toNode.b, std::string("cloth0[2,2]"));
    QCOMPARE(toAnchor.a, std::string("p0"));
    QCOMPARE(*toAnchor.anchor, (Point2{4.0, 3.0}));
    QVERIFY(toNode.id != toAnchor.id);

    Document doc;
    QVERIFY(doc.loadFromDesc(s));
    const QByteArray before = bytes(doc);
    QStringList ids;
    QVERIFY(doc.addObjects(pasted, nullptr, &ids));
    QCOMPARE(ids.size(), 4);
    QCOMPARE(doc.world().particles().size(), std::size_t(2 + 1 + 2 * 9));
    doc.undoStack()->undo();
    QCOMPARE(bytes(doc), before);
}
