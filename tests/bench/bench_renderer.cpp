// bench_renderer: what drawing a frame costs on the raster path (the canvas's default, and the
// only one under the offscreen platform and software GL). A 1280 × 800 ARGB32 premultiplied
// QImage, as the raster backing store is: 10,000 gas disks (sprite blits) and a 64 × 64 cloth
// (4,096 nodes, one drawLines call), each also with a world step per frame, and for
// comparison the disks drawn as antialiased ellipses. Median of the frames. Target: 16.7 ms
// (60 frames per second) for 10,000 particles, render alone.
//
//   bench_renderer [--repeat FRAMES] [--quick] [--json]

#include "BenchCommon.h"

#include "physics/scene/BuildWorld.h"
#include "physics/scene/SceneLibrary.h"
#include "ui/canvas/SceneRenderer.h"

#include <QGuiApplication>
#include <QImage>
#include <QPainter>

#include <climits>
#include <cstdio>
#include <string>
#include <vector>

using namespace phasebox;
using namespace phasebox::bench;
using namespace phasebox::ui;

namespace {

const QSize kViewport(1280, 800);

struct Case {
    std::string name;
    int objects = 0;
    double renderMs = 0.0;         // median per frame
    double stepAndRenderMs = 0.0;  // median per frame, 0 when not measured
    double pixelsPerMetre = 0.0;
};

ViewTransform framing(const World& world) {
    QRectF bounds;
    for (int i = 0; i < static_cast<int>(world.particles().size()); ++i) {
        const Vec2 p = world.particlePosition(i);
        bounds = bounds.isNull() ? QRectF(p.x(), p.y(), 1e-9, 1e-9)
                                 : bounds.united(QRectF(p.x(), p.y(), 1e-9, 1e-9));
    }
    ViewTransform view;
    view.fit(bounds.adjusted(-0.1, -0.1, 0.1, 0.1), QSizeF(kViewport), 24.0);
    return view;
}

double renderOnce(QImage& image, const ViewTransform& view, const World& world,
                  const RenderOptions& options) {
    const auto start = Clock::now();
    {
        QPainter painter(&image);  // a widget's paint event opens one per frame too
        SceneRenderer::paint(painter, view, kViewport, world, options);
    }
    clobber(image.constBits());
    return 1000.0 * secondsBetween(start, Clock::now());
}

Case measure(const std::string& name, const SceneDesc& scene, int frames, bool step,
             const RenderOptions& options = {}) {
    auto world = buildWorld(scene).world;
    world->commit();
    QImage image(kViewport, QImage::Format_ARGB32_Premultiplied);
    const ViewTransform view = framing(*world);
    for (int k = 0; k < 3; ++k) renderOnce(image, view, *world, options);  // sprites, fonts, caches
    std::vector<double> render, both;
    for (int k = 0; k < frames; ++k) render.push_back(renderOnce(image, view, *world, options));
    if (step)
        for (int k = 0; k < frames; ++k) {
            const auto start = Clock::now();
            world->step();
            renderOnce(image, view, *world, options);
            both.push_back(1000.0 * secondsBetween(start, Clock::now()));
        }
    Case c;
    c.name = name;
    c.objects = static_cast<int>(world->particles().size());
    c.renderMs = median(render);
    c.stepAndRenderMs = step ? median(both) : 0.0;
    c.pixelsPerMetre = view.pixelsPerMetre();
    return c;
}

}  // namespace

int main(int argc, char** argv) {
    // The raster path needs no display: offscreen unless the caller chose a platform.
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
    QGuiApplication app(argc, argv);
    const Options options =
        parseOptions(argc, argv, "[--repeat FRAMES] [--quick] [--json]", {"--quick"});
    const int frames = options.repeat > 0 ? options.repeat : options.quick ? 20 : 100;

    RenderOptions ellipses;
    ellipses.spriteThreshold = INT_MAX;  // every disc rasterised as an antialiased ellipse
    std::vector<Case> cases;
    cases.push_back(measure("gas_10k_particles", scenes::elasticGas(10000), frames, true));
    cases.push_back(
        measure("gas_10k_particles_ellipses", scenes::elasticGas(10000), frames, false, ellipses));
    cases.push_back(measure("cloth_64x64", scenes::cloth(64, 2e4), frames, true));

    if (options.json) {
        Json json;
        json.beginObject();
        json.value("width", kViewport.width());
        json.value("height", kViewport.height());
        json.value("frames", frames);
        json.beginArray("cases");
        for (const Case& c : cases) {
            json.beginObject();
            json.value("name", c.name);
            json.value("particles", c.objects);
            json.value("render_ms", c.renderMs);
            json.value("render_fps", 1000.0 / c.renderMs);
            if (c.stepAndRenderMs > 0.0) {
                json.value("step_and_render_ms", c.stepAndRenderMs);
                json.value("step_and_render_fps", 1000.0 / c.stepAndRenderMs);
            }
            json.endObject();
        }
        json.endArray();
        json.endObject();
        std::printf("%s\n", json.str().c_str());
        return 0;
    }
    std::printf("Raster canvas, %d x %d, median of %d frames\n", kViewport.width(),
                kViewport.height(), frames);
    std::printf("%-28s %9s %8s %11s %8s %13s %8s\n", "case", "particles", "px/m", "render ms",
                "fps", "step+render", "fps");
    for (const Case& c : cases) {
        std::printf("%-28s %9d %8.1f %11.2f %8.0f", c.name.c_str(), c.objects, c.pixelsPerMetre,
                    c.renderMs, 1000.0 / c.renderMs);
        if (c.stepAndRenderMs > 0.0)
            std::printf(" %10.2f ms %8.0f\n", c.stepAndRenderMs, 1000.0 / c.stepAndRenderMs);
        else
            std::printf(" %13s %8s\n", "-", "-");
    }
    return 0;
}
