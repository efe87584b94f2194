// Scene input the loader used to get wrong (issue #20): numbers the JSON grammar forbids
// ("invalid number" with line and column, where Qt said "unterminated object"), duplicate keys
// (Qt keeps the last silently), a 20 MB token echoed whole in a message, a tolerance below
// what a double can meet, and a FIFO, device or folder given as the scene (a FIFO blocked the
// open for ever, in the CLI and in the app's Open). Also the size limits of the largest scenes.

#include "app/document/Document.h"
#include "app/io/SceneIO.h"
#include "physics/scene/BuildWorld.h"
#include "physics/scene/SceneDesc.h"

#include <QElapsedTimer>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include <sys/stat.h>

using namespace phasebox;

namespace {

const QString kName = QStringLiteral("input.json");

QByteArray scene(const QByteArray& body) {
    return R"({"format": "phasebox-scene", "version": 1, )" + body + "}";
}

QString parseError(const QByteArray& json) {
    const SceneLoadResult r = SceneIO::parse(json, kName);
    return r.ok() ? QStringLiteral("<accepted>") : r.errorText();
}

std::string firstIssue(const SceneDesc& s) {
    const auto issues = validateScene(s);
    return issues.empty() ? std::string("<valid>")
                          : issues.front().path + ": " + issues.front().message;
}

}  // namespace

class TestSceneInput : public QObject {
    Q_OBJECT

private slots:
    // The number sits at column 65 in every row: {"format": ..., "simulation": {"dt": HERE}}.
    void invalidNumbersAreNamedWithLineAndColumn_data() {
        QTest::addColumn<QByteArray>("number");
        QTest::addColumn<QString>("what");
        QTest::newRow("0x10") << QByteArray("0x10")
                              << "invalid number \"0x10\": hexadecimal numbers are not JSON; "
                                 "write it in decimal";
        QTest::newRow("01") << QByteArray("01")
                            << "invalid number \"01\": leading zeros are not allowed (write 1, "
                               "not 01)";
        QTest::newRow("-01") << QByteArray("-01")
                             << "invalid number \"-01\": leading zeros are not allowed (write "
                                "1, not 01)";
        QTest::newRow("+1") << QByteArray("+1")
                            << "invalid number \"+1\": JSON numbers have no leading +";
        QTest::newRow(".5") << QByteArray(".5")
                            << "invalid number \".5\": a digit is needed before the decimal "
                               "point (0.5, not .5)";
        QTest::newRow("1.") << QByteArray("1.")
                            << "invalid number \"1.\": a digit is needed after the decimal point "
                               "(1.0, not 1.)";
        QTest::newRow("1e") << QByteArray("1e")
                            << "invalid number \"1e\": the exponent has no digits";
        QTest::newRow("1e+") << QByteArray("1e+")
                             << "invalid number \"1e+\": the exponent has no digits";
        QTest::newRow("1.2.3") << QByteArray("1.2.3")
                               << "invalid number \"1.2.3\": not a number JSON allows";
        QTest::newRow("-") << QByteArray("-") << "invalid number \"-\": a sign without digits";
        QTest::newRow("20 MB hexadecimal")
            << "0x" + QByteArray(20000000, '7')
            << QStringLiteral("invalid number \"0x") + QString(38, '7') +
                   QStringLiteral(
                       "... (20000002 characters)\": hexadecimal numbers are not "
                       "JSON; write it in decimal");
    }

    void invalidNumbersAreNamedWithLineAndColumn() {
        QFETCH(QByteArray, number);
        QFETCH(QString, what);
        const QByteArray json = scene(R"("simulation": {"dt": )" + number + "}");
        QCOMPARE(parseError(json), kName + QStringLiteral(":1:65: ") + what);
        // On a later line, and after an earlier valid number: line and column follow it.
        const QByteArray later = scene(
            "\n  \"name\": \"x\",\n  \"simulation\": {\"substeps\": 2, \"dt\": " + number + "}");
        QCOMPARE(parseError(later), kName + QStringLiteral(":3:39: ") + what);
    }

    // Valid JSON numbers of every form still load.
    void everyValidNumberFormLoads() {
        for (const char* n : {"0", "-0", "0.5", "1e-3", "1E-3", "1e+0", "2.5e-1", "-0.0e0"}) {
            const QByteArray json =
                scene(R"("particles": [{"position": [)" + QByteArray(n) + R"(, 0]}])");
            QVERIFY2(SceneIO::parse(json, kName).ok(), n);
        }
    }

    // A 20 MB number (too large for a double) is not echoed whole.
    void aHugeNumberIsCutInTheMessage() {
        const QByteArray json = scene(R"("simulation": {"dt": )" + QByteArray(20000000, '9') + "}");
        const QString error = parseError(json);
        QVERIFY2(error.size() < 300, qPrintable(error.left(300)));
        QCOMPARE(error, kName + QStringLiteral(":1:65: illegal number: ") + QString(40, '9') +
                            QStringLiteral("... (20000000 characters) is beyond the range of "
                                           "numbers (about ±1.8e308)"));
    }

    void aHugeStringIsCutInTheMessage() {
        const QByteArray name(20000000, 'q');
        // (Not raw strings: moc misreads a raw string that ends in a quote.)
        QString error = parseError(scene("\"simulation\": {\"integrator\": \"" + name + "\"}"));
        QVERIFY2(error.size() < 400, qPrintable(error.left(400)));
        QVERIFY2(error.startsWith(kName +
                                  QStringLiteral(": simulation.integrator: unknown "
                                                 "integrator \"") +
                                  QString(40, 'q') + QStringLiteral("...\" (20000000 bytes)")),
                 qPrintable(error));
        error =
            parseError(scene("\"particles\": [{\"position\": [0, 0]}], \"springs\": "
                             "[{\"a\": \"" +
                             name + "\", \"anchor\": [0, 0], \"stiffness\": 1}]"));
        QVERIFY2(error.size() < 300, qPrintable(error.left(300)));
        QVERIFY2(error.contains(QStringLiteral("unknown object id \"") + QString(40, 'q') +
                                QStringLiteral("...\" (20000000 bytes)")),
                 qPrintable(error));
    }

    // Duplicate keys: refused with their JSON path and both places.
    void duplicateKeysAreRefusedWithTheirPath_data() {
        QTest::addColumn<QByteArray>("json");
        QTest::addColumn<QString>("expected");
        QTest::newRow("top level")
            << QByteArray(R"({"format": "phasebox-scene", "version": 1, "name": "a", "name": "b"})")
            << kName +
                   ": name: duplicate key (at 1:44 and again at 1:57); "
                   "JSON keeps only one of them, so give it once";
        QTest::newRow("simulation.dt")
            << scene(R"("simulation": {"dt": 0.1, "dt": 0.2})")
            << kName +
                   ": simulation.dt: duplicate key (at 1:59 and again at 1:70); JSON keeps "
                   "only one of them, so give it once";
        QTest::newRow("in an array element")
            << scene(
                   "\"particles\": [{\"position\": [0, 0]},\n{\"position\": [1, 0], \"mass\": 1, "
                   "\"mass\": 2}]")
            << kName +
                   ": particles[1].mass: duplicate key (at 2:22 and again at 2:33); JSON "
                   "keeps only one of them, so give it once";
        QTest::newRow("escaped spelling")
            << scene(R"("particles": [{"position": [0, 0], "mass": 1, "m\u0061ss": 2}])")
            << kName +
                   ": particles[0].mass: duplicate key (at 1:79 and again at 1:90); JSON "
                   "keeps only one of them, so give it once";
        QTest::newRow("stiffness of a cloth")
            << scene(R"("cloths": [{"id": "c", "stiffness": {"shear": 1, "shear": 2}}])")
            << kName +
                   ": cloths[0].stiffness.shear: duplicate key (at 1:81 and again at 1:93); "
                   "JSON keeps only one of them, so give it once";
    }

    void duplicateKeysAreRefusedWithTheirPath() {
        QFETCH(QByteArray, json);
        QFETCH(QString, expected);
        QCOMPARE(parseError(json), expected);
    }

    // Hundreds of duplicates: ten named, the rest counted; an object of many keys is checked
    // with a hash map, and still finds them.
    void manyDuplicatesAreCounted() {
        QByteArray keys;
        for (int i = 0; i < 100; ++i) keys += QStringLiteral("\"k%1\": 0, ").arg(i).toLatin1();
        for (int i = 0; i < 30; ++i) keys += QStringLiteral("\"k%1\": 1, ").arg(i).toLatin1();
        const QString error = parseError(scene(R"("simulation": {)" + keys + R"("dt": 0.1})"));
        const QStringList lines = error.split(QLatin1Char('\n'));
        QCOMPARE(lines.size(), 11);
        QVERIFY2(lines.first().startsWith(kName + QStringLiteral(": simulation.k0: duplicate key")),
                 qPrintable(lines.first()));
        QCOMPARE(lines.last(), kName + QStringLiteral(": and 20 more duplicate keys"));
    }

    // The same key in different objects is not a duplicate.
    void equalKeysInDifferentObjectsLoad() {
        QVERIFY(SceneIO::parse(scene(R"("particles": [{"position": [0, 0], "mass": 1},)"
                                     R"( {"position": [1, 0], "mass": 1}])"),
                               kName)
                    .ok());
    }

    // Every number has a range; the tolerance's is at least 1e-14 (CONTRACT §1).
    void toleranceBelowWhatADoubleMeetsIsRefused() {
        QCOMPARE(parseError(scene(R"("simulation": {"tolerance": 1e-300})")),
                 kName + QStringLiteral(": simulation.tolerance: must be >= 1e-14 (got 1e-300)"));
        QCOMPARE(parseError(scene(R"("simulation": {"tolerance": 1e-15})")),
                 kName + QStringLiteral(": simulation.tolerance: must be >= 1e-14 (got 1e-15)"));
        QVERIFY(SceneIO::parse(scene(R"("simulation": {"tolerance": 1e-14})"), kName).ok());
    }

    // A FIFO, a device and a folder as the scene: refused at once, by SceneIO and by the app's
    // document (what File → Open calls), which keeps the scene it had.
    void sceneThatIsNotARegularFileIsRefusedAtOnce() {
        QTemporaryDir dir;
        const QString fifo = dir.filePath(QStringLiteral("pipe.json"));
        QCOMPARE(::mkfifo(QFile::encodeName(fifo).constData(), 0644), 0);
        const QList<QPair<QString, QString>> cases{
            {fifo, QStringLiteral("it is a FIFO (named pipe), not a scene file")},
            {QStringLiteral("/dev/zero"), QStringLiteral("it is a device, not a scene file")},
            {QStringLiteral("/dev/null"), QStringLiteral("it is a device, not a scene file")},
            {dir.path(), QStringLiteral("it is a folder")},
        };
        Document document;
        const QByteArray before = SceneIO::serialize(document.setup());
        for (const auto& [path, what] : cases) {
            QElapsedTimer timer;
            timer.start();
            const SceneLoadResult r = SceneIO::load(path);
            QCOMPARE(r.errorText(), path + QStringLiteral(": cannot read the file: ") + what);
            QString error;
            QVERIFY(!document.load(path, &error));
            QCOMPARE(error, path + QStringLiteral(": cannot read the file: ") + what);
            QVERIFY(timer.elapsed() < 5000);
        }
        QCOMPARE(SceneIO::serialize(document.setup()), before);
        // A NUL ends a name for the system: "scene.json\0x" would read "scene.json".
        const QString real = dir.filePath(QStringLiteral("scene.json"));
        QFile file(real);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(R"({"format": "phasebox-scene", "version": 1})");
        file.close();
        QVERIFY(SceneIO::load(real).ok());
        const QString nul = real + QChar(u'\0') + QStringLiteral("x");
        QCOMPARE(SceneIO::load(nul).errorText(),
                 nul + QStringLiteral(": cannot read the file: the name holds a NUL character"));
        // A regular file and a built-in scene still load.
        QVERIFY(SceneIO::load(QStringLiteral(":/scenes/demo.phasebox.json")).ok());
    }

    // The size limits (SceneLimits): the largest of each kind is valid, one more is refused
    // with a message that names the limit.
    void sizeLimitsNameTheLimit() {
        SceneDesc cloth;
        ClothDesc c;
        c.id = "c";
        c.resolution = {128, 128};
        cloth.cloths = {c};
        QCOMPARE(firstIssue(cloth), std::string("<valid>"));
        cloth.cloths[0].resolution = {129, 128};
        QCOMPARE(firstIssue(cloth),
                 std::string("cloths[0].resolution: the cloth has 16512 nodes (129 x 128); at most "
                             "16384 cloth nodes (128 x 128) are allowed in a scene"));

        SceneDesc particles;
        particles.particles.resize(SceneLimits::kMaxParticles);
        for (std::size_t i = 0; i < particles.particles.size(); ++i)
            particles.particles[i].position = {double(i % 500), double(i / 500)};
        QCOMPARE(firstIssue(particles), std::string("<valid>"));
        particles.particles.emplace_back();
        QCOMPARE(firstIssue(particles),
                 std::string("particles: the scene has 250001 particles (cloth nodes included); at "
                             "most 250000 are allowed"));

        SceneDesc boxes;
        boxes.boxes.resize(SceneLimits::kMaxRigidBodies + 1);
        for (BoxDesc& b : boxes.boxes) b.size = {1.0, 1.0};
        QCOMPARE(firstIssue(boxes),
                 std::string("boxes: at most 25000 rigid bodies (boxes, disks and polygons) are "
                             "allowed"));
        SceneDesc springs;
        springs.springs.resize(SceneLimits::kMaxSprings + 1);
        QCOMPARE(firstIssue(springs), std::string("springs: at most 250000 springs are allowed"));
        SceneDesc joints;
        joints.joints.resize(SceneLimits::kMaxJoints + 1);
        QCOMPARE(firstIssue(joints), std::string("joints: at most 250000 joints are allowed"));
    }
};

QTEST_GUILESS_MAIN(TestSceneInput)
#include "tst_scene_input.moc"
