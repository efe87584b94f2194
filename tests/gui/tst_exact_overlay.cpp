// The exact solution beside the simulation (View > Exact Solution, issue 19 item 8 and issue 18
// item 4): where a scene has a closed form the canvas draws where each body would be now and
// its path, and the phase plot the exact curve; both are checked here against the closed forms
// themselves (x = cos 2t for the midpoint lesson's spring, the pendulum's circle), not against
// numbers the code printed. A scene with contacts has none, and the View action clears it.

#include "MainWindowTestSupport.h"
#include "app/desktop/MainWindow.h"
#include "app/desktop/presenters/ExactPresenter.h"
#include "app/document/Document.h"
#include "app/sim/SimulationController.h"
#include "physics/contacts/ContactModel.h"
#include "physics/scene/SceneDesc.h"
#include "physics/world/World.h"
#include "ui/canvas/SceneView.h"
#include "ui/plots/PlotsPanel.h"

#include <QAction>
#include <QChart>
#include <QChartView>
#include <QDir>
#include <QFile>
#include <QLineSeries>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <numbers>

using namespace phasebox;
using namespace phasebox::testing::parts;

namespace {

struct Window {
    MainWindow w;
    Window() {
        w.resize(1400, 900);
        w.show();
    }
    void open(const QString& path) {
        QString error;
        QVERIFY2(w.openFile(path, true, &error), qPrintable(error));
    }
    const ui::ReferenceOverlay& overlay() {
        return w.findChild<ui::SceneView*>()->referenceOverlay();
    }
    QLineSeries* exactSeries() {
        auto* plots = w.findChild<ui::PlotsPanel*>();
        for (QAbstractSeries* s : plots->phaseView()->chart()->series())
            if (s->name() == QStringLiteral("exact")) return qobject_cast<QLineSeries*>(s);
        return nullptr;
    }
};

}  // namespace

class TestExactOverlay : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    // k = 4 N/m, m = 1 kg, x0 = 1 m at rest: x = cos 2t, v = −2 sin 2t.
    void midpointLessonShowsCosTwoT() {
        Window window;
        window.open(QStringLiteral(":/lessons/midpoint-vs-rk4.phasebox.json"));
        QCOMPARE(exactSolutionOf(window.w)->kind(), QStringLiteral("harmonic oscillator"));
        QVERIFY(window.w.controller().advance(5.0));
        window.w.document().setSelection({QStringLiteral("ball")});
        window.w.refreshNow();
        const double t = window.w.document().world().time();
        QCOMPARE(window.overlay().ghosts.size(), 1);
        const QPointF ghost = window.overlay().ghosts.front().centre;
        qInfo("t = %.2f s: ghost at (%.9f, %.9f), cos 2t = %.9f; the midpoint ball at %.9f", t,
              ghost.x(), ghost.y(), std::cos(2.0 * t),
              window.w.document().world().particlePosition(0).x());
        QVERIFY(std::abs(ghost.x() - std::cos(2.0 * t)) < 1e-9);
        QVERIFY(std::abs(ghost.y()) < 1e-12);
        // The path covers one period: x from −1 to 1 on the axis.
        QCOMPARE(window.overlay().paths.size(), 1);
        double lo = 1e9, hi = -1e9;
        for (const QPointF& p : window.overlay().paths.front()) {
            lo = std::min(lo, p.x());
            hi = std::max(hi, p.x());
        }
        QVERIFY(std::abs(lo + 1.0) < 1e-4 && std::abs(hi - 1.0) < 1e-12);
        QVERIFY(window.overlay().label.contains(QStringLiteral("harmonic oscillator")));
        // The phase plot's exact curve lies on the ellipse x² + (v/2)² = 1.
        QLineSeries* exact = window.exactSeries();
        QVERIFY(exact != nullptr);
        QVERIFY(exact->count() > 100);
        double worst = 0.0;
        for (const QPointF& p : exact->points())
            worst = std::max(worst, std::abs(p.x() * p.x() + 0.25 * p.y() * p.y() - 1.0));
        qInfo("exact phase curve: %lld points, largest |x² + (v/2)² − 1| = %.2e",
              static_cast<long long>(exact->count()), worst);
        QVERIFY(worst < 1e-6);
        // It spans the simulated times: its last point is the state at t.
        const QPointF last = exact->points().back();
        QVERIFY(std::abs(last.x() - std::cos(2.0 * t)) < 1e-9);
        QVERIFY(std::abs(last.y() + 2.0 * std::sin(2.0 * t)) < 1e-6);

        // View > Exact Solution off: nothing drawn, no curve; on again: back.
        QAction* action = window.w.action(QStringLiteral("viewExact"));
        QVERIFY(action && action->isChecked());
        action->trigger();
        window.w.refreshNow();
        QVERIFY(window.overlay().isEmpty());
        QVERIFY(window.exactSeries() == nullptr);
        action->trigger();
        window.w.refreshNow();
        QCOMPARE(window.overlay().ghosts.size(), 1);
        QVERIFY(window.exactSeries() != nullptr);
    }

    // Rods of 1 m: every ghost lies on its circle about the pivot, at any amplitude.
    void pendulumGhostsStayOnTheirCircles() {
        Window window;
        window.open(QStringLiteral(":/lessons/simple-pendulum.phasebox.json"));
        QCOMPARE(exactSolutionOf(window.w)->kind(), QStringLiteral("simple pendulum"));
        const World& world = window.w.document().world();
        QVERIFY(window.w.controller().advance(1.7));
        window.w.refreshNow();
        QCOMPARE(window.overlay().ghosts.size(), 2);
        for (const auto& ghost : window.overlay().ghosts) {
            double nearest = 1e9;
            for (const Joint& j : world.joints())
                nearest = std::min(nearest, std::abs(std::hypot(ghost.centre.x() - j.b.point.x(),
                                                                ghost.centre.y() - j.b.point.y()) -
                                                     j.length));
            QVERIFY2(nearest < 1e-9, qPrintable(QString::number(nearest)));
        }
    }

    // The lesson "Three ways to collide" (issue 18 item 4): under penalty contacts the dropped
    // ball's closed form (free fall, then the damped contact spring) is drawn beside it, the
    // only ghost of the scene; under impulses there is none.
    void penaltyBallHasItsClosedFormInTheLesson() {
        Window window;
        window.open(QStringLiteral(":/lessons/three-ways-to-collide.phasebox.json"));
        QCOMPARE(exactSolutionOf(window.w)->kind(), QStringLiteral("bounce"));  // impulses
        SimulationDesc simulation = window.w.document().setup().simulation;
        simulation.contactModel = ContactModel::Penalty;
        QVERIFY(window.w.document().applySimulationSettings(simulation));
        QCOMPARE(exactSolutionOf(window.w)->kind(), QStringLiteral("penalty bounce"));
        const double g = 9.81, h0 = 2.25, r = 0.25;
        QVERIFY(window.w.controller().advance(0.5));
        window.w.refreshNow();
        QCOMPARE(window.overlay().ghosts.size(), 1);
        const double t = window.w.document().world().time();
        const QPointF ghost = window.overlay().ghosts.front().centre;
        QVERIFY(std::abs(ghost.y() - (h0 - 0.5 * g * t * t)) < 1e-9);
        QVERIFY(std::abs(ghost.x() + 4.0) < 1e-12);
        // The first rebound's apex, from the reference, against (e·v)²/(2g) above the touch
        // with e = exp(−ζπ/√(1 − ζ²)): gravity during the 26 ms contact costs a little.
        const auto& ref = exactSolutionOf(window.w)->reference();
        int dof = -1;
        for (const Particle& p : window.w.document().world().particles())
            if (p.id == "ball") dof = p.dof;
        QVERIFY(ref && ref->covers(dof) && ref->covers(dof + 1));
        double apex = 0.0;
        for (int i = 0; i <= 4000; ++i) {
            const double y = ref->position(dof + 1, 0.7 + 1.1 * i / 4000.0);
            apex = std::max(apex, y);
        }
        const double k = window.w.document().world().penaltyStiffness(), m = 1.0;
        const double zeta = simulation.contactDamping / (2.0 * std::sqrt(k * m));
        const double e = std::exp(-zeta * std::numbers::pi / std::sqrt(1.0 - zeta * zeta));
        const double rise = e * e * (h0 - r);
        qInfo("k = %.0f N/m, zeta = %.4f, e = %.4f: apex %.4f m, r + e^2 h = %.4f m", k, zeta, e,
              apex, r + rise);
        QVERIFY(std::abs(apex - (r + rise)) < 0.03 * rise);
    }

    // Contacts act as impulses: a scene's closed form holds only until the first contact that
    // can happen. A ball thrown sideways over a floor falls freely until it lands, and nothing
    // is drawn after it; boxes resting on one another from the start have none at all.
    void contactScenesHaveOnlyUntilTheFirstContact() {
        Window window;
        QTemporaryDir dir;
        QFile file(dir.filePath(QStringLiteral("throw.json")));
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(R"({"format": "phasebox-scene", "version": 1, "effects": {"gravity": {}},
  "particles": [{"id": "ball", "position": [0, 3], "velocity": [1, 0], "radius": 0.1}],
  "planes": [{"id": "floor", "point": [0, 0], "normal": [0, 1]}]})");
        file.close();
        window.open(file.fileName());
        QCOMPARE(exactSolutionOf(window.w)->kind(), QStringLiteral("free fall"));
        const auto& ref = exactSolutionOf(window.w)->reference();
        QVERIFY(ref.has_value());
        // It lands after √(2·2.9/g) = 0.769 s; the check (2 cm margin and the distance moved
        // between its samples) stops a little earlier.
        const double until = ref->validUntil();
        QVERIFY2(until > 0.74 && until <= 0.769, qPrintable(QString::number(until)));
        QVERIFY(window.w.controller().advance(0.5 * until));
        window.w.refreshNow();
        QVERIFY(!window.overlay().ghosts.isEmpty());
        QVERIFY(window.overlay().label.contains(QStringLiteral("where a contact begins or ends")));
        QVERIFY(window.w.controller().advance(until));
        window.w.refreshNow();
        QVERIFY(window.overlay().ghosts.isEmpty());
        for (const char* name : {"box-pyramid", "dominoes", "polygon-pile", "newtons-cradle"}) {
            window.open(QStringLiteral(":/scenes/%1.phasebox.json").arg(QLatin1String(name)));
            QVERIFY2(exactSolutionOf(window.w)->kind().isEmpty(), name);
            QVERIFY(window.w.controller().advance(0.5));
            window.w.refreshNow();
            QVERIFY(window.overlay().isEmpty());
            QVERIFY(window.exactSeries() == nullptr);
        }
    }

    // The Atwood machine lesson: the weights' constant accelerations until the first weight
    // lands (app/accuracy tst_exact_reference checks the numbers against the simulation).
    void atwoodLessonDrawsItsClosedFormUntilAWeightLands() {
        Window window;
        window.open(QStringLiteral(":/lessons/atwood-machine.phasebox.json"));
        QCOMPARE(exactSolutionOf(window.w)->kind(), QStringLiteral("Atwood machine"));
        QVERIFY(window.w.controller().advance(0.5));
        window.w.refreshNow();
        QCOMPARE(window.overlay().ghosts.size(), 4);
        const double t = window.w.document().world().time();
        bool found = false;
        for (const auto& ghost : window.overlay().ghosts)
            if (std::abs(ghost.centre.x() + 1.9) < 1e-12) {
                found = true;
                QVERIFY(std::abs(ghost.centre.y() - (3.22 - 0.5 * 4.905 * t * t)) < 1e-9);
            }
        QVERIFY(found);
        QVERIFY(window.w.controller().advance(1.0));
        window.w.refreshNow();
        QVERIFY(window.overlay().ghosts.isEmpty());
    }

    // "Impulse and spin": the box's ghost is its outline, turned by the closed form's spin
    // after the hit (tst_exact_reference checks the numbers).
    void impulseSpinLessonDrawsTheBoxTurning() {
        Window window;
        window.open(QStringLiteral(":/lessons/impulse-spin.phasebox.json"));
        QCOMPARE(exactSolutionOf(window.w)->kind(), QStringLiteral("impact"));
        QVERIFY(window.w.controller().advance(1.0));
        window.w.refreshNow();
        QCOMPARE(window.overlay().ghosts.size(), 2);
        const World& world = window.w.document().world();
        const RigidBody& box = world.rigidBodies()[0];
        bool found = false;
        for (const auto& ghost : window.overlay().ghosts)
            if (!ghost.size.isEmpty()) {
                found = true;
                QCOMPARE(ghost.size, QSizeF(1.0, 0.5));
                // Clockwise after the hit, as the simulated box turns.
                QVERIFY(ghost.angle < -1.0);
                QVERIFY(std::abs(ghost.angle - world.positions()[box.dof + 2]) < 1e-6);
            }
        QVERIFY(found);
    }

    // Every lesson and example is searched; which have a closed form is printed to look at.
    void lessonsWithClosedFormsHaveOne() {
        Window window;
        for (const QString& folder : {QStringLiteral(":/lessons"), QStringLiteral(":/scenes")})
            for (const QString& name : QDir(folder).entryList()) {
                window.open(folder + QLatin1Char('/') + name);
                qInfo("%s: %s", qPrintable(name),
                      qPrintable(exactSolutionOf(window.w)->kind().isEmpty()
                                     ? QStringLiteral("-")
                                     : exactSolutionOf(window.w)->kind()));
            }
        for (const auto& [name, kind] :
             {std::pair{"midpoint-vs-rk4", "harmonic oscillator"},
              std::pair{"atwood-machine", "Atwood machine"},
              std::pair{"rolling-race", "rolling and sliding"},
              std::pair{"restitution-friction", "bounce, rolling and sliding"},
              std::pair{"three-ways-to-collide", "bounce"},
              std::pair{"stiff-spring-implicit", "coupled oscillators"},
              std::pair{"impulse-spin", "impact"}, std::pair{"simple-pendulum", "simple pendulum"},
              std::pair{"bead-on-hoop", "simple pendulum"},
              std::pair{"euler-orbit-spiral", "Kepler orbit"}}) {
            window.open(QStringLiteral(":/lessons/%1.phasebox.json").arg(QLatin1String(name)));
            QCOMPARE(exactSolutionOf(window.w)->kind(), QString::fromLatin1(kind));
        }
        for (const auto& [name, kind] :
             {std::pair{"pendulum-wave", "simple pendulum"},
              std::pair{"damped-oscillators", "damped harmonic oscillator"},
              std::pair{"spring-oscillator", "harmonic oscillator"},
              std::pair{"box-incline", "rolling and sliding"},
              std::pair{"bouncing-balls", "bounce"}, std::pair{"orbit", "Kepler orbit"}}) {
            window.open(QStringLiteral(":/scenes/%1.phasebox.json").arg(QLatin1String(name)));
            QCOMPARE(exactSolutionOf(window.w)->kind(), QString::fromLatin1(kind));
        }
    }
};

QTEST_MAIN(TestExactOverlay)
#include "tst_exact_overlay.moc"
