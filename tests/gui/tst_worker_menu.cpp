// Simulation > Worker Threads: the choice applies at once to the world the window steps, stays
// with every world the document builds after (a new scene, an opened file, a reset), is stored
// for the next start, and changes nothing the class sees: the same scene run on one thread and
// on every core ends in the same state, bit for bit.

#include "app/desktop/MainWindow.h"
#include "app/desktop/WorkerMenu.h"
#include "app/document/Document.h"
#include "physics/core/WorkerPool.h"
#include "physics/world/World.h"
#include "tests/support/StateBits.h"

#include <QAction>
#include <QApplication>
#include <QMenu>
#include <QSettings>
#include <QStandardPaths>
#include <QTest>

using namespace phasebox;

class TestWorkerMenu : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }
    void init() { QSettings().clear(); }
    void choiceAppliesToEveryWorldAndIsStored();
    void storedChoiceAppliesAtStart();
    void resultsDoNotDependOnTheChoice();
};

namespace {
QAction* workersAction(MainWindow& window, int n) {
    return window.findChild<QAction*>(QStringLiteral("workers_%1").arg(n));
}

// The box pyramid example, run for steps steps, as bits.
auto runPyramid(MainWindow& window, int steps) {
    if (!window.openFile(QStringLiteral(":/scenes/box-pyramid.phasebox.json"), true))
        return decltype(testing::stateBits(window.document().world())){};
    for (int i = 0; i < steps; ++i) window.document().world().step();
    return testing::stateBits(window.document().world());
}
}  // namespace

void TestWorkerMenu::choiceAppliesToEveryWorldAndIsStored() {
    MainWindow window;
    auto* menu = window.findChild<QMenu*>(QStringLiteral("workerMenu"));
    QVERIFY(menu);
    QVERIFY(workersAction(window, 0));
    QVERIFY(workersAction(window, 0)->isChecked());  // every core by default
    QCOMPARE(window.document().world().workers(), WorkerPool::allCores());
    QAction* one = workersAction(window, 1);
    QVERIFY(one);
    one->trigger();
    QVERIFY(one->isChecked());
    QCOMPARE(window.document().world().workers(), 1);
    QCOMPARE(WorkerMenu::stored(QSettings()), 1);
    window.document().reset();
    QCOMPARE(window.document().world().workers(), 1);
    QVERIFY(window.openFile(QStringLiteral(":/scenes/box-pyramid.phasebox.json"), true));
    QCOMPARE(window.document().world().workers(), 1);
    workersAction(window, 0)->trigger();
    QCOMPARE(window.document().world().workers(), WorkerPool::allCores());
    QCOMPARE(WorkerMenu::stored(QSettings()), 0);
}

void TestWorkerMenu::storedChoiceAppliesAtStart() {
    QSettings settings;
    WorkerMenu::store(settings, 2);
    settings.sync();
    MainWindow window;
    QCOMPARE(window.document().world().workers(), 2);
    QAction* two = workersAction(window, 2);
    QVERIFY(two);
    QVERIFY(two->isChecked());
}

void TestWorkerMenu::resultsDoNotDependOnTheChoice() {
    MainWindow window;
    workersAction(window, 1)->trigger();
    const auto one = runPyramid(window, 20);
    QVERIFY(!one.empty());
    workersAction(window, 0)->trigger();
    QCOMPARE(runPyramid(window, 20), one);
    // A settings value that is not a count falls back to every core.
    QSettings().setValue(QStringLiteral("simulation/workers"), QStringLiteral("many"));
    QCOMPARE(WorkerMenu::stored(QSettings()), 0);
}

QTEST_MAIN(TestWorkerMenu)
#include "tst_worker_menu.moc"
