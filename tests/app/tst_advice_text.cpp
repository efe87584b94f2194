// The stability advisor's sentences as the window shows them (app/i18n/AdviceText): composed in
// the app from the advice's numbers so that they can be translated, they must say what the
// engine says. In English each is the engine's sentence word for word (its "omega*h" written
// ω·h), for every case the advisor has: nothing oscillates, stable, past a method's limit,
// between the penalty contacts' margin and the limit, a method that gains energy at every step,
// and the warning about a stack on kinematic contacts. In German each is another sentence with
// the same numbers in the German form.

#include "app/i18n/AdviceText.h"
#include "app/i18n/Language.h"
#include "physics/diagnostics/StabilityAdvisor.h"
#include "physics/scene/BuildWorld.h"
#include "tests/physics/PhysicsTestSupport.h"

#include <QLocale>
#include <QTest>

using namespace phasebox;

namespace {

SceneDesc oscillator(double k, const std::string& integrator, double dt) {
    return testing::oscillatorScene(integrator, dt, {0.1, 0.0}, {0.0, 0.0}, k, 1.0);
}

// A ball resting on a floor under penalty contacts of stiffness k (ω = √k for 1 kg).
SceneDesc ballOnFloor(double k, const std::string& integrator, double dt) {
    SceneDesc scene;
    scene.simulation = testing::simulation(integrator, dt);
    scene.simulation.contactModel = ContactModel::Penalty;
    scene.simulation.contactStiffness = k;
    scene.effects.gravity = GravityDesc{{0.0, -9.81}};
    ParticleDesc ball;
    ball.id = "ball";
    ball.position = {0.0, 0.1};
    ball.radius = 0.1;
    scene.particles.push_back(ball);
    scene.planes.push_back(PlaneDesc{});
    return scene;
}

// Two boxes stacked on a floor under kinematic contacts.
SceneDesc kinematicStack() {
    SceneDesc scene;
    scene.simulation.contactModel = ContactModel::Kinematic;
    scene.effects.gravity = GravityDesc{{0.0, -9.81}};
    for (const auto& [id, y] : {std::pair{"lower", 0.5}, std::pair{"upper", 1.5}}) {
        BoxDesc box;
        box.id = id;
        box.position = {0.0, y};
        box.size = {1.0, 1.0};
        scene.boxes.push_back(box);
    }
    scene.planes.push_back(PlaneDesc{});
    return scene;
}

QString engineText(const StabilityAdvice& advice) {
    return QString::fromStdString(advice.message)
        .replace(QLatin1String("omega*h"), QStringLiteral("ω·h"));
}

}  // namespace

Q_DECLARE_METATYPE(phasebox::SceneDesc)

class TestAdviceText : public QObject {
    Q_OBJECT

private slots:
    void cleanup() { i18n::install(QStringLiteral("en")); }

    void composedSentenceIsTheEngines_data() {
        QTest::addColumn<SceneDesc>("scene");
        QTest::addColumn<QString>("marker");  // the words that show which case this is
        SceneDesc still;
        still.particles.push_back(ParticleDesc{});
        QTest::newRow("nothing oscillates") << still << "nothing in the scene oscillates";
        QTest::newRow("stable") << oscillator(100.0, "symplectic_euler", 0.01)
                                << "is stable at this step";
        QTest::newRow("past the limit")
            << oscillator(1e6, "symplectic_euler", 1.0 / 60.0) << "it will blow up";
        QTest::newRow("rk4 past the limit")
            << oscillator(1e6, "rk4", 1.0 / 60.0) << "it will blow up";
        QTest::newRow("gains energy")
            << oscillator(100.0, "explicit_euler", 0.01) << "gains energy at every step";
        QTest::newRow("penalty margin")
            << ballOnFloor(1e4, "symplectic_euler", 0.015) << "the margin for penalty contacts";
    }

    void composedSentenceIsTheEngines() {
        QFETCH(SceneDesc, scene);
        QFETCH(QString, marker);
        auto world = buildWorld(scene).world;
        QVERIFY(world);
        const StabilityAdvice advice = adviseStability(*world);
        const QString engine = engineText(advice);
        QVERIFY2(engine.contains(marker), qPrintable(engine));
        QVERIFY(i18n::install(QStringLiteral("en")));
        QCOMPARE(i18n::adviceText(advice, world->settings()), engine);

        QVERIFY(i18n::install(QStringLiteral("de")));
        const QString german = i18n::adviceText(advice, world->settings());
        QVERIFY2(german != engine, qPrintable(german));
        QVERIFY2(!german.contains(marker), qPrintable(german));
        // The same numbers, each in German form: ω·h to three digits.
        if (advice.omegaMax > 0.0) {
            const QString wh =
                QLocale(QLocale::German).toString(advice.omegaMax * advice.dt, 'g', 3);
            QVERIFY2(german.contains(QStringLiteral("ω·h = ") + wh), qPrintable(german));
        }
    }

    void stackWarningIsTranslated() {
        auto world = buildWorld(kinematicStack()).world;
        const std::string warning = contactModelWarning(*world);
        QVERIFY(!warning.empty());
        QVERIFY(i18n::install(QStringLiteral("en")));
        QCOMPARE(i18n::contactWarningText(warning), QString::fromStdString(warning));
        QVERIFY(i18n::install(QStringLiteral("de")));
        const QString german = i18n::contactWarningText(warning);
        QVERIFY2(german.startsWith(QStringLiteral("Kinematische Kontakte")), qPrintable(german));
        QVERIFY(german.contains(QStringLiteral("„upper“")));
        QVERIFY(german.contains(QStringLiteral("„lower“")));
        // A sentence the app does not know is shown as the engine wrote it.
        QCOMPARE(i18n::contactWarningText("Something new."), QStringLiteral("Something new."));
        QCOMPARE(i18n::contactWarningText(""), QString());
    }
};

QTEST_MAIN(TestAdviceText)
#include "tst_advice_text.moc"
