// The window's run is the command line's: an example opened in the window and run there, with
// everything the window does around a run (the local-error estimate, the recorders of the energy
// and phase plots, a probe graphed in the Instruments dock, an object selected, the canvas and
// the panels redrawn every quarter second, the Parameters panel's stability advice with them),
// ends in the state a bare World stepped from the same file reaches, bit for bit. No plot,
// panel or instrument moves a body. The ragdoll and the Galton board are chaotic (a last-bit
// difference sends the ragdoll to another landing place within seconds), so any disturbance
// shows: before the advisor's force evaluation was kept out of the run, the ragdoll's state here
// differed from the bare world's (the panel asks the advisor whenever it is redrawn, and on every
// edit and change of settings: a method switched mid-run, as Compare does).

#include "app/desktop/MainWindow.h"
#include "app/document/Document.h"
#include "app/io/SceneIO.h"
#include "app/sim/SimulationController.h"
#include "physics/scene/BuildWorld.h"
#include "physics/world/World.h"
#include "tests/gui/MainWindowTestSupport.h"
#include "tests/support/StateBits.h"

#include <QApplication>
#include <QSettings>
#include <QStandardPaths>
#include <QTest>

#include <memory>

using namespace phasebox;
using testing::stateBits;

class TestWindowRun : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }
    void init() { QSettings().clear(); }
    void theWindowsRunIsABareWorlds_data();
    void theWindowsRunIsABareWorlds();
};

void TestWindowRun::theWindowsRunIsABareWorlds_data() {
    QTest::addColumn<QString>("scene");
    QTest::addColumn<QString>("selected");  // followed by the phase plot
    QTest::addColumn<QString>("probe");     // graphed in the Instruments dock
    QTest::newRow("ragdoll") << "ragdoll"
                             << "torso"
                             << "torso.vx";
    QTest::newRow("chain bridge") << "chain-bridge"
                                  << "plank5"
                                  << "system.kinetic";
    QTest::newRow("car") << "car"
                         << "chassis"
                         << "chassis.vx";
    QTest::newRow("box pyramid") << "box-pyramid"
                                 << ""
                                 << "system.potential";
    QTest::newRow("galton board") << "galton-board"
                                  << ""
                                  << "system.kinetic";
    QTest::newRow("cloth flag") << "cloth-flag"
                                << ""
                                << "system.total";
}

void TestWindowRun::theWindowsRunIsABareWorlds() {
    QFETCH(QString, scene);
    QFETCH(QString, selected);
    QFETCH(QString, probe);
    const QString path = QStringLiteral(":/scenes/%1.phasebox.json").arg(scene);

    MainWindow window;
    window.resize(1024, 700);
    QVERIFY(window.openFile(path, true));
    window.show();
    QApplication::processEvents();
    if (!selected.isEmpty()) {
        window.document().setSelection({selected});
        QCOMPARE(window.document().selection(), QStringList{selected});
    }
    QString error;
    QVERIFY2(testing::parts::instrumentsOf(window)->plotProbe(probe, {}, &error),
             qPrintable(error));
    // As playing does: a few steps, then every view redrawn.
    for (int frame = 0; frame < 12; ++frame) {
        QVERIFY(window.controller().advance(0.25));
        window.refreshNow();
        QApplication::processEvents();
    }
    const World& shown = window.document().world();
    QVERIFY(shown.time() > 2.9);

    const SceneLoadResult loaded = SceneIO::load(path);
    QVERIFY2(loaded.ok(), qPrintable(loaded.errorText()));
    const std::unique_ptr<World> bare = buildWorld(*loaded.scene).world;
    const double dt = bare->settings().dt;
    while (bare->time() + 0.5 * dt < shown.time()) QVERIFY(bare->step());
    QCOMPARE(bare->time(), shown.time());
    QVERIFY(stateBits(*bare) == stateBits(shown));
}

QTEST_MAIN(TestWindowRun)
#include "tst_window_run.moc"
