// The contact model keys of CONTRACT §6 in scene files: simulation.contact_model,
// contact_stiffness and contact_damping save and load (and make a version 2 scene), are left
// out at their defaults (a scene that does not use them saves unchanged), and bad values are
// refused with their JSON path.

#include "SceneIOTestSupport.h"

#include <QTest>

using namespace phasebox;
using namespace phasebox::testing;

class TestContactModelSceneIO : public QObject {
    Q_OBJECT

private slots:
    void modelsRoundTrip_data() {
        QTest::addColumn<int>("model");
        for (int m = 0; m < 3; ++m) QTest::newRow(contactModelName(ContactModel(m)).data()) << m;
    }
    void modelsRoundTrip() {
        QFETCH(int, model);
        SceneDesc original;
        original.simulation.contactModel = ContactModel(model);
        original.simulation.contactStiffness = 2.5e4;
        original.simulation.contactDamping = 12.75;
        const QByteArray first = SceneIO::serialize(original);
        QVERIFY(first.contains("\"version\": 2"));
        const SceneLoadResult loaded = SceneIO::parse(first, kName);
        QVERIFY2(loaded.ok(), qPrintable(loaded.errorText()));
        QCOMPARE(loaded.scene->simulation.contactModel, ContactModel(model));
        QCOMPARE(loaded.scene->simulation.contactStiffness, std::optional<double>(2.5e4));
        QCOMPARE(loaded.scene->simulation.contactDamping, 12.75);
        QCOMPARE(SceneIO::serialize(*loaded.scene), first);
    }

    void defaultsAreLeftOut() {
        // Impulse, automatic stiffness, no damping: nothing written, still a version 1 scene.
        const QByteArray text = SceneIO::serialize(SceneDesc{});
        QVERIFY(!text.contains("contact_"));
        QVERIFY(text.contains("\"version\": 1"));
        const SceneLoadResult loaded =
            SceneIO::parse(scene(R"("simulation": {"contact_model": "kinematic"})"), kName);
        QVERIFY2(loaded.ok(), qPrintable(loaded.errorText()));
        QCOMPARE(loaded.scene->simulation.contactModel, ContactModel::Kinematic);
        QVERIFY(!loaded.scene->simulation.contactStiffness);
    }

    void badValuesAreRefused_data() {
        QTest::addColumn<QByteArray>("json");
        QTest::addColumn<QString>("message");
        QTest::newRow("unknown model")
            << scene(R"("simulation": {"contact_model": "springy"})")
            << msg("simulation.contact_model",
                   "must be one of impulse, penalty, kinematic (got \"springy\")");
        QTest::newRow("model not a string")
            << scene(R"("simulation": {"contact_model": 2})")
            << msg("simulation.contact_model", "must be one of impulse, penalty, kinematic");
        QTest::newRow("stiffness 0") << scene(R"("simulation": {"contact_stiffness": 0})")
                                     << msg("simulation.contact_stiffness", "must be > 0 (got 0)");
        QTest::newRow("stiffness negative")
            << scene(R"("simulation": {"contact_stiffness": -1e4})")
            << msg("simulation.contact_stiffness", "must be > 0 (got -10000)");
        QTest::newRow("damping negative")
            << scene(R"("simulation": {"contact_damping": -0.5})")
            << msg("simulation.contact_damping", "must be >= 0 (got -0.5)");
        QTest::newRow("misspelt key")
            << scene(R"("simulation": {"contact_stifness": 10})") << QString();
    }
    void badValuesAreRefused() {
        QFETCH(QByteArray, json);
        QFETCH(QString, message);
        if (!message.isEmpty()) {
            expectRefused(json, {message});
            return;
        }
        // A misspelt known key is reported by its name (CONTRACT §1).
        const SceneLoadResult result = SceneIO::parse(json, kName);
        QVERIFY(!result.ok());
        QVERIFY2(result.errorText().contains("contact_stifness"), qPrintable(result.errorText()));
    }
};

QTEST_GUILESS_MAIN(TestContactModelSceneIO)
#include "tst_sceneio_contact_models.moc"
