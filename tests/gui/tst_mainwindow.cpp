// The desktop app as a user drives it, offscreen: its docks, pulling an object while running,
// switching the integrator or contact model while running, what a drawn cloth does to the
// integrator, the view, the plots, files, autosave, exports, and the screenshot mode of
// CONTRACT.md §5. The canvas tools and their undo steps are in tst_mainwindow_tools.

#include "MainWindowTestSupport.h"
#include "app/desktop/DesktopOptions.h"
#include "app/desktop/MainWindow.h"
#include "app/document/Autosave.h"
#include "app/io/SceneIO.h"
#include "physics/diagnostics/StabilityAdvisor.h"
#include "physics/world/World.h"
#include "ui/canvas/SceneView.h"
#include "ui/panels/ParametersPanel.h"

#include <QAction>
#include <QChart>
#include <QChartView>
#include <QComboBox>
#include <QDockWidget>
#include <QFile>
#include <QImage>
#include <QLabel>
#include <QLineSeries>
#include <QMenu>
#include <QProcess>
#include <QSpinBox>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QUndoStack>

#include <cmath>

using namespace phasebox;
using namespace phasebox::testing::parts;
using testing::drag;
using testing::serialized;
using testing::worldAt;

namespace {
int pointsIn(QChartView* view) {
    int points = 0;
    for (QAbstractSeries* s : view->chart()->series())
        if (auto* line = qobject_cast<QLineSeries*>(s)) points += line->count();
    return points;
}
}  // namespace

class TestMainWindow : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void windowStartsWithTheDocks() {
        MainWindow w;
        w.show();
        QVERIFY(canvasOf(w) && !canvasOf(w)->usingOpenGL());  // offscreen: the raster canvas
        for (const char* dock :
             {"parametersDock", "effectsDock", "propertiesDock", "plotsDock", "sceneDock"})
            QVERIFY2(w.findChild<QDockWidget*>(dock), dock);
        QVERIFY(w.openFile(kDemoScene, true));
        QVERIFY(!w.document().world().particles().empty());
    }

    // While running, dragging a dynamic object pulls it with a mouse spring: it follows the
    // mouse, and letting go releases it.
    void grabbingPullsAnObjectWhileRunning() {
        MainWindow w;
        w.resize(1200, 800);
        w.show();
        QVERIFY(w.openFile(kDemoScene, true));
        QVERIFY(w.controller().advance(0.2));
        const World& world = w.document().world();
        const QPoint ball =
            canvasOf(w)
                ->toWidget(QPointF(world.particlePosition(0).x(), world.particlePosition(0).y()))
                .toPoint();
        const QPoint target = ball + QPoint(150, -100);
        QWidget* canvas = canvasOf(w);
        QTest::mousePress(canvas, Qt::LeftButton, {}, ball);
        QTest::mouseMove(canvas, ball + QPoint(75, -50));
        QTest::mouseMove(canvas, target);
        QVERIFY(w.document().isGrabbing());
        QVERIFY(w.controller().advance(3.0));
        const QPointF goal = worldAt(w, target);
        const Vec2 p = w.document().world().particlePosition(0);
        // The spring is stiff against the ball's own spring and gravity: it ends near the mouse.
        QVERIFY2((p - Vec2(goal.x(), goal.y())).norm() < 0.25,
                 qPrintable(QString("ball at (%1, %2), mouse at (%3, %4)")
                                .arg(p.x())
                                .arg(p.y())
                                .arg(goal.x())
                                .arg(goal.y())));
        QTest::mouseRelease(canvas, Qt::LeftButton, {}, target);
        QVERIFY(!w.document().isGrabbing());
        // Pulling is not an edit of the setup.
        QCOMPARE(w.document().undoStack()->count(), 0);
    }

    void switchingIntegratorWhileRunningKeepsTheState() {
        MainWindow w;
        w.show();
        QVERIFY(w.openFile(kDemoScene, true));
        w.controller().play();
        QVERIFY(w.controller().advance(0.5));
        const Eigen::VectorXd q = w.document().world().positions();
        const Eigen::VectorXd u = w.document().world().velocities();
        const double t = w.document().world().time();
        auto* combo = parametersPanelOf(w)->findChild<QComboBox*>();
        QVERIFY(combo);
        const int rk4 = combo->findData(QStringLiteral("rk4"));
        QVERIFY(rk4 >= 0);
        combo->setCurrentIndex(rk4);
        QCOMPARE(QString::fromStdString(w.document().world().settings().integrator),
                 QStringLiteral("rk4"));
        QVERIFY(w.document().world().positions() == q);
        QVERIFY(w.document().world().velocities() == u);
        QCOMPARE(w.document().world().time(), t);
        QVERIFY(w.controller().advance(0.5));
        w.controller().pause();
        // The energy plot has the samples and a marker where the integrator changed.
        w.refreshNow();
        QVERIFY(recorderOf(w).energySamples().size() >= 59);
        QVERIFY(pointsIn(plotsPanelOf(w)->energyView()) > 0);
        QCOMPARE(recorderOf(w).markers().empty(), false);
        QVERIFY(recorderOf(w).markers().back().label.contains(QStringLiteral("rk4")));
    }

    // CONTRACT §6: the contact model switched live from the Parameters panel keeps the state,
    // keeps the drift continuous, marks the plots and goes into the setup (saved with it).
    void switchingContactModelWhileRunningKeepsTheState() {
        MainWindow w;
        w.show();
        QVERIFY(w.openFile(kDemoScene, true));
        QVERIFY(w.document().world().contacts());
        w.controller().play();
        QVERIFY(w.controller().advance(0.5));
        const World& before = w.document().world();
        const Eigen::VectorXd q = before.positions(), u = before.velocities();
        const double t = before.time(), drift = before.energy().drift;
        auto* combo = parametersPanelOf(w)->findChild<QComboBox*>("contactModel");
        QVERIFY(combo);
        auto* stiffness = parametersPanelOf(w)->findChild<QDoubleSpinBox*>("contactStiffness");
        QVERIFY(stiffness && !stiffness->isEnabled());
        combo->setCurrentIndex(static_cast<int>(ContactModel::Penalty));
        const World& world = w.document().world();
        QCOMPARE(world.settings().contactModel, ContactModel::Penalty);
        QCOMPARE(w.document().setup().simulation.contactModel, ContactModel::Penalty);
        QVERIFY(world.positions() == q);
        QVERIFY(world.velocities() == u);
        QCOMPARE(world.time(), t);
        QVERIFY(std::abs(world.energy().drift - drift) < 1e-9);
        // The automatic stiffness is shown, and the field is live under penalty.
        QVERIFY(stiffness->isEnabled());
        QCOMPARE(stiffness->value(), world.penaltyStiffness());
        QVERIFY(w.controller().advance(0.5));
        w.controller().pause();
        w.refreshNow();
        QCOMPARE(recorderOf(w).markers().empty(), false);
        QVERIFY(recorderOf(w).markers().back().label.contains(QStringLiteral("penalty contacts")));
        // One undo step takes it back.
        w.document().undoStack()->undo();
        QCOMPARE(w.document().world().settings().contactModel, ContactModel::Impulse);
        QCOMPARE(combo->currentIndex(), static_cast<int>(ContactModel::Impulse));
    }

    // Issue 19: what a user draws on a new scene is stable at the defaults. A cloth under
    // symplectic Euler at 1/60 s would blow up; drawing it switches the integrator to one the
    // stability advisor finds stable with margin, in an undo step of its own, and says so.
    void drawingAClothKeepsANewSceneStable() {
        MainWindow w;
        w.resize(1200, 800);
        w.show();
        QCOMPARE(QString::fromStdString(w.document().setup().simulation.integrator),
                 QStringLiteral("symplectic_euler"));
        QWidget* canvas = canvasOf(w);
        const QPoint c = canvas->rect().center();
        w.action("toolCloth")->trigger();
        drag(canvas, c + QPoint(-250, -200), c + QPoint(150, 0));
        QCOMPARE(w.document().setup().cloths.size(), std::size_t(1));
        const std::string method = w.document().setup().simulation.integrator;
        const StabilityAdvice advice = adviseStability(w.document().world());
        qInfo("cloth %d x %d: omega %.1f rad/s, integrator now %s",
              w.document().setup().cloths[0].resolution[0],
              w.document().setup().cloths[0].resolution[1], advice.omegaMax, method.c_str());
        QVERIFY(method != "symplectic_euler");
        QVERIFY(advice.currentStable);
        bool said = false;
        for (QLabel* label : w.statusBar()->findChildren<QLabel*>())
            said = said || label->text().contains(
                               QStringLiteral("Switched to Implicit Euler so the cloth stays "
                                              "stable; Undo to go back to Symplectic Euler"));
        QVERIFY(said);
        w.controller().play();
        QVERIFY(w.controller().advance(3.0));
        w.controller().pause();
        QVERIFY(!w.document().world().divergence().has_value());
        QVERIFY(w.document().world().positions().allFinite());
        // Issue 37: the switch is its own undo step after the cloth's. One Undo gives the method
        // back and keeps the cloth; a second takes the cloth away.
        w.controller().reset();
        w.document().undoStack()->undo();
        QCOMPARE(w.document().setup().cloths.size(), std::size_t(1));
        QCOMPARE(QString::fromStdString(w.document().setup().simulation.integrator),
                 QStringLiteral("symplectic_euler"));
        QCOMPARE(w.document().world().cloths().size(), std::size_t(1));
        QCOMPARE(w.document().world().settings().integrator, std::string("symplectic_euler"));
        w.document().undoStack()->undo();
        QCOMPARE(w.document().setup().cloths.size(), std::size_t(0));
        QVERIFY(!w.document().undoStack()->canUndo());
    }

    // Issue 19: an example opens with a view that holds its motion over its duration, and
    // View > Follow keeps the selection in view however far it goes.
    void viewHoldsTheMotionAndFollows() {
        MainWindow w;
        w.resize(1200, 800);
        w.show();
        QVERIFY(w.openFile(QStringLiteral(":/scenes/projectile-drag.phasebox.json"), true));
        const QRectF opened = canvasOf(w)->view().visibleWorldRect();
        w.controller().play();
        QVERIFY(w.controller().advance(3.0));  // every ball has landed
        w.controller().pause();
        const World& world = w.document().world();
        for (int i = 0; i < static_cast<int>(world.particles().size()); ++i) {
            const Vec2 p = world.particlePosition(i);
            QVERIFY2(opened.contains(QPointF(p.x(), p.y())),
                     qPrintable(QString("%1 at (%2, %3) outside the opening view")
                                    .arg(QString::fromStdString(world.particles()[i].id))
                                    .arg(p.x())
                                    .arg(p.y())));
        }

        // Zoomed in on the start, following the farthest ball: it stays in view.
        w.controller().reset();
        ui::ViewTransform close = canvasOf(w)->view();
        close.setPixelsPerMetre(close.pixelsPerMetre() * 8.0);
        close.setCentre(QPointF(0.0, 0.0));
        canvasOf(w)->setView(close);
        // (Reset rebuilt the world: read it afresh.)
        const std::string far = w.document().world().particles().back().id;
        w.document().setSelection({QString::fromStdString(far)});
        w.action("follow")->setChecked(true);
        w.controller().play();
        for (int k = 0; k < 30; ++k) {
            QVERIFY(w.controller().advance(0.1));
            const Vec2 p = w.document().world().particlePosition(
                static_cast<int>(w.document().world().particles().size()) - 1);
            const QRectF r = canvasOf(w)->view().visibleWorldRect();
            QVERIFY2(r.contains(QPointF(p.x(), p.y())),
                     qPrintable(QString("t %1: (%2, %3) outside [%4, %5] x [%6, %7]")
                                    .arg(w.document().world().time())
                                    .arg(p.x())
                                    .arg(p.y())
                                    .arg(r.left())
                                    .arg(r.right())
                                    .arg(r.top())
                                    .arg(r.bottom())));
        }
        w.controller().pause();
        w.action("follow")->setChecked(false);
    }

    void selectingAnObjectPlotsItsPhaseSpace() {
        MainWindow w;
        w.show();
        QVERIFY(w.openFile(kDemoScene, true));
        const QString id = QString::fromStdString(w.document().setup().particles[0].id);
        w.document().setSelection({id});
        QVERIFY(w.controller().advance(1.0));
        w.refreshNow();
        QCOMPARE(recorderOf(w).phaseObject(), id);
        QVERIFY(recorderOf(w).phaseSamples().size() >= 59);
        QVERIFY(pointsIn(plotsPanelOf(w)->phaseView()) > 0);
    }

    // The live error estimate: recorded while running, plotted, in the status bar, and larger
    // when dt is raised (local error ∝ h² for symplectic Euler: doubling dt quadruples it).
    void liveErrorEstimateFollowsDt() {
        MainWindow w;
        w.show();
        QVERIFY(w.openFile(QStringLiteral(":/scenes/spring-oscillator.phasebox.json"), true));
        QVERIFY(w.controller().advance(1.0));
        w.refreshNow();
        QVERIFY(recorderOf(w).errorSamples().size() >= 55);
        QVERIFY(pointsIn(plotsPanelOf(w)->errorView()) > 0);
        const double small = w.controller().lastErrorEstimate();
        QVERIFY(small > 0.0);
        SimulationDesc s = w.document().setup().simulation;
        s.dt *= 2.0;
        QVERIFY(w.document().applySimulationSettings(s));
        QVERIFY(w.controller().advance(0.05));
        const double large = w.controller().lastErrorEstimate();
        QVERIFY2(large > 2.5 * small, qPrintable(QString("%1 -> %2").arg(small).arg(large)));
        w.action("errorEstimate")->trigger();  // off
        QVERIFY(!w.controller().estimatesErrors());
        QVERIFY(w.controller().advance(0.2));
        QVERIFY(std::isnan(w.controller().lastErrorEstimate()));
    }

    // File → Examples lists every built-in scene, and each opens with its notes.
    void examplesMenuOpensEveryExample() {
        MainWindow w;
        auto* menu = w.findChild<QMenu*>("examplesMenu");
        QVERIFY(menu);
        const QList<QAction*> actions = menu->actions();
        QVERIFY(actions.size() >= 11);
        for (QAction* a : actions) {
            a->trigger();
            QCOMPARE(w.document().filePath(), a->data().toString());
            QCOMPARE(QString::fromStdString(w.document().setup().name), a->text());
            QVERIFY(!a->toolTip().isEmpty());
        }
    }

    // The open scene is autosaved; a window that goes away without closing (a crash) leaves
    // the recovery file, with the scene's own path, and a clean close removes it.
    void autosaveKeepsTheSceneForRecovery() {
        QString dir;
        QByteArray edited;
        {
            MainWindow w;
            QVERIFY(w.openFile(kDemoScene, true));
            dir = autosaveOf(w)->recoveryDir();
            ParticleDesc p;
            p.position = {0.5, 3.0};
            QVERIFY(w.document().addObject(p));
            edited = serialized(w);
            QVERIFY(autosaveOf(w)->autosaveNow());
        }  // destroyed without closeEvent, as a crash would leave it
        const auto recovery = Autosave::findRecovery(dir);
        QVERIFY(recovery.has_value());
        QCOMPARE(recovery->originalPath, kDemoScene);
        const SceneLoadResult loaded = SceneIO::load(recovery->recoveryFile);
        QVERIFY(loaded.ok());
        QCOMPARE(SceneIO::serialize(*loaded.scene), edited);
        MainWindow w;
        w.show();
        QVERIFY(w.close());  // unmodified: no prompt; a clean exit discards the autosave
        QVERIFY(!Autosave::findRecovery(dir).has_value());
    }

    void saveAndOpenRoundTrip() {
        QTemporaryDir dir;
        MainWindow w;
        QVERIFY(w.openFile(kDemoScene, true));
        const QByteArray scene = serialized(w);
        const QString path = dir.filePath("copy.phasebox.json");
        QString error;
        QVERIFY2(w.saveFile(path, &error), qPrintable(error));
        QVERIFY(!w.document().isModified());
        w.document().newScene();
        QVERIFY(serialized(w) != scene);
        QVERIFY(w.openFile(path, true));
        QCOMPARE(serialized(w), scene);
        QCOMPARE(w.document().filePath(), path);
    }

    void aBadFileLeavesTheOpenSceneUntouched() {
        QTemporaryDir dir;
        MainWindow w;
        QVERIFY(w.openFile(kDemoScene, true));
        const QByteArray before = serialized(w);
        const QString bad = dir.filePath("bad.phasebox.json");
        QFile f(bad);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(
            R"({"format": "phasebox-scene", "version": 1, "particles": [{"position": [0, 0], "mass": -1}]})");
        f.close();
        QString error;
        QVERIFY(!w.openFile(bad, true, &error));
        QVERIFY2(error.contains("particles[0].mass"), qPrintable(error));
        QCOMPARE(serialized(w), before);
        QCOMPARE(w.document().filePath(), kDemoScene);
    }

    void exportsWriteValidFiles() {
        QTemporaryDir dir;
        MainWindow w;
        w.show();
        QVERIFY(w.openFile(kDemoScene, true));
        w.document().setSelection({QString::fromStdString(w.document().setup().particles[0].id)});
        QVERIFY(w.controller().advance(1.0));
        QString error;
        for (auto plot : {ui::PlotsPanel::Plot::Energy, ui::PlotsPanel::Plot::Phase,
                          ui::PlotsPanel::Plot::Error}) {
            const QString base = dir.filePath(plot == ui::PlotsPanel::Plot::Energy  ? "energy"
                                              : plot == ui::PlotsPanel::Plot::Phase ? "phase"
                                                                                    : "error");
            QVERIFY2(w.exportPlot(plot, base + ".png", &error), qPrintable(error));
            QImage image(base + ".png");
            QVERIFY(!image.isNull() && image.width() >= 800);
            QVERIFY2(w.exportPlot(plot, base + ".svg", &error), qPrintable(error));
            QFile svg(base + ".svg");
            QVERIFY(svg.open(QIODevice::ReadOnly));
            QVERIFY(svg.readAll().contains("<svg"));
            QVERIFY2(w.exportPlot(plot, base + ".csv", &error), qPrintable(error));
            QFile csv(base + ".csv");
            QVERIFY(csv.open(QIODevice::ReadOnly));
            const QList<QByteArray> lines = csv.readAll().split('\n');
            QVERIFY2(lines.size() > 55, qPrintable(base));
            if (plot == ui::PlotsPanel::Plot::Energy)
                QCOMPARE(lines[0],
                         QByteArray("t,kinetic,potential,work_nc,drift,correction,total"));
            else
                QVERIFY(lines[0].startsWith("t,"));
            QCOMPARE(lines[1].count(','), lines[0].count(','));
        }
        QVERIFY2(w.exportCanvas(dir.filePath("canvas.png"), &error), qPrintable(error));
        QVERIFY(!QImage(dir.filePath("canvas.png")).isNull());
    }

    void helpAndVersionNeedNoDisplay() {
        // No window system at all (QApplication would abort): --help and --version still answer.
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        for (const char* name : {"QT_QPA_PLATFORM", "DISPLAY", "WAYLAND_DISPLAY"}) env.remove(name);
        env.insert("QT_QPA_PLATFORM", "xcb");
        env.insert("DISPLAY", ":9753");  // nobody listens there
        for (const QStringList& args : {QStringList{"--help"}, QStringList{"--version"}}) {
            QProcess app;
            app.setProcessEnvironment(env);
            app.start(QStringLiteral(PHASEBOX_DESKTOP), args);
            QVERIFY(app.waitForFinished(30000));
            QCOMPARE(app.exitStatus(), QProcess::NormalExit);
            QCOMPARE(app.exitCode(), 0);
            const QByteArray out = app.readAllStandardOutput();
            QVERIFY2(out.contains(args[0] == "--help" ? "--screenshot" : PHASEBOX_VERSION),
                     out.constData());
        }
        // An unknown option before --help is an error, still without a display.
        QProcess app;
        app.setProcessEnvironment(env);
        app.start(QStringLiteral(PHASEBOX_DESKTOP), {"--no-such-option", "--help"});
        QVERIFY(app.waitForFinished(30000));
        QCOMPARE(app.exitCode(), 2);
        QVERIFY(app.readAllStandardError().contains("phasebox: error:"));
    }

    void statusBarForgetsTheSceneBefore() {
        // Every label of the status bar after New from a run equals New in a fresh window.
        const auto statusTexts = [](MainWindow& w) {
            QStringList texts;
            for (const QLabel* l : w.statusBar()->findChildren<QLabel*>())
                texts << l->objectName() + QLatin1Char('=') + l->text();
            return texts;
        };
        MainWindow fresh;
        fresh.show();
        fresh.findChild<QAction*>(QStringLiteral("new"))->trigger();
        MainWindow w;
        w.show();
        QVERIFY(w.openFile(QStringLiteral(":/scenes/box-pyramid.phasebox.json"), true));
        QVERIFY(w.controller().advance(1.0));
        w.controller().play();  // running: the speed label and the error estimate show figures
        QVERIFY(QTest::qWaitFor([&] { return w.controller().msPerStep() > 0.0; }, 5000));
        const QStringList running = statusTexts(w);
        QVERIFY(w.findChild<QLabel*>(QStringLiteral("statusMessage"))->text().contains("Opened"));
        w.findChild<QAction*>(QStringLiteral("new"))->trigger();
        QVERIFY(!w.controller().isRunning());
        QCOMPARE(statusTexts(w), statusTexts(fresh));
        QVERIFY(statusTexts(w) != running);
    }

    void statusMessagesExpire() {
        MainWindow w;
        w.show();
        QVERIFY(w.openFile(QStringLiteral(":/scenes/box-pyramid.phasebox.json"), true));
        const QLabel* message = w.findChild<QLabel*>(QStringLiteral("statusMessage"));
        QVERIFY(!message->text().isEmpty());
        auto* expiry = w.findChild<QTimer*>(QStringLiteral("statusMessageExpiry"));
        QVERIFY(expiry && expiry->isActive());
        QCOMPARE(expiry->interval(), 10000);
        expiry->setInterval(50);  // the same timer, sooner
        expiry->start();
        QVERIFY(QTest::qWaitFor([&] { return message->text().isEmpty(); }, 2000));
    }

    void saveAsIsControlShiftS() {
        MainWindow w;
        const QAction* saveAs = w.findChild<QAction*>(QStringLiteral("saveAs"));
        QVERIFY(saveAs);
        QCOMPARE(saveAs->shortcut(), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_S));
        // No other action of the window takes it.
        for (const QAction* a : w.findChildren<QAction*>())
            if (a != saveAs) QVERIFY2(a->shortcut() != saveAs->shortcut(), qPrintable(a->text()));
    }

    void screenshotModeWritesAPicture() {
        QTemporaryDir dir;
        const QString png = dir.filePath("shot.png");
        QProcess app;
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert("QT_QPA_PLATFORM", "offscreen");
        app.setProcessEnvironment(env);
        app.start(
            QStringLiteral(PHASEBOX_DESKTOP),
            {"--screenshot", png, "--run-for", "1",
             QStringLiteral(PHASEBOX_SOURCE_DIR "/resources/scenes/box-pyramid.phasebox.json")});
        QVERIFY(app.waitForFinished(60000));
        QCOMPARE(app.exitCode(), 0);
        const QImage image(png);
        QVERIFY(!image.isNull());
        QVERIFY(image.width() >= 800 && image.height() >= 500);
        // A bad scene: exit 2 with the loader's message, no picture.
        app.start(QStringLiteral(PHASEBOX_DESKTOP),
                  {"--screenshot", dir.filePath("none.png"), "/no/such.json"});
        QVERIFY(app.waitForFinished(60000));
        QCOMPARE(app.exitCode(), 2);
        QVERIFY(app.readAllStandardError().contains("phasebox: error:"));
        QVERIFY(!QFile::exists(dir.filePath("none.png")));
    }

    void divergenceIsReportedAndTheStateStaysFinite() {
        MainWindow w;
        w.show();
        QVERIFY(w.openFile(QStringLiteral(":/scenes/stiff-spring-blowup.phasebox.json"), true));
        SimulationDesc s = w.document().setup().simulation;
        s.integrator = "symplectic_euler";
        QVERIFY(w.document().applySimulationSettings(s));
        QVERIFY(!w.controller().advance(2.0));
        QVERIFY(!w.controller().isRunning());
        const World& world = w.document().world();
        QVERIFY(world.divergence().has_value());
        QVERIFY(world.positions().allFinite() && world.velocities().allFinite());
    }
};

QTEST_MAIN(TestMainWindow)
#include "tst_mainwindow.moc"
