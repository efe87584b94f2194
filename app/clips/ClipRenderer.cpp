#include "app/clips/ClipRenderer.h"

#include "app/io/OutputFile.h"
#include "app/sim/Recorder.h"
#include "physics/scene/BuildWorld.h"
#include "physics/scene/SceneDesc.h"
#include "physics/world/World.h"
#include "ui/canvas/SceneView.h"
#include "ui/plots/Charts.h"

#include <QChart>
#include <QCoreApplication>
#include <QImage>
#include <QPainter>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <vector>

namespace phasebox {

namespace {

QString tr(const char* text) {
    return QCoreApplication::translate("phasebox::ClipRenderer", text);
}

// The steps a frame at time t shows: the last step with t_step = n·dt ≤ t. The small allowance
// keeps a frame time that is a whole number of steps (t = 0.1 at dt = 1/60 and 30 fps) from
// falling one step short by rounding.
long long stepsAt(double t, double dt) {
    return static_cast<long long>(std::floor(t / dt + 1e-7));
}

double frameTime(const ClipOptions& o, int k) {
    return o.from + static_cast<double>(k) / o.fps;
}

// What a run of its own (the same scene gives the same run) shows of the clip's frames: where
// the dynamic objects go, which the canvas frames so that nothing leaves the picture, and which
// particle (not of a cloth) or body travels farthest along an axis, which the phase plot
// follows unless told otherwise.
struct MotionSurvey {
    QRectF extent;
    QString object, coordinate;
};

MotionSurvey surveyMotion(const SceneDesc& scene, const ClipOptions& o, int frames) {
    BuildResult built = buildWorld(scene);
    World& world = *built.world;
    world.setWorkers(o.workers);
    const double dt = world.settings().dt;
    double lo[2] = {HUGE_VAL, HUGE_VAL}, hi[2] = {-HUGE_VAL, -HUGE_VAL};
    const auto include = [&](const Vec2& p, double reach) {
        for (int k = 0; k < 2; ++k) {
            lo[k] = std::min(lo[k], p[k] - reach);
            hi[k] = std::max(hi[k], p[k] + reach);
        }
    };
    // Per particle, then per body: the range of x and of y over the frames.
    const std::size_t particles = world.particles().size();
    std::vector<std::array<double, 4>> ranges(particles + world.rigidBodies().size(),
                                              {HUGE_VAL, -HUGE_VAL, HUGE_VAL, -HUGE_VAL});
    const auto track = [&](std::size_t slot, const Vec2& p) {
        std::array<double, 4>& r = ranges[slot];
        r = {std::min(r[0], p.x()), std::max(r[1], p.x()), std::min(r[2], p.y()),
             std::max(r[3], p.y())};
    };
    for (int k = 0; k < frames; ++k) {
        const long long steps = stepsAt(frameTime(o, k), dt);
        bool ok = true;
        while (ok && world.stepCount() < steps) ok = world.step();
        for (std::size_t i = 0; i < particles; ++i) {
            const Particle& p = world.particles()[i];
            if (p.dof < 0) continue;
            const Vec2 at = world.particlePosition(static_cast<int>(i));
            include(at, p.radius);
            if (p.cloth < 0) track(i, at);
        }
        for (std::size_t i = 0; i < world.rigidBodies().size(); ++i) {
            if (world.rigidBodies()[i].dof < 0) continue;
            const Vec2 at = world.bodyPosition(static_cast<int>(i));
            include(at, 0.5 * world.rigidBodies()[i].size.norm());
            track(particles + i, at);
        }
        if (!ok) break;  // a runaway: the frames after it show the restored state
    }
    MotionSurvey survey;
    if (lo[0] <= hi[0]) survey.extent = QRectF(QPointF(lo[0], lo[1]), QPointF(hi[0], hi[1]));
    double farthest = 0.0;
    for (std::size_t slot = 0; slot < ranges.size(); ++slot) {
        const std::array<double, 4>& r = ranges[slot];
        const double dx = r[1] - r[0], dy = r[3] - r[2];
        if (!(std::max(dx, dy) > farthest)) continue;  // untracked ranges are −inf
        farthest = std::max(dx, dy);
        survey.object =
            QString::fromStdString(slot < particles ? world.particles()[slot].id
                                                    : world.rigidBodies()[slot - particles].id);
        survey.coordinate = dy > dx ? QStringLiteral("y") : QStringLiteral("x");
    }
    return survey;
}

// The phase plot's default where no survey chose one (nothing moves, or the app's view made a
// survey unnecessary): the first dynamic particle (not of a cloth) or body, along the axis it
// moves most, or at rest the one gravity pulls along (as the Plots dock chooses).
void choosePhaseTarget(const World& world, const SceneDesc& scene, QString& object,
                       QString& coordinate) {
    if (!object.isEmpty()) {
        if (coordinate.isEmpty()) coordinate = QStringLiteral("x");
        return;
    }
    Vec2 v = Vec2::Zero();
    for (int i = 0; i < static_cast<int>(world.particles().size()) && object.isEmpty(); ++i)
        if (world.particles()[i].dof >= 0 && world.particles()[i].cloth < 0) {
            object = QString::fromStdString(world.particles()[i].id);
            v = world.particleVelocity(i);
        }
    for (int i = 0; i < static_cast<int>(world.rigidBodies().size()) && object.isEmpty(); ++i)
        if (world.rigidBodies()[i].dof >= 0) {
            object = QString::fromStdString(world.rigidBodies()[i].id);
            v = world.bodyVelocity(i);
        }
    if (object.isEmpty() || !coordinate.isEmpty()) return;
    if (v.squaredNorm() == 0.0 && scene.effects.gravity)
        v = Vec2(scene.effects.gravity->g[0], scene.effects.gravity->g[1]);
    coordinate = std::abs(v.y()) > std::abs(v.x()) ? QStringLiteral("y") : QStringLiteral("x");
}

// Draws the frames: the canvas on the left (all of the picture without plots), the energy plot
// above the phase plot on the right.
class FramePainter {
public:
    FramePainter(const SceneDesc& scene, const ClipOptions& o, World& world)
        : options_(o), world_(world) {
        const int plotWidth = o.plots ? o.size.width() * 2 / 5 : 0;
        canvasSize_ = QSize(o.size.width() - plotWidth, o.size.height());
        view_.setBackend(ui::CanvasBackend::Raster);
        view_.setRenderOptions(o.renderOptions);
        view_.setWorld(&world_);
        if (o.plots) {
            choosePhaseTarget(world_, scene, phaseObject_, phaseCoordinate_);
            recorder_.setPhaseTarget(phaseObject_, phaseCoordinate_);
            recorder_.record(world_);
        }
        const SimulationSettings& s = world_.settings();
        method_ = tr("%1, dt %2 s").arg(QString::fromStdString(s.integrator)).arg(s.dt, 0, 'g', 4);
    }

    // Frames the view (the app's view, or the motion) once the world is at the first frame.
    void frame(const QRectF& extent) {
        if (options_.view) {
            view_.resize(options_.view->widgetSize().toSize());
            view_.setView(*options_.view);
        } else {
            view_.resize(canvasSize_);
            view_.fitToWorld(32.0, extent);
        }
    }

    // After each step: the plots' samples.
    void stepped() {
        if (options_.plots) recorder_.record(world_);
    }

    QImage draw() {
        if (options_.renderOptions.trails) view_.trails().record(world_);
        view_.setHudText(tr("t = %1 s   %2").arg(world_.time(), 0, 'f', 2).arg(method_));
        QImage frame(options_.size, QImage::Format_RGB32);
        frame.fill(Qt::white);
        QPainter painter(&frame);
        painter.drawImage(0, 0, view_.renderImage(canvasSize_, true));
        if (!options_.plots) return frame;
        const int x = canvasSize_.width(), w = options_.size.width() - x;
        const int half = options_.size.height() / 2;
        std::unique_ptr<QChart> energy(ui::createEnergyChart(
            recorder_.energySamples(), recorder_.markers(), tr("Energy (%1)").arg(method_)));
        ui::paintChart(energy.get(), painter, QRectF(x, 0, w, half));
        std::unique_ptr<QChart> phase;
        if (phaseObject_.isEmpty()) {
            phase.reset(ui::createPhaseChart({}, {}, {}, tr("Phase space")));
        } else {
            const QString coordinate = phaseObject_ + QLatin1Char('.') + phaseCoordinate_;
            phase.reset(ui::createPhaseChart(
                recorder_.phaseSamples(), coordinate,
                phaseObject_ + QLatin1Char('.') + recorder_.phaseVelocityName(),
                tr("Phase space of %1").arg(coordinate)));
        }
        ui::paintChart(phase.get(), painter, QRectF(x, half, w, options_.size.height() - half));
        return frame;
    }

private:
    const ClipOptions& options_;
    World& world_;
    ui::SceneView view_;
    QSize canvasSize_;
    Recorder recorder_;
    QString phaseObject_ = options_.phaseObject, phaseCoordinate_ = options_.phaseCoordinate;
    QString method_;
};

}  // namespace

int clipFrameCount(double duration, int fps) {
    const double n = std::round(duration * fps);
    return n > kMaxClipFrames ? kMaxClipFrames + 1 : static_cast<int>(n);
}

QString clipOptionsProblem(ClipFormat format, const ClipOptions& o) {
    if (!(o.from >= 0.0) || !std::isfinite(o.from))
        return QStringLiteral("the start time must be >= 0 s");
    if (!(o.duration > 0.0) || !std::isfinite(o.duration))
        return QStringLiteral("the duration must be > 0 s");
    if (o.fps < 1 || o.fps > kMaxClipFps)
        return QStringLiteral("the frame rate must be 1 to %1 frames per second").arg(kMaxClipFps);
    if (o.size.width() < 16 || o.size.height() < 16 || o.size.width() > kMaxClipSide ||
        o.size.height() > kMaxClipSide)
        return QStringLiteral("the size must be 16 to %1 pixels each way").arg(kMaxClipSide);
    const int frames = clipFrameCount(o.duration, o.fps);
    if (frames < 1)
        return QStringLiteral("%1 s at %2 frames per second is less than one frame")
            .arg(o.duration)
            .arg(o.fps);
    if (frames > kMaxClipFrames)
        return QStringLiteral("%1 s at %2 frames per second is more than %3 frames")
            .arg(o.duration)
            .arg(o.fps)
            .arg(kMaxClipFrames);
    return clipSpecProblem(format, ClipSpec{o.size, o.fps, frames, o.duration});
}

ClipResult renderClip(const SceneDesc& scene, const ClipOptions& o, const QString& path,
                      const std::function<bool(int, int)>& progress) {
    ClipResult result;
    const int frames = clipFrameCount(o.duration, o.fps);
    const ClipSpec spec{o.size, o.fps, frames, o.duration};
    OutputFile out(path, tr("the clip"));
    std::unique_ptr<ClipEncoder> encoder;
    // By value: the message may be the encoder's own, which is gone once it is reset.
    const auto fail = [&](QString message) {
        const bool interrupted = out.interrupted();
        encoder.reset();  // before the output it writes to is abandoned
        out.cancel();
        result.status = interrupted ? ClipResult::Interrupted : ClipResult::WriteFailed;
        result.message = std::move(message);
        return result;
    };
    // Opened first: an output that cannot be written is known before the run costs anything.
    if (!out.open()) return fail(out.error());
    QString error;
    encoder = openClipEncoder(clipFormatOf(path).value_or(ClipFormat::Gif), spec, out, &error);
    if (!encoder) return fail(error);

    ClipOptions options = o;
    MotionSurvey motion;
    if (!o.view || (o.plots && o.phaseObject.isEmpty())) motion = surveyMotion(scene, o, frames);
    if (options.phaseObject.isEmpty()) {
        options.phaseObject = motion.object;
        options.phaseCoordinate = motion.coordinate;
    }
    BuildResult built = buildWorld(scene);
    World& world = *built.world;
    world.setWorkers(o.workers);
    const double dt = world.settings().dt;
    FramePainter painter(scene, options, world);
    bool diverged = false;
    for (int k = 0; k < frames; ++k) {
        const long long steps = stepsAt(frameTime(o, k), dt);
        while (!diverged && world.stepCount() < steps) {
            diverged = !world.step();
            painter.stepped();
        }
        if (diverged && result.message.isEmpty())
            result.message = QString::fromStdString(world.divergence()->message());
        if (k == 0) painter.frame(motion.extent);
        if (!encoder->addFrame(painter.draw())) return fail(encoder->error());
        result.frames = k + 1;
        if (progress && !progress(k + 1, frames)) {
            encoder.reset();
            out.cancel();
            result.status = ClipResult::Cancelled;
            return result;
        }
    }
    if (!encoder->finish()) return fail(encoder->error());
    encoder.reset();
    if (!out.commit()) return fail(out.error());
    result.status = diverged ? ClipResult::Diverged : ClipResult::Written;
    return result;
}

}  // namespace phasebox
