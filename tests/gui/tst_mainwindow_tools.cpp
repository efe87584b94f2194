// The desktop app's canvas tools as a user drives them, offscreen, with real mouse events:
// particles, springs, boxes, cloths, disks and polygons drawn on the canvas, copy and paste,
// the joint tool, dragging a selected object, and each edit as one undo step.

#include "MainWindowTestSupport.h"
#include "app/desktop/CanvasTools.h"
#include "app/desktop/MainWindow.h"
#include "physics/world/World.h"
#include "ui/canvas/SceneView.h"

#include <QAction>
#include <QClipboard>
#include <QComboBox>
#include <QGuiApplication>
#include <QLabel>
#include <QSpinBox>
#include <QStandardPaths>
#include <QTest>
#include <QUndoStack>

#include <cmath>
#include <numbers>

using namespace phasebox;
using namespace phasebox::testing::parts;
using testing::drag;
using testing::serialized;
using testing::worldAt;

class TestMainWindowTools : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void toolsAddObjectsWithTheMouse() {
        MainWindow w;
        w.resize(1200, 800);
        w.show();
        QWidget* canvas = canvasOf(w);
        const QRect r = canvas->rect();
        const QPoint c = r.center();

        // A click drops a particle where the mouse is.
        w.action("toolParticle")->trigger();
        QCOMPARE(toolsOf(w)->tool(), CanvasTools::Tool::Particle);
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

        // The cloth would blow symplectic Euler up: the switch to a stable method is an undo
        // step of its own after the cloth's.
        QVERIFY(w.document().setup().simulation.integrator != "symplectic_euler");

        // Every edit is one undo step; undo all of them and redo all of them.
        QUndoStack* stack = w.document().undoStack();
        QCOMPARE(stack->count(), 7);
        const QByteArray full = serialized(w);
        for (int k = 0; k < 7; ++k) w.action("undo")->trigger();
        QVERIFY(w.document().setup().particles.empty() && w.document().setup().cloths.empty());
        QCOMPARE(w.document().setup().simulation.integrator, std::string("symplectic_euler"));
        for (int k = 0; k < 7; ++k) w.action("redo")->trigger();
        QCOMPARE(serialized(w), full);
    }

    // Issue 16: the disk tool. A drag from the centre to the rim gives that radius, a click a
    // disk of kClickDiskRadius; both are one undo step, and the disk can be selected, made
    // static with the pin tool and deleted like any object.
    void diskToolAddsDisks() {
        MainWindow w;
        w.resize(1200, 800);
        w.show();
        QWidget* canvas = canvasOf(w);
        const QPoint c = canvas->rect().center();
        w.action("toolDisk")->trigger();
        QCOMPARE(toolsOf(w)->tool(), CanvasTools::Tool::Disk);
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
        QCOMPARE(w.document().world().rigidBodies().size(), std::size_t(2));

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
        QWidget* canvas = canvasOf(w);
        const QPoint c = canvas->rect().center();
        w.action("toolPolygon")->trigger();
        QCOMPARE(toolsOf(w)->tool(), CanvasTools::Tool::Polygon);
        drag(canvas, c, c + QPoint(80, 0));
        QCOMPARE(w.document().setup().polygons.size(), std::size_t(1));
        const PolygonDesc& hexagon = w.document().setup().polygons[0];
        QCOMPARE(hexagon.vertices.size(), std::size_t(CanvasTools::kPolygonSides));
        const QPointF centre = worldAt(w, c), corner = worldAt(w, c + QPoint(80, 0));
        QVERIFY(std::abs(hexagon.position[0] - centre.x()) < 1e-9);
        QVERIFY(std::abs(std::hypot(hexagon.vertices[0][0], hexagon.vertices[0][1]) -
                         QLineF(centre, corner).length()) < 1e-9);
        QCOMPARE(w.document().world().rigidBodies().size(), std::size_t(1));
        QVERIFY(w.document().world().rigidBodies()[0].shape == RigidShape::Polygon);
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
        QWidget* canvas = canvasOf(w);
        const QPoint c = canvas->rect().center();
        auto* sides = w.findChild<QSpinBox*>(QStringLiteral("polygonSides"));
        QVERIFY(sides);
        for (const int n : {3, 5, 16}) {
            sides->setValue(n);
            QCOMPARE(toolsOf(w)->tool(), CanvasTools::Tool::Polygon);
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
        QWidget* canvas = canvasOf(w);
        const QPoint c = canvas->rect().center();
        const auto* status = w.findChild<QLabel*>(QStringLiteral("statusMessage"));
        QVERIFY(status);
        w.action("toolPolygon")->trigger();
        const QPoint a = c, b = c + QPoint(100, 0), d = c + QPoint(100, -100);
        const QPoint dent = c + QPoint(70, -30);  // inside the triangle a b d: a dent
        const QPoint e = c + QPoint(0, -100);
        for (const QPoint& p : {a, b, d}) QTest::mouseClick(canvas, Qt::LeftButton, {}, p);
        QCOMPARE(toolsOf(w)->outline().size(), 3);
        QTest::mouseClick(canvas, Qt::LeftButton, {}, dent);
        QCOMPARE(toolsOf(w)->outline().size(), 3);
        QVERIFY2(status->text().contains(QStringLiteral("non-convex")), qPrintable(status->text()));
        QVERIFY(w.document().setup().polygons.empty());
        QTest::mouseClick(canvas, Qt::LeftButton, {}, e);
        QTest::mouseClick(canvas, Qt::LeftButton, {}, a + QPoint(2, 1));  // on the first: close
        QVERIFY(toolsOf(w)->outline().isEmpty());
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
        QCOMPARE(toolsOf(w)->outline().size(), 2);
        QVERIFY2(status->text().contains(QStringLiteral("line")), qPrintable(status->text()));
        QTest::mouseClick(canvas, Qt::LeftButton, {}, c + QPoint(50, 250));
        QCOMPARE(toolsOf(w)->outline().size(), 3);
        QTest::keyClick(canvas, Qt::Key_Backspace);
        QCOMPARE(toolsOf(w)->outline().size(), 2);
        QTest::keyClick(canvas, Qt::Key_Escape);
        QVERIFY(toolsOf(w)->outline().isEmpty());
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
        QWidget* canvas = canvasOf(w);
        const QPoint c = canvas->rect().center();
        const QPoint pivot = c + QPoint(0, -250), bob = pivot + QPoint(120, 0);
        w.action("toolParticle")->trigger();
        QTest::mouseClick(canvas, Qt::LeftButton, {}, bob);
        w.action("toolJoint")->trigger();
        QCOMPARE(toolsOf(w)->tool(), CanvasTools::Tool::Joint);
        auto* type = w.findChild<QComboBox*>(QStringLiteral("jointType"));
        QVERIFY(type);
        type->setCurrentIndex(type->findText(QStringLiteral("rod")));
        QCOMPARE(toolsOf(w)->jointType(), JointType::Rod);
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
        QWidget* canvas = canvasOf(w);
        const QPoint c = canvas->rect().center() + QPoint(0, -150);
        w.action("toolParticle")->trigger();
        for (const QPoint& p : {c, c + QPoint(100, 0), c + QPoint(250, 0)})
            QTest::mouseClick(canvas, Qt::LeftButton, {}, p);
        auto* type = w.findChild<QComboBox*>(QStringLiteral("jointType"));
        type->setCurrentIndex(type->findText(QStringLiteral("pulley")));
        QCOMPARE(toolsOf(w)->tool(), CanvasTools::Tool::Joint);
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
        QWidget* canvas = canvasOf(w);
        const QPoint c = canvas->rect().center() + QPoint(0, -200);
        w.action("toolBox")->trigger();
        drag(canvas, c, c + QPoint(120, 20));
        drag(canvas, c + QPoint(130, 0), c + QPoint(250, 20));
        QCOMPARE(w.document().setup().boxes.size(), std::size_t(2));
        w.action("toolJoint")->trigger();
        QCOMPARE(toolsOf(w)->jointType(), JointType::Hinge);
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
        const Vec2 bar = w.document().world().bodyPosition(0);
        QTest::mouseClick(canvas, Qt::LeftButton, {},
                          canvasOf(w)->toWidget(QPointF(bar.x(), bar.y())).toPoint());
        QCOMPARE(w.document().setup().joints.size(), std::size_t(2));
        const auto* status = w.findChild<QLabel*>(QStringLiteral("statusMessage"));
        QVERIFY2(status->text().contains(QStringLiteral("two bodies")), qPrintable(status->text()));
    }

    void draggingAnObjectIsOneUndoStep() {
        MainWindow w;
        w.resize(1200, 800);
        w.show();
        QWidget* canvas = canvasOf(w);
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
};

QTEST_MAIN(TestMainWindowTools)
#include "tst_mainwindow_tools.moc"
