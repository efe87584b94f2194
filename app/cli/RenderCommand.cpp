// phasebox-cli render: a run drawn offscreen as an MP4 (H.264) or animated GIF clip
// (CONTRACT.md §8), frame by frame with the canvas's own drawing code (app/clips).

#include "app/cli/Cli.h"
#include "app/cli/CommandLine.h"
#include "app/cli/Interrupt.h"
#include "app/clips/ClipRenderer.h"
#include "app/io/NumberFormat.h"
#include "app/io/OutputFile.h"
#include "app/io/SceneIO.h"
#include "physics/scene/BuildWorld.h"

#include <QRegularExpression>

#include <cmath>
#include <optional>

namespace phasebox::cli {

namespace {

const char* kRenderUsage =
    "usage: phasebox-cli render SCENE --out FILE.mp4|FILE.gif [--from S] [--duration S]\n"
    "                                 [--fps N] [--size WxH] [--plots] [--threads N]\n"
    "\n"
    "Draws the run offscreen, as the app's canvas draws it, and writes a clip:\n"
    "  --out FILE      .mp4 (H.264 video) or .gif (animated GIF, looping)\n"
    "  --from S        simulated seconds before the first frame; default 0\n"
    "  --duration S    simulated seconds the clip shows; default the scene's duration\n"
    "  --fps N         frames per second (1 to 120; a GIF at most 50); default 30\n"
    "  --size WxH      pixels of each frame (even for MP4); default 1280x720\n"
    "  --plots         the energy and phase plots beside the canvas\n"
    "  --threads N     workers, 1 to 1024 (the same frames for every N)\n"
    "\n"
    "The clip has round(duration*fps) frames at t = from + k/fps, each showing the last step\n"
    "at or before t; a GIF's delays (hundredths of a second) add up to the duration. A write\n"
    "that fails (exit 3) or Ctrl-C (exit 130) leaves no partial file.\n";

struct RenderOptions {
    QString scene, out;
    std::optional<double> from, duration;
    int fps = 30;
    QSize size{1280, 720};
    bool plots = false;
    int threads = 0;  // 0: every core
};

QString parseRenderOptions(const QStringList& args, RenderOptions& o) {
    CommandLine line;
    if (const QString error = parseCommandLine(
            QStringLiteral("render"),
            {{"plots", 0}, {"out"}, {"from"}, {"duration"}, {"fps"}, {"size"}, {"threads"}}, args,
            line);
        !error.isEmpty())
        return error;
    QStringList outputsSeen;
    for (const GivenOption& option : line.options) {
        if (option.is("--plots")) {
            o.plots = true;
            continue;
        }
        const QString& a = option.name;
        const QString& v = option.value();
        bool ok = false;
        if (option.is("--threads")) {
            if (QString error = threadsProblem(v); !error.isEmpty()) return error;
            o.threads = v.toInt();
        } else if (option.is("--out")) {
            if (QString error = noteOutputOption(a, v, outputsSeen); !error.isEmpty()) return error;
            o.out = v;
        } else if (option.is("--fps")) {
            o.fps = v.toInt(&ok);
            if (!ok) return QStringLiteral("--fps: must be an integer (got \"%1\")").arg(v);
        } else if (option.is("--size")) {
            static const QRegularExpression pattern(QStringLiteral("^(\\d{1,5})[xX](\\d{1,5})$"));
            const QRegularExpressionMatch m = pattern.match(v);
            if (!m.hasMatch())
                return QStringLiteral("--size: must be WxH in pixels, e.g. 1280x720 (got \"%1\")")
                    .arg(v);
            o.size = QSize(m.captured(1).toInt(), m.captured(2).toInt());
        } else {
            const double d = v.toDouble(&ok);
            if (!ok || !std::isfinite(d))
                return QStringLiteral("%1: must be a number (got \"%2\")").arg(a, v);
            (option.is("--from") ? o.from : o.duration) = d;
        }
    }
    if (QString error = takeScene(QStringLiteral("render"), line, o.scene); !error.isEmpty())
        return error;
    if (o.out.isEmpty()) return QStringLiteral("render needs --out FILE.mp4 or --out FILE.gif");
    return {};
}

}  // namespace

int renderCommand(const QStringList& args, QTextStream& out, QTextStream& err) {
    if (asksForHelp(args)) {
        out << kRenderUsage;
        return kSuccess;
    }
    RenderOptions o;
    if (const QString error = parseRenderOptions(args, o); !error.isEmpty())
        return fail(err, error);
    const std::optional<ClipFormat> format = clipFormatOf(o.out);
    if (!format)
        return fail(err, QStringLiteral("--out %1: unknown clip format; known: %2")
                             .arg(o.out, clipFormatList()));
    if (const QString error = checkOutputs(o.scene, {{"--out", o.out}}); !error.isEmpty())
        return fail(err, error);

    SceneLoadResult loaded = SceneIO::load(o.scene);
    if (!loaded.ok()) return fail(err, loaded.errorText());
    const SceneDesc& scene = *loaded.scene;
    try {
        buildWorld(scene);
    } catch (const SceneError& e) {
        QStringList lines;
        for (const SceneIssue& issue : e.issues())
            lines << QStringLiteral("%1: %2: %3")
                         .arg(o.scene, QString::fromStdString(issue.path),
                              QString::fromStdString(issue.message));
        return fail(err, lines.join(QLatin1Char('\n')));
    }
    ClipOptions clip;
    clip.from = o.from.value_or(0.0);
    clip.duration = o.duration.value_or(scene.simulation.duration);
    clip.fps = o.fps;
    clip.size = o.size;
    clip.plots = o.plots;
    clip.workers = o.threads;
    if (const QString problem = clipOptionsProblem(*format, clip); !problem.isEmpty())
        return fail(err, problem);
    if (const QString problem = runLengthProblem(clip.from + clip.duration, scene.simulation.dt);
        !problem.isEmpty())
        return fail(err, problem);
    if (interrupted()) {
        err << "phasebox-cli: interrupted before the clip began; nothing was written\n";
        return kInterrupted;
    }

    const ClipResult result =
        renderClip(scene, clip, o.out, [](int, int) { return !interrupted(); });
    const int frames = clipFrameCount(clip.duration, clip.fps);
    switch (result.status) {
        case ClipResult::Cancelled:
        case ClipResult::Interrupted:
            err << "phasebox-cli: interrupted after " << result.frames << " of " << frames
                << " frames; the partial clip was removed\n";
            err.flush();
            return kInterrupted;
        case ClipResult::WriteFailed:
            return failWrite(err, result.message);
        case ClipResult::Written:
        case ClipResult::Diverged:
            break;
    }
    if (!OutputFile::isStandardOutput(o.out))
        out << "wrote " << o.out << ": " << frames << " frames, " << clip.size.width() << "x"
            << clip.size.height() << " at " << clip.fps << " fps, t = " << formatNumber(clip.from)
            << " to " << formatNumber(clip.from + clip.duration) << " s\n";
    if (result.status == ClipResult::Diverged) {
        err << "phasebox-cli: diverged: " << result.message
            << " The frames after it show the restored state.\n";
        err.flush();
        return kDiverged;
    }
    return kSuccess;
}

}  // namespace phasebox::cli
