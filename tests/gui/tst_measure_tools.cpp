// The canvas instruments of issue #19, offscreen: the ruler and the protractor driven by the
// mouse on the canvas (a 3-4-5 triangle reads 5.000 m; arms at right angles read 90°), a ruler
// attached to two moving particles following them against their straight-line motion, the
// free-body view of a body at rest (on a plane; on a spring at equilibrium) whose forces sum to
// zero with gravity m·g, and the total momentum of a free system the view shows staying at its
// initial Σ m·v.
//
// With PHASEBOX_SCREENSHOT_DIR set, pictures of the canvas are written there to look at.

#include "GuiTestSupport.h"
#include "MainWindowTestSupport.h"
#include "app/desktop/CanvasTools.h"
#include "app/desktop/DesktopOptions.h"
#include "app/desktop/MainWindow.h"
#include "app/desktop/MeasureTools.h"
#include "app/desktop/presenters/InstrumentsPresenter.h"
#include "app/io/SceneIO.h"
#include "physics/world/FreeBody.h"
#include "physics/world/World.h"
#include "ui/canvas/MeasureOverlay.h"
#include "ui/canvas/SceneView.h"

#include <QAction>
#include <QDir>
#include <QImage>
#include <QTest>

#include <cmath>
#include <numbers>

using namespace phasebox;
using namespace phasebox::testing::parts;
using phasebox::testing::freeScene;
using phasebox::testing::visibleParticle;

namespace {

constexpr double kG = 9.81;

struct Window {
    MainWindow w;
    Window() {
        w.resize(1200, 800);
        w.show();
        // The docks settle their sizes once shown (their tab bars are styled then): the canvas
        // has its final size before a test fixes its view.
        if (QTest::qWaitForWindowExposed(&w)) QCoreApplication::processEvents();
    }
    ui::SceneView* canvas() { return canvasOf(w); }
    MeasureTools* measure() { return measureToolsOf(w); }
    void load(const SceneDesc& scene) {
        QString error;
        QVERIFY2(w.document().loadFromDesc(scene, {}, &error), qPrintable(error));
    }
    // 64 px per metre with the world's origin on a whole pixel, so that the pixels of whole
    // metres are exact and a drag between them measures exactly (a power of two: the half
    // pixel by which an odd-sized canvas's centre lies off the origin is exact in binary too).
    void exactView() {
        ui::ViewTransform v = canvas()->view();
        const QSizeF size = v.widgetSize();
        v.setPixelsPerMetre(64.0);
        v.setCentre(QPointF((0.5 * size.width() - std::round(0.5 * size.width())) / 64.0,
                            (std::round(0.5 * size.height()) - 0.5 * size.height()) / 64.0));
        canvas()->setView(v);
    }
    // A scene of one particle, seen through exactView.
    void openWithParticle(const std::string& id, Point2 position) {
        SceneDesc scene;
        scene.particles.push_back(visibleParticle(id, position));
        load(scene);
        exactView();
    }
    QPoint pixel(double x, double y) { return canvas()->toWidget(QPointF(x, y)).toPoint(); }
    void drag(QPoint from, QPoint to) {
        QTest::mousePress(canvas(), Qt::LeftButton, {}, from);
        for (int k = 1; k <= 4; ++k) QTest::mouseMove(canvas(), from + (to - from) * k / 4);
        QTest::mouseRelease(canvas(), Qt::LeftButton, {}, to);
    }
    void snapshot(const QString& name) {
        const QString dir = qEnvironmentVariable("PHASEBOX_SCREENSHOT_DIR");
        if (dir.isEmpty()) return;
        w.refreshNow();
        canvas()->renderImage(canvas()->size()).save(QDir(dir).filePath(name));
    }
};

// A body of mass m at rest on the plane y = 0 under gravity.
SceneDesc restingScene(double m) {
    SceneDesc scene;
    scene.name = "Resting";
    scene.effects.gravity = GravityDesc{{0.0, -kG}};
    scene.particles.push_back(visibleParticle("ball", {0.0, 0.1}, m));
    PlaneDesc floor;
    floor.id = "floor";
    scene.planes.push_back(floor);
    return scene;
}

}  // namespace

class TestMeasureTools : public QObject {
    Q_OBJECT

private slots:
    void rulerByMouseReadsTheHypotenuse();
    void rulerAttachedToParticlesFollowsThem();
    void protractorReadsRightAndHalfRightAngles();
    void instrumentsAreRemovedWithEscDeleteOrClear();
    void draggingAnEndMovesAndAttachesIt();
    void freeBodyOfABodyRestingOnAPlane();
    void freeBodyOfABodyHangingAtEquilibrium();
    void freeBodyOfABoxHangingOnARod();
    void freeBodyOfTheCarsBodyShowsItsAxles();
    void momentumOfAFreeSystemStaysConstant();
    void arrowScaleIsOneTwoFive();
    void commandLineSwitches();
};

void TestMeasureTools::rulerByMouseReadsTheHypotenuse() {
    Window win;
    win.load(SceneDesc{});
    win.exactView();
    toolsOf(win.w)->setTool(CanvasTools::Tool::Ruler);
    QCOMPARE(win.w.action(QStringLiteral("toolRuler"))->isChecked(), true);
    win.drag(win.pixel(0.0, 0.0), win.pixel(3.0, 4.0));
    QCOMPARE(win.measure()->rulerCount(), 1);
    // 3-4-5: the distance is 5 m exactly (the pixels are those of whole metres).
    QVERIFY(std::abs(win.measure()->rulerLength(0) - 5.0) < 1e-12);
    QCOMPARE(win.measure()->rulerLabel(0), QStringLiteral("5.000 m\ndx 3.000  dy 4.000"));
    // What the canvas draws is what was measured, ends at fixed points.
    const ui::MeasureOverlay& drawn = win.canvas()->measurements();
    QCOMPARE(drawn.rulers.size(), 1);
    QCOMPARE(drawn.rulers[0].label, win.measure()->rulerLabel(0));
    QVERIFY(!drawn.rulers[0].attachedA && !drawn.rulers[0].attachedB);
    QVERIFY(drawn.rulers[0].selected);
    // A click is no ruler.
    QTest::mouseClick(win.canvas(), Qt::LeftButton, {}, win.pixel(-2.0, -2.0));
    QCOMPARE(win.measure()->rulerCount(), 1);
    win.snapshot(QStringLiteral("ruler.png"));
}

void TestMeasureTools::rulerAttachedToParticlesFollowsThem() {
    // No force: a moves along x at 1 m/s, b along y at 0.5 m/s, so at time t the ruler reads
    // √((3 − t)² + (4 + 0.5 t)²).
    SceneDesc scene;
    scene.particles.push_back(visibleParticle("a", {0.0, 0.0}, 1.0, {1.0, 0.0}));
    scene.particles.push_back(visibleParticle("b", {3.0, 4.0}, 2.0, {0.0, 0.5}));
    Window win;
    win.load(scene);
    win.exactView();
    toolsOf(win.w)->setTool(CanvasTools::Tool::Ruler);
    win.drag(win.pixel(0.0, 0.0), win.pixel(3.0, 4.0));
    QCOMPARE(win.measure()->rulerCount(), 1);
    QVERIFY(win.canvas()->measurements().rulers[0].attachedA);
    QVERIFY(win.canvas()->measurements().rulers[0].attachedB);
    QVERIFY(std::abs(win.measure()->rulerLength(0) - 5.0) < 1e-12);
    QVERIFY(win.w.controller().advance(1.5));
    const double t = win.w.document().world().time();
    QVERIFY(t > 1.4);
    const double expected = std::hypot(3.0 - t, 4.0 + 0.5 * t);
    qInfo("t = %.4f s: ruler %.9f m, closed form %.9f m", t, win.measure()->rulerLength(0),
          expected);
    QVERIFY(std::abs(win.measure()->rulerLength(0) - expected) < 1e-9);
    // The end on a is where a is.
    QVERIFY(std::abs(win.measure()->rulerEnd(0, 0).x() - t) < 1e-9);
    QCOMPARE(win.canvas()->measurements().rulers[0].label, win.measure()->rulerLabel(0));
    win.snapshot(QStringLiteral("ruler-attached.png"));
    // Deleting a takes the ruler attached to it away.
    win.w.document().setSelection({QStringLiteral("a")});
    win.w.action(QStringLiteral("delete"))->trigger();
    QCOMPARE(win.measure()->rulerCount(), 0);
}

void TestMeasureTools::protractorReadsRightAndHalfRightAngles() {
    Window win;
    win.load(SceneDesc{});
    win.exactView();
    toolsOf(win.w)->setTool(CanvasTools::Tool::Protractor);
    // Vertex at the origin, first arm along x, then a click on the y axis.
    win.drag(win.pixel(0.0, 0.0), win.pixel(2.0, 0.0));
    QCOMPARE(win.measure()->protractorCount(), 0);
    QTest::mouseMove(win.canvas(), win.pixel(0.0, 3.0));
    QTest::mouseClick(win.canvas(), Qt::LeftButton, {}, win.pixel(0.0, 3.0));
    QCOMPARE(win.measure()->protractorCount(), 1);
    QVERIFY(std::abs(win.measure()->protractorDegrees(0) - 90.0) < 1e-12);
    QCOMPARE(win.measure()->protractorLabel(0), QStringLiteral("90.0°"));
    // It is the probe angle(A,B,C) with the vertex in the middle: the first arm's end, the
    // vertex, the second arm's end, points written X:Y.
    QCOMPARE(win.measure()->protractorProbe(0), QStringLiteral("angle(2:0,0:0,0:3)"));
    // 45°, clockwise or counter-clockwise, from the command line's form A,B,C (B the vertex).
    QString error;
    QVERIFY2(win.measure()->addProtractor(QStringLiteral("1:0,0:0,1:1"), &error),
             qPrintable(error));
    QVERIFY(std::abs(win.measure()->protractorDegrees(1) - 45.0) < 1e-12);
    QVERIFY(win.measure()->addProtractor(QStringLiteral("3:1, 1:1, 2:0"), &error));
    QVERIFY(std::abs(win.measure()->protractorDegrees(2) - 45.0) < 1e-12);
    QCOMPARE(win.measure()->protractorProbe(2), QStringLiteral("angle(3:1,1:1,2:0)"));
    // The canvas draws the vertex where the middle end is.
    QCOMPARE(win.canvas()->measurements().protractors.size(), 3);
    QCOMPARE(win.canvas()->measurements().protractors[2].vertex, QPointF(1.0, 1.0));
    QCOMPARE(win.canvas()->measurements().protractors[0].vertex, QPointF(0.0, 0.0));
    // The Instruments dock offers every instrument's probe.
    for (int i = 0; i < 3; ++i)
        QVERIFY(instrumentsOf(win.w)->offered().contains(win.measure()->protractorProbe(i)));
    QVERIFY(!win.measure()->addProtractor(QStringLiteral("0:0,1:0"), &error));
    QVERIFY2(error.contains(QStringLiteral("A,B,C")), qPrintable(error));
    win.snapshot(QStringLiteral("protractor.png"));
}

void TestMeasureTools::instrumentsAreRemovedWithEscDeleteOrClear() {
    Window win;
    win.openWithParticle("p", {5.0, 5.0});
    toolsOf(win.w)->setTool(CanvasTools::Tool::Ruler);
    win.drag(win.pixel(0.0, 0.0), win.pixel(2.0, 0.0));
    win.drag(win.pixel(0.0, 1.0), win.pixel(2.0, 1.0));
    QCOMPARE(win.measure()->rulerCount(), 2);
    // A click on the first selects it; Delete on the canvas removes it, not the scene's objects.
    QTest::mouseClick(win.canvas(), Qt::LeftButton, {}, win.pixel(1.0, 0.0));
    win.w.document().setSelection({QStringLiteral("p")});
    win.canvas()->setFocus();
    QTest::keyClick(win.canvas(), Qt::Key_Delete);
    QCOMPARE(win.measure()->rulerCount(), 1);
    QVERIFY(std::abs(win.measure()->rulerEnd(0, 0).y() - 1.0) < 1e-12);
    QCOMPARE(win.w.document().world().particles().size(), std::size_t(1));
    // Nothing selected now: Delete goes back to the objects. Esc removes a selected one.
    QTest::mouseClick(win.canvas(), Qt::LeftButton, {}, win.pixel(1.0, 1.0));
    QTest::keyClick(win.canvas(), Qt::Key_Escape);
    QCOMPARE(win.measure()->rulerCount(), 0);
    win.drag(win.pixel(0.0, 0.0), win.pixel(2.0, 0.0));
    QVERIFY(win.measure()->addRuler(QStringLiteral("p,0:0"), nullptr));
    QCOMPARE(win.measure()->rulerCount(), 2);
    QVERIFY(std::abs(win.measure()->rulerLength(1) - std::sqrt(50.0)) < 1e-12);
    win.w.action(QStringLiteral("clearMeasurements"))->trigger();
    QCOMPARE(win.measure()->rulerCount(), 0);
    QVERIFY(win.canvas()->measurements().rulers.isEmpty());
}

void TestMeasureTools::draggingAnEndMovesAndAttachesIt() {
    Window win;
    win.openWithParticle("p", {4.0, 3.0});
    QCOMPARE(win.w.action(QStringLiteral("toolRuler"))->shortcut(), QKeySequence(Qt::Key_R));
    QCOMPARE(win.w.action(QStringLiteral("toolProtractor"))->shortcut(), QKeySequence(Qt::Key_P));
    QCOMPARE(win.w.action(QStringLiteral("freeBody"))->shortcut(), QKeySequence(Qt::Key_B));
    toolsOf(win.w)->setTool(CanvasTools::Tool::Ruler);
    win.drag(win.pixel(0.0, 0.0), win.pixel(2.0, 0.0));
    QVERIFY(std::abs(win.measure()->rulerLength(0) - 2.0) < 1e-12);
    // The end at (2, 0) dropped on p: attached, 5 m from the origin.
    win.drag(win.pixel(2.0, 0.0), win.pixel(4.0, 3.0));
    QCOMPARE(win.measure()->rulerCount(), 1);
    QVERIFY(win.canvas()->measurements().rulers[0].attachedB);
    QVERIFY(std::abs(win.measure()->rulerLength(0) - 5.0) < 1e-12);
    // Moving p moves the end.
    QString error;
    QVERIFY2(win.w.document().moveObject(QStringLiteral("p"), {0.0, 3.0}, &error),
             qPrintable(error));
    QVERIFY(std::abs(win.measure()->rulerLength(0) - 3.0) < 1e-12);
    // Dragged off into empty space the end stays there, detached.
    win.drag(win.pixel(0.0, 3.0), win.pixel(0.0, -1.0));
    QVERIFY(!win.canvas()->measurements().rulers[0].attachedB);
    QVERIFY(std::abs(win.measure()->rulerLength(0) - 1.0) < 1e-12);
}

void TestMeasureTools::freeBodyOfABodyRestingOnAPlane() {
    const double m = 2.0;
    Window win;
    win.load(restingScene(m));
    win.w.document().setSelection({QStringLiteral("ball")});
    win.w.action(QStringLiteral("freeBody"))->trigger();
    QVERIFY(win.measure()->freeBodyShown());
    QVERIFY(win.w.controller().advance(2.0));
    const ui::MeasureOverlay& drawn = win.canvas()->measurements();
    QVERIFY(drawn.freeBodyShown);
    QVERIFY(drawn.freeBody.has_value());
    QCOMPARE(drawn.freeBodyName, QStringLiteral("ball"));
    const FreeBody& body = *drawn.freeBody;
    const BodyForce* gravity = nullptr;
    const BodyForce* contact = nullptr;
    for (const BodyForce& f : body.forces) {
        if (f.source == BodyForce::Source::Effect && f.name == "gravity") gravity = &f;
        if (f.source == BodyForce::Source::Contact) contact = &f;
    }
    QVERIFY(gravity && contact);
    QCOMPARE(body.forces.size(), std::size_t(2));
    // Gravity is m·g straight down; the floor's push holds it: the sum is zero.
    QVERIFY(std::abs(gravity->force.y() + m * kG) < 1e-12 && gravity->force.x() == 0.0);
    qInfo("gravity (%.9g, %.9g) N, contact (%.9g, %.9g) N, net %.3g N", gravity->force.x(),
          gravity->force.y(), contact->force.x(), contact->force.y(), body.net().norm());
    QVERIFY(std::abs(contact->force.y() - m * kG) < 1e-6 * m * kG);
    QVERIFY(body.net().norm() < 1e-6 * m * kG);
    QVERIFY(body.momentum.norm() < 1e-6);
    // The centre of mass of the one body is the body.
    QVERIFY(drawn.centreOfMass.has_value());
    QVERIFY(std::abs(drawn.centreOfMass->y() - body.position.y()) < 1e-12);
    win.snapshot(QStringLiteral("free-body-resting.png"));
    // Nothing selected: the view asks for a body.
    win.w.document().setSelection({});
    QVERIFY(!win.canvas()->measurements().freeBody.has_value());
    win.w.action(QStringLiteral("freeBody"))->trigger();
    QVERIFY(!win.canvas()->measurements().freeBodyShown);
}

void TestMeasureTools::freeBodyOfABodyHangingAtEquilibrium() {
    // m on a spring k of rest length L0 hangs at L0 + m·g/k below its anchor: the spring pulls
    // m·g up, gravity m·g down.
    const double m = 1.5, k = 60.0, L0 = 1.0;
    SceneDesc scene;
    scene.effects.gravity = GravityDesc{{0.0, -kG}};
    scene.particles.push_back(visibleParticle("bob", {0.0, -(L0 + m * kG / k)}, m));
    SpringDesc spring;
    spring.id = "spring";
    spring.a = "bob";
    spring.anchor = Point2{0.0, 0.0};
    spring.stiffness = k;
    spring.restLength = L0;
    spring.damping = 0.5;
    scene.springs.push_back(spring);
    Window win;
    win.load(scene);
    win.w.document().setSelection({QStringLiteral("bob")});
    win.measure()->setFreeBodyShown(true);
    QVERIFY(win.w.action(QStringLiteral("freeBody"))->isChecked());
    QVERIFY(win.w.controller().advance(1.0));
    const std::optional<FreeBody> body = win.canvas()->measurements().freeBody;
    QVERIFY(body.has_value());
    QCOMPARE(body->forces.size(), std::size_t(2));
    const BodyForce& gravity = body->forces[0];
    const BodyForce& pull = body->forces[1];
    QCOMPARE(pull.source, BodyForce::Source::Spring);
    QCOMPARE(pull.name, std::string("spring"));
    qInfo("gravity %.12g N, spring %.12g N, net %.3g N", gravity.force.y(), pull.force.y(),
          body->net().norm());
    QVERIFY(std::abs(gravity.force.y() + m * kG) < 1e-12);
    QVERIFY(std::abs(pull.force.y() - m * kG) < 1e-9);
    QVERIFY(body->net().norm() < 1e-9);
    win.snapshot(QStringLiteral("free-body-spring.png"));
}

void TestMeasureTools::freeBodyOfABoxHangingOnARod() {
    // A box hangs at rest straight below the rod's fixed end: the rod holds its weight m·g.
    SceneDesc scene;
    scene.effects.gravity = GravityDesc{{0.0, -kG}};
    BoxDesc box;
    box.id = "crate";
    box.position = {0.0, -1.5};
    box.mass = 3.0;
    scene.boxes.push_back(box);
    JointDesc rod;
    rod.id = "rod";
    rod.type = JointType::Rod;
    rod.a = "crate";
    rod.anchor = Point2{0.0, 0.0};
    scene.joints.push_back(rod);
    Window win;
    win.load(scene);
    win.w.document().setSelection({QStringLiteral("crate")});
    win.measure()->setFreeBodyShown(true);
    QVERIFY(win.w.controller().advance(1.0));
    const std::optional<FreeBody> body = win.measure()->freeBody();
    QVERIFY(body.has_value());
    QVERIFY(body->body.rigid);
    QCOMPARE(body->forces.size(), std::size_t(2));
    const BodyForce& joint = body->forces[1];
    QCOMPARE(joint.source, BodyForce::Source::Joint);
    QCOMPARE(joint.name, std::string("rod"));
    qInfo("gravity %.12g N, rod %.12g N (x %.3g), net %.3g N", body->forces[0].force.y(),
          joint.force.y(), joint.force.x(), body->net().norm());
    QVERIFY(std::abs(body->forces[0].force.y() + 3.0 * kG) < 1e-12);
    QVERIFY(std::abs(joint.force.y() - 3.0 * kG) < 1e-9 * 3.0 * kG);
    QVERIFY(body->net().norm() < 1e-9 * 3.0 * kG);
    // What the canvas shows is the same.
    QCOMPARE(win.canvas()->measurements().freeBody->forces.size(), std::size_t(2));
    win.snapshot(QStringLiteral("free-body-rod.png"));
}

void TestMeasureTools::freeBodyOfTheCarsBodyShowsItsAxles() {
    // The car example's body, rolling at a steady speed on level ground at 1.5 s, is held up by
    // its two axles: their hinge forces carry its weight (4 kg: 39.24 N), and the net force is
    // its mass times an acceleration near zero. (The status bar's local-error estimate evaluates
    // the joints on a trial step without the contacts, where the car falls freely and the
    // hinges pull nothing: the view showed that trial's forces, 1e-23 N, and a net force of the
    // whole weight.)
    const SceneLoadResult loaded =
        SceneIO::load(QStringLiteral(PHASEBOX_SOURCE_DIR "/resources/scenes/car.phasebox.json"));
    QVERIFY(loaded.ok());
    Window win;
    win.load(*loaded.scene);
    win.w.document().setSelection({QStringLiteral("chassis")});
    win.measure()->setFreeBodyShown(true);
    QVERIFY(win.w.controller().advance(1.5));
    const std::optional<FreeBody> body = win.measure()->freeBody();
    QVERIFY(body.has_value());
    double up = 0.0;
    for (const BodyForce& f : body->forces) {
        qInfo("%s: (%.4g, %.4g) N", f.name.c_str(), f.force.x(), f.force.y());
        if (f.source == BodyForce::Source::Joint) up += f.force.y();
    }
    const double weight = 4.0 * 9.81;
    qInfo("the axles hold %.4g N of its %.4g N; net %.4g N", up, weight, body->net().norm());
    QVERIFY2(std::abs(up / weight - 1.0) < 0.05, qPrintable(QString::number(up)));
    QVERIFY2(body->net().norm() < 0.05 * weight, qPrintable(QString::number(body->net().norm())));
}

void TestMeasureTools::momentumOfAFreeSystemStaysConstant() {
    // GuiTestSupport's free system: Σ m·v = (0.4, 0.8), and the centre of mass moves with
    // Σ m·v / Σ m.
    const SceneDesc scene = freeScene();
    Window win;
    win.load(scene);
    win.w.document().setSelection({QStringLiteral("a")});
    win.measure()->setFreeBodyShown(true);
    const double boxMass = scene.boxes[0].resolvedMass();
    const double mass = 1.0 + 3.0 + boxMass;
    const QPointF com0((-1.0 * 1.0 + 1.0 * 3.0) / mass, 3.0 * boxMass / mass);
    double worst = 0.0;
    for (int k = 0; k < 6; ++k) {
        QVERIFY(win.w.controller().advance(0.5));
        const ui::MeasureOverlay& drawn = win.canvas()->measurements();
        const QPointF p = drawn.systemMomentum;
        worst = std::max(worst, std::hypot(p.x() - 0.4, p.y() - 0.8));
        const double t = win.w.document().world().time();
        QVERIFY(drawn.centreOfMass.has_value());
        const QPointF com = *drawn.centreOfMass;
        QVERIFY(std::abs(com.x() - (com0.x() + 0.4 / mass * t)) < 1e-9);
        QVERIFY(std::abs(com.y() - (com0.y() + 0.8 / mass * t)) < 1e-9);
        // The body's arrow is its own m·v, which the spring changes.
        const World& world = win.w.document().world();
        QVERIFY((drawn.freeBody->momentum - 1.0 * world.particleVelocity(0)).norm() < 1e-12);
    }
    qInfo("largest |P - (0.4, 0.8)| over 3 s: %.3g kg m/s", worst);
    QVERIFY(worst < 1e-12);
    win.snapshot(QStringLiteral("free-body-momentum.png"));
}

void TestMeasureTools::arrowScaleIsOneTwoFive() {
    using R = ui::MeasureRenderer;
    // 19.62 N in at most 120 px: 0.1635 N/px rounds up to 0.2.
    QCOMPARE(R::arrowScale(2.0 * kG, 120.0), 0.2);
    QCOMPARE(R::arrowScale(120.0, 120.0), 1.0);
    QCOMPARE(R::arrowScale(121.0, 120.0), 2.0);
    QCOMPARE(R::arrowScale(500.0, 100.0), 5.0);
    QCOMPARE(R::arrowScale(0.0, 120.0), 1.0);
    QCOMPARE(R::number(9.81), QStringLiteral("9.81"));
    QCOMPARE(R::number(19.62), QStringLiteral("19.6"));
}

void TestMeasureTools::commandLineSwitches() {
    DesktopOptions options;
    QString error;
    QVERIFY(parseDesktopOptions({QStringLiteral("phasebox"), QStringLiteral("--ruler"),
                                 QStringLiteral("0:0,3:4"), QStringLiteral("--protractor"),
                                 QStringLiteral("0:0,1:0,0:1"), QStringLiteral("--free-body")},
                                options, &error));
    QCOMPARE(options.rulers, QStringList{QStringLiteral("0:0,3:4")});
    QCOMPARE(options.protractors, QStringList{QStringLiteral("0:0,1:0,0:1")});
    QVERIFY(options.freeBody);
    Window win;
    win.load(SceneDesc{});
    QVERIFY(win.measure()->addRuler(options.rulers[0], &error));
    QVERIFY(std::abs(win.measure()->rulerLength(0) - 5.0) < 1e-12);
    QVERIFY(!win.measure()->addRuler(QStringLiteral("nobody,0:0"), &error));
    QVERIFY(error.contains(QStringLiteral("object id or X:Y")));
}

QTEST_MAIN(TestMeasureTools)
#include "tst_measure_tools.moc"
