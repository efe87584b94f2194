// The scene canvas: what SceneRenderer draws where (read back from the pixels), the view's
// arithmetic, picking, and SceneView's backend choice and mouse handling under the offscreen
// platform.

#include "physics/scene/BuildWorld.h"
#include "physics/scene/SceneLibrary.h"
#include "ui/canvas/GhostOverlay.h"
#include "ui/canvas/SceneRenderer.h"
#include "ui/canvas/SceneView.h"

#include <QApplication>
#include <QDir>
#include <QImage>
#include <QOpenGLWidget>
#include <QPainter>
#include <QSignalSpy>
#include <QTest>
#include <QWheelEvent>

#include <cmath>
#include <memory>
#include <numbers>

using namespace phasebox;
using namespace phasebox::ui;

namespace {

const QSize kSize(400, 300);

QImage render(const World& world, const ViewTransform& view, QSize size = kSize,
              const RenderOptions& options = {}) {
    QImage image(size, QImage::Format_ARGB32_Premultiplied);
    QPainter painter(&image);
    SceneRenderer::paint(painter, view, size, world, options);
    return image;
}

int colourDistance(QColor a, QColor b) {
    return std::max({std::abs(a.red() - b.red()), std::abs(a.green() - b.green()),
                     std::abs(a.blue() - b.blue())});
}

bool looksLike(const QImage& image, QPointF at, QColor expected, int tolerance = 10) {
    return colourDistance(image.pixelColor(at.toPoint()), expected) <= tolerance;
}

// Nothing drawn there: the background or a grid line.
bool isEmptyCanvas(const QImage& image, QPointF at) {
    const RenderOptions o;
    return looksLike(image, at, o.background, 2) || looksLike(image, at, o.colors.grid, 2) ||
           looksLike(image, at, o.colors.axis, 2);
}

std::unique_ptr<World> worldWithParticle(Vec2 position, double radius) {
    auto world = std::make_unique<World>();
    Particle p;
    p.id = "ball";
    p.position = position;
    p.radius = radius;
    world->addParticle(p);
    world->commit();
    return world;
}

std::unique_ptr<World> worldWithPlane(Vec2 point, Vec2 normal) {
    auto world = std::make_unique<World>();
    Plane plane;
    plane.id = "ground";
    plane.point = point;
    plane.normal = normal.normalized();
    world->addPlane(plane);
    world->commit();
    return world;
}

// A ball hanging from an anchor by a spring, a tilted box to its right, the ground below.
std::unique_ptr<World> pickingWorld() {
    auto world = std::make_unique<World>();
    Particle ball;
    ball.id = "ball";
    ball.radius = 0.1;
    world->addParticle(ball);
    RigidBody crate;
    crate.id = "crate";
    crate.position = {2.0, 0.0};
    crate.angle = 0.3;
    world->addRigidBody(crate);
    Plane ground;
    ground.id = "ground";
    ground.point = {0.0, -1.0};
    world->addPlane(ground);
    Spring spring;
    spring.id = "sp";
    spring.a = {SpringEnd::Kind::Anchor, -1, Vec2(-2.0, 1.0)};
    spring.b = {SpringEnd::Kind::Particle, 0, Vec2::Zero()};
    spring.stiffness = 10.0;
    spring.restLength = std::sqrt(5.0);
    world->addSpring(spring);
    world->commit();
    return world;
}

int countNear(const QImage& image, QColor colour, int tolerance) {
    int n = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            n += looksLike(image, QPointF(x, y), colour, tolerance);
    return n;
}

}  // namespace

class TestSceneRenderer : public QObject {
    Q_OBJECT

private slots:
    void viewTransformRoundTrip();
    void zoomAroundKeepsPointFixed();
    void fitFramesTheRect();
    void gridSpacingStaysApart();
    void particleDrawnWhereItIs();
    void rotatedBoxCoversItsRotatedShape();
    void planeFillsSolidSideOnly();
    void springColourFollowsStrain();
    void spritePathMatchesEllipsePath();
    void pickFindsEachKind();
    void trailsKeepRecentSamples();
    void offscreenUsesRasterEvenWhenOpenGLRequested();
    void mousePressReportsWorldCoordinates();
    void rightDragPansWithoutReporting();
    void wheelZoomKeepsPointUnderCursor();
    void emptyViewShowsAxesAtOrigin();
    void renderImageMatchesRenderer();
    void overlayIsDrawn();
    void updateRepaintsTheSurface();
    void decorationsAreDrawn();
    void libraryScenesRender();
    void ghostDimsItsSleepers();
};

void TestSceneRenderer::viewTransformRoundTrip() {
    const ViewTransform view({1.5, -2.0}, 37.0, {640, 480});
    QCOMPARE(view.toScreen(QPointF(1.5, -2.0)), QPointF(320, 240));
    // y points up in the world and down on screen.
    QVERIFY(view.toScreen(QPointF(1.5, -1.0)).y() < 240.0);
    for (const QPointF w : {QPointF(0, 0), QPointF(-3.25, 7.5), QPointF(1e3, -1e3)}) {
        const QPointF back = view.toWorld(view.toScreen(w));
        QVERIFY(std::abs(back.x() - w.x()) < 1e-9 && std::abs(back.y() - w.y()) < 1e-9);
    }
    QCOMPARE(view.worldToScreen().map(QPointF(-3.25, 7.5)), view.toScreen(QPointF(-3.25, 7.5)));
}

void TestSceneRenderer::zoomAroundKeepsPointFixed() {
    ViewTransform view({0.3, 0.7}, 50.0, {800, 600});
    const QPointF cursor(123.0, 456.0);
    const QPointF before = view.toWorld(cursor);
    for (const double factor : {1.2, 0.5, 3.0, 1e12 /* clamped */}) {
        view.zoomAround(cursor, factor);
        const QPointF after = view.toWorld(cursor);
        QVERIFY2(QLineF(before, after).length() < 1e-6 * std::max(1.0, 1.0 / view.pixelsPerMetre()),
                 qPrintable(QString("moved by %1 m").arg(QLineF(before, after).length())));
    }
    QCOMPARE(view.pixelsPerMetre(), ViewTransform::kMaxPixelsPerMetre);
}

void TestSceneRenderer::fitFramesTheRect() {
    ViewTransform view;
    const QRectF rect(-2.0, 0.0, 8.0, 3.0);  // wide: the width decides the scale
    view.fit(rect, QSizeF(500, 400), 20.0);
    QCOMPARE(view.pixelsPerMetre(), (500.0 - 40.0) / 8.0);
    const QPointF lo = view.toScreen(rect.topLeft()), hi = view.toScreen(rect.bottomRight());
    QVERIFY(std::abs(lo.x() - 20.0) < 1e-9 && std::abs(hi.x() - 480.0) < 1e-9);
    QVERIFY(hi.y() >= 20.0 && lo.y() <= 380.0);
}

void TestSceneRenderer::gridSpacingStaysApart() {
    for (const double ppm : {0.37, 3.0, 17.0, 40.0, 99.9, 100.0, 101.0, 250.0, 1234.5, 1e5}) {
        const double spacing = SceneRenderer::gridSpacing(ppm);
        QVERIFY2(spacing * ppm >= 40.0 - 1e-9, qPrintable(QString::number(ppm)));
        QVERIFY2(spacing * ppm < 100.0 + 1e-9, qPrintable(QString::number(ppm)));  // not sparse
        const double mantissa = spacing / std::pow(10.0, std::floor(std::log10(spacing) + 1e-9));
        QVERIFY(std::abs(mantissa - 1) < 1e-6 || std::abs(mantissa - 2) < 1e-6 ||
                std::abs(mantissa - 5) < 1e-6);
    }
    // And on the pixels: the vertical grid lines met along a row are at least 40 px apart.
    World empty;
    for (const double ppm : {37.0, 130.0, 2900.0}) {
        const QImage image =
            render(empty, ViewTransform({0.123, 0.0}, ppm, {600, 200}), {600, 200});
        int row = 0;  // a row with no horizontal grid line on it
        while (!looksLike(image, QPointF(300, row), RenderOptions{}.background, 0)) ++row;
        std::vector<int> lines;
        for (int x = 0; x < image.width(); ++x)
            if (!looksLike(image, QPointF(x, row), RenderOptions{}.background, 0))
                lines.push_back(x);
        QVERIFY2(lines.size() >= 3,
                 qPrintable(QString("ppm %1: %2 lines").arg(ppm).arg(lines.size())));
        for (std::size_t k = 1; k < lines.size(); ++k) QVERIFY(lines[k] - lines[k - 1] >= 40);
    }
}

void TestSceneRenderer::particleDrawnWhereItIs() {
    const auto world = worldWithParticle({1.0, 0.5}, 0.1);
    const ViewTransform view({0.0, 0.0}, 100.0, kSize);
    const QImage image = render(*world, view);
    const QPointF centre = view.toScreen(QPointF(1.0, 0.5));
    QCOMPARE(centre, QPointF(300, 100));
    QVERIFY(looksLike(image, centre, RenderOptions{}.colors.particle));
    QVERIFY(looksLike(image, centre + QPointF(6, 0), RenderOptions{}.colors.particle));
    QVERIFY(isEmptyCanvas(image, centre + QPointF(14, 0)));  // radius 10 px
    QVERIFY(isEmptyCanvas(image, QPointF(73, 237)));

    // A radius-0 particle still shows (at least 3 px).
    const auto dot = worldWithParticle({0.0, 0.0}, 0.0);
    const QImage small = render(*dot, view);
    QVERIFY(looksLike(small, view.toScreen(QPointF(0, 0)), RenderOptions{}.colors.particle, 40));
}

void TestSceneRenderer::rotatedBoxCoversItsRotatedShape() {
    World world;
    RigidBody box;
    box.id = "diamond";
    box.angle = std::numbers::pi / 4.0;  // corners on the axes at ±0.707 m
    world.addRigidBody(box);
    world.commit();
    const ViewTransform view({0.0, 0.0}, 100.0, kSize);
    const QImage image = render(world, view);
    const QColor fill = RenderOptions{}.colors.dynamicBox;
    QVERIFY(looksLike(image, view.toScreen(QPointF(0.0, 0.0)), fill));
    QVERIFY(looksLike(image, view.toScreen(QPointF(0.6, 0.0)), fill));  // beyond an unrotated box
    QVERIFY(looksLike(image, view.toScreen(QPointF(0.0, -0.6)), fill));
    QVERIFY(isEmptyCanvas(image, view.toScreen(QPointF(0.76, 0.0))));   // just past the corner
    QVERIFY(isEmptyCanvas(image, view.toScreen(QPointF(0.45, 0.45))));  // an unrotated corner
}

void TestSceneRenderer::planeFillsSolidSideOnly() {
    const ViewTransform view({0.0, 0.0}, 100.0, kSize);
    const QColor solid = RenderOptions{}.colors.plane;
    const auto ground = worldWithPlane({0.0, 0.0}, {0.0, 1.0});
    const QImage flat = render(*ground, view);
    QVERIFY(looksLike(flat, view.toScreen(QPointF(0.3, -0.5)), solid));
    QVERIFY(looksLike(flat, view.toScreen(QPointF(1.7, -1.2)), solid));
    QVERIFY(isEmptyCanvas(flat, view.toScreen(QPointF(0.3, 0.5))));

    const auto slope = worldWithPlane({0.0, 0.0}, {1.0, 1.0});
    const QImage tilted = render(*slope, view);
    QVERIFY(looksLike(tilted, view.toScreen(QPointF(-0.6, -0.2)), solid));
    QVERIFY(looksLike(tilted, view.toScreen(QPointF(0.5, -0.9)), solid));
    QVERIFY(isEmptyCanvas(tilted, view.toScreen(QPointF(0.2, 0.6))));
    QVERIFY(isEmptyCanvas(tilted, view.toScreen(QPointF(0.9, -0.5))));
}

void TestSceneRenderer::springColourFollowsStrain() {
    const SceneColors c;
    QCOMPARE(SceneRenderer::springColor(0.0), c.springRest);
    QCOMPARE(SceneRenderer::springColor(1.0), c.springStretched);
    QCOMPARE(SceneRenderer::springColor(-1.0), c.springCompressed);
    const QColor half = SceneRenderer::springColor(0.5 * SceneRenderer::kFullStrain);
    QVERIFY(half.red() > c.springRest.red() && half.red() < c.springStretched.red() + 1);

    // Drawn: a spring stretched to twice its length shows red, one squeezed to half blue.
    for (const double rest : {1.0, 4.0}) {
        World world;
        Spring s;
        s.a = {SpringEnd::Kind::Anchor, -1, Vec2(-1.0, 0.0)};
        s.b = {SpringEnd::Kind::Anchor, -1, Vec2(1.0, 0.0)};
        s.stiffness = 100.0;
        s.restLength = rest;
        world.addSpring(s);
        world.commit();
        const QImage image = render(world, ViewTransform({0, 0}, 100.0, kSize));
        const QColor expected = rest < 2.0 ? c.springStretched : c.springCompressed;
        const QColor other = rest < 2.0 ? c.springCompressed : c.springStretched;
        QVERIFY2(countNear(image, expected, 30) > 100, qPrintable(QString::number(rest)));
        QCOMPARE(countNear(image, other, 30), 0);
    }
}

void TestSceneRenderer::spritePathMatchesEllipsePath() {
    const ViewTransform view({0.0, 0.0}, 100.0, kSize);
    const QPointF at(0.5, 0.25);
    const auto one = worldWithParticle({at.x(), at.y()}, 0.1);
    // The same particle among 600 others far off screen: more than spriteThreshold discs.
    World many;
    Particle p;
    p.radius = 0.1;
    p.position = {at.x(), at.y()};
    many.addParticle(p);
    for (int i = 0; i < 600; ++i) {
        p.position = {1000.0 + i, 0.0};
        many.addParticle(p);
    }
    many.commit();
    const QImage ellipse = render(*one, view), sprite = render(many, view);
    const QPointF centre = view.toScreen(at);
    QVERIFY(looksLike(sprite, centre, RenderOptions{}.colors.particle));
    QVERIFY(colourDistance(sprite.pixelColor(centre.toPoint()),
                           ellipse.pixelColor(centre.toPoint())) <= 2);
    int differ = 0, inEllipse = 0, inSprite = 0;
    for (int y = -15; y <= 15; ++y)
        for (int x = -15; x <= 15; ++x) {
            const QPoint q = centre.toPoint() + QPoint(x, y);
            differ += colourDistance(ellipse.pixelColor(q), sprite.pixelColor(q)) > 64;
            inEllipse += looksLike(ellipse, q, RenderOptions{}.colors.particle, 20);
            inSprite += looksLike(sprite, q, RenderOptions{}.colors.particle, 20);
        }
    // Only the rim may differ (the sprite sits at a whole pixel): far less than its 63 px.
    QVERIFY2(differ < 40, qPrintable(QString::number(differ)));
    QVERIFY2(std::abs(inEllipse - inSprite) <= 0.1 * inEllipse,
             qPrintable(QString("%1 vs %2").arg(inEllipse).arg(inSprite)));
    QVERIFY(inEllipse > 200);  // ~π·9² px of fill
}

void TestSceneRenderer::pickFindsEachKind() {
    const auto world = pickingWorld();
    const ViewTransform view({0.0, 0.0}, 100.0, {600, 400});
    const auto at = [&](double x, double y) {
        return SceneRenderer::pick(*world, view, view.toScreen(QPointF(x, y)));
    };
    PickResult r = at(0.0, 0.0);
    QCOMPARE(r.kind, PickResult::Particle);
    QCOMPARE(r.id, std::string("ball"));
    QCOMPARE(at(0.14, 0.0).kind, PickResult::Particle);  // radius 10 px + tolerance 6 px
    QCOMPARE(at(0.18, 0.0).kind, PickResult::None);
    r = at(2.3, 0.3);
    QCOMPARE(r.kind, PickResult::Box);
    QCOMPARE(r.id, std::string("crate"));
    QCOMPARE(r.index, 0);
    QCOMPARE(at(2.55, -0.55).kind, PickResult::None);  // the box's corner, turned away by 0.3 rad
    r = at(-1.0, 0.5);
    QCOMPARE(r.kind, PickResult::Spring);
    QCOMPARE(r.id, std::string("sp"));
    QCOMPARE(at(-1.0, 0.6).kind, PickResult::None);
    r = at(0.5, -1.5);
    QCOMPARE(r.kind, PickResult::Plane);
    QCOMPARE(r.id, std::string("ground"));
    QCOMPARE(at(0.5, 2.0).kind, PickResult::None);
    QVERIFY(!at(0.5, 2.0));
}

void TestSceneRenderer::trailsKeepRecentSamples() {
    World world;
    Particle p;
    p.position = {0.0, 0.37};  // off the grid's axis, so the trail is not read as a grid line
    p.velocity = {1.0, 0.0};
    world.addParticle(p);
    Particle pinned;
    pinned.pinned = true;
    world.addParticle(pinned);
    world.commit();
    TrailHistory trails(240, 16);
    for (int k = 0; k < 300; ++k) {
        trails.record(world);
        trails.record(world);  // a repaint without a step adds nothing
        world.step();
    }
    trails.record(world);
    QCOMPARE(static_cast<int>(trails.tracks().size()), 1);  // the pinned one does not move
    QCOMPARE(trails.sampleCount(), 240);
    QCOMPARE(trails.sample(0, 239).x(), world.particlePosition(0).x());
    const double dt = world.settings().dt;
    QVERIFY(std::abs(trails.sample(0, 238).x() - (world.particlePosition(0).x() - dt)) < 1e-9);
    QVERIFY(std::abs(trails.sample(0, 0).x() - (world.particlePosition(0).x() - 239 * dt)) < 1e-9);
    trails.clear();
    QCOMPARE(trails.sampleCount(), 0);
    // Drawn: the trail leaves particle-coloured pixels behind the particle.
    for (int k = 0; k < 30; ++k) {
        trails.record(world);
        world.step();
    }
    RenderOptions options;
    options.trails = true;
    const ViewTransform view(QPointF(world.particlePosition(0).x() - 0.25, 0.37), 400.0, kSize);
    QImage image(kSize, QImage::Format_ARGB32_Premultiplied);
    QPainter painter(&image);
    SceneRenderer::paint(painter, view, kSize, world, options, &trails);
    painter.end();
    QVERIFY(
        !isEmptyCanvas(image, view.toScreen(QPointF(world.particlePosition(0).x() - 0.3, 0.37))));
}

void TestSceneRenderer::offscreenUsesRasterEvenWhenOpenGLRequested() {
    QCOMPARE(QGuiApplication::platformName(), QStringLiteral("offscreen"));
    QVERIFY(!SceneView::hardwareGlAvailable());
    QCOMPARE(SceneView::resolveBackend(CanvasBackend::OpenGL), CanvasBackend::Raster);
    SceneView view;
    view.setBackend(CanvasBackend::OpenGL);
    QCOMPARE(view.backend(), CanvasBackend::OpenGL);
    QVERIFY(!view.usingOpenGL());
    qputenv("PHASEBOX_CANVAS", "opengl");
    view.setBackend(CanvasBackend::Auto);
    SceneView forced;
    qunsetenv("PHASEBOX_CANVAS");
    QVERIFY(!view.usingOpenGL() && !forced.usingOpenGL());
    QVERIFY(view.findChildren<QOpenGLWidget*>().isEmpty());
    QVERIFY(forced.findChildren<QOpenGLWidget*>().isEmpty());
}

void TestSceneRenderer::mousePressReportsWorldCoordinates() {
    SceneView view;
    view.resize(kSize);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    view.setView(ViewTransform({1.0, 2.0}, 80.0, kSize));
    QSignalSpy pressed(&view, &SceneView::worldMousePressed);
    QSignalSpy released(&view, &SceneView::worldMouseReleased);
    const QPoint pixel(100, 80);
    QTest::mousePress(&view, Qt::LeftButton, Qt::ShiftModifier, pixel);
    QTest::mouseRelease(&view, Qt::LeftButton, Qt::ShiftModifier, pixel);
    QCOMPARE(pressed.count(), 1);
    QCOMPARE(released.count(), 1);
    const QPointF expected = view.view().toWorld(pixel);
    QCOMPARE(expected, QPointF(1.0 + (100 - 200) / 80.0, 2.0 - (80 - 150) / 80.0));
    const QPointF got = pressed.at(0).at(0).toPointF();
    QVERIFY2(QLineF(got, expected).length() < 1e-9,
             qPrintable(QString("%1, %2").arg(got.x()).arg(got.y())));
    QCOMPARE(pressed.at(0).at(1).value<Qt::MouseButton>(), Qt::LeftButton);
    QCOMPARE(pressed.at(0).at(2).value<Qt::KeyboardModifiers>(),
             Qt::KeyboardModifiers(Qt::ShiftModifier));
}

void TestSceneRenderer::rightDragPansWithoutReporting() {
    SceneView view;
    view.resize(kSize);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    view.setView(ViewTransform({0.0, 0.0}, 100.0, kSize));
    QSignalSpy pressed(&view, &SceneView::worldMousePressed);
    QSignalSpy changed(&view, &SceneView::viewChanged);
    QSignalSpy menu(&view, &SceneView::worldContextMenuRequested);
    QTest::mousePress(&view, Qt::RightButton, {}, QPoint(200, 150));
    QTest::mouseMove(&view, QPoint(250, 120));
    QTest::mouseRelease(&view, Qt::RightButton, {}, QPoint(250, 120));
    QCOMPARE(pressed.count(), 0);
    QCOMPARE(menu.count(), 0);  // it moved: a pan, not a click
    QVERIFY(changed.count() >= 1);
    // The world point that was under the cursor followed it.
    const QPointF c = view.view().centre();
    QVERIFY(std::abs(c.x() - -0.5) < 1e-9 && std::abs(c.y() - -0.3) < 1e-9);
    QTest::mouseClick(&view, Qt::RightButton, {}, QPoint(20, 20));
    QCOMPARE(menu.count(), 1);
}

void TestSceneRenderer::wheelZoomKeepsPointUnderCursor() {
    SceneView view;
    view.resize(kSize);
    view.setView(ViewTransform({0.5, -0.5}, 60.0, kSize));
    const QPointF cursor(310.0, 70.0);
    const QPointF before = view.toWorld(cursor);
    QWheelEvent wheel(cursor, view.mapToGlobal(cursor), QPoint(), QPoint(0, 120), Qt::NoButton,
                      Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(&view, &wheel);
    QVERIFY(std::abs(view.view().pixelsPerMetre() - 72.0) < 1e-9);
    QVERIFY(QLineF(view.toWorld(cursor), before).length() < 1e-9);
    QWheelEvent back(cursor, view.mapToGlobal(cursor), QPoint(), QPoint(0, -240), Qt::NoButton,
                     Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(&view, &back);
    QVERIFY(view.view().pixelsPerMetre() < 60.0);
    QVERIFY(QLineF(view.toWorld(cursor), before).length() < 1e-9);
}

void TestSceneRenderer::emptyViewShowsAxesAtOrigin() {
    SceneView view;
    view.resize(kSize);
    QCOMPARE(view.view().pixelsPerMetre(), kSize.width() / 10.0);  // 10 m across
    const QImage image = view.renderImage(kSize);
    QCOMPARE(image.size(), kSize);
    QVERIFY(looksLike(image, view.toWidget(QPointF(0, 0)), RenderOptions{}.colors.axis, 0));
    view.fitToWorld();  // nothing to frame: the same default
    QCOMPARE(view.view().pixelsPerMetre(), kSize.width() / 10.0);
    SceneView other;
    other.resize(640, 480);  // the size a default ViewTransform assumes: framed all the same
    QCOMPARE(other.view().pixelsPerMetre(), 64.0);
}

void TestSceneRenderer::renderImageMatchesRenderer() {
    const auto world = pickingWorld();
    SceneView view;
    view.resize(kSize);
    view.setWorld(world.get());
    view.fitToWorld();
    const QRectF framed(view.toWidget(QPointF(-2.0, 1.0)), view.toWidget(QPointF(2.7, -1.0)));
    QVERIFY2(QRectF(QPointF(0, 0), QSizeF(kSize)).contains(framed.normalized()),
             qPrintable(QString("%1 %2 %3 %4 size %5x%6 ppm %7")
                            .arg(framed.left())
                            .arg(framed.top())
                            .arg(framed.right())
                            .arg(framed.bottom())
                            .arg(view.width())
                            .arg(view.height())
                            .arg(view.view().pixelsPerMetre())));
    QCOMPARE(view.renderImage(kSize), render(*world, view.view()));
    QCOMPARE(view.pick(view.toWidget(QPointF(0, 0))).id, std::string("ball"));
    // Twice the size: the same framing in more pixels.
    const QImage big = view.renderImage(kSize * 2);
    QVERIFY(looksLike(big, 2.0 * view.toWidget(QPointF(0, 0)), RenderOptions{}.colors.particle));
}

void TestSceneRenderer::overlayIsDrawn() {
    SceneView view;
    view.resize(kSize);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    const QImage before = view.grab().toImage();
    view.setOverlay({ToolOverlay::Rect, QPointF(-1.0, -1.0), QPointF(1.0, 1.0), "2 m", {}});
    view.setHudText("t = 3.20 s");
    const QImage after = view.grab().toImage().convertToFormat(before.format());
    int changed = 0;
    const QPointF corner = view.toWidget(QPointF(-1.0, 1.0));
    for (int x = 0; x < 60; ++x)
        changed += before.pixel(corner.toPoint() + QPoint(x, 0)) !=
                   after.pixel(corner.toPoint() + QPoint(x, 0));
    QVERIFY2(changed > 20, qPrintable(QString::number(changed)));  // dashed: not every pixel
    QVERIFY(before.pixel(14, 14) != after.pixel(14, 14));          // the HUD's backdrop
}

namespace {
struct PaintCounter : QObject {
    int paints = 0;
    bool eventFilter(QObject*, QEvent* event) override {
        paints += event->type() == QEvent::Paint;
        return false;
    }
};
}  // namespace

// The app repaints the canvas after a step with a plain update() on the SceneView: that must
// reach the surface that draws.
void TestSceneRenderer::updateRepaintsTheSurface() {
    SceneView view;
    view.resize(kSize);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    const QList<QWidget*> surfaces = view.findChildren<QWidget*>();
    QCOMPARE(surfaces.size(), 1);
    PaintCounter counter;
    surfaces.front()->installEventFilter(&counter);
    view.update();
    QTRY_VERIFY(counter.paints >= 1);
}

// Springs of both signs, arrows, labels, a selection and a hover, all in one picture.
void TestSceneRenderer::decorationsAreDrawn() {
    World world;
    const auto particle = [&](const char* id, Vec2 at, Vec2 velocity, bool pinned = false) {
        Particle p;
        p.id = id;
        p.position = at;
        p.velocity = velocity;
        p.radius = 0.12;
        p.pinned = pinned;
        return world.addParticle(p);
    };
    const int bob = particle("bob", {0.0, 0.5}, {0.0, 0.0});
    const int q = particle("q", {3.0, 1.2}, {0.0, 0.0});
    particle("fast", {-1.0, -0.3}, {2.0, 1.0});
    particle("pin", {-1.0, 1.5}, {0.0, 0.0}, true);
    RigidBody crate;
    crate.id = "crate";
    crate.position = {1.5, 0.0};
    crate.velocity = {1.0, 0.5};
    const int box = world.addRigidBody(crate);
    RigidBody wall;
    wall.id = "wall";
    wall.position = {-2.5, 0.0};
    wall.size = {0.3, 2.0};
    wall.isStatic = true;
    world.addRigidBody(wall);
    Plane ground;
    ground.id = "ground";
    ground.point = {0.0, -1.0};
    world.addPlane(ground);
    Spring hang;  // stretched by half its rest length
    hang.id = "hang";
    hang.a = {SpringEnd::Kind::Anchor, -1, Vec2(0.0, 2.0)};
    hang.b = {SpringEnd::Kind::Particle, bob, Vec2::Zero()};
    hang.stiffness = 20.0;
    hang.restLength = 1.0;
    world.addSpring(hang);
    Spring push = hang;  // compressed
    push.id = "push";
    push.a = {SpringEnd::Kind::Rigid, box, Vec2(0.5, 0.5)};
    push.b = {SpringEnd::Kind::Particle, q, Vec2::Zero()};
    push.restLength = 2.0;
    world.addSpring(push);
    world.commit();

    RenderOptions options;
    options.labels = options.velocityArrows = options.forceArrows = true;
    options.selectedIds = {"crate"};
    options.hoveredId = "bob";
    const ViewTransform view({0.3, 0.4}, 110.0, {640, 480});
    const QImage image = render(world, view, {640, 480}, options);
    const SceneColors& c = options.colors;
    QVERIFY(countNear(image, c.velocity, 30) > 30);
    QVERIFY(countNear(image, c.force, 30) > 30);
    QVERIFY(countNear(image, c.selection, 30) > 30);
    QVERIFY(countNear(image, c.hover, 30) > 10);
    QVERIFY(countNear(image, c.springStretched, 40) > 30);
    QVERIFY(countNear(image, c.springCompressed, 40) > 30);
    QVERIFY(countNear(image, c.staticBox, 4) > 200);
    QVERIFY(countNear(image, c.pinnedParticle, 4) > 30);
    // No labels, no arrows, no highlights: those colours are gone.
    const QImage plain = render(world, view, {640, 480});
    QCOMPARE(countNear(plain, c.velocity, 30), 0);
    QCOMPARE(countNear(plain, c.selection, 30), 0);
    QVERIFY(countNear(image, c.text, 40) > countNear(plain, c.text, 40) + 50);  // the ids

    const QString dir = qEnvironmentVariable("PHASEBOX_CANVAS_PNG_DIR");
    if (!dir.isEmpty()) {
        QVERIFY(image.save(QDir(dir).filePath("canvas_decorations.png")));
        options.lineWidthScale = 2.0;
        options.fontScale = 1.6;
        QVERIFY(render(world, view, {640, 480}, options)
                    .save(QDir(dir).filePath("canvas_presentation.png")));
    }
}

void TestSceneRenderer::libraryScenesRender() {
    const QString dir = qEnvironmentVariable("PHASEBOX_CANVAS_PNG_DIR");
    const RenderOptions o;
    for (const scenes::NamedScene& named : scenes::library()) {
        const auto world = buildWorld(named.make()).world;
        SceneView view;
        view.resize(640, 480);
        view.setWorld(world.get());
        view.fitToWorld();
        const QImage image = view.renderImage({640, 480});
        int drawn = 0;
        for (int y = 0; y < image.height(); y += 2)
            for (int x = 0; x < image.width(); x += 2)
                drawn += !isEmptyCanvas(image, QPointF(x, y));
        QVERIFY2(drawn > 500, qPrintable(QString::fromStdString(named.name)));
        if (!dir.isEmpty())
            QVERIFY(image.save(QDir(dir).filePath(
                QString("canvas_%1.png").arg(QString::fromStdString(named.name)))));
    }
}

// The compare ghost dims its sleepers as the live canvas does: a box at rest on the floor, drawn
// as the ghost in the step before it falls asleep and in the step it does, is fainter asleep.
void TestSceneRenderer::ghostDimsItsSleepers() {
    SceneDesc scene = scenes::tower(1);
    scene.simulation.sleep = true;
    const auto world = buildWorld(scene).world;
    const ViewTransform view(QPointF(0.0, 0.5), 100.0, QSizeF(kSize));
    const Vec2 start = world->bodyPosition(0);
    const QPointF centre = view.toScreen(start.x(), start.y());
    const auto ghostAlpha = [&] {
        QImage image(kSize, QImage::Format_ARGB32_Premultiplied);
        image.fill(Qt::transparent);
        QPainter painter(&image);
        drawGhost(painter, view, kSize, *world, RenderOptions{});
        painter.end();
        return image.pixelColor(centre.toPoint()).alpha();
    };
    int awake = ghostAlpha();
    for (int i = 0; i < 2000 && world->sleepingBodies() == 0; ++i) {
        awake = ghostAlpha();
        QVERIFY(world->step());
    }
    QCOMPARE(world->sleepingBodies(), 1);
    QVERIFY2((world->bodyPosition(0) - start).norm() < 0.01, "the box moved");
    const int asleep = ghostAlpha();
    QVERIFY2(awake > 0 && asleep > 0 && 2 * asleep <= awake + 2,
             qPrintable(QStringLiteral("alpha awake %1, asleep %2").arg(awake).arg(asleep)));
}

QTEST_MAIN(TestSceneRenderer)
#include "tst_scene_renderer.moc"
