// bench_recording: what the run's recording (RunRecording) costs and how fast it shows a moment.
//
//   - overhead: the 20-row pyramid stepped with and without recording a frame after every step
//     (and a keyframe every 120 steps), in alternating repeats; the figure is the extra time as a
//     share of the step (the bound: at most 10 %);
//   - scrub: a 60 s recording of the 40-row pyramid, then jumps to random frames, each shown in
//     the world and drawn at 1280x720 as the canvas draws it (the bound: 50 ms);
//   - memory: the recording's own count and the process's resident memory after the run, with
//     the default budget (--minutes N records N minutes of the 40-row pyramid instead of
//     one, the case being 10).
//
//   bench_recording [--steps N] [--repeat N] [--minutes N] [--json]

#include "BenchCommon.h"

#include "app/sim/RunRecording.h"
#include "physics/scene/BuildWorld.h"
#include "physics/scene/SceneLibrary.h"
#include "physics/world/World.h"
#include "ui/canvas/SceneRenderer.h"

#include <QGuiApplication>
#include <QImage>
#include <QPainter>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <random>
#include <string>
#include <vector>

namespace {

using namespace phasebox;
using namespace phasebox::bench;
using phasebox::ui::SceneRenderer;
using phasebox::ui::ViewTransform;

const QSize kViewport(1280, 720);

double residentMegabytes() {
    std::ifstream status("/proc/self/status");
    std::string key;
    while (status >> key) {
        if (key == "VmRSS:") {
            double kb = 0.0;
            status >> kb;
            return kb / 1024.0;
        }
        status.ignore(4096, '\n');
    }
    return std::nan("");
}

struct Overhead {
    double stepMs = 0.0, recordedStepMs = 0.0;
};

Overhead measureOverhead(int steps, int repeat) {
    auto plain = buildWorld(scenes::pyramid(20)).world;
    auto recorded = buildWorld(scenes::pyramid(20)).world;
    RunRecording recording;
    for (int i = 0; i < 300; ++i) {  // settled, warm starts primed
        plain->step();
        recorded->step();
    }
    recording.record(*recorded);
    std::vector<double> a, b;
    for (int r = 0; r < repeat; ++r) {
        auto start = Clock::now();
        for (int i = 0; i < steps; ++i) plain->step();
        a.push_back(1000.0 * secondsBetween(start, Clock::now()) / steps);
        start = Clock::now();
        for (int i = 0; i < steps; ++i) {
            recorded->step();
            recording.record(*recorded);
        }
        b.push_back(1000.0 * secondsBetween(start, Clock::now()) / steps);
    }
    return {median(a), median(b)};
}

struct Scrub {
    double medianMs = 0.0, maxMs = 0.0, recordSeconds = 0.0;
    int frames = 0, keyframes = 0;
    double megabytes = 0.0, residentMegabytes = 0.0;
};

Scrub measureScrub(double seconds, int jumps) {
    auto world = buildWorld(scenes::pyramid(40)).world;
    RunRecording recording;
    recording.record(*world);
    const double rssBefore = residentMegabytes();
    const int steps = static_cast<int>(std::lround(seconds / world->settings().dt));
    const auto start = Clock::now();
    for (int i = 0; i < steps; ++i) {
        world->step();
        recording.record(*world);
    }
    Scrub s;
    s.recordSeconds = secondsBetween(start, Clock::now());
    s.frames = recording.frameCount();
    s.keyframes = recording.keyframeCount();
    s.megabytes = static_cast<double>(recording.bytesUsed()) / (1 << 20);
    s.residentMegabytes = residentMegabytes() - rssBefore;

    QImage image(kViewport, QImage::Format_ARGB32_Premultiplied);
    ViewTransform view;
    view.fit(QRectF(-25.0, -1.0, 50.0, 45.0), QSizeF(kViewport), 24.0);
    std::mt19937 random(7);
    std::vector<double> times;
    for (int k = 0; k < jumps; ++k) {
        const int frame = static_cast<int>(random() % static_cast<unsigned>(s.frames));
        const auto t0 = Clock::now();
        recording.show(*world, frame);
        {
            QPainter painter(&image);
            SceneRenderer::paint(painter, view, kViewport, *world, {});
        }
        clobber(image.constBits());
        times.push_back(1000.0 * secondsBetween(t0, Clock::now()));
    }
    s.medianMs = median(times);
    s.maxMs = *std::max_element(times.begin(), times.end());
    return s;
}

}  // namespace

int main(int argc, char** argv) {
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
    // --minutes is ours; the rest is the shared command line.
    double minutes = 1.0;
    std::vector<char*> args;
    for (int i = 0; i < argc; ++i) {
        if (std::string(argv[i]) == "--minutes" && i + 1 < argc)
            minutes = std::atof(argv[++i]);
        else
            args.push_back(argv[i]);
    }
    int count = static_cast<int>(args.size());
    QGuiApplication app(count, args.data());
    const Options options =
        parseOptions(count, args.data(), "[--steps N] [--repeat N] [--minutes N] [--json]");
    const int steps = options.steps > 0 ? options.steps : 120;
    const int repeat = options.repeat > 0 ? options.repeat : 7;

    const Overhead o = measureOverhead(steps, repeat);
    const double overhead = (o.recordedStepMs - o.stepMs) / o.stepMs;
    const Scrub s = measureScrub(60.0 * minutes, 200);
    if (options.json) {
        std::printf(
            "{\"step_ms\": %.4f, \"recorded_step_ms\": %.4f, \"overhead\": %.4f, "
            "\"minutes\": %.2f, \"frames\": %d, \"keyframes\": %d, \"recording_mb\": %.1f, "
            "\"resident_mb\": %.1f, \"scrub_median_ms\": %.3f, \"scrub_max_ms\": %.3f}\n",
            o.stepMs, o.recordedStepMs, overhead, minutes, s.frames, s.keyframes, s.megabytes,
            s.residentMegabytes, s.medianMs, s.maxMs);
        return 0;
    }
    std::printf("pyramid 20: step %.3f ms, with recording %.3f ms: overhead %.1f %%\n", o.stepMs,
                o.recordedStepMs, 100.0 * overhead);
    std::printf(
        "pyramid 40, %.1f min recorded in %.1f s: %d frames, %d keyframes, %.1f MB "
        "counted, %.1f MB resident\n",
        minutes, s.recordSeconds, s.frames, s.keyframes, s.megabytes, s.residentMegabytes);
    std::printf("scrub: a jump shown and drawn in %.2f ms (median), %.2f ms (max) over 200 jumps\n",
                s.medianMs, s.maxMs);
    return 0;
}
