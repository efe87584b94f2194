// A lesson's instruments in scene files (CONTRACT §7): every instrument round-trips byte for
// byte, they make a scene version 2 and a scene without them stays version 1, the reader
// refuses unknown keys and wrong shapes at their JSON paths, and building the world checks
// every probe and end against the scene's objects.

#include "SceneIOTestSupport.h"

#include "app/io/SceneIO.h"
#include "physics/scene/BuildWorld.h"

#include <QTest>

using namespace phasebox;
using namespace phasebox::testing;

namespace {

const char* kPendulum = R"("particles": [ { "id": "bob", "position": [1, -1] } ],
  "joints": [ { "id": "j", "type": "rod", "a": "bob", "anchor": [0, 0] } ])";

QByteArray lesson(const char* instruments) {
    QByteArray body = kPendulum;
    body += R"(, "instruments": )";
    body += instruments;
    return scene(body.constData());
}

InstrumentsDesc everyInstrument() {
    InstrumentsDesc in;
    in.probes = {"bob.x", "system.total"};
    in.graphs = {{"bob.y", ""}, {"bob.vx", "bob.x"}};
    in.timers = {"bob.x", "bob.y"};
    in.stopwatch = true;
    in.rulers = {{{"bob", "0.25:-1.5"}}};
    in.protractors = {{{"0:-1", "0:0", "bob"}}};
    in.freeBody = "bob";
    in.view = ViewDesc{{0.125, -0.5}, 3.75};
    in.plots = {"energy", "error"};
    return in;
}

}  // namespace

class TestSceneIOInstruments : public QObject {
    Q_OBJECT

private slots:
    void everyInstrumentRoundTripsByteIdentical() {
        const SceneLoadResult base = SceneIO::parse(lesson("{}"), kName);
        QVERIFY2(base.ok(), qPrintable(base.errorText()));
        SceneDesc s = *base.scene;
        s.instruments = everyInstrument();
        const QByteArray first = SceneIO::serialize(s);
        const SceneLoadResult read = SceneIO::parse(first, kName);
        QVERIFY2(read.ok(), qPrintable(read.errorText()));
        const InstrumentsDesc& in = read.scene->instruments;
        QCOMPARE(in.probes, s.instruments.probes);
        QCOMPARE(in.graphs.size(), std::size_t(2));
        QCOMPARE(in.graphs[1].x, std::string("bob.x"));
        QCOMPARE(in.graphs[0].x, std::string());
        QCOMPARE(in.timers, s.instruments.timers);
        QVERIFY(in.stopwatch);
        QCOMPARE(in.rulers[0].ends[1], std::string("0.25:-1.5"));
        QCOMPARE(in.protractors[0].ends[1], std::string("0:0"));
        QCOMPARE(in.freeBody, std::string("bob"));
        QVERIFY(in.view);
        QCOMPARE(in.view->center[0], 0.125);
        QCOMPARE(in.view->width, 3.75);
        QCOMPARE(in.plots, s.instruments.plots);
        QCOMPARE(SceneIO::serialize(*read.scene), first);
        // The world checks them: every probe and end names the bob, the rod or a point.
        QVERIFY(buildWorld(*read.scene).world);
    }

    void instrumentsMakeAVersionTwoScene() {
        SceneDesc plain;
        QCOMPARE(plain.formatVersion(), 1);
        QVERIFY(!SceneIO::serialize(plain).contains("instruments"));
        plain.instruments.stopwatch = true;
        QCOMPARE(plain.formatVersion(), 2);
        QVERIFY(SceneIO::serialize(plain).contains("\"instruments\": {\n    \"stopwatch\": true"));
    }

    void shapesAreRefusedAtTheirPaths_data() {
        QTest::addColumn<QByteArray>("instruments");
        QTest::addColumn<QString>("path");
        QTest::addColumn<QString>("what");
        QTest::newRow("not an object") << QByteArray(R"([])") << "instruments"
                                       << "must be an object";
        QTest::newRow("unknown key") << QByteArray(R"({"rulerz": []})") << "instruments.rulerz"
                                     << "unknown key; did you mean \"rulers\"?";
        QTest::newRow("probe not a string")
            << QByteArray(R"({"probes": ["bob.x", 3]})") << "instruments.probes[1]"
            << "must be a string";
        QTest::newRow("empty probe") << QByteArray(R"({"timers": [""]})") << "instruments.timers[0]"
                                     << "must not be empty";
        QTest::newRow("graph without y")
            << QByteArray(R"({"graphs": [{"x": "bob.x"}]})") << "instruments.graphs[0].y"
            << "is required";
        QTest::newRow("graph key")
            << QByteArray(R"({"graphs": [{"y": "bob.x", "z": "a"}]})") << "instruments.graphs[0].z"
            << "unknown key; known: y, x";
        QTest::newRow("ruler ends")
            << QByteArray(R"({"rulers": [{"ends": ["bob"]}]})") << "instruments.rulers[0].ends"
            << "must be an array of 2 strings";
        QTest::newRow("protractor ends")
            << QByteArray(R"({"protractors": [{}]})") << "instruments.protractors[0].ends"
            << "is required";
        QTest::newRow("stopwatch")
            << QByteArray(R"({"stopwatch": "yes"})") << "instruments.stopwatch"
            << "must be true or false";
        QTest::newRow("view width")
            << QByteArray(R"({"view": {"center": [0, 0]}})") << "instruments.view.width"
            << "is required";
        QTest::newRow("view key misspelt, said once")
            << QByteArray(R"({"view": {"center": [0, 0], "width": 1, "widht": 2}})")
            << "instruments.view.widht"
            << "unknown key; did you mean \"width\"?";
        QTest::newRow("view zero")
            << QByteArray(R"({"view": {"center": [0, 0], "width": 0}})") << "instruments.view.width"
            << "must be > 0 and at most 2e6";
        QTest::newRow("plot") << QByteArray(R"({"plots": ["energy", "phaze"]})")
                              << "instruments.plots[1]"
                              << "must be one of energy, phase, error (got \"phaze\")";
    }
    void shapesAreRefusedAtTheirPaths() {
        QFETCH(QByteArray, instruments);
        QFETCH(QString, path);
        QFETCH(QString, what);
        expectRefused(lesson(instruments.constData()), {msg(path, what)});
    }

    void theWorldChecksWhatTheInstrumentsName() {
        const SceneLoadResult read =
            SceneIO::parse(lesson(R"({"probes": ["bob.x", "bob.z"], "graphs": [{"y": "j.force"}],
                       "protractors": [{"ends": ["bob", "0:0", "ghost"]}], "free_body": "nobody"})"),
                           kName);
        QVERIFY2(read.ok(), qPrintable(read.errorText()));
        try {
            buildWorld(*read.scene);
            QFAIL("built a world whose instruments name nothing");
        } catch (const SceneError& e) {
            QStringList paths;
            for (const SceneIssue& issue : e.issues()) {
                paths << QString::fromStdString(issue.path);
                QVERIFY2(issue.message.find("; known") == std::string::npos, issue.message.c_str());
            }
            QCOMPARE(paths,
                     (QStringList{"instruments.probes[1]", "instruments.graphs[0].y",
                                  "instruments.protractors[0].ends", "instruments.free_body"}));
            QVERIFY(e.issues()[2].message.find("no object \"ghost\"") != std::string::npos);
        }
    }
};

QTEST_GUILESS_MAIN(TestSceneIOInstruments)
#include "tst_sceneio_instruments.moc"
