#include "app/cli/Cli.h"

#include "app/io/OutputFile.h"
#include "app/io/SceneIO.h"

#include <QFile>
#include <QFileInfo>
#include <QRegularExpression>

#include <algorithm>
#include "physics/diagnostics/StabilityAdvisor.h"
#include "physics/integrators/Integrator.h"
#include "physics/scene/BuildWorld.h"
#include "physics/scene/SceneLibrary.h"

namespace phasebox::cli {

namespace {
const char* kUsage =
    "usage: phasebox-cli COMMAND [OPTIONS]\n"
    "\n"
    "commands:\n"
    "  integrators              list the integrators: name, order, explicit/implicit,\n"
    "                           symplectic, force evaluations per step\n"
    "  info SCENE               objects, effects that will run, integrator, dt\n"
    "  run SCENE [OPTIONS]      simulate; see 'phasebox-cli run --help'\n"
    "  accuracy SCENE [OPTIONS] error against CPU time per integrator and dt; see\n"
    "                           'phasebox-cli accuracy --help'\n"
    "  render SCENE --out FILE  draw the run as an MP4 (H.264) or animated GIF clip; see\n"
    "                           'phasebox-cli render --help'\n"
    "  scene [NAME] [FILE]      write a built-in scene (pyramid, cloth, gas, ...) as a scene\n"
    "                           file, to FILE or standard output; no NAME lists them\n"
    "\n"
    "exit status: 0 success, 1 the simulation diverged, 2 bad input, 3 an output could not\n"
    "be written, 130 interrupted (Ctrl-C, SIGTERM or SIGHUP: the results so far are written)\n";
}  // namespace

int fail(QTextStream& err, const QString& message) {
    for (const QString& line : message.split(QLatin1Char('\n')))
        err << "phasebox-cli: error: " << line << "\n";
    err.flush();
    return kBadInput;
}

int failWrite(QTextStream& err, const QString& message) {
    fail(err, message);
    return kWriteFailed;
}

QString checkOutputPath(const QString& option, const QString& path) {
    if (path.isEmpty())
        return QStringLiteral("%1: the file name is empty; give a file, or - for standard output")
            .arg(option);
    if (const QString why = OutputFile::unusablePath(path); !why.isEmpty())
        return QStringLiteral("%1 %2: %3").arg(option, path, why);
    return {};
}

QString noteOutputOption(const QString& option, const QString& path, QStringList& seen) {
    if (seen.contains(option))
        return QStringLiteral("%1 given twice; each output is written once, give it one file")
            .arg(option);
    seen << option;
    if (path.isEmpty()) return checkOutputPath(option, path);
    return {};
}

QString runLengthProblem(double duration, double dt) {
    // Checked as a double: the count of a 1e6 s run at dt = 1e-300 does not fit any integer.
    const double stepCount = std::ceil(duration / dt - 1e-9);
    if (stepCount <= kMaxRunSteps) return {};
    return QStringLiteral(
               "a run of %1 s at dt = %2 s takes %3 steps; at most %4 are "
               "allowed: use a larger --dt or a shorter --duration")
        .arg(QString::number(duration, 'g', 15), QString::number(dt, 'g', 15),
             QString::number(stepCount, 'g', 3), QString::number(kMaxRunSteps, 'g', 3));
}

QString checkOutputs(const QString& scene, const QList<QPair<QString, QString>>& outputs) {
    // Standard output that is the scene itself (`>> scene.json`): the summary would be
    // appended to the scene.
    if (!scene.isEmpty() && scene != QLatin1String("-") && OutputFile::isStandardOutput(scene))
        return QStringLiteral(
                   "standard output is the scene file being read (%1); writing it would destroy "
                   "the "
                   "scene. Send the output elsewhere")
            .arg(scene);
    QList<QPair<QString, QString>> files;
    QString onStandardOutput;
    for (const auto& [option, path] : outputs) {
        if (path.isEmpty()) continue;  // not given (an empty name is refused while parsing)
        if (const QString problem = checkOutputPath(option, path); !problem.isEmpty())
            return problem;
        if (!OutputFile::isStandardOutput(path)) {
            files.append({option, path});
            continue;
        }
        // "-", /dev/stdout, /proc/self/fd/1 or the file standard output is: one stream, which
        // two outputs would write over each other.
        if (!onStandardOutput.isEmpty())
            return QStringLiteral("%1 and %2 %3 both write to standard output; give %2 a file")
                .arg(onStandardOutput, option, path);
        onStandardOutput = option;
    }
    for (qsizetype i = 0; i < files.size(); ++i) {
        const auto& [option, path] = files[i];
        // The same inode: a hard link, a symbolic link or another spelling of the scene's path.
        if (OutputFile::sameFile(path, scene))
            return QStringLiteral(
                       "%1 %2: that is the scene file being read; writing it would "
                       "destroy the scene. Choose another file")
                .arg(option, path);
        for (qsizetype j = 0; j < i; ++j) {
            const auto& [otherOption, otherPath] = files[j];
            const bool same =
                OutputFile::sameFile(path, otherPath) ||
                QFileInfo(path).absoluteFilePath() == QFileInfo(otherPath).absoluteFilePath();
            if (same)
                return QStringLiteral("%1 and %2 both write %3; give each its own file")
                    .arg(otherOption, option, path);
        }
    }
    return {};
}

bool needsGui(const QStringList& arguments) {
    // A clip is drawn by the canvas and Qt Charts, which draw through widgets.
    if (!arguments.isEmpty() && arguments.first() == QLatin1String("render")) return true;
    // The plot options in every spelling the parser takes: --plot F, --plot=F, -plot F.
    static const QRegularExpression plot(QStringLiteral("^--?plot(-energy|-phase)?(=|$)"));
    return std::any_of(arguments.begin(), arguments.end(),
                       [](const QString& a) { return plot.match(a).hasMatch(); });
}

int run(const QStringList& arguments, QTextStream& out, QTextStream& err) {
    if (arguments.isEmpty()) {
        err << kUsage;
        return kBadInput;
    }
    const QString command = arguments.first();
    const QStringList rest = arguments.mid(1);
    if (command == QLatin1String("--help") || command == QLatin1String("-h") ||
        command == QLatin1String("help")) {
        out << kUsage;
        return kSuccess;
    }
    if (command == QLatin1String("--version")) {
        out << "phasebox-cli " << PHASEBOX_VERSION << "\n";
        return kSuccess;
    }
    if (command == QLatin1String("integrators")) return integratorsCommand(rest, out, err);
    if (command == QLatin1String("info")) return infoCommand(rest, out, err);
    if (command == QLatin1String("run")) return runCommand(rest, out, err);
    if (command == QLatin1String("scene")) return sceneCommand(rest, out, err);
    if (command == QLatin1String("accuracy")) return accuracyCommand(rest, out, err);
    if (command == QLatin1String("render")) return renderCommand(rest, out, err);
    return fail(err, QStringLiteral("unknown command \"%1\"; known: integrators, info, run, "
                                    "scene, accuracy, render")
                         .arg(command));
}

int integratorsCommand(const QStringList& args, QTextStream& out, QTextStream& err) {
    if (!args.isEmpty()) return fail(err, QStringLiteral("integrators takes no arguments"));
    out << QStringLiteral("%1 %2 %3 %4 %5\n")
               .arg(QStringLiteral("name"), -18)
               .arg(QStringLiteral("order"), -6)
               .arg(QStringLiteral("kind"), -9)
               .arg(QStringLiteral("symplectic"), -11)
               .arg(QStringLiteral("force evaluations per step"));
    for (const IntegratorInfo& info : integratorRegistry()) {
        out << QStringLiteral("%1 %2 %3 %4 %5\n")
                   .arg(QString::fromUtf8(info.name.data(), info.name.size()), -18)
                   .arg(info.order, -6)
                   .arg(info.implicit ? QStringLiteral("implicit") : QStringLiteral("explicit"), -9)
                   .arg(info.symplectic ? QStringLiteral("yes") : QStringLiteral("no"), -11)
                   .arg(QString::fromUtf8(info.evaluations.data(), info.evaluations.size()));
    }
    return kSuccess;
}

int sceneCommand(const QStringList& args, QTextStream& out, QTextStream& err) {
    const auto& library = scenes::library();
    if (args.isEmpty()) {
        for (const scenes::NamedScene& s : library)
            out << QString::fromStdString(s.name).leftJustified(16)
                << QString::fromStdString(s.summary) << "\n";
        return kSuccess;
    }
    if (args.size() > 2)
        return fail(err, QStringLiteral("usage: phasebox-cli scene [NAME] [FILE]"));
    for (const scenes::NamedScene& s : library) {
        if (QString::fromStdString(s.name) != args[0]) continue;
        const SceneDesc scene = s.make();
        if (args.size() == 1) {
            out << SceneIO::serialize(scene);
            return kSuccess;
        }
        if (const QString problem = checkOutputPath(QStringLiteral("scene FILE"), args[1]);
            !problem.isEmpty())
            return fail(err, problem);
        QString error;
        if (!SceneIO::save(scene, args[1], &error)) return failWrite(err, error);
        return kSuccess;
    }
    QStringList names;
    for (const scenes::NamedScene& s : library) names << QString::fromStdString(s.name);
    return fail(err, QStringLiteral("unknown scene \"%1\"; known: %2")
                         .arg(args[0], names.join(QStringLiteral(", "))));
}

int infoCommand(const QStringList& args, QTextStream& out, QTextStream& err) {
    if (args.size() != 1) return fail(err, QStringLiteral("usage: phasebox-cli info SCENE"));
    if (const QString problem = checkOutputs(args.first(), {}); !problem.isEmpty())
        return fail(err, problem);
    const SceneLoadResult loaded = SceneIO::load(args.first());
    if (!loaded.ok()) return fail(err, loaded.errorText());
    BuildResult built;
    try {
        built = buildWorld(*loaded.scene);
    } catch (const SceneError& e) {
        return fail(err, args.first() + QStringLiteral(": ") + QString::fromStdString(e.what()));
    }
    const SceneDesc& scene = *loaded.scene;
    const World& world = *built.world;

    int pinned = 0, clothNodes = 0;
    for (const Particle& p : world.particles()) {
        pinned += p.pinned;
        clothNodes += p.cloth >= 0;
    }
    // The rigid bodies by shape (the world keeps them in one array): boxes, disks, polygons.
    int rigid[3] = {0, 0, 0}, rigidStatic[3] = {0, 0, 0};
    for (const RigidBody& b : world.rigidBodies()) {
        const auto shape = static_cast<std::size_t>(b.shape);
        ++rigid[shape];
        rigidStatic[shape] += b.isStatic;
    }
    const int clothSprings = [&] {
        int n = 0;
        for (const Cloth& c : world.cloths()) n += c.springCount;
        return n;
    }();

    out << "scene:       "
        << (scene.name.empty() ? QStringLiteral("(unnamed)") : QString::fromStdString(scene.name))
        << "\n";
    if (!scene.description.empty())
        out << "description: " << QString::fromStdString(scene.description) << "\n";
    out << "objects:\n";
    out << "  particles  " << world.particles().size() - clothNodes << " (" << pinned
        << " pinned in all)\n";
    static_assert(static_cast<int>(RigidShape::Rectangle) == 0 &&
                  static_cast<int>(RigidShape::Disk) == 1 &&
                  static_cast<int>(RigidShape::Polygon) == 2);
    out << "  boxes      " << rigid[0] << " (" << rigidStatic[0] << " static)\n";
    out << "  disks      " << rigid[1] << " (" << rigidStatic[1] << " static)\n";
    out << "  polygons   " << rigid[2] << " (" << rigidStatic[2] << " static)\n";
    out << "  planes     " << world.planes().size() << "\n";
    out << "  springs    " << world.springs().size() - clothSprings << "\n";
    out << "  cloths     " << world.cloths().size();
    if (!world.cloths().empty())
        out << " (" << clothNodes << " nodes, " << clothSprings << " springs)";
    out << "\n";
    out << "  joints     " << world.joints().size() << "\n";
    out << "state:       " << world.dimension() << " degrees of freedom\n";
    // The same list as run --json's effects: everything that costs time per step.
    out << "effects that will run:";
    const std::vector<EffectCost> costs = world.effectCosts();
    if (costs.empty()) out << " none";
    for (const EffectCost& cost : costs) out << " " << QString::fromStdString(cost.name);
    out << "\n";
    for (const std::string& name : built.unsupported)
        out << "not simulated yet: " << QString::fromStdString(name) << "\n";
    const SimulationDesc& sim = scene.simulation;
    const IntegratorInfo* info = findIntegrator(sim.integrator);
    out << "integrator:  " << QString::fromStdString(sim.integrator);
    if (info)
        out << " (" << QString::fromUtf8(info->label.data(), info->label.size()) << ", order "
            << info->order << ")";
    out << "\n";
    out << "dt:          " << sim.dt << " s, " << sim.substeps << " sub-step(s)\n";
    out << "duration:    " << sim.duration << " s\n";
    if (world.contacts()) {
        const std::string_view model = contactModelName(sim.contactModel);
        out << "contacts:    "
            << QString::fromLatin1(model.data(), static_cast<qsizetype>(model.size()));
        if (sim.contactModel == ContactModel::Penalty)
            out << ", stiffness " << QString::number(world.penaltyStiffness(), 'g', 4)
                << " N/m per point"
                << (sim.contactStiffness ? "" : " (automatic: the lightest body has omega*h = 0.5)")
                << ", damping " << QString::number(sim.contactDamping, 'g', 4) << " N s/m";
        out << "\n";
    }

    // The stability advisor: the stiffest mode and each explicit method's largest stable step.
    const StabilityAdvice advice = adviseStability(*built.world);
    if (advice.omegaMax > 0.0) {
        out << "stability:   stiffest mode omega = " << QString::number(advice.omegaMax, 'g', 4)
            << " rad/s (period " << QString::number(2.0 * M_PI / advice.omegaMax, 'g', 3)
            << " s); largest stable sub-step per method:\n";
        for (const StepLimit& limit : advice.limits) {
            out << "  "
                << QString::fromLatin1(limit.integrator.data(), limit.integrator.size())
                       .leftJustified(18);
            if (std::isinf(limit.maxDt))
                out << "any";
            else if (limit.maxDt == 0.0)
                out << "none";
            else
                out << QString::number(limit.maxDt, 'g', 3) << " s";
            out << "  (" << QString::fromStdString(limit.note) << ")\n";
        }
    } else {
        out << "stability:   nothing in the scene oscillates; every method is stable\n";
    }
    out << (advice.currentStable ? "advice:      " : "warning:     ")
        << QString::fromStdString(advice.message) << "\n";
    if (!advice.contactWarning.empty())
        out << "warning:     " << QString::fromStdString(advice.contactWarning) << "\n";
    return kSuccess;
}

}  // namespace phasebox::cli
