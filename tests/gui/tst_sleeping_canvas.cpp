// Sleeping on the canvas (CONTRACT §6): with simulation.sleep a body at rest falls asleep and is
// drawn dimmed; dragging it wakes it (and it is drawn as before); a scene without sleep never
// dims anything.

#include "MainWindowTestSupport.h"
#include "app/desktop/MainWindow.h"
#include "app/document/Document.h"
#include "app/sim/SimulationController.h"
#include "physics/world/World.h"
#include "ui/canvas/SceneRenderer.h"
#include "ui/canvas/SceneView.h"

#include <QFile>
#include <QTemporaryDir>
#include <QTest>

using namespace phasebox;
using namespace phasebox::testing::parts;

namespace {

QString writeScene(const QTemporaryDir& dir, bool sleep) {
    const QString path = dir.filePath(sleep ? "asleep.json" : "awake.json");
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly)) return {};
    f.write(QByteArray(R"({"format": "phasebox-scene", "version": 2,
        "simulation": {"dt": 0.016666666666666666, "sleep": )") +
            (sleep ? "true" : "false") + R"(},
        "effects": {"gravity": {}},
        "planes": [{"id": "ground", "point": [0, 0], "normal": [0, 1]}],
        "boxes": [{"id": "crate", "position": [0, 0.5], "size": [1, 1]},
                  {"id": "lid", "position": [0, 1.25], "size": [0.8, 0.5]}]})");
    return path;
}

QColor colourAt(MainWindow& w, const Vec2& point) {
    const QImage image = canvasOf(w)->renderImage(canvasOf(w)->size());
    return image.pixelColor(canvasOf(w)->toWidget(QPointF(point.x(), point.y())).toPoint());
}

}  // namespace

class TestSleepingCanvas : public QObject {
    Q_OBJECT

private slots:
    void asleepIsDimmedAndADragWakesIt() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        MainWindow w;
        w.resize(1200, 800);
        w.show();
        QVERIFY(w.openFile(writeScene(dir, true), true));
        QVERIFY(w.document().setup().simulation.sleep);
        const ui::SceneColors colours;
        QCOMPARE(colourAt(w, w.document().world().bodyPosition(0)), colours.dynamicBox);
        QVERIFY(w.controller().advance(1.5));
        const World& world = w.document().world();
        QCOMPARE(world.sleepingBodies(), 2);
        QVERIFY(world.rigidBodies()[0].asleep);
        QCOMPARE(colourAt(w, world.bodyPosition(0)), colours.sleepingBox);
        QCOMPARE(colourAt(w, world.bodyPosition(1)), colours.sleepingBox);

        // A drag on the crate pulls it with the mouse spring: its island wakes.
        QWidget* canvas = canvasOf(w);
        const Vec2 at = w.document().world().bodyPosition(0);
        const QPoint crate = canvasOf(w)->toWidget(QPointF(at.x(), at.y())).toPoint();
        QTest::mousePress(canvas, Qt::LeftButton, {}, crate);
        QTest::mouseMove(canvas, crate + QPoint(10, -5));
        QTest::mouseMove(canvas, crate + QPoint(20, -10));
        QVERIFY(w.document().isGrabbing());
        QCOMPARE(w.document().world().sleepingBodies(), 0);
        QVERIFY(!w.document().world().rigidBodies()[0].asleep);
        QCOMPARE(colourAt(w, w.document().world().bodyPosition(0)), colours.dynamicBox);
        QVERIFY(w.controller().advance(0.3));
        // Held by the mouse, the crate does not fall asleep.
        QVERIFY(!w.document().world().rigidBodies()[0].asleep);
        QTest::mouseRelease(canvas, Qt::LeftButton, {}, crate + QPoint(20, -10));
        QVERIFY(!w.document().isGrabbing());
        // Let go, the two come to rest and sleep again.
        QVERIFY(w.controller().advance(4.0));
        QCOMPARE(w.document().world().sleepingBodies(), 2);
    }

    void withoutSleepNothingDims() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        MainWindow w;
        w.resize(1200, 800);
        w.show();
        QVERIFY(w.openFile(writeScene(dir, false), true));
        QVERIFY(w.controller().advance(1.5));
        QCOMPARE(w.document().world().sleepingBodies(), 0);
        QCOMPARE(colourAt(w, w.document().world().bodyPosition(0)), ui::SceneColors{}.dynamicBox);
    }
};

QTEST_MAIN(TestSleepingCanvas)
#include "tst_sleeping_canvas.moc"
