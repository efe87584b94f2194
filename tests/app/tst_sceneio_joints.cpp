// Joints in scene files (CONTRACT §6): one of each type round-trips byte for byte, a scene with
// joints is version 2, each type writes only the fields it uses, every refusal names its JSON
// path word for word, and a joint's points follow a polygon re-centred on load.

#include "SceneIOTestSupport.h"

#include "app/io/SceneIO.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTest>

using namespace phasebox;
using namespace phasebox::testing;

namespace {

// richScene() with a disk, a centred polygon and a joint of every type (CONTRACT §6): limits and
// a motor, both ends of rods and ropes, a pulley's ratio, both kinds of track, ids given and
// left out. The hinge's a_point is set although a hinge does not use it: it is not written.
SceneDesc jointScene() {
    SceneDesc s = richScene();
    DiskDesc wheel;
    wheel.id = "wheel";
    wheel.position = {1.0, 2.0};
    wheel.radius = 0.25;
    s.disks = {wheel};
    PolygonDesc tri;
    tri.id = "tri";
    tri.position = {-3.0, 1.0};
    tri.vertices = {{-1.0, -1.0}, {1.0, -1.0}, {0.0, 2.0}};  // centred on its centroid
    s.polygons = {tri};

    JointDesc elbow;
    elbow.id = "elbow";
    elbow.type = JointType::Hinge;
    elbow.a = "crate";
    elbow.b = "wheel";
    elbow.aPoint = {9.0, 9.0};
    elbow.anchor = Point2{2.0, 0.5};
    elbow.limits = std::array<double, 2>{-0.5, 1.25};
    elbow.motor = JointMotorDesc{2.0, 15.0};
    JointDesc pivot;  // id left out: j1
    pivot.type = JointType::Hinge;
    pivot.a = "tri";
    pivot.anchor = Point2{-3.0, 2.0};
    JointDesc rod;
    rod.id = "rod";
    rod.type = JointType::Rod;
    rod.a = "p1";
    rod.b = "crate";
    rod.bPoint = {0.4, 0.25};
    rod.length = 2.5;
    JointDesc rope;
    rope.id = "tether";
    rope.type = JointType::Rope;
    rope.a = "crate";
    rope.aPoint = {0.1, 0.2};
    rope.anchor = Point2{3.0, 2.0};
    JointDesc weld;
    weld.id = "weld";
    weld.type = JointType::Weld;
    weld.a = "wheel";
    weld.b = "tri";
    JointDesc pulley;
    pulley.id = "pulley";
    pulley.type = JointType::Pulley;
    pulley.a = "p1";
    pulley.b = "wheel";
    pulley.bPoint = {0.1, 0.0};
    pulley.groundA = {-1.0, 5.0};
    pulley.groundB = {1.0, 5.0};
    pulley.ratio = 2.0;
    JointDesc ring;
    ring.id = "ring";
    ring.type = JointType::Track;
    ring.a = "flag[1,1]";
    ring.circle = TrackCircleDesc{{5.0, 0.0}, 1.5};
    JointDesc rail;
    rail.id = "rail";
    rail.type = JointType::Track;
    rail.a = "p1";
    rail.line = TrackLineDesc{{0.0, 0.0}, {1.0, 1.0}};
    s.joints = {elbow, pivot, rod, rope, weld, pulley, ring, rail};
    return s;
}

// A version 2 file with bodies of every kind for joints to hold, and the given joints:
// p (free) at [0, 0], pin (pinned) at [0, 2], box (free) at [2, 0], wall (static), wheel (a
// disk), tri (a polygon whose vertices are off its centroid), the plane ground, and cloth c,
// whose top nodes c[0,0] and c[1,0] are pinned.
QByteArray jointFile(const char* joints) {
    return QByteArray(R"({"format": "phasebox-scene", "version": 2,
        "particles": [{"id": "p", "position": [0, 0]},
                      {"id": "pin", "position": [0, 2], "pinned": true}],
        "boxes": [{"id": "box", "position": [2, 0], "size": [1, 1]},
                  {"id": "wall", "position": [5, 0], "size": [1, 4], "static": true}],
        "disks": [{"id": "wheel", "position": [-2, 0], "radius": 0.5}],
        "polygons": [{"id": "tri", "position": [2, 1], "vertices": [[0, 0], [0, 4], [3, 0]]}],
        "planes": [{"id": "ground", "point": [0, -5], "normal": [0, 1]}],
        "cloths": [{"id": "c", "origin": [10, 10], "resolution": [2, 2]}],
        "joints": [)") +
           joints + "]}";
}

}  // namespace

class TestJointSceneIO : public QObject {
    Q_OBJECT

private slots:
    void jointsRoundTripByteIdentical();
    void jointsMakeAVersionTwoScene();
    void jointsWriteOnlyTheFieldsTheirTypeUses();
    void jointErrors_data();
    void jointErrors();
    void jointPointsFollowARecentredPolygon();
};

// CONTRACT §6: one joint of each type, with limits, a motor, a circle and a line, saves, loads
// and saves again byte for byte, and keeps its values.
void TestJointSceneIO::jointsRoundTripByteIdentical() {
    const SceneDesc original = jointScene();
    const auto issues = validateScene(original);
    QVERIFY2(issues.empty(),
             issues.empty()
                 ? ""
                 : qPrintable(QString::fromStdString(issues[0].path + ": " + issues[0].message)));
    const QByteArray first = SceneIO::serialize(original);
    const SceneLoadResult loaded = SceneIO::parse(first, kName);
    QVERIFY2(loaded.ok(), qPrintable(loaded.errorText()));
    QCOMPARE(SceneIO::serialize(*loaded.scene), first);
    // ... and through Qt's own JSON writer.
    const QByteArray qts = QJsonDocument::fromJson(first).toJson(QJsonDocument::Indented);
    const SceneLoadResult again = SceneIO::parse(qts, kName);
    QVERIFY2(again.ok(), qPrintable(again.errorText()));
    QCOMPARE(SceneIO::serialize(*again.scene), first);

    const std::vector<JointDesc>& j = loaded.scene->joints;
    QCOMPARE(j.size(), std::size_t(8));
    QCOMPARE(j[0].type, JointType::Hinge);
    QCOMPARE(j[0].b, std::optional<std::string>("wheel"));
    QVERIFY(j[0].limits && (*j[0].limits == std::array<double, 2>{-0.5, 1.25}));
    QVERIFY(j[0].motor && j[0].motor->speed == 2.0 && j[0].motor->maxTorque == 15.0);
    QCOMPARE(j[0].aPoint, (Point2{0.0, 0.0}));  // a hinge's a_point is not part of the file
    QVERIFY(j[1].id.empty());
    QCOMPARE(jointId(*loaded.scene, 1), std::string("j1"));
    QVERIFY(!j[1].b && !j[1].limits && !j[1].motor);
    QCOMPARE(j[2].type, JointType::Rod);
    QVERIFY(j[2].length && *j[2].length == 2.5);
    QCOMPARE(j[2].bPoint, (Point2{0.4, 0.25}));
    QCOMPARE(j[3].type, JointType::Rope);
    QVERIFY(!j[3].b && !j[3].length);
    QVERIFY(j[3].anchor && (*j[3].anchor == Point2{3.0, 2.0}));
    QCOMPARE(j[4].type, JointType::Weld);
    QCOMPARE(j[5].type, JointType::Pulley);
    QCOMPARE(j[5].ratio, 2.0);
    QCOMPARE(j[5].groundB, (Point2{1.0, 5.0}));
    QCOMPARE(j[6].type, JointType::Track);
    QVERIFY(j[6].circle && j[6].circle->radius == 1.5 && !j[6].line);
    QCOMPARE(j[6].a, std::string("flag[1,1]"));
    QVERIFY(j[7].line && (j[7].line->direction == Point2{1.0, 1.0}) && !j[7].circle);
}

// CONTRACT §6: joints make a scene version 2; without them it stays version 1 and has no
// `joints` key.
void TestJointSceneIO::jointsMakeAVersionTwoScene() {
    SceneDesc scene = richScene();
    const QByteArray old = SceneIO::serialize(scene);
    QVERIFY(old.contains(R"("version": 1)"));
    QVERIFY(!old.contains(R"("joints")"));
    JointDesc weld;
    weld.type = JointType::Weld;
    weld.a = "crate";
    scene.joints = {weld};
    const QByteArray text = SceneIO::serialize(scene);
    QVERIFY(text.startsWith("{\n  \"format\": \"phasebox-scene\",\n  \"version\": 2,\n"));
    QVERIFY(text.contains(R"("joints": [)"));
    QVERIFY(!text.contains(R"("disks")"));  // still only the kinds the scene has
    const SceneLoadResult loaded = SceneIO::parse(text, kName);
    QVERIFY2(loaded.ok(), qPrintable(loaded.errorText()));
    QCOMPARE(loaded.scene->formatVersion(), 2);
}

// The writer writes id (when given), type, a, b (when given) and the fields the type uses, all
// of them, defaults included; nothing else.
void TestJointSceneIO::jointsWriteOnlyTheFieldsTheirTypeUses() {
    const QByteArray text = SceneIO::serialize(jointScene());
    QVERIFY2(text.contains("    {\n      \"id\": \"weld\",\n      \"type\": \"weld\",\n"
                           "      \"a\": \"wheel\",\n      \"b\": \"tri\"\n    }"),
             text.constData());
    const QJsonArray joints = QJsonDocument::fromJson(text).object()["joints"].toArray();
    QCOMPARE(joints.size(), 8);
    const auto keys = [&](qsizetype i) { return joints[i].toObject().keys(); };  // sorted
    QCOMPARE(keys(0), (QStringList{"a", "anchor", "b", "id", "limits", "motor", "type"}));
    QCOMPARE(joints[0]["motor"].toObject().keys(), (QStringList{"max_torque", "speed"}));
    QCOMPARE(keys(1), (QStringList{"a", "anchor", "type"}));
    QCOMPARE(keys(2), (QStringList{"a", "a_point", "b", "b_point", "id", "length", "type"}));
    QCOMPARE(keys(3), (QStringList{"a", "a_point", "anchor", "id", "type"}));
    QCOMPARE(keys(4), (QStringList{"a", "b", "id", "type"}));
    QCOMPARE(keys(5), (QStringList{"a", "a_point", "b", "b_point", "ground_a", "ground_b", "id",
                                   "ratio", "type"}));
    QCOMPARE(keys(6), (QStringList{"a", "circle", "id", "type"}));
    QCOMPARE(joints[6]["circle"].toObject().keys(), (QStringList{"center", "radius"}));
    QCOMPARE(keys(7), (QStringList{"a", "id", "line", "type"}));
    QCOMPARE(joints[7]["line"].toObject().keys(), (QStringList{"direction", "point"}));
    // Defaults are written like any other field's.
    QCOMPARE(joints[2]["a_point"].toArray(), (QJsonArray{0, 0}));
    QCOMPARE(joints[5]["a_point"].toArray(), (QJsonArray{0, 0}));
    JointDesc pulley = jointScene().joints[5];
    pulley.ratio = 1.0;
    SceneDesc scene = jointScene();
    scene.joints = {pulley};
    QVERIFY(SceneIO::serialize(scene).contains("\"ratio\": 1\n"));
}

void TestJointSceneIO::jointErrors_data() {
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<QStringList>("expected");
    const auto row = [](const char* name, const char* joints, const QStringList& expected) {
        QTest::newRow(name) << jointFile(joints) << expected;
    };
    const QString oneOf = QStringLiteral("must be one of hinge, rod, rope, weld, pulley, track");
    const QString noTurn = QStringLiteral(
        "neither body can turn, so the joint angle cannot change; limits and a motor need a "
        "dynamic box, disk or polygon");
    // Issue #38: a free particle takes no torque, so a limit or motor against it is refused.
    const QString freeParticle = QStringLiteral(
        "a free particle has no angle and takes no torque; limits and a motor need both ends to "
        "be boxes, disks, polygons or fixed, so that their torque acts on both");
    const QString sameEnds = QStringLiteral(
        "its two ends start at the same point, so its length would be 0; give a length > 0");
    const QString noDirection =
        QStringLiteral(" at load, so the rope there would have no direction");

    // -- reading: types, keys, the type's own fields
    row("unknown type",
        R"({"type": "weld", "a": "p"}, {"type": "rod", "a": "p", "anchor": [0, 1]},
           {"type": "slider", "a": "p"})",
        {msg("joints[2].type", oneOf + R"( (got "slider"))")});
    row("type not a string", R"({"type": 3, "a": "p"})", {msg("joints[0].type", oneOf)});
    row("type missing", R"({"a": "p", "length": 2})", {msg("joints[0].type", "is required")});
    row("a missing", R"({"type": "weld"})", {msg("joints[0].a", "is required")});
    row("misspelt keys", R"({"type": "hinge", "a": "box", "anchr": [2, 0]},
                            {"type": "hinge", "a": "box", "anchor": [2, 0],
                             "motor": {"sped": 1, "max_torque": 1}})",
        {msg("joints[0].anchr", R"(unknown key; did you mean "anchor"?)"),
         msg("joints[1].motor.sped", R"(unknown key; did you mean "speed"?)")});
    row("types", R"({"type": "hinge", "a": "box", "anchor": [2, 0], "limits": [1], "motor": 5},
                    {"type": "track", "a": "p", "circle": {"center": [0, 0]}})",
        {msg("joints[0].limits", "must be an array of 2 numbers [lower, upper]"),
         msg("joints[0].motor", "must be an object"),
         msg("joints[1].circle.radius", "is required")});
    row("a motor needs its torque",
        R"({"type": "hinge", "a": "box", "anchor": [2, 0], "motor": {"speed": 1}})",
        {msg("joints[0].motor.max_torque", "is required")});
    row("pulley grounds", R"({"type": "pulley", "a": "p", "b": "box"})",
        {msg("joints[0].ground_a", "is required"), msg("joints[0].ground_b", "is required")});
    row("fields the type does not use",
        R"({"type": "weld", "a": "p", "anchor": [0, 0]},
           {"type": "hinge", "a": "box", "anchor": [2, 0], "a_point": [0, 0], "length": 1,
            "ratio": 2},
           {"type": "rod", "a": "p", "anchor": [0, 1], "b_point": [0, 0], "limits": [0, 1]},
           {"type": "track", "a": "p", "line": {"point": [0, 0], "direction": [1, 0]},
            "circle": {"center": [0, 0], "radius": 1}, "ground_a": [0, 0]})",
        {msg("joints[0].anchor", "is only for hinge, rod and rope joints"),
         msg("joints[1].a_point", "is only for rod, rope and pulley joints"),
         msg("joints[1].length", "is only for rod and rope joints"),
         msg("joints[1].ratio", "is only for pulley joints"),
         msg("joints[2].b_point", "is only for rod, rope and pulley joints with b"),
         msg("joints[2].limits", "is only for hinge joints"),
         msg("joints[3].ground_a", "is only for pulley joints")});

    // -- bodies
    row("a empty", R"({"type": "weld", "a": ""})", {msg("joints[0].a", "is required")});
    row("unknown ids",
        R"({"type": "weld", "a": "q7"}, {"type": "weld", "a": "p", "b": "nope"},
           {"type": "weld", "a": "c[5,5]"})",
        {msg("joints[0].a", R"(unknown object id "q7")"),
         msg("joints[1].b", R"(unknown object id "nope")"),
         msg("joints[2].a", R"(unknown object id "c[5,5]")")});
    row("not a body", R"({"type": "weld", "a": "ground"})",
        {msg("joints[0].a", R"("ground" is planes[0]; joints hold particles, boxes, disks, )"
                            "polygons and cloth nodes")});
    row("a is b", R"({"type": "weld", "a": "box", "b": "box"})",
        {msg("joints[0].b", "must differ from a")});
    row("duplicate id", R"({"id": "p", "type": "weld", "a": "box"})",
        {msg("joints[0].id", R"(duplicate id "p" (also used by particles[0]))")});
    row("no dynamic body",
        R"({"type": "weld", "a": "wall", "b": "pin"}, {"type": "weld", "a": "pin"},
           {"type": "rope", "a": "c[1,0]", "anchor": [0, 0]},
           {"type": "weld", "a": "c[0,1]"}, {"type": "weld", "a": "pin", "b": "box"})",
        {msg("joints[0]", R"(a joint needs a dynamic body: "wall" is static and "pin" is pinned)"),
         msg("joints[1]", R"(a joint needs a dynamic body: "pin" is pinned and b is the world)"),
         msg("joints[2]",
             R"(a joint needs a dynamic body: "c[1,0]" is pinned and b is the world)")});

    // -- hinge
    row("hinge without anchor", R"({"type": "hinge", "a": "box"})",
        {msg("joints[0].anchor", "is required")});
    row("hinge limits reversed", R"({"type": "hinge", "a": "box", "anchor": [2, 0],
                                     "limits": [1, -1]})",
        {msg("joints[0].limits", "must be [lower, upper] with lower <= upper (got [1, -1])")});
    row("hinge that cannot turn",
        R"({"type": "hinge", "a": "p", "b": "c[0,1]", "anchor": [0, 0], "limits": [-1, 1],
            "motor": {"speed": 1, "max_torque": 2}},
           {"type": "hinge", "a": "p", "anchor": [0, 0], "motor": {"max_torque": 1}},
           {"type": "hinge", "a": "p", "b": "wall", "anchor": [0, 0], "limits": [0, 1]},
           {"type": "hinge", "a": "p", "b": "wheel", "anchor": [0, 0], "limits": [0, 1]})",
        {msg("joints[0].limits", noTurn), msg("joints[0].motor", noTurn),
         msg("joints[1].motor", noTurn), msg("joints[2].limits", noTurn),
         msg("joints[3].limits", freeParticle)});
    row("motor torque", R"({"type": "hinge", "a": "box", "anchor": [2, 0],
                            "motor": {"speed": 1e7, "max_torque": -1}})",
        {msg("joints[0].motor.speed", "must be between -1e6 and 1e6 (got 1e7)"),
         msg("joints[0].motor.max_torque", "must be >= 0 (got -1)")});

    // -- rod and rope
    row("length not > 0",
        R"({"type": "rod", "a": "p", "b": "box", "length": 0},
           {"type": "rope", "a": "p", "anchor": [0, 1], "length": -2})",
        {msg("joints[0].length", "must be > 0 (got 0)"),
         msg("joints[1].length", "must be > 0 (got -2)")});
    row("initial length 0",
        R"({"type": "rod", "a": "p", "anchor": [0, 0]},
           {"type": "rope", "a": "box", "a_point": [-2, 0], "b": "p"},
           {"type": "rod", "a": "wheel", "a_point": [0, 1], "b": "c[0,1]", "b_point": [5, 5]},
           {"type": "rope", "a": "tri", "anchor": [2, 1]},
           {"type": "rod", "a": "p", "anchor": [0, 0], "length": 1})",
        {msg("joints[0]", sameEnds), msg("joints[1]", sameEnds), msg("joints[3]", sameEnds)});
    row("rod ends",
        R"({"type": "rod", "a": "p"}, {"type": "rope", "a": "p", "b": "box", "anchor": [1, 1]})",
        {msg("joints[0]", "needs either b (an object id) or anchor [x, y]"),
         msg("joints[1]", "has both b and anchor; give one")});

    // -- pulley
    row("pulley ratio",
        R"({"type": "pulley", "a": "p", "b": "box", "ground_a": [0, 5], "ground_b": [2, 5],
            "ratio": 0})",
        {msg("joints[0].ratio", "must be > 0 (got 0)")});
    row("pulley ground at its point",
        R"({"type": "pulley", "a": "p", "b": "box", "ground_a": [0, 0], "ground_b": [2, 0]},
           {"type": "pulley", "a": "p", "b": "box", "b_point": [0, 1], "ground_a": [0, 3],
            "ground_b": [2, 1]})",
        {msg("joints[0].ground_a", "is where the point on a is" + noDirection),
         msg("joints[0].ground_b", "is where the point on b is" + noDirection),
         msg("joints[1].ground_b", "is where the point on b is" + noDirection)});
    row("pulley without b", R"({"type": "pulley", "a": "p", "ground_a": [0, 5],
                                "ground_b": [2, 5]})",
        {msg("joints[0].b", "is required: a pulley holds two bodies")});

    // -- track
    row("track body",
        R"({"type": "track", "a": "box", "circle": {"center": [0, 0], "radius": 1}},
           {"type": "track", "a": "p", "b": "box", "line": {"point": [0, 0], "direction": [1, 0]}},
           {"type": "track", "a": "c[1,1]", "line": {"point": [0, 0], "direction": [1, 0]}})",
        {msg("joints[0].a", R"("box" is not a particle; a track holds a particle or a cloth node)"),
         msg("joints[1].b", "a track has no b: it holds a on a fixed curve")});
    row("track curve",
        R"({"type": "track", "a": "p"},
           {"type": "track", "a": "p", "circle": {"center": [0, 0], "radius": 1},
            "line": {"point": [0, 0], "direction": [1, 0]}},
           {"type": "track", "a": "p", "circle": {"center": [0, 0], "radius": 0}},
           {"type": "track", "a": "p", "line": {"point": [0, 0], "direction": [0, 0]}})",
        {msg("joints[0]", "needs either circle {center, radius} or line {point, direction}"),
         msg("joints[1]", "has both circle and line; give one"),
         msg("joints[2].circle.radius", "must be > 0 (got 0)"),
         msg("joints[3].line.direction", "must be non-zero")});

    // -- magnitudes
    row("ranges",
        R"({"type": "hinge", "a": "box", "anchor": [1e300, 0], "limits": [-1e7, 0]},
           {"type": "rod", "a": "box", "a_point": [0, 2e6], "b": "p", "length": 1e7},
           {"type": "track", "a": "p", "line": {"point": [0, -1e9], "direction": [1e-300, 0]}})",
        {msg("joints[0].anchor[0]", "must be between -1e6 and 1e6 (got 1e300)"),
         msg("joints[0].limits[0]", "must be between -1e6 and 1e6 (got -1e7)"),
         msg("joints[1].a_point[1]", "must be between -1e6 and 1e6 (got 2e6)"),
         msg("joints[1].length", "must be <= 1e6 (got 1e7)"),
         msg("joints[2].line.point[1]", "must be between -1e6 and 1e6 (got -1e9)"),
         msg("joints[2].line.direction",
             "is too short to give a direction (length 1e-300; at least 1e-12)")});
    QTest::newRow("joints not an array")
        << QByteArray(R"({"format": "phasebox-scene", "version": 2, "joints": {}})")
        << QStringList{msg("joints", "must be an array")};
}

void TestJointSceneIO::jointErrors() {
    QFETCH(QByteArray, json);
    QFETCH(QStringList, expected);
    expectRefused(json, expected);
}

// CONTRACT §6: a joint's points on a polygon are in the frame its vertices are written in; when
// the polygon is re-centred on load by c, they shift by −c, so they stay on the same material
// points (and the file saves in the centred form).
void TestJointSceneIO::jointPointsFollowARecentredPolygon() {
    // tri's centroid is (1, 4/3) in the frame of its vertices.
    const SceneLoadResult loaded = SceneIO::parse(
        jointFile(R"({"type": "rope", "a": "tri", "a_point": [1, 0], "anchor": [2, 5]},
                     {"type": "pulley", "a": "p", "b": "tri", "b_point": [3, 0],
                      "ground_a": [0, 5], "ground_b": [4, 5]},
                     {"type": "rod", "a": "box", "b": "p", "a_point": [1, 0]})"),
        kName);
    QVERIFY2(loaded.ok(), qPrintable(loaded.errorText()));
    const SceneDesc& s = *loaded.scene;
    const auto near = [](const Point2& p, const Point2& q) {
        return std::abs(p[0] - q[0]) < 1e-15 && std::abs(p[1] - q[1]) < 1e-15;
    };
    QVERIFY(near(s.polygons[0].position, {3.0, 7.0 / 3.0}));
    QVERIFY(near(s.joints[0].aPoint, {0.0, -4.0 / 3.0}));
    QVERIFY(near(s.joints[1].bPoint, {2.0, -4.0 / 3.0}));
    QCOMPARE(s.joints[1].aPoint, (Point2{0.0, 0.0}));  // on p: not moved
    QCOMPARE(s.joints[2].aPoint, (Point2{1.0, 0.0}));  // on a box: not moved
    // The same world point as before: position + a_point.
    QVERIFY(near({s.polygons[0].position[0] + s.joints[0].aPoint[0],
                  s.polygons[0].position[1] + s.joints[0].aPoint[1]},
                 {3.0, 1.0}));
    const QByteArray first = SceneIO::serialize(s);
    const SceneLoadResult again = SceneIO::parse(first, kName);
    QVERIFY2(again.ok(), qPrintable(again.errorText()));
    QCOMPARE(SceneIO::serialize(*again.scene), first);
}

QTEST_APPLESS_MAIN(TestJointSceneIO)
#include "tst_sceneio_joints.moc"
