// The desktop app as a user drives it, offscreen: tools on the canvas with real mouse events,
// undo and redo, switching the integrator while running, the plots, files, exports, and the
// screenshot mode of CONTRACT.md §5.

#include "app/desktop/CanvasTools.h"
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
#include <QClipboard>
#include <QComboBox>
#include <QDockWidget>
#include <QFile>
#include <QGuiApplication>
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
#include <QUndoStack>

#include <cmath>
#include <numbers>

using namespace phasebox;

namespace {
QByteArray serialized(MainWindow& w) {
    return SceneIO::serialize(w.document().setup());
}

// A press, a few moves and a release, as a hand would drag.
void drag(QWidget* widget, QPoint from, QPoint to) {
    QTest::mousePress(widget, Qt::LeftButton, {}, from);
    for (int k = 1; k <= 4; ++k) QTest::mouseMove(widget, from + (to - from) * k / 4);
    QTest::mouseRelease(widget, Qt::LeftButton, {}, to);
}

QPointF worldAt(MainWindow& w, QPoint pixel) {
    return w.canvas()->toWorld(QPointF(pixel));
}

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
        QVERIFY(w.canvas() && !w.canvas()->usingOpenGL());  // offscreen: the raster canvas
        for (const char* dock :
             {"parametersDock", "effectsDock", "propertiesDock", "plotsDock", "sceneDock"})
            QVERIFY2(w.findChild<QDockWidget*>(dock), dock);
        QVERIFY(w.openFile(kDemoScene, true));
        QVERIFY(!w.document().world().particles().empty());
    }

    void toolsAddObjectsWithTheMouse() {
        MainWindow w;
        w.resize(1200, 800);
        w.show();
        QWidget* canvas = w.canvas();
        const QRect r = canvas->rect();
        const QPoint c = r.center();

        // A click drops a particle where the mouse is.
        w.action("toolParticle")->trigger();
        QCOMPARE(w.tools()->tool(), CanvasTools::Tool::Particle);
        QTest::mouseClick(canvas, Qt::LeftButton, {}, c);
        QCOMPARE(w.document().setup().particles.size(), std::size_t(1));
        const auto& p = w.document().setup().particles[0];
        const QPointF at = worldAt(w, c);
        QVERIFY(std::abs(p.position[0] - at.x()) < 1e-9 && std::abs(p.position[1] - at.y()) < 1e-9);
        QCOMPARE(p.velocity[0], 0.0);

        // A drag launches one: velocity = metres dragged × 1 m/s per metre.
        const QPoint from = c + QPoint(-200, 0), to = c + QPoint(-100, -50);
        drag(canvas, from, to);
        QCOMPARE(w.document().setup().particles.size(), std::size_t(2));
        const QPointF v = worldAt(w, to) - worldAt(w, from);
        const auto& launched = w.document().setup().particles[1];
        QVERIFY(std::abs(launched.velocity[0] - v.x()) < 1e-9);
        QVERIFY(std::abs(launched.velocity[1] - v.y()) < 1e-9);

        // A spring from the first particle to empty space hangs it from an anchor.
        w.action("toolSpring")->trigger();
        drag(canvas, c, c + QPoint(0, -120));
        QCOMPARE(w.document().setup().springs.size(), std::size_t(1));
        const SpringDesc& s = w.document().setup().springs[0];
        QCOMPARE(s.a, w.document().setup().particles[0].id);
        QVERIFY(s.anchor.has_value() && !s.b.has_value());
        // A spring between the two particles.
        drag(canvas, c, from);
        QCOMPARE(w.document().setup().springs.size(), std::size_t(2));
        QVERIFY(w.document().setup().springs[1].b.has_value());

        // A box and a cloth from rectangles.
        w.action("toolBox")->trigger();
        drag(canvas, c + QPoint(100, 100), c + QPoint(200, 150));
        QCOMPARE(w.document().setup().boxes.size(), std::size_t(1));
        const BoxDesc& box = w.document().setup().boxes[0];
        const QPointF size = worldAt(w, c + QPoint(200, 150)) - worldAt(w, c + QPoint(100, 100));
        QVERIFY(std::abs(box.size[0] - std::abs(size.x())) < 1e-9);
        QVERIFY(std::abs(box.size[1] - std::abs(size.y())) < 1e-9);
        w.action("toolCloth")->trigger();
        drag(canvas, c + QPoint(-300, -250), c + QPoint(-150, -150));
        QCOMPARE(w.document().setup().cloths.size(), std::size_t(1));
        QVERIFY(w.document().world().cloths().size() == 1);

        // Every edit is one undo step; undo all of them and redo all of them.
        QUndoStack* stack = w.document().undoStack();
        QCOMPARE(stack->count(), 6);
        const QByteArray full = serialized(w);
        for (int k = 0; k < 6; ++k) w.action("undo")->trigger();
        QVERIFY(w.document().setup().particles.empty() && w.document().setup().cloths.empty());
        for (int k = 0; k < 6; ++k) w.action("redo")->trigger();
        QCOMPARE(serialized(w), full);
    }

    // Issue 16: the disk tool. A drag from the centre to the rim gives that radius, a click a
    // disk of kClickDiskRadius; both are one undo step, and the disk can be selected, made
    // static with the pin tool and deleted like any object.
    void diskToolAddsDisks() {
        MainWindow w;
        w.resize(1200, 800);
        w.show();
        QWidget* canvas = w.canvas();
        const QPoint c = canvas->rect().center();
        w.action("toolDisk")->trigger();
        QCOMPARE(w.tools()->tool(), CanvasTools::Tool::Disk);
        drag(canvas, c, c + QPoint(60, 80));
        QCOMPARE(w.document().setup().disks.size(), std::size_t(1));
        const DiskDesc& dragged = w.document().setup().disks[0];
        const QPointF centre = worldAt(w, c);
        const QPointF rim = worldAt(w, c + QPoint(60, 80));
        QVERIFY(std::abs(dragged.position[0] - centre.x()) < 1e-9);
        QVERIFY(std::abs(dragged.radius - QLineF(centre, rim).length()) < 1e-9);
        QTest::mouseClick(canvas, Qt::LeftButton, {}, c + QPoint(-300, 0));
        QCOMPARE(w.document().setup().disks.size(), std::size_t(2));
        QCOMPARE(w.document().setup().disks[1].radius, CanvasTools::kClickDiskRadius);
        QCOMPARE(w.document().world().boxes().size(), std::size_t(2));

        // The pin tool makes it static; the select tool finds it by its circle.
        w.action("toolPin")->trigger();
        QTest::mouseClick(canvas, Qt::LeftButton, {}, c + QPoint(10, 10));
        QVERIFY(w.document().setup().disks[0].isStatic);
        w.action("toolSelect")->trigger();
        QTest::mouseClick(canvas, Qt::LeftButton, {}, c + QPoint(-300, 20));
        QCOMPARE(w.document().selection(), QStringList{QStringLiteral("d1")});

        QUndoStack* stack = w.document().undoStack();
        QCOMPARE(stack->count(), 3);
        for (int k = 0; k < 3; ++k) w.action("undo")->trigger();
        QVERIFY(w.document().setup().disks.empty());
        for (int k = 0; k < 3; ++k) w.action("redo")->trigger();
        QCOMPARE(w.document().setup().disks.size(), std::size_t(2));
        QVERIFY(w.document().setup().disks[0].isStatic);
    }

    // The polygon tool: a drag from the centre to a corner gives a regular hexagon of that
    // size, centred there, as one undo step; the canvas picks it inside its outline.
    void polygonToolAddsHexagons() {
        MainWindow w;
        w.resize(1200, 800);
        w.show();
        QWidget* canvas = w.canvas();
        const QPoint c = canvas->rect().center();
        w.action("toolPolygon")->trigger();
        QCOMPARE(w.tools()->tool(), CanvasTools::Tool::Polygon);
        drag(canvas, c, c + QPoint(80, 0));
        QCOMPARE(w.document().setup().polygons.size(), std::size_t(1));
        const PolygonDesc& hexagon = w.document().setup().polygons[0];
        QCOMPARE(hexagon.vertices.size(), std::size_t(CanvasTools::kPolygonSides));
        const QPointF centre = worldAt(w, c), corner = worldAt(w, c + QPoint(80, 0));
        QVERIFY(std::abs(hexagon.position[0] - centre.x()) < 1e-9);
        QVERIFY(std::abs(std::hypot(hexagon.vertices[0][0], hexagon.vertices[0][1]) -
                         QLineF(centre, corner).length()) < 1e-9);
        QCOMPARE(w.document().world().boxes().size(), std::size_t(1));
        QVERIFY(w.document().world().boxes()[0].shape == RigidShape::Polygon);
        w.action("toolSelect")->trigger();
        QTest::mouseClick(canvas, Qt::LeftButton, {}, c + QPoint(20, 20));
        QCOMPARE(w.document().selection(), QStringList{QStringLiteral("poly0")});
        w.action("undo")->trigger();
        QVERIFY(w.document().setup().polygons.empty());
        w.action("redo")->trigger();
        QCOMPARE(w.document().setup().polygons.size(), std::size_t(1));
    }

    // The sides box sets the regular polygon's n; it is drawn flat side down (its two lowest
    // corners level) with every corner at the dragged radius.
    void polygonToolTakesItsNumberOfSides() {
        MainWindow w;
        w.resize(1200, 800);
        w.show();
        QWidget* canvas = w.canvas();
        const QPoint c = canvas->rect().center();
        auto* sides = w.findChild<QSpinBox*>(QStringLiteral("polygonSides"));
        QVERIFY(sides);
        for (const int n : {3, 5, 16}) {
            sides->setValue(n);
            QCOMPARE(w.tools()->tool(), CanvasTools::Tool::Polygon);
            w.document().newScene();
            drag(canvas, c, c + QPoint(90, 0));
            QCOMPARE(w.document().setup().polygons.size(), std::size_t(1));
            std::vector<Point2> v = w.document().setup().polygons[0].vertices;
            QCOMPARE(v.size(), std::size_t(n));
            std::sort(v.begin(), v.end(),
                      [](const Point2& a, const Point2& b) { return a[1] < b[1]; });
            QVERIFY2(std::abs(v[0][1] - v[1][1]) < 1e-9, qPrintable(QString::number(n)));
        }
    }

    // Corners clicked one by one make a convex polygon, closed by a click on the first corner
    // or by Enter; a corner that would make it non-convex is refused with the reason and the
    // outline stays as it was; Backspace takes a corner back and Esc drops the outline.
    void polygonToolClicksCorners() {
        MainWindow w;
        w.resize(1200, 800);
        w.show();
        QWidget* canvas = w.canvas();
        const QPoint c = canvas->rect().center();
        const auto* status = w.findChild<QLabel*>(QStringLiteral("statusMessage"));
        QVERIFY(status);
        w.action("toolPolygon")->trigger();
        const QPoint a = c, b = c + QPoint(100, 0), d = c + QPoint(100, -100);
        const QPoint dent = c + QPoint(70, -30);  // inside the triangle a b d: a dent
        const QPoint e = c + QPoint(0, -100);
        for (const QPoint& p : {a, b, d}) QTest::mouseClick(canvas, Qt::LeftButton, {}, p);
        QCOMPARE(w.tools()->outline().size(), 3);
        QTest::mouseClick(canvas, Qt::LeftButton, {}, dent);
        QCOMPARE(w.tools()->outline().size(), 3);
        QVERIFY2(status->text().contains(QStringLiteral("non-convex")), qPrintable(status->text()));
        QVERIFY(w.document().setup().polygons.empty());
        QTest::mouseClick(canvas, Qt::LeftButton, {}, e);
        QTest::mouseClick(canvas, Qt::LeftButton, {}, a + QPoint(2, 1));  // on the first: close
        QVERIFY(w.tools()->outline().isEmpty());
        QCOMPARE(w.document().setup().polygons.size(), std::size_t(1));
        const PolygonDesc& square = w.document().setup().polygons[0];
        QCOMPARE(square.vertices.size(), std::size_t(4));
        // Its frame at the centroid (the square's centre), the area that of the clicks.
        const QPointF centre = worldAt(w, c + QPoint(50, -50));
        QVERIFY(std::abs(square.position[0] - centre.x()) < 1e-9);
        QVERIFY(std::abs(square.position[1] - centre.y()) < 1e-9);
        const double side = QLineF(worldAt(w, a), worldAt(w, b)).length();
        QVERIFY(std::abs(square.area() - side * side) < 1e-9 * side * side);
        QCOMPARE(w.document().selection(), QStringList{QStringLiteral("poly0")});
        w.action("undo")->trigger();
        QVERIFY(w.document().setup().polygons.empty());
        w.action("redo")->trigger();
        QCOMPARE(w.document().setup().polygons.size(), std::size_t(1));

        // Three corners in a line are refused; Backspace and Esc; Enter closes a triangle.
        canvas->setFocus();
        for (const QPoint& p : {a, b})
            QTest::mouseClick(canvas, Qt::LeftButton, {}, p + QPoint(0, 150));
        QTest::mouseClick(canvas, Qt::LeftButton, {}, c + QPoint(200, 150));
        QCOMPARE(w.tools()->outline().size(), 2);
        QVERIFY2(status->text().contains(QStringLiteral("line")), qPrintable(status->text()));
        QTest::mouseClick(canvas, Qt::LeftButton, {}, c + QPoint(50, 250));
        QCOMPARE(w.tools()->outline().size(), 3);
        QTest::keyClick(canvas, Qt::Key_Backspace);
        QCOMPARE(w.tools()->outline().size(), 2);
        QTest::keyClick(canvas, Qt::Key_Escape);
        QVERIFY(w.tools()->outline().isEmpty());
        for (const QPoint& p : {a, b, d})
            QTest::mouseClick(canvas, Qt::LeftButton, {}, p + QPoint(-300, 0));
        QTest::keyClick(canvas, Qt::Key_Return);
        QCOMPARE(w.document().setup().polygons.size(), std::size_t(2));
        QCOMPARE(w.document().setup().polygons[1].vertices.size(), std::size_t(3));
    }

    // Copy and paste: a disk and a box joined by a spring come back as a new pair under fresh
    // ids, joined by their own spring, 0.5 m up and right, as one undo step; the clipboard
    // holds a scene file's text, so a scene pasted as text adds its objects too.
    void copyAndPasteObjects() {
        MainWindow w;
        w.show();
        SceneDesc scene;
        DiskDesc disk;
        disk.id = "wheel";
        disk.position = {0.0, 2.0};
        disk.radius = 0.3;
        BoxDesc box;
        box.id = "crate";
        box.position = {2.0, 2.0};
        box.size = {0.5, 0.5};
        SpringDesc spring;
        spring.id = "link";
        spring.a = "wheel";
        spring.b = "crate";
        spring.stiffness = 20.0;
        scene.disks = {disk};
        scene.boxes = {box};
        scene.springs = {spring};
        QVERIFY(w.document().loadFromDesc(scene));
        w.document().setSelection({"wheel", "crate"});
        w.action("copy")->trigger();
        const int steps = w.document().undoStack()->count();
        w.action("paste")->trigger();
        QCOMPARE(w.document().undoStack()->count(), steps + 1);
        const SceneDesc& s = w.document().setup();
        QCOMPARE(s.disks.size(), std::size_t(2));
        QCOMPARE(s.boxes.size(), std::size_t(2));
        QCOMPARE(s.springs.size(), std::size_t(2));
        QCOMPARE(s.disks[1].id, std::string("d0"));
        QCOMPARE(s.boxes[1].id, std::string("b0"));
        QCOMPARE(s.springs[1].a, std::string("d0"));
        QCOMPARE(*s.springs[1].b, std::string("b0"));
        QCOMPARE(s.disks[1].position[0], 0.5);
        QCOMPARE(s.disks[1].position[1], 2.5);
        QCOMPARE(s.disks[1].radius, 0.3);
        QCOMPARE(w.document().selection().size(), 3);
        // A second paste lands further on, not on the first.
        w.action("paste")->trigger();
        QCOMPARE(w.document().setup().disks[2].position[0], 1.0);
        w.action("undo")->trigger();
        w.action("undo")->trigger();
        QCOMPARE(serialized(w), SceneIO::serialize([&] {
                     SceneDesc original = scene;
                     return original;
                 }()));
        // Cut takes the objects away (and their spring); paste brings them back.
        w.document().setSelection({"wheel"});
        w.action("cut")->trigger();
        QVERIFY(w.document().setup().disks.empty());
        QVERIFY(w.document().setup().springs.empty());
        w.action("paste")->trigger();
        QCOMPARE(w.document().setup().disks.size(), std::size_t(1));
        // Plain text holding a scene pastes its objects; other text is refused with a message.
        QGuiApplication::clipboard()->setText(QString::fromUtf8(SceneIO::serialize(scene)));
        w.action("paste")->trigger();
        QCOMPARE(w.document().setup().disks.size(), std::size_t(2));
        QCOMPARE(w.document().setup().boxes.size(), std::size_t(2));
        QGuiApplication::clipboard()->setText(QStringLiteral("not a scene"));
        const QByteArray before = serialized(w);
        w.action("paste")->trigger();
        QCOMPARE(serialized(w), before);
        const auto* status = w.findChild<QLabel*>(QStringLiteral("statusMessage"));
        QVERIFY2(status->text().contains(QStringLiteral("clipboard")), qPrintable(status->text()));
    }

    // A teacher builds a pendulum with the tools: a particle, then a rod dragged from it to a
    // fixed point; released horizontal it swings with T = 4·√(L/g)·K(sin 45°) (within 0.2% at
    // the defaults, symplectic Euler at dt 1/60). Deleting the particle takes the rod with it
    // in one undo step.
    void jointToolBuildsAPendulum() {
        MainWindow w;
        w.resize(1200, 800);
        w.show();
        QWidget* canvas = w.canvas();
        const QPoint c = canvas->rect().center();
        const QPoint pivot = c + QPoint(0, -250), bob = pivot + QPoint(120, 0);
        w.action("toolParticle")->trigger();
        QTest::mouseClick(canvas, Qt::LeftButton, {}, bob);
        w.action("toolJoint")->trigger();
        QCOMPARE(w.tools()->tool(), CanvasTools::Tool::Joint);
        auto* type = w.findChild<QComboBox*>(QStringLiteral("jointType"));
        QVERIFY(type);
        type->setCurrentIndex(type->findText(QStringLiteral("rod")));
        QCOMPARE(w.tools()->jointType(), JointType::Rod);
        drag(canvas, bob, pivot);
        QCOMPARE(w.document().setup().joints.size(), std::size_t(1));
        const JointDesc& rod = w.document().setup().joints[0];
        QCOMPARE(rod.type, JointType::Rod);
        QCOMPARE(rod.a, std::string("p0"));
        QVERIFY(!rod.b && rod.anchor);
        QCOMPARE(w.document().selection(), QStringList{QStringLiteral("j0")});

        // Its period, from the bob's upward crossings below the pivot.
        World& world = w.document().world();
        const QPointF top = worldAt(w, pivot);
        const double length = (world.particlePosition(0) - Vec2(top.x(), top.y())).norm();
        const double exact =
            4.0 * std::sqrt(length / 9.81) * std::comp_ellint_1(std::sin(0.25 * std::numbers::pi));
        std::vector<double> crossings;
        double x = world.particlePosition(0).x() - top.x(), t = world.time();
        while (world.time() < 3.2 * exact) {
            QVERIFY(world.step());
            const double x1 = world.particlePosition(0).x() - top.x();
            if (x < 0.0 && x1 >= 0.0) crossings.push_back(t + (world.time() - t) * -x / (x1 - x));
            x = x1;
            t = world.time();
            QVERIFY(world.jointErrors().position < 1e-3);
        }
        QVERIFY(crossings.size() >= 2);
        const double period = (crossings.back() - crossings.front()) / double(crossings.size() - 1);
        QVERIFY2(std::abs(period / exact - 1.0) < 2e-3,
                 qPrintable(QString("T %1 s, exact %2 s").arg(period).arg(exact)));

        // Deleting the bob deletes its rod, as one undo step; undo brings both back.
        w.document().reset();
        w.document().setSelection({QStringLiteral("p0")});
        const int steps = w.document().undoStack()->count();
        w.action("delete")->trigger();
        QVERIFY(w.document().setup().joints.empty());
        QCOMPARE(w.document().undoStack()->count(), steps + 1);
        w.action("undo")->trigger();
        QCOMPARE(w.document().setup().joints.size(), std::size_t(1));
        QCOMPARE(w.document().setup().particles.size(), std::size_t(1));
    }

    // The pulley and track kinds of the joint tool: a drag from one particle to another hangs
    // them over two wheels a metre above the higher (an Atwood machine that then runs), a drag
    // from a particle to a point puts it on a hoop about that point.
    void jointToolMakesPulleysAndTracks() {
        MainWindow w;
        w.resize(1200, 800);
        w.show();
        QWidget* canvas = w.canvas();
        const QPoint c = canvas->rect().center() + QPoint(0, -150);
        w.action("toolParticle")->trigger();
        for (const QPoint& p : {c, c + QPoint(100, 0), c + QPoint(250, 0)})
            QTest::mouseClick(canvas, Qt::LeftButton, {}, p);
        auto* type = w.findChild<QComboBox*>(QStringLiteral("jointType"));
        type->setCurrentIndex(type->findText(QStringLiteral("pulley")));
        QCOMPARE(w.tools()->tool(), CanvasTools::Tool::Joint);
        drag(canvas, c, c + QPoint(100, 0));
        type->setCurrentIndex(type->findText(QStringLiteral("track")));
        drag(canvas, c + QPoint(250, 0), c + QPoint(250, -80));
        const auto& joints = w.document().setup().joints;
        QCOMPARE(joints.size(), std::size_t(2));
        const QPointF a = worldAt(w, c), b = worldAt(w, c + QPoint(100, 0));
        QCOMPARE(joints[0].type, JointType::Pulley);
        QCOMPARE(*joints[0].b, std::string("p1"));
        QVERIFY(std::abs(joints[0].groundA[1] - (a.y() + CanvasTools::kPulleyHeight)) < 1e-9);
        QVERIFY(std::abs(joints[0].groundB[0] - b.x()) < 1e-9);
        QCOMPARE(joints[1].type, JointType::Track);
        QVERIFY(joints[1].circle && !joints[1].b);
        const QPointF centre = worldAt(w, c + QPoint(250, -80));
        QVERIFY(std::abs(joints[1].circle->radius -
                         QLineF(worldAt(w, c + QPoint(250, 0)), centre).length()) < 1e-9);
        // Equal masses balance: the pulley holds both; the bead swings on its hoop.
        QVERIFY(w.controller().advance(1.0));
        QVERIFY(w.document().world().jointErrors().position < 1e-3);
        QVERIFY(std::abs(w.document().world().particlePosition(0).y() - a.y()) < 1e-9);
    }

    // A hinge: a click on a bar pivots it on the world there; a drag from one box to another
    // hinges the two. Its properties (limits are absent, a motor is absent) edit with undo.
    void jointToolHingesBodies() {
        MainWindow w;
        w.resize(1200, 800);
        w.show();
        QWidget* canvas = w.canvas();
        const QPoint c = canvas->rect().center() + QPoint(0, -200);
        w.action("toolBox")->trigger();
        drag(canvas, c, c + QPoint(120, 20));
        drag(canvas, c + QPoint(130, 0), c + QPoint(250, 20));
        QCOMPARE(w.document().setup().boxes.size(), std::size_t(2));
        w.action("toolJoint")->trigger();
        QCOMPARE(w.tools()->jointType(), JointType::Hinge);
        QTest::mouseClick(canvas, Qt::LeftButton, {}, c + QPoint(5, 10));
        drag(canvas, c + QPoint(115, 10), c + QPoint(140, 10));
        const auto& joints = w.document().setup().joints;
        QCOMPARE(joints.size(), std::size_t(2));
        QVERIFY(!joints[0].b);
        QCOMPARE(*joints[1].b, std::string("b1"));
        const QPointF pivot = worldAt(w, c + QPoint(115, 10));
        QVERIFY(std::abs((*joints[1].anchor)[0] - pivot.x()) < 1e-9);
        // A click on a pivot selects its joint (drawn over the bodies), for the Properties.
        w.action("toolSelect")->trigger();
        QTest::mouseClick(canvas, Qt::LeftButton, {}, c + QPoint(5, 10));
        QCOMPARE(w.document().selection(), QStringList{QStringLiteral("j0")});
        w.action("toolJoint")->trigger();
        // The two swing as a double pendulum; the hinges hold.
        QVERIFY(w.controller().advance(2.0));
        QVERIFY(w.document().world().jointErrors().position < 1e-3);
        // A weld needs a second body.
        w.document().reset();
        auto* type = w.findChild<QComboBox*>(QStringLiteral("jointType"));
        type->setCurrentIndex(type->findText(QStringLiteral("weld")));
        const Vec2 bar = w.document().world().boxPosition(0);
        QTest::mouseClick(canvas, Qt::LeftButton, {},
                          w.canvas()->toWidget(QPointF(bar.x(), bar.y())).toPoint());
        QCOMPARE(w.document().setup().joints.size(), std::size_t(2));
        const auto* status = w.findChild<QLabel*>(QStringLiteral("statusMessage"));
        QVERIFY2(status->text().contains(QStringLiteral("two bodies")), qPrintable(status->text()));
    }

    void draggingAnObjectIsOneUndoStep() {
        MainWindow w;
        w.resize(1200, 800);
        w.show();
        QWidget* canvas = w.canvas();
        const QPoint c = canvas->rect().center();
        w.action("toolParticle")->trigger();
        QTest::mouseClick(canvas, Qt::LeftButton, {}, c);
        w.action("toolSelect")->trigger();
        const int before = w.document().undoStack()->count();
        drag(canvas, c, c + QPoint(80, 40));
        QCOMPARE(w.document().undoStack()->count(), before + 1);
        const QPointF expected = worldAt(w, c + QPoint(80, 40));
        const auto& p = w.document().setup().particles[0];
        QVERIFY(std::abs(p.position[0] - expected.x()) < 1e-9);
        QCOMPARE(w.document().selection(), QStringList{QString::fromStdString(p.id)});
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
            w.canvas()
                ->toWidget(QPointF(world.particlePosition(0).x(), world.particlePosition(0).y()))
                .toPoint();
        const QPoint target = ball + QPoint(150, -100);
        QWidget* canvas = w.canvas();
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
        auto* combo = w.parametersPanel()->findChild<QComboBox*>();
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
        QVERIFY(w.recorder().energySamples().size() >= 59);
        QVERIFY(pointsIn(w.plotsPanel()->energyView()) > 0);
        QCOMPARE(w.recorder().markers().empty(), false);
        QVERIFY(w.recorder().markers().back().label.contains(QStringLiteral("rk4")));
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
        auto* combo = w.parametersPanel()->findChild<QComboBox*>("contactModel");
        QVERIFY(combo);
        auto* stiffness = w.parametersPanel()->findChild<QDoubleSpinBox*>("contactStiffness");
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
        QCOMPARE(w.recorder().markers().empty(), false);
        QVERIFY(w.recorder().markers().back().label.contains(QStringLiteral("penalty contacts")));
        // One undo step takes it back.
        w.document().undoStack()->undo();
        QCOMPARE(w.document().world().settings().contactModel, ContactModel::Impulse);
        QCOMPARE(combo->currentIndex(), static_cast<int>(ContactModel::Impulse));
    }

    // Issue 19: what a user draws on a new scene is stable at the defaults. A cloth under
    // symplectic Euler at 1/60 s would blow up; drawing it switches the integrator to one the
    // stability advisor finds stable with margin, in the same undo step, and says so.
    void drawingAClothKeepsANewSceneStable() {
        MainWindow w;
        w.resize(1200, 800);
        w.show();
        QCOMPARE(QString::fromStdString(w.document().setup().simulation.integrator),
                 QStringLiteral("symplectic_euler"));
        QWidget* canvas = w.canvas();
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
            said = said || label->text().contains(QStringLiteral("switched to implicit_euler"));
        QVERIFY(said);
        w.controller().play();
        QVERIFY(w.controller().advance(3.0));
        w.controller().pause();
        QVERIFY(!w.document().world().divergence().has_value());
        QVERIFY(w.document().world().positions().allFinite());
        // One undo takes back the cloth and the switch together.
        w.controller().reset();
        w.document().undoStack()->undo();
        QCOMPARE(w.document().setup().cloths.size(), std::size_t(0));
        QCOMPARE(QString::fromStdString(w.document().setup().simulation.integrator),
                 QStringLiteral("symplectic_euler"));
    }

    // Issue 19: an example opens with a view that holds its motion over its duration, and
    // View > Follow keeps the selection in view however far it goes.
    void viewHoldsTheMotionAndFollows() {
        MainWindow w;
        w.resize(1200, 800);
        w.show();
        QVERIFY(w.openFile(QStringLiteral(":/scenes/projectile-drag.phasebox.json"), true));
        const QRectF opened = w.canvas()->view().visibleWorldRect();
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
        ui::ViewTransform close = w.canvas()->view();
        close.setPixelsPerMetre(close.pixelsPerMetre() * 8.0);
        close.setCentre(QPointF(0.0, 0.0));
        w.canvas()->setView(close);
        // (Reset rebuilt the world: read it afresh.)
        const std::string far = w.document().world().particles().back().id;
        w.document().setSelection({QString::fromStdString(far)});
        w.action("follow")->setChecked(true);
        w.controller().play();
        for (int k = 0; k < 30; ++k) {
            QVERIFY(w.controller().advance(0.1));
            const Vec2 p = w.document().world().particlePosition(
                static_cast<int>(w.document().world().particles().size()) - 1);
            const QRectF r = w.canvas()->view().visibleWorldRect();
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
        QCOMPARE(w.recorder().phaseObject(), id);
        QVERIFY(w.recorder().phaseSamples().size() >= 59);
        QVERIFY(pointsIn(w.plotsPanel()->phaseView()) > 0);
    }

    // The live error estimate: recorded while running, plotted, in the status bar, and larger
    // when dt is raised (local error ∝ h² for symplectic Euler: doubling dt quadruples it).
    void liveErrorEstimateFollowsDt() {
        MainWindow w;
        w.show();
        QVERIFY(w.openFile(QStringLiteral(":/scenes/spring-oscillator.phasebox.json"), true));
        QVERIFY(w.controller().advance(1.0));
        w.refreshNow();
        QVERIFY(w.recorder().errorSamples().size() >= 55);
        QVERIFY(pointsIn(w.plotsPanel()->errorView()) > 0);
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
            dir = w.autosave()->recoveryDir();
            ParticleDesc p;
            p.position = {0.5, 3.0};
            QVERIFY(w.document().addObject(p));
            edited = serialized(w);
            QVERIFY(w.autosave()->autosaveNow());
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
                QCOMPARE(lines[0], QByteArray("t,kinetic,potential,work_nc,drift,correction"));
            else
                QVERIFY(lines[0].startsWith("t,"));
            QCOMPARE(lines[1].count(','), lines[0].count(','));
        }
        QVERIFY2(w.exportCanvas(dir.filePath("canvas.png"), &error), qPrintable(error));
        QVERIFY(!QImage(dir.filePath("canvas.png")).isNull());
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
