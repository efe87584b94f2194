// Scene files (CONTRACT.md §1): JSON ⇄ SceneDesc round trips, the defaults, every error
// message a user can meet (checked word for word), and saves that fail without harming the
// file that was there.

#include "SceneIOTestSupport.h"

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
using namespace phasebox::testing;

namespace {

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

}  // namespace

class TestSceneIO : public QObject {
    Q_OBJECT

private slots:
    void richSceneIsValid();
    void roundTripIsByteIdentical();
    void disksMakeAVersionTwoScene();
    void polygonsAreCheckedAndCentred();
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
    expectRefused(json, expected);
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
