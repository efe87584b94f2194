// bench_renderer: what drawing a frame costs on the raster path (the canvas's default, and the
// only one under the offscreen platform and software GL). A 1280 × 800 ARGB32 premultiplied
// QImage, as the raster backing store is: 10,000 gas disks (sprite blits; for comparison also
// as antialiased ellipses) and a 64 × 64 cloth (4,096 nodes, its mesh in one drawLines call),
// rendered alone and with a world step per frame. Medians. Target: 16.7 ms (60 frames per
// second) for 10,000 particles, render alone.
//
//   bench_renderer [--repeat FRAMES] [--quick] [--json]

#include "BenchCommon.h"

#include "physics/scene/BuildWorld.h"
#include "physics/scene/SceneLibrary.h"
#include "ui/canvas/SceneRenderer.h"

#include <QGuiApplication>
#include <QImage>
#include <QPainter>

#include <algorithm>
#include <climits>
#include <cstdio>
#include <ctime>
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
    double renderMs = 0.0;         // median per frame, wall clock
    double renderCpuMs = 0.0;      // median per frame, this thread's CPU time
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

// This thread's CPU time: on two cores shared with compilers, the wall clock of a frame says
// more about the neighbours than about the renderer.
double threadCpuMs() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return 1e3 * static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_nsec);
}

struct FrameTime {
    double wallMs, cpuMs;
};

FrameTime renderOnce(QImage& image, const ViewTransform& view, const World& world,
                     const RenderOptions& options) {
    const auto start = Clock::now();
    const double cpu = threadCpuMs();
    {
        QPainter painter(&image);  // a widget's paint event opens one per frame too
        SceneRenderer::paint(painter, view, kViewport, world, options);
    }
    clobber(image.constBits());
    return {1000.0 * secondsBetween(start, Clock::now()), threadCpuMs() - cpu};
}

Case measure(const std::string& name, const SceneDesc& scene, int frames, int stepFrames,
             const RenderOptions& options = {}) {
    auto world = buildWorld(scene).world;
    world->commit();
    QImage image(kViewport, QImage::Format_ARGB32_Premultiplied);
    const ViewTransform view = framing(*world);
    for (int k = 0; k < 3; ++k) renderOnce(image, view, *world, options);  // sprites, fonts, caches
    std::vector<double> render, renderCpu, both;
    for (int k = 0; k < frames; ++k) {
        const FrameTime t = renderOnce(image, view, *world, options);
        render.push_back(t.wallMs);
        renderCpu.push_back(t.cpuMs);
    }
    for (int k = 0; k < stepFrames; ++k) {
        const auto start = Clock::now();
        world->step();
        renderOnce(image, view, *world, options);
        both.push_back(1000.0 * secondsBetween(start, Clock::now()));
    }
    Case c;
    c.name = name;
    c.objects = static_cast<int>(world->particles().size());
    c.renderMs = median(render);
    c.renderCpuMs = median(renderCpu);
    c.stepAndRenderMs = stepFrames > 0 ? median(both) : 0.0;
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
    // The library's 10,000-disk gas starts with its disks overlapping (0.036 m apart, 0.1 m
    // wide), which makes a step take seconds: it is drawn here, not stepped. For the frame with
    // a step the same gas has disks 0.4 spacing wide, so they start apart.
    SceneDesc sparseGas = scenes::elasticGas(10000);
    for (ParticleDesc& p : sparseGas.particles) p.radius = 0.4 * (4.0 - 0.4) / 100.0;
    // Steps of these scenes take from tens of milliseconds (cloth) to most of a second (the
    // 10,000-disk gas): a few frames give the figure.
    const int stepFrames = std::max(3, frames / 20);
    std::vector<Case> cases;
    cases.push_back(measure("gas_10k", scenes::elasticGas(10000), frames, 0));
    cases.push_back(measure("gas_10k_ellipses", scenes::elasticGas(10000), frames, 0, ellipses));
    cases.push_back(measure("gas_10k_small_disks", sparseGas, frames, stepFrames));
    cases.push_back(measure("cloth_64x64", scenes::cloth(64, 2e4), frames, stepFrames));

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
            json.value("render_cpu_ms", c.renderCpuMs);
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
    std::printf("%-22s %9s %7s %10s %8s %6s %14s %6s\n", "case", "particles", "px/m", "render ms",
                "cpu ms", "fps", "step+render ms", "fps");
    for (const Case& c : cases) {
        std::printf("%-22s %9d %7.1f %10.2f %8.2f %6.0f", c.name.c_str(), c.objects,
                    c.pixelsPerMetre, c.renderMs, c.renderCpuMs, 1000.0 / c.renderMs);
        if (c.stepAndRenderMs > 0.0)
            std::printf(" %14.2f %6.1f\n", c.stepAndRenderMs, 1000.0 / c.stepAndRenderMs);
        else
            std::printf(" %14s %6s\n", "-", "-");
    }
    return 0;
}
