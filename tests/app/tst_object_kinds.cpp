// The object kinds as the app visits them (physics/scene/ObjectKinds.h): every kind's entry
// agrees with its table and its array, ids and nodes resolve, a plane's normal is edited as its
// tilt, moves set the field a kind is placed by (and refuse what moves with its bodies), pins
// set the kind's own flag, and deleting a body takes its connectors along.

#include "app/document/Document.h"
#include "app/document/PropertyTable.h"
#include "physics/scene/ObjectKinds.h"
#include "tests/support/SceneBuilders.h"

#include <QTest>

#include <cmath>
#include <numbers>
#include <set>
#include <string>

using namespace phasebox;
using testing::anchorSpring;
using testing::bodySpring;

namespace {

// A particle, a box, a plane, a cloth, a spring between the particle and the box, a spring from
// the box to an anchor and a hinge of the box to the world.
SceneDesc mixedScene() {
    SceneDesc s;
    ParticleDesc p;
    p.id = "p";
    p.position = {1.0, 2.0};
    s.particles = {p};
    BoxDesc b;
    b.id = "b";
    b.position = {3.0, 0.0};
    b.angle = std::numbers::pi / 2;
    s.boxes = {b};
    PlaneDesc ground;
    ground.id = "ground";
    ground.point = {0.0, -2.0};
    s.planes = {ground};
    ClothDesc cloth;
    cloth.id = "c";
    cloth.origin = {-3.0, 3.0};
    cloth.size = {2.0, 1.0};
    cloth.resolution = {3, 2};
    s.cloths = {cloth};
    s.springs = {bodySpring("p", "b", 10.0), anchorSpring("b", {3.0, 4.0}, 10.0)};
    s.springs[0].id = "between";
    s.springs[1].id = "hung";
    JointDesc hinge;
    hinge.id = "h";
    hinge.a = "b";
    hinge.anchor = Point2{3.0, 0.0};
    s.joints = {hinge};
    return s;
}

}  // namespace

class TestObjectKinds : public QObject {
    Q_OBJECT

private slots:
    void everyKindHasItsEntryTableAndArray();
    void idsAndNodesResolve();
    void setupPointsFollowTheBodysFrame();
    void planeNormalIsEditedAsItsTilt();
    void connectorLengthShowsTheEndsDistance();
    void movesSetThePlacingFieldOrAreRefused();
    void pinsSetTheKindsFlag();
    void deletingABodyTakesItsConnectors();
};

void TestObjectKinds::everyKindHasItsEntryTableAndArray() {
    std::set<std::string_view> names, prefixes;
    std::size_t kinds = 0;
    forEachKind([&]<typename D>(std::type_identity<D>, ObjectKind kind) {
        ++kinds;
        QCOMPARE(kindOf<D>(), kind);
        QCOMPARE(objectKind(ObjectDesc(D{})), kind);
        const schema::KindInfo& info = schema::kindInfo(kind);
        names.insert(info.name);
        prefixes.insert(info.idPrefix);
        // The keys it names are fields of its own table.
        const auto hasField = [](std::string_view key) {
            if (key.empty()) return true;
            for (const schema::Field<D>& f : schema::table<D>().fields)
                if (f.key == key) return true;
            return false;
        };
        QVERIFY(hasField(info.placeKey));
        QVERIFY(hasField(info.pinKey));
        QVERIFY(hasField(info.endsLengthKey));
        // arrayOf<D> is the array forEachObjectKind pairs with D's table.
        SceneDesc scene;
        arrayOf<D>(scene).push_back(D{});
        QCOMPARE(objectCount(scene, kind), std::size_t{1});
    });
    QCOMPARE(kinds, kObjectKindCount);
    QCOMPARE(names.size(), kinds);
    QCOMPARE(prefixes.size(), kinds);
    QCOMPARE(schema::kindInfo(ObjectKind::None).name, std::string_view("object"));
}

void TestObjectKinds::idsAndNodesResolve() {
    SceneDesc s = mixedScene();
    s.particles.push_back(ParticleDesc{});  // no id: p1 by position
    const ObjectRef unnamed = findObject(s, "p1");
    QCOMPARE(unnamed, (ObjectRef{kindOf<ParticleDesc>(), 1}));
    QCOMPARE(objectId(s, unnamed), std::string("p1"));
    const ObjectRef node = findObject(s, "c[2,1]");
    QCOMPARE(node, (ObjectRef{kindOf<ClothDesc>(), 0}));
    QCOMPARE(nodeIds(s, node).size(), std::size_t{6});
    QVERIFY(nodeIds(s, findObject(s, "b")).empty());
    QVERIFY(!findObject(s, "nobody").isValid());
    // Every id once, nodes left out, the kinds with nodes last.
    const std::vector<std::string> ids = objectIds(s);
    QCOMPARE(ids.size(), std::size_t{8});
    QCOMPARE(ids.back(), std::string("c"));
    assignDefaultIds(s);
    QCOMPARE(s.particles[1].id, std::string("p1"));
}

void TestObjectKinds::setupPointsFollowTheBodysFrame() {
    const SceneDesc s = mixedScene();
    // The box is turned by 90°: its local (1, 0) is 1 m up from its centre.
    const auto onBox = setupPoint(s, "b", {1.0, 0.0});
    QVERIFY(onBox);
    QVERIFY(std::abs((*onBox)[0] - 3.0) < 1e-12);
    QVERIFY(std::abs((*onBox)[1] - 1.0) < 1e-12);
    // A particle has no frame; a node sits on the cloth's grid (1 m apart either way).
    QCOMPARE(*setupPoint(s, "p", {5.0, 5.0}), (Point2{1.0, 2.0}));
    QCOMPARE(*setupPoint(s, "c[2,1]", {0.0, 0.0}), (Point2{-1.0, 2.0}));
    QVERIFY(!setupPoint(s, "ground", {0.0, 0.0}));
}

void TestObjectKinds::planeNormalIsEditedAsItsTilt() {
    SceneDesc s = mixedScene();
    QCOMPARE(propertyValue(s, QStringLiteral("ground"), QStringLiteral("angle")).value(), 0.0);
    QVERIFY(setPropertyValue(s, QStringLiteral("ground"), QStringLiteral("angle"),
                             std::numbers::pi / 2));
    // A wall facing −x.
    QVERIFY(std::abs(s.planes[0].normal[0] + 1.0) < 1e-12);
    QVERIFY(std::abs(s.planes[0].normal[1]) < 1e-12);
    QVERIFY(!propertyValue(s, QStringLiteral("ground"), QStringLiteral("normal.x")));
}

void TestObjectKinds::connectorLengthShowsTheEndsDistance() {
    const SceneDesc s = mixedScene();
    // Particle (1, 2) to the box's centre (3, 0); anchor (3, 4) to the box's centre.
    QVERIFY(std::abs(*propertyValue(s, QStringLiteral("between"), QStringLiteral("rest_length")) -
                     std::sqrt(8.0)) < 1e-12);
    QVERIFY(std::abs(*propertyValue(s, QStringLiteral("hung"), QStringLiteral("rest_length")) -
                     4.0) < 1e-12);
}

void TestObjectKinds::movesSetThePlacingFieldOrAreRefused() {
    Document doc;
    QVERIFY(doc.loadFromDesc(mixedScene()));
    QVERIFY(doc.moveObject(QStringLiteral("ground"), {0.5, -1.0}));
    QCOMPARE(doc.setup().planes[0].point, (Point2{0.5, -1.0}));
    QVERIFY(doc.moveObject(QStringLiteral("c[1,1]"), {0.0, 5.0}));  // a node moves its cloth
    QCOMPARE(doc.setup().cloths[0].origin, (Point2{0.0, 5.0}));
    QVERIFY(doc.moveObject(QStringLiteral("hung"), {3.0, 5.0}));  // by its anchor
    QCOMPARE(*doc.setup().springs[1].anchor, (Point2{3.0, 5.0}));
    QString error;
    QVERIFY(!doc.moveObject(QStringLiteral("between"), {0.0, 0.0}, &error));
    QCOMPARE(error, QStringLiteral("spring between hangs between two bodies; move them instead"));
    QVERIFY(!doc.moveObject(QStringLiteral("h"), {0.0, 0.0}, &error));
    QCOMPARE(error, QStringLiteral("joint h moves with its bodies; move them instead"));
}

void TestObjectKinds::pinsSetTheKindsFlag() {
    SceneDesc s = mixedScene();
    s.joints.clear();  // a hinge to the world needs its box dynamic
    Document doc;
    QVERIFY(doc.loadFromDesc(s));
    QVERIFY(doc.setPinned(QStringLiteral("p"), true));
    QVERIFY(doc.setup().particles[0].pinned);
    QVERIFY(doc.setPinned(QStringLiteral("b"), true));
    QVERIFY(doc.setup().boxes[0].isStatic);
    QString error;
    QVERIFY(!doc.setPinned(QStringLiteral("ground"), true, &error));
    QCOMPARE(error, QStringLiteral("only particles and rigid bodies can be pinned"));
    QCOMPARE(pinPropertyKey(kindOf<BoxDesc>()), QStringLiteral("static"));
    QVERIFY(pinPropertyKey(kindOf<PlaneDesc>()).isEmpty());
}

void TestObjectKinds::deletingABodyTakesItsConnectors() {
    Document doc;
    QVERIFY(doc.loadFromDesc(mixedScene()));
    QVERIFY(doc.deleteObjects({QStringLiteral("b")}));
    QVERIFY(doc.setup().boxes.empty());
    QVERIFY(doc.setup().springs.empty());
    QVERIFY(doc.setup().joints.empty());
    QCOMPARE(doc.setup().particles.size(), std::size_t{1});
    doc.undoStack()->undo();
    QCOMPARE(doc.setup().springs.size(), std::size_t{2});
    QCOMPARE(doc.setup().springs[1].id, std::string("hung"));
    QCOMPARE(doc.setup().joints.size(), std::size_t{1});
}

QTEST_GUILESS_MAIN(TestObjectKinds)
#include "tst_object_kinds.moc"
