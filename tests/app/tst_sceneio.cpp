// Scene files (CONTRACT.md §1): JSON ⇄ SceneDesc round trips, the defaults, every error
// message a user can meet (checked word for word), and saves that fail without harming the
// file that was there.

#include "app/io/SceneIO.h"
#include "physics/integrators/Integrator.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#ifdef Q_OS_UNIX
#include <unistd.h>
#endif

using namespace phasebox;

namespace {

const QString kName = QStringLiteral("lesson.json");

// A file with the required header and then body, e.g. scene(R"("particles": [])").
QByteArray scene(const char* body = "") {
    QByteArray json = R"({"format": "phasebox-scene", "version": 1)";
    if (*body) json += ", ";
    json += body;
    json += "}";
    return json;
}

// "lesson.json: PATH: what", the shape of every message but a syntax error's.
QString msg(const QString& path, const QString& what) {
    return kName + QStringLiteral(": ") + path + QStringLiteral(": ") + what;
}

QByteArray readAll(const QString& path) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) return QByteArray("<unreadable>");
    return file.readAll();
}

bool writeFile(const QString& path, const QByteArray& bytes) {
    QFile file(path);
    return file.open(QIODevice::WriteOnly) && file.write(bytes) == bytes.size();
}

bool sameBits(double a, double b) {
    return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

// Every field away from its default, ids given and left out, both kinds of spring end, both
// kinds of box mass and of cloth pinning, and numbers that have no short decimal form.
SceneDesc richScene() {
    SceneDesc s;
    s.name =
        "Rich \"scene\" \xc3\xbcnic\xc3\xb6"
        "de\ttab";
    s.description = "Every field set.\nA backslash \\, a slash / and a control char \x01.";

    s.simulation.integrator = "rk45";
    s.simulation.dt = 1.0 / 300.0;
    s.simulation.substeps = 3;
    s.simulation.tolerance = 1e-9;
    s.simulation.newtonIterations = 4;
    s.simulation.duration = 12.5;
    s.simulation.solver = {{"iterations", 25.0}, {"baumgarte", 0.2}, {"slop", 1e-3}};

    s.effects.gravity = GravityDesc{{0.1, -9.80665}};
    s.effects.drag = DragDesc{0.1, 0.02, 0.3};
    NewtonianGravityDesc ng;
    ng.G = 1.5;
    ng.attractors = {{{1.0 / 3.0, -2.0 / 7.0}, 1e3}, {{-4.0, 5.0}, 0.5}};
    ng.mutual = true;
    ng.softening = 0.05;
    s.effects.newtonianGravity = ng;
    s.effects.buoyancy = BuoyancyDesc{998.2, -1.5, 0.4};
    s.effects.wind = WindDesc{{2.5, -0.5}, 0.7};
    s.effects.flocking = FlockingDesc{1.5, 2.0, 0.5, 0.25, 3.0};
    s.effects.particleCollisions = ParticleCollisionsDesc{0.8};

    ParticleDesc ball;
    ball.id = "ball";
    ball.position = {0.1, 0.2};
    ball.velocity = {1.0 / 3.0, -1e-300};
    ball.mass = 2.5;
    ball.radius = 0.125;
    ball.pinned = true;
    ball.restitution = 0.9;
    ball.friction = 0.35;
    ball.charge = -1.602176634e-19;
    ParticleDesc anonymous;  // id left out: p1
    anonymous.position = {-1.0, 2.0};
    anonymous.mass = 0.1;
    s.particles = {ball, anonymous};

    BoxDesc crate;
    crate.id = "crate";
    crate.position = {3.0, -1.25};
    crate.size = {0.8, 0.5};
    crate.angle = 0.3;
    crate.velocity = {1.0, -0.5};
    crate.angularVelocity = -2.0;
    crate.mass = 3.0;
    crate.friction = 0.4;
    crate.restitution = 0.2;
    BoxDesc wall;
    wall.id = "wall";
    wall.position = {-6.0, 0.0};
    wall.size = {0.5, 4.0};
    wall.density = 2.5;
    wall.isStatic = true;
    s.boxes = {crate, wall};

    PlaneDesc ground;
    ground.id = "ground";
    ground.point = {0.0, -3.0};
    ground.normal = {0.6, 0.8};
    ground.friction = 0.7;
    ground.restitution = 0.1;
    s.planes = {ground};

    SpringDesc rope;
    rope.id = "rope";
    rope.a = "ball";
    rope.b = "crate";
    rope.aPoint = {0.01, 0.02};
    rope.bPoint = {0.4, 0.25};
    rope.stiffness = 150.0;
    rope.damping = 0.5;
    rope.restLength = 1.25;
    SpringDesc hook;  // id left out: s1
    hook.a = "flag[0,0]";
    hook.anchor = Point2{1.0, 2.0};
    hook.stiffness = 20.0;
    s.springs = {rope, hook};

    ClothDesc flag;
    flag.id = "flag";
    flag.origin = {5.0, 1.0};
    flag.size = {2.0, 1.5};
    flag.resolution = {4, 3};
    flag.mass = 0.3;
    flag.stiffness = {500.0, 50.0, 5.0};
    flag.damping = 0.01;
    flag.radius = 0.02;
    flag.pinned = std::vector<std::array<int, 2>>{{0, 0}, {3, 0}};
    ClothDesc sheet;
    sheet.id = "sheet";
    sheet.origin = {-5.0, 3.0};
    sheet.resolution = {3, 5};
    sheet.pinned = std::string("top_corners");
    s.cloths = {flag, sheet};
    return s;
}

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

class TestSceneIO : public QObject {
    Q_OBJECT

private slots:
    void richSceneIsValid();
    void roundTripIsByteIdentical();
    void disksMakeAVersionTwoScene();
    void polygonsAreCheckedAndCentred();
    void jointsRoundTripByteIdentical();
    void jointsMakeAVersionTwoScene();
    void jointsWriteOnlyTheFieldsTheirTypeUses();
    void jointErrors_data();
    void jointErrors();
    void jointPointsFollowARecentredPolygon();
    void roundTripKeepsValues();
    void roundTripThroughQJsonDocumentIndented();
    void numbersRoundTripExactly_data();
    void numbersRoundTripExactly();
    void serializeKeepsContractKeyOrder();
    void serializeWritesOptionalFieldsOnlyWhenSet();
    void minimalFileGivesDefaults();
    void effectsTrueOrEmptyMeanDefaults();
    void errors_data();
    void errors();
    void syntaxErrorColumnCountsCharacters();
    void farAwayUnknownKeysAreIgnored();
    void typeErrorsSkipValueChecks();
    void loadErrors();
    void saveAndLoad();
    void failedSaveLeavesFilesIntact();
    void demoSceneLoads();
};

void TestSceneIO::richSceneIsValid() {
    // The round trips below go through parse(), which validates; make a broken fixture
    // show up as itself rather than as a round-trip failure.
    const auto issues = validateScene(richScene());
    QString text;
    for (const SceneIssue& issue : issues)
        text += QString::fromStdString(issue.path + ": " + issue.message) + '\n';
    QVERIFY2(issues.empty(), qPrintable(text));
}

void TestSceneIO::roundTripIsByteIdentical() {
    const QByteArray first = SceneIO::serialize(richScene());
    const SceneLoadResult loaded = SceneIO::parse(first, kName);
    QVERIFY2(loaded.ok(), qPrintable(loaded.errorText()));
    const QByteArray second = SceneIO::serialize(*loaded.scene);
    QCOMPARE(second, first);
}

// CONTRACT §6: disks make a scene version 2; a scene without them stays version 1 with no
// `disks` key, so old files save unchanged. Both round-trip byte for byte.
void TestSceneIO::disksMakeAVersionTwoScene() {
    SceneDesc scene = richScene();
    const QByteArray old = SceneIO::serialize(scene);
    QVERIFY(old.contains(R"("version": 1)"));
    QVERIFY(!old.contains(R"("disks")"));
    DiskDesc wheel;
    wheel.id = "wheel";
    wheel.position = {1.0, 2.0};
    wheel.radius = 0.25;
    wheel.angularVelocity = -3.0;
    wheel.density = 2.0;
    scene.disks.push_back(wheel);
    DiskDesc heavy;
    heavy.position = {3.0, 0.5};
    heavy.mass = 7.5;
    heavy.isStatic = true;
    scene.disks.push_back(heavy);
    const QByteArray first = SceneIO::serialize(scene);
    QVERIFY(first.contains(R"("version": 2)"));
    const SceneLoadResult loaded = SceneIO::parse(first, kName);
    QVERIFY2(loaded.ok(), qPrintable(loaded.errorText()));
    QCOMPARE(loaded.scene->disks.size(), std::size_t(2));
    QCOMPARE(loaded.scene->disks[0].radius, 0.25);
    QCOMPARE(*loaded.scene->disks[1].mass, 7.5);
    QVERIFY(loaded.scene->disks[1].isStatic);
    QCOMPARE(SceneIO::serialize(*loaded.scene), first);
    // Bad input keeps its JSON path.
    const SceneLoadResult bad = SceneIO::parse(
        R"({"format": "phasebox-scene", "version": 2, "disks": [{"position": [0, 0], "radius": 0}]})",
        kName);
    QVERIFY(!bad.ok());
    QVERIFY2(bad.errorText().contains(QStringLiteral("disks[0].radius: must be")),
             qPrintable(bad.errorText()));
}

// CONTRACT §6: a bad polygon is refused at the vertex that breaks it; a good one is moved to
// its centroid on load, and saves in that form, byte for byte thereafter.
void TestSceneIO::polygonsAreCheckedAndCentred() {
    const auto errorsOf = [](const char* vertices) {
        const QByteArray text = QByteArray(R"({"format": "phasebox-scene", "version": 2, )") +
                                R"("polygons": [{"position": [0, 0], "vertices": )" + vertices +
                                "}]}";
        return SceneIO::parse(text, kName).errorText();
    };
    const auto expect = [&](const char* vertices, const QString& message) {
        const QString text = errorsOf(vertices);
        QVERIFY2(text.contains(message), qPrintable(text));
    };
    expect("[[0, 0], [2, 0], [1, 0.5], [2, 2], [0, 2]]",
           QStringLiteral("polygons[0].vertices[2]: the polygon is not convex here"));
    expect("[[0, 0], [1, 0], [2, 0], [1, 1]]",
           QStringLiteral("polygons[0].vertices[1]: three vertices in a line here"));
    expect("[[0, 0], [1, 0]]", QStringLiteral("polygons[0].vertices: must have 3 to 16 vertices "
                                              "(got 2)"));
    expect("[[0, 0], [1, 0], [1, 1], [1, 1]]",
           QStringLiteral("polygons[0].vertices[3]: repeats the vertex before it"));
    // A pentagram turns the same way at every vertex, twice round.
    expect("[[1, 0], [-0.809, 0.588], [0.309, -0.951], [0.309, 0.951], [-0.809, -0.588]]",
           QStringLiteral("polygons[0].vertices: the polygon is not convex: its edges cross"));
    expect("[[0, 0], [1e300, 0], [0, 1]]",
           QStringLiteral("polygons[0].vertices[1][0]: must be between"));

    const QByteArray offCentre =
        R"({"format": "phasebox-scene", "version": 2, "polygons": [{"id": "tri", )"
        R"("position": [2, 1], "vertices": [[0, 0], [0, 4], [3, 0]], "angle": 0, )"
        R"("angular_velocity": 3}]})";
    const SceneLoadResult loaded = SceneIO::parse(offCentre, kName);
    QVERIFY2(loaded.ok(), qPrintable(loaded.errorText()));
    const PolygonDesc& tri = loaded.scene->polygons[0];
    QVERIFY(std::abs(tri.position[0] - 3.0) < 1e-15 &&
            std::abs(tri.position[1] - 7.0 / 3.0) < 1e-15);
    QVERIFY(std::abs(tri.centroid()[0]) < 1e-15 && std::abs(tri.centroid()[1]) < 1e-15);
    QVERIFY(std::abs(tri.velocity[0] + 4.0) < 1e-15 && std::abs(tri.velocity[1] - 3.0) < 1e-15);
    const QByteArray first = SceneIO::serialize(*loaded.scene);
    const SceneLoadResult again = SceneIO::parse(first, kName);
    QVERIFY2(again.ok(), qPrintable(again.errorText()));
    QCOMPARE(SceneIO::serialize(*again.scene), first);
}

// CONTRACT §6: one joint of each type, with limits, a motor, a circle and a line, saves, loads
// and saves again byte for byte, and keeps its values.
void TestSceneIO::jointsRoundTripByteIdentical() {
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
void TestSceneIO::jointsMakeAVersionTwoScene() {
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
void TestSceneIO::jointsWriteOnlyTheFieldsTheirTypeUses() {
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

void TestSceneIO::jointErrors_data() {
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<QStringList>("expected");
    const auto row = [](const char* name, const char* joints, const QStringList& expected) {
        QTest::newRow(name) << jointFile(joints) << expected;
    };
    const QString oneOf = QStringLiteral("must be one of hinge, rod, rope, weld, pulley, track");
    const QString noTurn = QStringLiteral(
        "neither body can turn, so the joint angle cannot change; limits and a motor need a "
        "dynamic box, disk or polygon");
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
         msg("joints[1].motor", noTurn), msg("joints[2].limits", noTurn)});
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

void TestSceneIO::jointErrors() {
    QFETCH(QByteArray, json);
    QFETCH(QStringList, expected);
    const SceneLoadResult result = SceneIO::parse(json, kName);
    QVERIFY(!result.ok());
    QCOMPARE(result.errorText(), expected.join(QLatin1Char('\n')));
}

// CONTRACT §6: a joint's points on a polygon are in the frame its vertices are written in; when
// the polygon is re-centred on load by c, they shift by −c, so they stay on the same material
// points (and the file saves in the centred form).
void TestSceneIO::jointPointsFollowARecentredPolygon() {
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

void TestSceneIO::roundTripKeepsValues() {
    const SceneDesc original = richScene();
    const SceneLoadResult loaded = SceneIO::parse(SceneIO::serialize(original), kName);
    QVERIFY2(loaded.ok(), qPrintable(loaded.errorText()));
    const SceneDesc& s = *loaded.scene;

    QCOMPARE(s.name, original.name);
    QCOMPARE(s.description, original.description);
    QCOMPARE(s.simulation.integrator, std::string("rk45"));
    QVERIFY(sameBits(s.simulation.dt, 1.0 / 300.0));
    QCOMPARE(s.simulation.substeps, 3);
    QCOMPARE(s.simulation.newtonIterations, 4);
    QVERIFY(s.simulation.solver == original.simulation.solver);

    QVERIFY(s.effects.gravity && s.effects.drag && s.effects.newtonianGravity &&
            s.effects.buoyancy && s.effects.wind && s.effects.flocking &&
            s.effects.particleCollisions);
    QVERIFY(sameBits(s.effects.gravity->g[1], -9.80665));
    QCOMPARE(s.effects.newtonianGravity->attractors.size(), std::size_t(2));
    QVERIFY(sameBits(s.effects.newtonianGravity->attractors[0].position[0], 1.0 / 3.0));
    QVERIFY(sameBits(s.effects.newtonianGravity->attractors[0].position[1], -2.0 / 7.0));
    QVERIFY(s.effects.newtonianGravity->mutual);
    QVERIFY(sameBits(s.effects.flocking->maxSpeed, 3.0));

    QCOMPARE(s.particles.size(), std::size_t(2));
    QCOMPARE(s.particles[0].id, std::string("ball"));
    QVERIFY(s.particles[0].pinned);
    QVERIFY(sameBits(s.particles[0].velocity[1], -1e-300));
    QVERIFY(sameBits(s.particles[0].charge, -1.602176634e-19));
    QVERIFY(s.particles[1].id.empty());

    QVERIFY(s.boxes[0].mass && *s.boxes[0].mass == 3.0);
    QVERIFY(!s.boxes[1].mass);
    QVERIFY(sameBits(s.boxes[1].density, 2.5));
    QVERIFY(s.boxes[1].isStatic);
    QVERIFY(sameBits(s.planes[0].normal[0], 0.6));  // written as given, normalised only on build

    QCOMPARE(s.springs[0].b, std::optional<std::string>("crate"));
    QVERIFY(!s.springs[0].anchor);
    QVERIFY(s.springs[0].restLength && *s.springs[0].restLength == 1.25);
    QVERIFY(!s.springs[1].b);
    QVERIFY(s.springs[1].anchor && (*s.springs[1].anchor == Point2{1.0, 2.0}));
    QVERIFY(!s.springs[1].restLength);

    using Nodes = std::vector<std::array<int, 2>>;
    QVERIFY(std::holds_alternative<Nodes>(s.cloths[0].pinned));
    QVERIFY((std::get<Nodes>(s.cloths[0].pinned) == Nodes{{0, 0}, {3, 0}}));
    QCOMPARE(s.cloths[0].resolution, (std::array<int, 2>{4, 3}));
    QVERIFY(sameBits(s.cloths[0].stiffness.shear, 50.0));
    QCOMPARE(std::get<std::string>(s.cloths[1].pinned), std::string("top_corners"));
}

void TestSceneIO::roundTripThroughQJsonDocumentIndented() {
    // Whatever edits a file with Qt's own JSON writer (the app, a script) must not change a
    // number: re-emit our output with QJsonDocument::Indented and read it back.
    const QByteArray ours = SceneIO::serialize(richScene());
    QJsonParseError error;
    const QJsonDocument document = QJsonDocument::fromJson(ours, &error);
    QCOMPARE(error.error, QJsonParseError::NoError);
    const QByteArray qts = document.toJson(QJsonDocument::Indented);
    const SceneLoadResult loaded = SceneIO::parse(qts, kName);
    QVERIFY2(loaded.ok(), qPrintable(loaded.errorText()));
    QCOMPARE(SceneIO::serialize(*loaded.scene), ours);
}

void TestSceneIO::numbersRoundTripExactly_data() {
    QTest::addColumn<double>("value");
    QTest::newRow("0.1") << 0.1;
    QTest::newRow("1/3") << 1.0 / 3.0;
    QTest::newRow("-2/7") << -2.0 / 7.0;
    QTest::newRow("1/60") << 1.0 / 60.0;
    QTest::newRow("pi") << 3.141592653589793;
    QTest::newRow("2^53 + 2") << 9007199254740994.0;
    QTest::newRow("1e21") << 1e21;
    QTest::newRow("tiny") << 1e-300;
    QTest::newRow("denormal") << std::numeric_limits<double>::denorm_min();
    QTest::newRow("max") << std::numeric_limits<double>::max();
    QTest::newRow("-0 reads as +0") << -0.0;
}

void TestSceneIO::numbersRoundTripExactly() {
    QFETCH(double, value);
    // Carried by an engine-defined solver key: the only number the format keeps without a
    // range (scene-format.md, Limits), so that even DBL_MAX can be tried.
    SceneDesc s;
    s.simulation.solver["roundtrip_probe"] = value;
    const QByteArray text = SceneIO::serialize(s);
    const SceneLoadResult loaded = SceneIO::parse(text, kName);
    QVERIFY2(loaded.ok(), qPrintable(loaded.errorText()));
    // QJsonDocument reads "-0" and "-0.0" as +0, so the sign of zero is the one thing a file
    // cannot keep; it changes nothing in the physics.
    if (value == 0.0) value = 0.0;
    const double back = loaded.scene->simulation.solver.at("roundtrip_probe");
    QVERIFY2(sameBits(back, value), qPrintable(QString::number(back, 'g', 17)));
    // ... and through Qt's writer too.
    const QByteArray qts = QJsonDocument::fromJson(text).toJson(QJsonDocument::Indented);
    const SceneLoadResult again = SceneIO::parse(qts, kName);
    QVERIFY2(again.ok(), qPrintable(again.errorText()));
    QVERIFY(sameBits(again.scene->simulation.solver.at("roundtrip_probe"), value));
}

void TestSceneIO::serializeKeepsContractKeyOrder() {
    const QByteArray text = SceneIO::serialize(richScene());
    auto inOrder = [&](const QList<QByteArray>& keys) {
        qsizetype last = -1;
        for (const QByteArray& key : keys) {
            const qsizetype at = text.indexOf('"' + key + "\":", last + 1);
            if (at < 0 || at < last) return false;
            last = at;
        }
        return true;
    };
    QVERIFY(inOrder({"format", "version", "name", "description", "simulation", "effects",
                     "particles", "boxes", "planes", "springs", "cloths"}));
    QVERIFY(inOrder(
        {"integrator", "dt", "substeps", "tolerance", "newton_iterations", "duration", "solver"}));
    QVERIFY(inOrder({"gravity", "drag", "newtonian_gravity", "buoyancy", "wind", "flocking",
                     "particle_collisions"}));
    QVERIFY(inOrder({"id", "position", "velocity", "mass", "radius", "pinned", "restitution",
                     "friction", "charge"}));
    QVERIFY(text.startsWith("{\n  \"format\": \"phasebox-scene\",\n  \"version\": 1,\n"));
    QVERIFY(text.endsWith("}\n"));
}

void TestSceneIO::serializeWritesOptionalFieldsOnlyWhenSet() {
    SceneDesc s;
    BoxDesc byDensity;
    byDensity.density = 3.0;
    s.boxes = {byDensity};
    ParticleDesc p;
    s.particles = {p};
    SpringDesc spring;
    spring.a = "p0";
    spring.anchor = Point2{0.0, 0.0};
    spring.stiffness = 1.0;
    s.springs = {spring};

    const QByteArray text = SceneIO::serialize(s);
    QVERIFY(!text.contains("\"mass\": 3"));
    QVERIFY(text.contains("\"density\": 3"));
    QVERIFY(!text.contains("\"id\""));
    QVERIFY(!text.contains("\"b\""));
    QVERIFY(text.contains("\"anchor\": [0, 0]"));
    QVERIFY(!text.contains("\"rest_length\""));
    QVERIFY(!text.contains("\"solver\""));
    QVERIFY(text.contains("\"effects\": {}"));
    QVERIFY(text.contains("\"cloths\": []"));
    // Defaults are written: the file says what the scene is.
    QVERIFY(text.contains("\"integrator\": \"symplectic_euler\""));
    QVERIFY(text.contains("\"friction\": 0.2"));

    s.boxes[0].mass = 4.0;
    const QByteArray withMass = SceneIO::serialize(s);
    QVERIFY(withMass.contains("\"mass\": 4"));
    QVERIFY(!withMass.contains("\"density\""));
}

void TestSceneIO::minimalFileGivesDefaults() {
    const SceneLoadResult loaded =
        SceneIO::parse(R"({"format":"phasebox-scene","version":1})", kName);
    QVERIFY2(loaded.ok(), qPrintable(loaded.errorText()));
    QVERIFY(loaded.errors.isEmpty());
    const SceneDesc& s = *loaded.scene;
    const SceneDesc d;
    QCOMPARE(s.name, d.name);
    QCOMPARE(s.description, d.description);
    QCOMPARE(s.simulation.integrator, std::string("symplectic_euler"));
    QVERIFY(sameBits(s.simulation.dt, 1.0 / 60.0));
    QCOMPARE(s.simulation.substeps, 1);
    QVERIFY(sameBits(s.simulation.tolerance, 1e-6));
    QCOMPARE(s.simulation.newtonIterations, 1);
    QVERIFY(sameBits(s.simulation.duration, 10.0));
    QVERIFY(s.simulation.solver.empty());
    QVERIFY(!s.effects.gravity && !s.effects.drag && !s.effects.newtonianGravity &&
            !s.effects.buoyancy && !s.effects.wind && !s.effects.flocking &&
            !s.effects.particleCollisions);
    QVERIFY(s.particles.empty() && s.boxes.empty() && s.planes.empty() && s.springs.empty() &&
            s.cloths.empty());
    // And it serialises to what serialising the default scene gives.
    QCOMPARE(SceneIO::serialize(s), SceneIO::serialize(d));
}

void TestSceneIO::effectsTrueOrEmptyMeanDefaults() {
    const SceneLoadResult loaded = SceneIO::parse(
        scene(R"("effects": {"gravity": {}, "drag": true, "wind": false, "buoyancy": null,
                             "newtonian_gravity": {"G": 2},
                             "particles_collisions_note": "far away: ignored"},
                 "particles": [{"position": [0, 0]}],
                 "boxes": [{"position": [1, 1], "size": [1, 2]}],
                 "cloths": [{"id": "c"}])"),
        kName);
    QVERIFY2(loaded.ok(), qPrintable(loaded.errorText()));
    const SceneDesc& s = *loaded.scene;
    QVERIFY(s.effects.gravity);
    QCOMPARE(s.effects.gravity->g, (Point2{0.0, -9.81}));
    QVERIFY(s.effects.drag);
    QCOMPARE(s.effects.drag->linear, 0.0);
    QVERIFY(!s.effects.wind);
    QVERIFY(!s.effects.buoyancy);
    QVERIFY(s.effects.newtonianGravity);
    QCOMPARE(s.effects.newtonianGravity->G, 2.0);
    QVERIFY(s.effects.newtonianGravity->attractors.empty());
    QVERIFY(!s.effects.particleCollisions);
    // Object defaults.
    QCOMPARE(s.particles[0].mass, 1.0);
    QCOMPARE(s.particles[0].radius, 0.05);
    QVERIFY(!s.boxes[0].mass);
    QCOMPARE(s.boxes[0].resolvedMass(), 2.0);  // density 1 · 1 · 2
    QCOMPARE(s.cloths[0].resolution, (std::array<int, 2>{10, 10}));
    QCOMPARE(std::get<std::string>(s.cloths[0].pinned), std::string("top"));
}

void TestSceneIO::errors_data() {
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<QStringList>("expected");

    // -- syntax: one message, FILE:LINE:COL, 1-based
    QTest::newRow("syntax: bad value") << QByteArray("{\n  \"format\": 1,\n  \"b\": @\n}")
                                       << QStringList{"lesson.json:3:8: illegal number"};
    QTest::newRow("syntax: missing comma") << QByteArray("{\n  \"a\": 1\n  \"b\": 2\n}")
                                           << QStringList{"lesson.json:3:4: unterminated object"};
    // Qt puts the offset of an unterminated string one past the end of the text.
    QTest::newRow("syntax: unterminated string")
        << QByteArray("{\n  \"a\": 1,\n  \"b\": \"abc\n}")
        << QStringList{"lesson.json:4:2: unterminated string"};
    QTest::newRow("syntax: empty")
        << QByteArray("") << QStringList{"lesson.json:1:1: illegal value"};

    // -- header
    QTest::newRow("top level array")
        << QByteArray("[1, 2]")
        << QStringList{"lesson.json: the top level must be a JSON object {...}"};
    QTest::newRow("format missing")
        << QByteArray(R"({"version": 1})") << QStringList{msg("format", "is required")};
    QTest::newRow("format wrong")
        << QByteArray(R"({"format": "phasebox-scen", "version": 1})")
        << QStringList{msg("format", R"(must be "phasebox-scene" (got "phasebox-scen"))")};
    QTest::newRow("format not a string")
        << QByteArray(R"({"format": 1, "version": 1})")
        << QStringList{msg("format", R"(must be "phasebox-scene")")};
    QTest::newRow("version missing") << QByteArray(R"({"format": "phasebox-scene"})")
                                     << QStringList{msg("version", "is required")};
    QTest::newRow("version a string")
        << QByteArray(R"({"format": "phasebox-scene", "version": "1"})")
        << QStringList{msg("version", "must be an integer")};
    QTest::newRow("version fractional")
        << QByteArray(R"({"format": "phasebox-scene", "version": 1.5})")
        << QStringList{msg("version", "must be an integer")};
    QTest::newRow("version 0") << QByteArray(R"({"format": "phasebox-scene", "version": 0})")
                               << QStringList{msg("version", "must be >= 1 (got 0)")};
    QTest::newRow("version newer")
        << QByteArray(R"({"format": "phasebox-scene", "version": 3, "bodies": [], "x": 1})")
        << QStringList{msg("version",
                           "the file is scene format version 3, but this Phasebox reads "
                           "version 2 at most; please update Phasebox")};
    QTest::newRow("format and version both wrong")
        << QByteArray(R"({"format": "other", "version": "one"})")
        << QStringList{msg("format", R"(must be "phasebox-scene" (got "other"))"),
                       msg("version", "must be an integer")};

    // -- misspelt keys
    QTest::newRow("stifness") << scene(R"("particles": [{"id": "ball", "position": [0, 0]}],
                    "springs": [{"a": "ball", "anchor": [0, 1], "stifness": 10}])")
                              << QStringList{msg("springs[0].stifness",
                                                 R"(unknown key; did you mean "stiffness"?)"),
                                             msg("springs[0].stiffness", "is required")};
    QTest::newRow("solver iteratons")
        << scene(R"("simulation": {"solver": {"iteratons": 8, "engine_private_knob": 1}})")
        << QStringList{
               msg("simulation.solver.iteratons", R"(unknown key; did you mean "iterations"?)")};
    QTest::newRow("gravty") << scene(R"("effects": {"gravty": {"g": [0, -1]}})")
                            << QStringList{msg("effects.gravty",
                                               R"(unknown key; did you mean "gravity"?)")};
    QTest::newRow("g for G") << scene(R"("effects": {"newtonian_gravity": {"g": 1}})")
                             << QStringList{msg("effects.newtonian_gravity.g",
                                                R"(unknown key; did you mean "G"?)")};
    QTest::newRow("camelCase") << scene(R"("particles": [{"id": "ball", "position": [0, 0]}],
                    "springs": [{"a": "ball", "anchor": [0, 1], "stiffness": 1,
                                 "restLength": 2}])")
                               << QStringList{msg("springs[0].restLength",
                                                  R"(unknown key; did you mean "rest_length"?)")};
    QTest::newRow("top level") << scene(R"("partcles": [])")
                               << QStringList{
                                      msg("partcles", R"(unknown key; did you mean "particles"?)")};
    QTest::newRow("nested objects")
        << scene(R"("simulation": {"substep": 2},
                    "effects": {"newtonian_gravity": {"attractors": [{"positon": [0, 0]}]},
                                "drag": {"Linear": 1}},
                    "cloths": [{"id": "c", "stiffness": {"structual": 1}}])")
        << QStringList{
               msg("simulation.substep", R"(unknown key; did you mean "substeps"?)"),
               msg("effects.drag.Linear", R"(unknown key; did you mean "linear"?)"),
               msg("effects.newtonian_gravity.attractors[0].positon",
                   R"(unknown key; did you mean "position"?)"),
               msg("cloths[0].stiffness.structual", R"(unknown key; did you mean "structural"?)")};

    // -- values (validateScene)
    QTest::newRow("negative mass") << scene(R"("particles": [{"position": [0, 0], "mass": -1}])")
                                   << QStringList{msg("particles[0].mass", "must be > 0 (got -1)")};
    QTest::newRow("box size") << scene(R"("boxes": [{"position": [0, 0], "size": [1, 1]},
                              {"position": [2, 0], "size": [1, 1]},
                              {"position": [4, 0], "size": [1, 1]},
                              {"position": [6, 0], "size": [-1, 1]}])")
                              << QStringList{msg("boxes[3].size[0]", "must be > 0 (got -1)")};
    QTest::newRow("unknown id") << scene(R"("particles": [{"id": "ball", "position": [0, 0]}],
                    "springs": [{"a": "ball", "b": "q7", "stiffness": 1}])")
                                << QStringList{msg("springs[0].b", R"(unknown object id "q7")")};
    QTest::newRow("rk5") << scene(R"("simulation": {"integrator": "rk5"})")
                         << QStringList{msg("simulation.integrator",
                                            QStringLiteral("unknown integrator \"rk5\"; known: ") +
                                                QString::fromStdString(knownIntegratorNames()))};
    QTest::newRow("all value problems")
        << scene(R"("simulation": {"dt": 2},
                    "effects": {"drag": {"linear": -1}},
                    "particles": [{"position": [0, 0], "radius": -0.5}])")
        << QStringList{msg("simulation.dt", "must be > 0 and <= 1 (got 2)"),
                       msg("effects.drag.linear", "must be >= 0 (got -1)"),
                       msg("particles[0].radius", "must be >= 0 (got -0.5)")};

    // -- types
    QTest::newRow("scalars")
        << scene(R"("name": 5, "simulation": {"integrator": 4, "dt": "fast", "substeps": 2.5,
                                               "newton_iterations": "2"})")
        << QStringList{msg("name", "must be a string"),
                       msg("simulation.integrator", "must be a string"),
                       msg("simulation.dt", "must be a number"),
                       msg("simulation.substeps", "must be an integer"),
                       msg("simulation.newton_iterations", "must be an integer")};
    QTest::newRow("points")
        << scene(R"("particles": [{"position": [1]}, {"position": [1, "a"]}, {"position": "here"},
                                  {"position": [0, 0], "velocity": [1, 2, 3]}],
                    "boxes": [{"position": [0, 0], "size": [1]}])")
        << QStringList{msg("particles[0].position", "must be an array of 2 numbers [x, y]"),
                       msg("particles[1].position[1]", "must be a number"),
                       msg("particles[2].position", "must be an array of 2 numbers [x, y]"),
                       msg("particles[3].velocity", "must be an array of 2 numbers [x, y]"),
                       msg("boxes[0].size", "must be an array of 2 numbers [w, h]")};
    QTest::newRow("booleans") << scene(R"("particles": [{"position": [0, 0], "pinned": "yes"}],
                    "effects": {"newtonian_gravity": {"mutual": 1}})")
                              << QStringList{msg("effects.newtonian_gravity.mutual",
                                                 "must be true or false"),
                                             msg("particles[0].pinned", "must be true or false")};
    QTest::newRow("containers")
        << scene(R"("simulation": [], "effects": 5, "particles": {}, "boxes": [3],
                    "cloths": [{"id": "c", "stiffness": 2}])")
        << QStringList{msg("simulation", "must be an object"), msg("effects", "must be an object"),
                       msg("particles", "must be an array"), msg("boxes[0]", "must be an object"),
                       msg("cloths[0].stiffness", "must be an object")};
    QTest::newRow("effect value") << scene(R"("effects": {"gravity": 5})")
                                  << QStringList{msg("effects.gravity",
                                                     "must be an object, true or false")};
    QTest::newRow("solver") << scene(R"("simulation": {"solver": {"iterations": "ten"}})")
                            << QStringList{msg("simulation.solver.iterations", "must be a number")};
    QTest::newRow("integers")
        << scene(R"("cloths": [{"id": "c", "resolution": [2.5, 3],
                                "pinned": [[0, 1.5], [1], "x"]},
                               {"id": "d", "resolution": 4, "pinned": 5}])")
        << QStringList{
               msg("cloths[0].resolution[0]", "must be an integer"),
               msg("cloths[0].pinned[0][1]", "must be an integer"),
               msg("cloths[0].pinned[1]", "must be an array of 2 integers [i, j]"),
               msg("cloths[0].pinned[2]", "must be an array of 2 integers [i, j]"),
               msg("cloths[1].resolution", "must be an array of 2 integers [nx, ny]"),
               msg("cloths[1].pinned",
                   "must be a string (top, top_corners, left, none) or an array of [i, j] pairs")};
    QTest::newRow("required")
        << scene(R"("particles": [{}], "boxes": [{}], "planes": [{}], "springs": [{}],
                    "cloths": [{}])")
        << QStringList{
               msg("particles[0].position", "is required"), msg("boxes[0].position", "is required"),
               msg("boxes[0].size", "is required"),         msg("planes[0].point", "is required"),
               msg("planes[0].normal", "is required"),      msg("springs[0].a", "is required"),
               msg("springs[0].stiffness", "is required"),  msg("cloths[0].id", "is required")};
    QTest::newRow("mass and density")
        << scene(R"("boxes": [{"position": [0, 0], "size": [1, 1], "mass": 1, "density": 1}])")
        << QStringList{msg("boxes[0]", "give mass or density, not both")};
}

void TestSceneIO::errors() {
    QFETCH(QByteArray, json);
    QFETCH(QStringList, expected);
    const SceneLoadResult result = SceneIO::parse(json, kName);
    QVERIFY(!result.ok());
    QCOMPARE(result.errorText(), expected.join(QLatin1Char('\n')));
}

void TestSceneIO::syntaxErrorColumnCountsCharacters() {
    // "é" is two bytes; the column counts it once, as an editor does: column 19 is the "x".
    const QByteArray json = "{\"name\": \"h\xc3\xa9llo\" \"x\"}";
    const SceneLoadResult result = SceneIO::parse(json, kName);
    QCOMPARE(result.errorText(), QStringLiteral("lesson.json:1:19: unterminated object"));
}

void TestSceneIO::farAwayUnknownKeysAreIgnored() {
    const SceneLoadResult loaded =
        SceneIO::parse(scene(R"("comment": "made by hand", "_editor": {"zoom": 2},
                 "simulation": {"integrator": "rk4", "note": "fast enough"},
                 "effects": {"my_plugin_effect": {"k": 1}},
                 "particles": [{"position": [0, 0], "x": 1, "colour": "red"}],
                 "springs": [{"a": "p0", "anchor": [0, 1], "stiffness": 1, "tags": []}])"),
                       kName);
    QVERIFY2(loaded.ok(), qPrintable(loaded.errorText()));
    QCOMPARE(loaded.scene->simulation.integrator, std::string("rk4"));
}

void TestSceneIO::typeErrorsSkipValueChecks() {
    // After a type error the description holds a default there; only the type error is real.
    const SceneLoadResult result = SceneIO::parse(
        scene(R"("particles": [{"position": [0, 0], "mass": -1, "radius": "big"}])"), kName);
    QCOMPARE(result.errorText(), msg("particles[0].radius", "must be a number"));
}

void TestSceneIO::loadErrors() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());

    const QString missing = dir.filePath("missing.phasebox.json");
    SceneLoadResult r = SceneIO::load(missing);
    QVERIFY(!r.ok());
    QCOMPARE(r.errors.size(), 1);
    QVERIFY2(r.errors[0].startsWith(missing + ": cannot read the file: "), qPrintable(r.errors[0]));
    QVERIFY(r.errors[0].size() > (missing + ": cannot read the file: ").size());

    const QString empty = dir.filePath("empty.json");
    QVERIFY(writeFile(empty, ""));
    r = SceneIO::load(empty);
    QCOMPARE(r.errorText(), empty + ": the file is empty");

    r = SceneIO::load(dir.path());
    QCOMPARE(r.errorText(), dir.path() + ": cannot read the file: it is a folder");

    const QString huge = dir.filePath("huge.json");
    {
        QFile file(huge);
        QVERIFY(file.open(QIODevice::WriteOnly));
        QVERIFY(file.resize(qint64(64) * 1024 * 1024 + 1));  // sparse: costs no disk
    }
    r = SceneIO::load(huge);
    QCOMPARE(r.errorText(), huge + ": the file is larger than 64 MiB, too large for a scene");

    // The message of a bad file names the path as given.
    const QString bad = dir.filePath("bad.json");
    QVERIFY(writeFile(bad, scene(R"("particles": [{"position": [0, 0], "mass": 0}])")));
    r = SceneIO::load(bad);
    QCOMPARE(r.errorText(), bad + ": particles[0].mass: must be > 0 (got 0)");
}

void TestSceneIO::saveAndLoad() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath("rich.phasebox.json");
    QVERIFY(writeFile(path, "old contents"));

    QString error;
    QVERIFY2(SceneIO::save(richScene(), path, &error), qPrintable(error));
    QVERIFY(error.isEmpty());
    QCOMPARE(readAll(path), SceneIO::serialize(richScene()));

    const SceneLoadResult loaded = SceneIO::load(path);
    QVERIFY2(loaded.ok(), qPrintable(loaded.errorText()));
    QCOMPARE(SceneIO::serialize(*loaded.scene), SceneIO::serialize(richScene()));
    // No temporary files left behind.
    QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden),
             QStringList{"rich.phasebox.json"});
}

void TestSceneIO::failedSaveLeavesFilesIntact() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const SceneDesc s = richScene();
    QString error;
    auto failsNaming = [&](const QString& path) {
        error.clear();
        const bool saved = SceneIO::save(s, path, &error);
        return !saved && error.startsWith(path + ": cannot write the file: ") &&
               error.size() > (path + ": cannot write the file: ").size();
    };

    // A folder that does not exist.
    const QString inMissingDir = dir.filePath("no/such/folder/scene.json");
    QVERIFY2(failsNaming(inMissingDir), qPrintable(error));
    QVERIFY(!QFileInfo::exists(dir.filePath("no")));

    // A regular file used as a folder: fails even for root, and the file is untouched.
    const QString plain = dir.filePath("plain.txt");
    QVERIFY(writeFile(plain, "keep me"));
    QVERIFY2(failsNaming(plain + "/scene.json"), qPrintable(error));
    QCOMPARE(readAll(plain), QByteArray("keep me"));

    // A folder where the scene file should be: nothing can replace it.
    const QString folder = dir.filePath("folder.json");
    QVERIFY(QDir().mkpath(folder));
    QVERIFY(writeFile(folder + "/inside.txt", "keep me too"));
    QVERIFY2(failsNaming(folder), qPrintable(error));
    QVERIFY(QFileInfo(folder).isDir());
    QCOMPARE(readAll(folder + "/inside.txt"), QByteArray("keep me too"));

    // A read-only folder holding an older scene. Root writes through permissions, so this
    // part needs an ordinary user.
#ifdef Q_OS_UNIX
    if (::geteuid() == 0) {
        qInfo("running as root: read-only folder case skipped (permissions do not stop root)");
        return;
    }
#endif
    const QString readOnly = dir.filePath("readonly");
    QVERIFY(QDir().mkpath(readOnly));
    const QString old = readOnly + "/scene.json";
    const QByteArray oldBytes = SceneIO::serialize(SceneDesc{});
    QVERIFY(writeFile(old, oldBytes));
    QVERIFY(QFile::setPermissions(readOnly, QFile::ReadOwner | QFile::ExeOwner));
    const bool failed = failsNaming(old);
    QFile::setPermissions(readOnly, QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner);
    QVERIFY2(failed, qPrintable(error));
    QCOMPARE(readAll(old), oldBytes);
    QCOMPARE(QDir(readOnly).entryList(QDir::Files | QDir::Hidden), QStringList{"scene.json"});
}

void TestSceneIO::demoSceneLoads() {
    const QString path = QStringLiteral(PHASEBOX_SOURCE_DIR) +
                         QStringLiteral("/resources/scenes/demo.phasebox.json");
    const SceneLoadResult loaded = SceneIO::load(path);
    QVERIFY2(loaded.ok(), qPrintable(loaded.errorText()));
    QVERIFY(!loaded.scene->particles.empty());
    // And it survives a save and reload unchanged.
    const QByteArray text = SceneIO::serialize(*loaded.scene);
    const SceneLoadResult again = SceneIO::parse(text, path);
    QVERIFY2(again.ok(), qPrintable(again.errorText()));
    QCOMPARE(SceneIO::serialize(*again.scene), text);
}

QTEST_APPLESS_MAIN(TestSceneIO)
#include "tst_sceneio.moc"
