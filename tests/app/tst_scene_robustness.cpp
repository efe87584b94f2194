// Bad input of every kind, one row each: absurd magnitudes, NaN and Infinity, numbers past the
// double range, deep nesting, truncated, binary, empty and huge files, duplicate ids, dangling
// references, count limits. Each row checks the exact message (file, JSON path or
// line:column, what is wrong) and that loading returns instead of throwing. Then failed saves
// (read-only folder, missing folder, full disk) leave the old file byte for byte, and the app's
// edits refuse the same values the loader refuses.

#include "app/document/Document.h"
#include "app/io/SceneIO.h"
#include "physics/scene/BuildWorld.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QTemporaryDir>
#include <QTest>

#include <sys/resource.h>
#include <cmath>
#include <csignal>
#include <exception>

using namespace phasebox;

namespace {

const QString kName = QStringLiteral("robust.json");

QByteArray scene(const QByteArray& body = {}) {
    QByteArray text = R"({"format": "phasebox-scene", "version": 1)";
    if (!body.isEmpty()) text += ", " + body;
    return text + "}";
}

QString msg(const QString& path, const QString& what) {
    return kName + QStringLiteral(": ") + path + QStringLiteral(": ") + what;
}

QString at(int line, int column, const QString& what) {
    return QStringLiteral("%1:%2:%3: %4").arg(kName).arg(line).arg(column).arg(what);
}

QByteArray readAll(const QString& path) {
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray("<unreadable>");
}

bool writeFile(const QString& path, const QByteArray& bytes) {
    QFile file(path);
    return file.open(QIODevice::WriteOnly) && file.write(bytes) == bytes.size();
}

// Parses without letting an exception escape the test: one escaping is a failure in itself.
SceneLoadResult parseSafely(const QByteArray& json, bool* threw) {
    *threw = false;
    try {
        return SceneIO::parse(json, kName);
    } catch (...) {
        *threw = true;
        return {};
    }
}

// Limits raised by setrlimit(RLIMIT_FSIZE) for the full-disk case, restored on scope exit.
class FileSizeLimit {
public:
    explicit FileSizeLimit(rlim_t bytes) {
        ::getrlimit(RLIMIT_FSIZE, &saved_);
        // Past the limit the kernel sends SIGXFSZ, which kills by default; ignored, the write
        // fails with EFBIG instead, as on a full disk.
        previous_ = std::signal(SIGXFSZ, SIG_IGN);
        rlimit limit = saved_;
        limit.rlim_cur = bytes;
        active_ = ::setrlimit(RLIMIT_FSIZE, &limit) == 0;
    }
    ~FileSizeLimit() {
        ::setrlimit(RLIMIT_FSIZE, &saved_);
        std::signal(SIGXFSZ, previous_);
    }
    bool active() const { return active_; }

private:
    rlimit saved_{};
    void (*previous_)(int) = SIG_DFL;
    bool active_ = false;
};

}  // namespace

class TestSceneRobustness : public QObject {
    Q_OBJECT

private slots:
    void badInput_data();
    void badInput();
    void byteOrderMarkIsSkipped();
    void valuesAtTheLimitsLoadAndBuild();
    void badFiles_data();
    void badFiles();
    void longPinnedListBuildsInLinearTime();
    void failedSaveInReadOnlyFolderKeepsOldFile();
    void failedSaveIntoMissingFolder();
    void failedSaveOnFullDiskKeepsOldFile();
    void documentStaysModifiedWhenSaveFails();
    void propertyEditsRefuseAbsurdValues_data();
    void propertyEditsRefuseAbsurdValues();
    void moveRefusesPositionsPastTheLimit();
};

void TestSceneRobustness::badInput_data() {
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<QString>("expected");  // one line of the message, exactly

    // -- absurd magnitudes (SceneLimits, docs/scene-format.md "Limits")
    const QByteArray three = R"({"position": [0, 0]}, {"position": [1, 0]}, )";
    QTest::newRow("mass 1e300") << scene(R"("particles": [)" + three +
                                         R"({"position": [2, 0], "mass": 1e300}])")
                                << msg("particles[2].mass", "must be <= 1e12 (got 1e300)");
    QTest::newRow("mass 1e-300") << scene(R"("particles": [{"position": [0, 0], "mass": 1e-300}])")
                                 << msg("particles[0].mass", "must be >= 1e-12 (got 1e-300)");
    QTest::newRow("position 1e300")
        << scene(R"("particles": [{"position": [1e300, 0]}])")
        << msg("particles[0].position[0]", "must be between -1e6 and 1e6 (got 1e300)");
    QTest::newRow("velocity -1e7")
        << scene(R"("particles": [{"position": [0, 0], "velocity": [0, -1e7]}])")
        << msg("particles[0].velocity[1]", "must be between -1e6 and 1e6 (got -1e7)");
    QTest::newRow("radius 1e300") << scene(
                                         R"("particles": [{"position": [0, 0], "radius": 1e300}])")
                                  << msg("particles[0].radius", "must be <= 1e6 (got 1e300)");
    QTest::newRow("charge -1e300")
        << scene(R"("particles": [{"position": [0, 0], "charge": -1e300}])")
        << msg("particles[0].charge", "must be between -1e6 and 1e6 (got -1e300)");
    QTest::newRow("friction 1e300")
        << scene(R"("particles": [{"position": [0, 0], "friction": 1e300}])")
        << msg("particles[0].friction", "must be <= 1e12 (got 1e300)");
    QTest::newRow("box size 1e300")
        << scene(R"("boxes": [{"position": [0, 0], "size": [1e300, 1]}])")
        << msg("boxes[0].size[0]", "must be <= 1e6 (got 1e300)");
    QTest::newRow("box size 1e-9") << scene(R"("boxes": [{"position": [0, 0], "size": [1, 1e-9]}])")
                                   << msg("boxes[0].size[1]", "must be >= 1e-6 (got 1e-9)");
    QTest::newRow("box angle 1e20")
        << scene(R"("boxes": [{"position": [0, 0], "size": [1, 1], "angle": 1e20}])")
        << msg("boxes[0].angle", "must be between -1e6 and 1e6 (got 1e20)");
    QTest::newRow("box spin 1e300")
        << scene(R"("boxes": [{"position": [0, 0], "size": [1, 1], "angular_velocity": 1e300}])")
        << msg("boxes[0].angular_velocity", "must be between -1e6 and 1e6 (got 1e300)");
    QTest::newRow("box density 1e13")
        << scene(R"("boxes": [{"position": [0, 0], "size": [1, 1], "density": 1e13}])")
        << msg("boxes[0].density", "must be <= 1e12 (got 1e13)");
    QTest::newRow("box mass 1e300")
        << scene(R"("boxes": [{"position": [0, 0], "size": [1, 1], "mass": 1e300}])")
        << msg("boxes[0].mass", "must be <= 1e12 (got 1e300)");
    QTest::newRow("plane point 1e300")
        << scene(R"("planes": [{"point": [0, 1e300], "normal": [0, 1]}])")
        << msg("planes[0].point[1]", "must be between -1e6 and 1e6 (got 1e300)");
    QTest::newRow("plane normal tiny")
        << scene(R"("planes": [{"point": [0, 0], "normal": [1e-300, 0]}])")
        << msg("planes[0].normal",
               "is too short to give a direction (length 1e-300; at least 1e-12)");
    QTest::newRow("plane normal zero")
        << scene(R"("planes": [{"point": [0, 0], "normal": [0, 0]}])")
        << msg("planes[0].normal", "must be non-zero");
    const QByteArray ball = R"("particles": [{"id": "ball", "position": [0, 0]}], )";
    QTest::newRow("stiffness 1e300")
        << scene(ball + R"("springs": [{"a": "ball", "anchor": [0, 1], "stiffness": 1e300}])")
        << msg("springs[0].stiffness", "must be <= 1e12 (got 1e300)");
    QTest::newRow("spring damping 1e13")
        << scene(ball +
                 R"("springs": [{"a": "ball", "anchor": [0, 1], "stiffness": 1, "damping": 1e13}])")
        << msg("springs[0].damping", "must be <= 1e12 (got 1e13)");
    QTest::newRow("rest length 1e7")
        << scene(
               ball +
               R"("springs": [{"a": "ball", "anchor": [0, 1], "stiffness": 1, "rest_length": 1e7}])")
        << msg("springs[0].rest_length", "must be <= 1e6 (got 1e7)");
    QTest::newRow("anchor 1e300")
        << scene(ball + R"("springs": [{"a": "ball", "anchor": [-1e300, 1], "stiffness": 1}])")
        << msg("springs[0].anchor[0]", "must be between -1e6 and 1e6 (got -1e300)");
    QTest::newRow("cloth mass 1e300") << scene(R"("cloths": [{"id": "c", "mass": 1e300}])")
                                      << msg("cloths[0].mass", "must be <= 1e12 (got 1e300)");
    QTest::newRow("cloth stiffness 1e13")
        << scene(R"("cloths": [{"id": "c", "stiffness": {"structural": 1e13}}])")
        << msg("cloths[0].stiffness.structural", "must be <= 1e12 (got 1e13)");
    QTest::newRow("cloth size 1e300") << scene(R"("cloths": [{"id": "c", "size": [1, 1e300]}])")
                                      << msg("cloths[0].size[1]", "must be <= 1e6 (got 1e300)");
    QTest::newRow("gravity 1e300")
        << scene(R"("effects": {"gravity": {"g": [0, -1e300]}})")
        << msg("effects.gravity.g[1]", "must be between -1e6 and 1e6 (got -1e300)");
    QTest::newRow("drag 1e300") << scene(R"("effects": {"drag": {"quadratic": 1e300}})")
                                << msg("effects.drag.quadratic", "must be <= 1e12 (got 1e300)");
    QTest::newRow("attractor mass 1e31")
        << scene(
               R"("effects": {"newtonian_gravity": {"attractors": [{"position": [0, 0], "mass": 1e31}]}})")
        << msg("effects.newtonian_gravity.attractors[0].mass", "must be <= 1e30 (got 1e31)");
    QTest::newRow("wind 1e300")
        << scene(R"("effects": {"wind": {"velocity": [1e300, 0], "drag": 1}})")
        << msg("effects.wind.velocity[0]", "must be between -1e6 and 1e6 (got 1e300)");
    QTest::newRow("duration 1e300") << scene(R"("simulation": {"duration": 1e300})")
                                    << msg("simulation.duration", "must be <= 1e6 (got 1e300)");
    QTest::newRow("tolerance 1e300") << scene(R"("simulation": {"tolerance": 1e300})")
                                     << msg("simulation.tolerance", "must be <= 1e12 (got 1e300)");
    QTest::newRow("dt 1e300") << scene(R"("simulation": {"dt": 1e300})")
                              << msg("simulation.dt", "must be > 0 and <= 1 (got 1e300)");
    QTest::newRow("substeps 1e300") << scene(R"("simulation": {"substeps": 1e300})")
                                    << msg("simulation.substeps", "is out of range (got 1e+300)");
    QTest::newRow("substeps 10001") << scene(R"("simulation": {"substeps": 10001})")
                                    << msg("simulation.substeps", "must be <= 10000");
    QTest::newRow("version 1e300")
        << QByteArray(R"({"format": "phasebox-scene", "version": 1e300})")
        << msg("version",
               "the file is scene format version 1e+300, but this Phasebox reads "
               "version 2 at most; please update Phasebox");

    // -- counts past the documented limits
    // Issue #20: a 1000 x 1000 cloth took 77 s and 5.6 GB for `info`; 128 x 128 is the most.
    QTest::newRow("cloth of a million nodes")
        << scene(R"("cloths": [{"id": "c", "resolution": [1000, 1000]}])")
        << msg("cloths[0].resolution",
               "the cloth has 1000000 nodes (1000 x 1000); at most 16384 cloth nodes (128 x 128) "
               "are allowed in a scene");
    QTest::newRow("cloth of 2e9 nodes")
        << scene(R"("cloths": [{"id": "c", "resolution": [2000000000, 2]}])")
        << msg("cloths[0].resolution",
               "the cloth has 4000000000 nodes (2000000000 x 2); at most 16384 cloth nodes (128 x "
               "128) are allowed in a scene");
    QTest::newRow("two cloths past the limit together")
        << scene(R"("cloths": [{"id": "c", "resolution": [128, 100]},)"
                 R"( {"id": "d", "resolution": [100, 100]}])")
        << msg("cloths[1].resolution",
               "the cloth has 10000 nodes (100 x 100), 22800 with the cloths before it; at most "
               "16384 cloth nodes (128 x 128) are allowed in a scene");
    {
        QByteArray planes;
        for (int i = 0; i < 1001; ++i)
            planes += QByteArray(i ? "," : "") + R"({"point": [0, 0], "normal": [0, 1]})";
        QTest::newRow("1001 planes") << scene(R"("planes": [)" + planes + "]")
                                     << msg("planes", "at most 1000 planes are allowed");
    }

    // -- ids and references
    QTest::newRow("duplicate id")
        << scene(
               R"("particles": [{"id": "a", "position": [0, 0]}, {"id": "a", "position": [1, 0]}])")
        << msg("particles[1].id", R"(duplicate id "a" (also used by particles[0]))");
    QTest::newRow("id clashes with a default")
        << scene(
               R"("particles": [{"position": [0, 0]}], "boxes": [{"id": "p0", "position": [0, 0], "size": [1, 1]}])")
        << msg("boxes[0].id", R"(duplicate id "p0" (also used by particles[0]))");
    QTest::newRow("id clashes with a cloth node")
        << scene(
               R"("particles": [{"id": "c[0,0]", "position": [0, 0]}], "cloths": [{"id": "c", "resolution": [2, 2]}])")
        << msg("cloths[0].id", R"(duplicate id "c[0,0]" (also used by particles[0]))");
    QTest::newRow("dangling a")
        << scene(R"("springs": [{"a": "nobody", "anchor": [0, 0], "stiffness": 1}])")
        << msg("springs[0].a", R"(unknown object id "nobody")");
    QTest::newRow("dangling cloth node")
        << scene(
               R"("particles": [{"id": "p", "position": [0, 0]}], "cloths": [{"id": "c", "resolution": [2, 2]}],
                    "springs": [{"a": "p", "b": "c[5,5]", "stiffness": 1}])")
        << msg("springs[0].b", R"(unknown object id "c[5,5]")");
    QTest::newRow("spring to a plane")
        << scene(
               R"("particles": [{"id": "p", "position": [0, 0]}], "planes": [{"id": "ground", "point": [0, 0], "normal": [0, 1]}],
                    "springs": [{"a": "p", "b": "ground", "stiffness": 1}])")
        << msg("springs[0].b",
               R"("ground" is planes[0]; springs attach to particles, boxes, disks, polygons and cloth nodes)");
    QTest::newRow("pinned node off the grid")
        << scene(
               R"("cloths": [{"id": "c", "resolution": [3, 3], "pinned": [[0, 0], [-1, 2147483647]]}])")
        << msg("cloths[0].pinned[1]", "node [-1,2147483647] is outside the 3x3 grid");

    // -- syntax: NaN, Infinity, numbers past the double range, nesting, truncation, binary
    QTest::newRow("NaN")
        << scene(R"("particles": [{"position": [NaN, 0]}])")
        << at(1, 72, "illegal number: NaN is not a number JSON allows; write a finite number");
    QTest::newRow("Infinity")
        << scene(R"("simulation": {"dt": Infinity})")
        << at(1, 65, "illegal number: Infinity is not a number JSON allows; write a finite number");
    QTest::newRow("-Infinity")
        << scene(R"("simulation": {"dt": -Infinity})")
        << at(1, 65,
              "illegal number: -Infinity is not a number JSON allows; write a finite number");
    QTest::newRow("1e400")
        << scene(R"("simulation": {"dt": 1e400})")
        << at(1, 65, "illegal number: 1e400 is beyond the range of numbers (about ±1.8e308)");
    QTest::newRow("1e-400")
        << scene(R"("simulation": {"dt": 1e-400})")
        << at(1, 65, "illegal number: 1e-400 is too close to zero to be represented; write 0");
    QTest::newRow("nested 2000 deep")
        << scene(R"("x": )" + QByteArray(2000, '[') + QByteArray(2000, ']'))
        << at(1, 1073, "too deeply nested document (more than 1024 levels of arrays and objects)");
    QTest::newRow("truncated in a number")
        << QByteArray(
               R"({"format": "phasebox-scene", "version": 1, "particles": [{"position": [1, 2)")
        << at(1, 76, "the file ends before the JSON is complete (is it truncated?)");
    QTest::newRow("truncated after a key")
        << QByteArray("{\"format\": \"phasebox-scene\",\n \"version\":  \n\n")
        << at(4, 1, "the file ends before the JSON is complete (is it truncated?)");
    QTest::newRow("truncated in a string")
        << QByteArray(R"({"format": "phasebox-sc)") << at(1, 24, "unterminated string");
    QTest::newRow("binary garbage")
        << QByteArray("\x89PNG\r\n\x1a\n\0\0\0\rIHDR", 16)
        << at(1, 1, "binary data (byte 0x89), not UTF-8 JSON text: is this a scene file?");
    QTest::newRow("zero byte")
        << scene(R"("name": "a)" + QByteArray(1, '\0') + R"(b")")
        << at(1, 54, "binary data (byte 0x00), not UTF-8 JSON text: is this a scene file?");
    QTest::newRow("bad UTF-8 in a string")
        << scene("\"name\": \"caf\xe9\"")
        << at(1, 56, "binary data (byte 0xe9), not UTF-8 JSON text: is this a scene file?");
    QTest::newRow("UTF-16 file")
        << QByteArray("\xff\xfe{\0\"\0", 6)
        << at(1, 1, "binary data (byte 0xff), not UTF-8 JSON text: is this a scene file?");
    QTest::newRow("top level a number")
        << QByteArray(" 42")
        << at(1, 2, "the top level must be a JSON object {...}, not a single value");

    // -- wrong types at depth
    QTest::newRow("position a string")
        << scene(R"("particles": [{"position": "here"}])")
        << msg("particles[0].position", "must be an array of 2 numbers [x, y]");
    QTest::newRow("stiffness null")
        << scene(R"("cloths": [{"id": "c", "stiffness": {"shear": null}}])")
        << msg("cloths[0].stiffness.shear", "must be a number");
}

void TestSceneRobustness::badInput() {
    QFETCH(QByteArray, json);
    QFETCH(QString, expected);
    bool threw = false;
    const SceneLoadResult result = parseSafely(json, &threw);
    QVERIFY2(!threw, "SceneIO::parse threw");
    QVERIFY(!result.ok());
    QVERIFY2(result.errors.contains(expected),
             qPrintable(QStringLiteral("expected the line\n  %1\ngot\n  %2")
                            .arg(expected, result.errors.join(QStringLiteral("\n  ")))));
    for (const QString& line : result.errors)
        QVERIFY2(line.startsWith(kName + ':'), qPrintable(line));
}

void TestSceneRobustness::byteOrderMarkIsSkipped() {
    // Notepad's UTF-8 files start with a byte order mark: the file loads, and a syntax error's
    // column on line 1 does not count the mark.
    const SceneLoadResult good = SceneIO::parse("\xEF\xBB\xBF" + scene(), kName);
    QVERIFY2(good.ok(), qPrintable(good.errorText()));
    const SceneLoadResult bad = SceneIO::parse("\xEF\xBB\xBF{\"a\" 1}", kName);
    const SceneLoadResult plain = SceneIO::parse("{\"a\" 1}", kName);
    QVERIFY(!bad.ok());
    QCOMPARE(bad.errorText(), plain.errorText());
    QVERIFY2(bad.errorText().startsWith(kName + ":1:"), qPrintable(bad.errorText()));
}

void TestSceneRobustness::valuesAtTheLimitsLoadAndBuild() {
    // The bounds themselves are allowed, and such a scene builds and steps without a NaN.
    const SceneLoadResult loaded = SceneIO::parse(scene(R"("effects": {"gravity": {"g": [0, -1e6]}},
                 "particles": [{"position": [1e6, -1e6], "velocity": [1e6, -1e6], "mass": 1e12, "radius": 1e6},
                               {"position": [0, 0], "mass": 1e-12, "radius": 0}],
                 "boxes": [{"position": [0, 0], "size": [1e-6, 1e6], "angle": 1e6, "mass": 1e12}],
                 "planes": [{"point": [0, -1e6], "normal": [1e-12, 0]}])"),
                                                  kName);
    QVERIFY2(loaded.ok(), qPrintable(loaded.errorText()));
    BuildResult built = buildWorld(*loaded.scene);
    for (int k = 0; k < 10; ++k) {
        built.world->step();
        QVERIFY(built.world->positions().allFinite());
        QVERIFY(built.world->velocities().allFinite());
    }
}

void TestSceneRobustness::badFiles_data() {
    QTest::addColumn<QByteArray>("bytes");
    QTest::addColumn<QString>("expected");  // after "PATH: "
    QTest::newRow("empty") << QByteArray() << QStringLiteral("the file is empty");
    QTest::newRow("only spaces") << QByteArray(" \n\t\r\n ") << QStringLiteral("the file is empty");
    QTest::newRow("ELF binary")
        << QByteArray(
               "\x7f"
               "ELF\x02\x01\x01\0\0\0",
               10)
        << QStringLiteral(
               "1:5: binary data (byte 0x02), not UTF-8 JSON text: is this a scene file?");
    QTest::newRow("truncated scene")
        << scene(R"("particles": [{"position": [1, 2]}])").left(40)
        << QStringLiteral("1:41: the file ends before the JSON is complete (is it truncated?)");
}

void TestSceneRobustness::badFiles() {
    QFETCH(QByteArray, bytes);
    QFETCH(QString, expected);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("bad.phasebox.json"));
    QVERIFY(writeFile(path, bytes));
    const SceneLoadResult result = SceneIO::load(path);
    QVERIFY(!result.ok());
    const QString separator =
        expected.front().isDigit() ? QStringLiteral(":") : QStringLiteral(": ");
    QCOMPARE(result.errorText(), path + separator + expected);
}

void TestSceneRobustness::longPinnedListBuildsInLinearTime() {
    // 128 × 128 nodes (the largest cloth, issue #20), each pinned by name three times over:
    // looking every node up in the 49,152-entry list took 8e8 comparisons; a mask built once
    // takes 49,152.
    QByteArray pinned;
    for (int repeat = 0; repeat < 3; ++repeat)
        for (int j = 0; j < 128; ++j)
            for (int i = 0; i < 128; ++i)
                pinned += (pinned.isEmpty() ? "" : ",") +
                          QStringLiteral("[%1,%2]").arg(i).arg(j).toLatin1();
    const SceneLoadResult loaded = SceneIO::parse(
        scene(R"("cloths": [{"id": "c", "resolution": [128, 128], "pinned": [)" + pinned + "]}]"),
        kName);
    QVERIFY2(loaded.ok(), qPrintable(loaded.errorText()));
    const BuildResult built = buildWorld(*loaded.scene);
    int pinnedCount = 0;
    for (const Particle& p : built.world->particles()) pinnedCount += p.pinned;
    QCOMPARE(pinnedCount, 128 * 128);
}

void TestSceneRobustness::failedSaveInReadOnlyFolderKeepsOldFile() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString folder = dir.filePath(QStringLiteral("readonly"));
    QVERIFY(QDir().mkpath(folder));
    const QString old = folder + QStringLiteral("/scene.phasebox.json");
    const QByteArray oldBytes = SceneIO::serialize(SceneDesc{});
    QVERIFY(writeFile(old, oldBytes));
    QVERIFY(QFile::setPermissions(folder, QFile::ReadOwner | QFile::ExeOwner));
    // Root writes through permissions: probe whether this folder really refuses a file.
    const bool readOnly = !writeFile(folder + QStringLiteral("/probe"), "x");
    QFile::remove(folder + QStringLiteral("/probe"));

    SceneDesc changed;
    changed.name = "changed";
    QString error;
    QString target = old;
    QByteArray keptBytes = oldBytes;
    QString kept = old;
    if (!readOnly) {
        // As root: a path whose "folder" is a regular file fails for everyone, and that file
        // must come through untouched.
        kept = dir.filePath(QStringLiteral("plain.txt"));
        keptBytes = "not a folder";
        QVERIFY(writeFile(kept, keptBytes));
        target = kept + QStringLiteral("/scene.phasebox.json");
    }
    const bool saved = SceneIO::save(changed, target, &error);
    QFile::setPermissions(folder, QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner);
    QVERIFY(!saved);
    QVERIFY2(error.startsWith(target + QStringLiteral(": cannot write the file: ")),
             qPrintable(error));
    QVERIFY2(error.size() > (target + QStringLiteral(": cannot write the file: ")).size(),
             qPrintable(error));
    QCOMPARE(readAll(kept), keptBytes);
    QCOMPARE(readAll(old), oldBytes);
    QCOMPARE(QDir(folder).entryList(QDir::Files | QDir::Hidden),
             QStringList{"scene.phasebox.json"});
}

void TestSceneRobustness::failedSaveIntoMissingFolder() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString target = dir.filePath(QStringLiteral("no/such/folder/scene.phasebox.json"));
    QString error;
    QVERIFY(!SceneIO::save(SceneDesc{}, target, &error));
    QVERIFY2(error.startsWith(target + QStringLiteral(": cannot write the file: ")),
             qPrintable(error));
    QVERIFY(!QFileInfo::exists(dir.filePath(QStringLiteral("no"))));
}

void TestSceneRobustness::failedSaveOnFullDiskKeepsOldFile() {
    // A full disk, simulated with the file-size limit (which binds root too): the write of the
    // new contents fails part way, and the old file is still all there.
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("scene.phasebox.json"));
    const QByteArray oldBytes = SceneIO::serialize(SceneDesc{});
    QVERIFY(writeFile(path, oldBytes));
    SceneDesc big;
    big.description = std::string(64 * 1024, 'x');
    QString error;
    bool saved = true;
    {
        FileSizeLimit limit(4096);
        QVERIFY(limit.active());
        saved = SceneIO::save(big, path, &error);
    }
    QVERIFY(!saved);
    QVERIFY2(error.startsWith(path + QStringLiteral(": cannot write the file: ")),
             qPrintable(error));
    qInfo("full disk: %s", qPrintable(error));
    QCOMPARE(readAll(path), oldBytes);
    QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden),
             QStringList{"scene.phasebox.json"});
}

void TestSceneRobustness::documentStaysModifiedWhenSaveFails() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    Document doc;
    ParticleDesc p;
    QVERIFY(doc.addObject(p));
    QVERIFY(doc.isModified());
    QString error;
    const QString target = dir.filePath(QStringLiteral("missing/scene.phasebox.json"));
    QVERIFY(!doc.save(target, &error));
    QVERIFY2(error.contains(QStringLiteral("cannot write the file")), qPrintable(error));
    QVERIFY(doc.isModified());  // the work is still unsaved, and the app still says so
    QVERIFY(doc.filePath() != target);
}

void TestSceneRobustness::propertyEditsRefuseAbsurdValues_data() {
    QTest::addColumn<QString>("key");
    QTest::addColumn<double>("value");
    QTest::addColumn<QString>("expected");
    QTest::newRow("mass 1e300") << "mass" << 1e300
                                << "particles[0].mass: must be <= 1e12 (got 1e300)";
    QTest::newRow("mass NaN") << "mass" << std::nan("")
                              << "particles[0].mass: must be a finite number";
    QTest::newRow("radius inf") << "radius" << HUGE_VAL
                                << "particles[0].radius: must be a finite number";
    QTest::newRow("mass 0") << "mass" << 0.0 << "particles[0].mass: must be > 0 (got 0)";
}

void TestSceneRobustness::propertyEditsRefuseAbsurdValues() {
    QFETCH(QString, key);
    QFETCH(double, value);
    QFETCH(QString, expected);
    Document doc;
    ParticleDesc p;
    p.id = "ball";
    QVERIFY(doc.addObject(p));
    const double before = doc.setup().particles[0].mass;
    QString error;
    QVERIFY(!doc.setProperty(QStringLiteral("ball"), key, value, &error));
    QVERIFY2(error.contains(expected), qPrintable(error));
    QCOMPARE(doc.setup().particles[0].mass, before);
}

void TestSceneRobustness::moveRefusesPositionsPastTheLimit() {
    Document doc;
    ParticleDesc p;
    p.id = "ball";
    QVERIFY(doc.addObject(p));
    QString error;
    QVERIFY(!doc.moveObject(QStringLiteral("ball"), {2e6, 0.0}, &error));
    QVERIFY2(error.contains(QStringLiteral("must lie within")), qPrintable(error));
    QVERIFY(!doc.moveObject(QStringLiteral("ball"), {0.0, std::nan("")}, &error));
    QVERIFY(doc.moveObject(QStringLiteral("ball"), {1e6, -1e6}, &error));
}

QTEST_GUILESS_MAIN(TestSceneRobustness)
#include "tst_scene_robustness.moc"
