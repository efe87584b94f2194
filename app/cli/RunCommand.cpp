// phasebox-cli run: simulate a scene and report (CONTRACT.md §4).

#include "app/cli/Cli.h"
#include "app/cli/CommandLine.h"
#include "app/cli/Interrupt.h"
#include "app/io/ChartFile.h"
#include "app/io/NumberFormat.h"
#include "app/io/OutputFile.h"
#include "app/io/SceneIO.h"
#include "physics/diagnostics/StabilityAdvisor.h"
#include "physics/integrators/Integrator.h"
#include "physics/scene/BuildWorld.h"
#include "physics/scene/SceneSchema.h"
#include "physics/world/Probes.h"
#include "ui/plots/Charts.h"

#include <QChart>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <numeric>
#include <optional>

namespace phasebox::cli {

namespace {

QString stageName(int stage) {
    const std::string_view name = StepProfile::kStageNames[stage];
    return QString::fromUtf8(name.data(), static_cast<qsizetype>(name.size()));
}

const char* kRunUsage =
    "usage: phasebox-cli run SCENE [--integrator NAME] [--dt S] [--substeps N] [--duration S]\n"
    "                              [--tolerance T] [--csv FILE] [--every K] [--track ID,ID...]\n"
    "                              [--json] [--plot-energy FILE] [--plot-phase ID.COORD FILE]\n"
    "                              [--probe EXPR]... [--contact-model NAME] [--threads N]\n"
    "\n"
    "  --contact-model M impulse, penalty or kinematic (the scene's simulation.contact_model)\n"
    "  --csv FILE        time series: t,kinetic,potential,work_nc,drift,correction,\n"
    "                    constraint_error and per tracked object\n"
    "                    ID.x,ID.y,ID.vx,ID.vy (boxes also ID.angle, ID.omega), then one column\n"
    "                    per probe; '-' = stdout\n"
    "  --every K         one CSV row every K steps (and at t = 0 and the end); default 1\n"
    "  --track IDS       objects in the CSV; default every particle and box not in a cloth\n"
    "  --json            one JSON object with timings, energies and every object's state\n"
    "                    (and per probe: final, min, max, mean, period over every step)\n"
    "  --probe EXPR      measure EXPR (repeatable): ID.x ID.y ID.vx ID.vy ID.speed ID.angle\n"
    "                    ID.omega ID.kinetic ID.px ID.py ID.L; system.kinetic .potential\n"
    "                    .total .work_nc .drift .correction .px .py .L .com_x .com_y;\n"
    "                    distance(A,B) angle(A,B,C) (ids or points X:Y; vertex B)\n"
    "                    force(JOINT) JOINT.angle contact_force(ID)\n"
    "  --plot-energy F   the energy plot as .png or .svg\n"
    "  --plot-phase ID.COORD F   phase plot of COORD (x, y or angle) of object ID\n"
    "  --threads N       workers, 1 to 1024, default every core; every output but the\n"
    "                    timings is the same for every N\n";

struct RunOptions {
    QString scene;
    std::optional<QString> integrator;
    std::optional<ContactModel> contactModel;
    std::optional<double> dt, duration, tolerance;
    std::optional<int> substeps;
    QString csv;
    int every = 1;
    std::optional<QStringList> track;
    bool json = false;
    QString plotEnergy;
    QString phaseTarget, plotPhase;
    QStringList probes;  // as given, in command-line order
    int threads = 0;     // the world's workers; 0: every core
};

// Splits "a,flag[1,2],b" at the commas outside brackets: cloth node ids hold commas.
QStringList splitIds(const QString& text) {
    QStringList ids;
    QString current;
    int depth = 0;
    for (const QChar c : text) {
        if (c == QLatin1Char('[')) ++depth;
        if (c == QLatin1Char(']')) depth = std::max(0, depth - 1);
        if (c == QLatin1Char(',') && depth == 0) {
            if (!current.isEmpty()) ids << current;
            current.clear();
            continue;
        }
        current += c;
    }
    if (!current.isEmpty()) ids << current;
    return ids;
}

// Parses the command line; returns an error message or an empty string.
QString parseOptions(const QStringList& args, RunOptions& o) {
    auto number = [](const QString& option, const QString& text, double& value) -> QString {
        bool ok = false;
        value = text.toDouble(&ok);
        if (!ok || !std::isfinite(value))
            return QStringLiteral("%1: must be a number (got \"%2\")").arg(option, text);
        return {};
    };
    auto integer = [](const QString& option, const QString& text, int& value) -> QString {
        bool ok = false;
        value = text.toInt(&ok);
        if (!ok) return QStringLiteral("%1: must be an integer (got \"%2\")").arg(option, text);
        return {};
    };
    CommandLine line;
    if (const QString error =
            parseCommandLine(QStringLiteral("run"),
                             {{"json", 0},
                              {"integrator"},
                              {"dt"},
                              {"duration"},
                              {"tolerance"},
                              {"substeps"},
                              {"every"},
                              {"csv"},
                              {"track"},
                              {"plot-energy"},
                              {"plot-phase", 2, "--plot-phase needs ID.COORD and FILE"},
                              {"probe"},
                              {"contact-model"},
                              {"threads"}},
                             args, line);
        !error.isEmpty())
        return error;
    QStringList outputsSeen;
    for (const GivenOption& option : line.options) {
        if (option.is("--json")) {
            o.json = true;
            continue;
        }
        const QString& a = option.name;
        const QString& v = option.value();
        QString error;
        double d = 0.0;
        int n = 0;
        if (a == QLatin1String("--threads")) {
            if (!(error = threadsProblem(v)).isEmpty()) return error;
            o.threads = v.toInt();
        } else if (a == QLatin1String("--integrator")) {
            if (!findIntegrator(v.toStdString()))
                return QStringLiteral("--integrator: unknown integrator \"%1\"; known: %2")
                    .arg(v, QString::fromStdString(knownIntegratorNames()));
            o.integrator = v;
        } else if (a == QLatin1String("--contact-model")) {
            o.contactModel = contactModelFromName(v.toStdString());
            if (!o.contactModel)
                return QStringLiteral("--contact-model: unknown contact model \"%1\"; known: %2")
                    .arg(v, QString::fromStdString(knownContactModelNames()));
        } else if (a == QLatin1String("--dt")) {
            if (!(error = number(a, v, d)).isEmpty()) return error;
            const double maxDt = schema::simulationField(schema::key::dt).range.max;
            if (!(d > 0.0 && d <= maxDt))
                return QStringLiteral("--dt: must be > 0 and <= %1 (got %2)").arg(maxDt).arg(v);
            o.dt = d;
        } else if (a == QLatin1String("--duration")) {
            if (!(error = number(a, v, d)).isEmpty()) return error;
            if (!(d > 0.0 && d <= SceneLimits::kMaxDuration))
                return QStringLiteral("--duration: must be > 0 and <= %1 (got %2)")
                    .arg(QString::number(SceneLimits::kMaxDuration, 'f', 0), v);
            o.duration = d;
        } else if (a == QLatin1String("--tolerance")) {
            if (!(error = number(a, v, d)).isEmpty()) return error;
            if (!(d > 0.0)) return QStringLiteral("--tolerance: must be > 0 (got %1)").arg(v);
            // The scene's own range (CONTRACT §1): a double cannot meet a tighter tolerance.
            static_assert(SceneLimits::kMinTolerance == 1e-14 &&
                          SceneLimits::kMaxCoefficient == 1e12);
            if (d < SceneLimits::kMinTolerance || d > SceneLimits::kMaxCoefficient)
                return QStringLiteral("--tolerance: must be >= 1e-14 and <= 1e12 (got %1)").arg(v);
            o.tolerance = d;
        } else if (a == QLatin1String("--substeps")) {
            if (!(error = integer(a, v, n)).isEmpty()) return error;
            if (n < 1 || n > SceneLimits::kMaxSubsteps)
                return QStringLiteral("--substeps: must be >= 1 and <= %1 (got %2)")
                    .arg(SceneLimits::kMaxSubsteps)
                    .arg(v);
            o.substeps = n;
        } else if (a == QLatin1String("--every")) {
            if (!(error = integer(a, v, n)).isEmpty()) return error;
            if (n < 1) return QStringLiteral("--every: must be >= 1 (got %1)").arg(v);
            o.every = n;
        } else if (a == QLatin1String("--csv")) {
            if (!(error = noteOutputOption(a, v, outputsSeen)).isEmpty()) return error;
            o.csv = v;
        } else if (a == QLatin1String("--track")) {
            o.track = splitIds(v);
        } else if (a == QLatin1String("--probe")) {
            o.probes << v;
        } else if (a == QLatin1String("--plot-energy")) {
            if (!(error = noteOutputOption(a, v, outputsSeen)).isEmpty()) return error;
            if (!isChartPath(v, &error)) return error;
            o.plotEnergy = v;
        } else if (a == QLatin1String("--plot-phase")) {
            o.phaseTarget = v;
            o.plotPhase = option.values[1];
            if (!(error = noteOutputOption(a, o.plotPhase, outputsSeen)).isEmpty()) return error;
            if (!isChartPath(o.plotPhase, &error)) return error;
        }
    }
    if (QString error = takeScene(QStringLiteral("run"), line, o.scene); !error.isEmpty())
        return error;
    return {};
}

// A series of unknown length kept to at most 2·capacity samples: when full, every other sample
// is dropped and the stride doubles, so what is kept stays spread evenly over the whole run and
// a billion-step run costs no more memory than a million-step one. The newest sample is always
// kept (the plots end at the end of the run).
template <typename T>
class BoundedSeries {
public:
    explicit BoundedSeries(std::size_t capacity) : capacity_(capacity) {}
    // Whether step k (counted from 1) is due for a sample at the current stride.
    bool due(long long k) const { return k % stride_ == 0; }
    void push(const T& value) {
        if (values_.size() >= 2 * capacity_) {
            std::size_t kept = 0;
            for (std::size_t i = 0; i < values_.size(); i += 2) values_[kept++] = values_[i];
            values_.resize(kept);
            stride_ *= 2;
        }
        values_.push_back(value);
    }
    const std::vector<T>& values() const { return values_; }

private:
    std::size_t capacity_;
    long long stride_ = 1;
    std::vector<T> values_;
};

// An object whose state is written to the CSV or plotted.
struct Tracked {
    QString id;
    bool isBox = false;
    int index = -1;
};

std::optional<Tracked> findObject(const World& world, const QString& id) {
    const std::string key = id.toStdString();
    for (int i = 0; i < static_cast<int>(world.particles().size()); ++i)
        if (world.particles()[i].id == key) return Tracked{id, false, i};
    for (int i = 0; i < static_cast<int>(world.rigidBodies().size()); ++i)
        if (world.rigidBodies()[i].id == key) return Tracked{id, true, i};
    return std::nullopt;
}

// Coordinate and velocity of a tracked object: 0 x, 1 y, 2 angle.
ui::PhaseSample phaseOf(const World& world, const Tracked& t, int coordinate) {
    if (t.isBox) {
        if (coordinate == 2) return {world.bodyAngle(t.index), world.bodyAngularVelocity(t.index)};
        return {world.bodyPosition(t.index)[coordinate], world.bodyVelocity(t.index)[coordinate]};
    }
    return {world.particlePosition(t.index)[coordinate],
            world.particleVelocity(t.index)[coordinate]};
}

// The --csv output: standard output ("-") as it is, anything else through OutputFile. Rows
// are written whole: an interrupted run stops between steps, never inside a row.
class CsvOutput {
public:
    bool open(const QString& path, QTextStream& out, QString* error) {
        if (OutputFile::isStandardOutput(path)) {
            stream_ = &out;
            return true;
        }
        file_ = std::make_unique<OutputFile>(path, QStringLiteral("the CSV file"));
        if (!file_->open()) {
            *error = file_->error();
            return false;
        }
        owned_ = std::make_unique<QTextStream>(file_->device());
        stream_ = owned_.get();
        return true;
    }
    QTextStream& stream() { return *stream_; }
    // Whether a write has failed already (a full disk, a reader gone): the run stops there.
    bool failed() const {
        return (file_ && file_->failed()) || stream_->status() == QTextStream::WriteFailed;
    }
    // Whether a signal abandoned a blocked write (exit 130 rather than 3).
    bool interrupted() const { return file_ && file_->interrupted(); }
    bool commit(QString* error) {
        if (!file_) return true;
        owned_->flush();
        if (file_->commit()) return true;
        *error = file_->error();
        return false;
    }

private:
    std::unique_ptr<OutputFile> file_;
    std::unique_ptr<QTextStream> owned_;
    QTextStream* stream_ = nullptr;
};

void writeCsvHeader(QTextStream& s, const std::vector<Tracked>& tracked,
                    const QStringList& probes) {
    // CONTRACT §4 and §6; constraint_error is the joints' largest positional error (0 without).
    s << "t,kinetic,potential,work_nc,drift,correction,constraint_error";
    for (const Tracked& t : tracked) {
        const QStringList cols = t.isBox ? QStringList{"x", "y", "angle", "vx", "vy", "omega"}
                                         : QStringList{"x", "y", "vx", "vy"};
        for (const QString& c : cols) s << ',' << csvField(t.id + QLatin1Char('.') + c);
    }
    for (const QString& probe : probes) s << ',' << csvField(probe);  // "distance(a,b)"
    s << '\n';
}

void writeCsvRow(QTextStream& s, const World& world, const std::vector<Tracked>& tracked,
                 const std::vector<double>& probeValues) {
    const EnergyLedger& e = world.energy();
    s << formatNumber(world.time()) << ',' << formatNumber(e.kinetic) << ','
      << formatNumber(e.potential) << ',' << formatNumber(e.workNc) << ',' << formatNumber(e.drift)
      << ',' << formatNumber(e.correction) << ',' << formatNumber(world.jointErrors().position);
    for (const Tracked& t : tracked) {
        if (t.isBox) {
            const Vec2 p = world.bodyPosition(t.index), v = world.bodyVelocity(t.index);
            s << ',' << formatNumber(p.x()) << ',' << formatNumber(p.y()) << ','
              << formatNumber(world.bodyAngle(t.index)) << ',' << formatNumber(v.x()) << ','
              << formatNumber(v.y()) << ',' << formatNumber(world.bodyAngularVelocity(t.index));
        } else {
            const Vec2 p = world.particlePosition(t.index), v = world.particleVelocity(t.index);
            s << ',' << formatNumber(p.x()) << ',' << formatNumber(p.y()) << ','
              << formatNumber(v.x()) << ',' << formatNumber(v.y());
        }
    }
    for (const double value : probeValues) s << ',' << formatNumber(value);
    s << '\n';
}

// A string as a JSON string literal.
QString jsonString(const std::string& text) {
    QString out = QStringLiteral("\"");
    for (const QChar c : QString::fromStdString(text)) {
        if (c == QLatin1Char('"') || c == QLatin1Char('\\'))
            out += QLatin1Char('\\') + c;
        else if (c.unicode() < 0x20)
            out += QStringLiteral("\\u%1").arg(c.unicode(), 4, 16, QLatin1Char('0'));
        else
            out += c;
    }
    return out + QLatin1Char('"');
}

// A number as QJsonDocument writes it: the shortest text that reads back the same, and null
// for what JSON cannot hold.
QString jsonNumber(double v) {
    return std::isfinite(v) ? formatNumber(v) : QStringLiteral("null");
}

QString jsonPair(const Vec2& v) {
    return QLatin1Char('[') + jsonNumber(v.x()) + QStringLiteral(", ") + jsonNumber(v.y()) +
           QLatin1Char(']');
}

// The --json report, with "objects" last and written object by object: a million cloth
// nodes held as one QJsonObject, then as its text, then as that text in a QString, cost
// several times the memory of the run itself; streamed, --json adds little to the run's own
// (docs/robustness.md gives the bound the tests pin).
void writeJsonReport(QTextStream& out, const QJsonObject& report, const World& world) {
    QByteArray head = QJsonDocument(report).toJson(QJsonDocument::Indented);
    head.truncate(head.lastIndexOf('}'));
    while (head.endsWith('\n') || head.endsWith(' ')) head.chop(1);
    out << head << (report.isEmpty() ? "" : ",") << "\n    \"objects\": {";
    bool first = true;
    auto next = [&](const std::string& id) {
        out << (first ? "\n" : ",\n") << "        " << jsonString(id) << ": {";
        first = false;
    };
    for (int i = 0; i < static_cast<int>(world.particles().size()); ++i) {
        next(world.particles()[i].id);
        out << "\"position\": " << jsonPair(world.particlePosition(i))
            << ", \"velocity\": " << jsonPair(world.particleVelocity(i)) << "}";
    }
    for (int i = 0; i < static_cast<int>(world.rigidBodies().size()); ++i) {
        next(world.rigidBodies()[i].id);
        out << "\"position\": " << jsonPair(world.bodyPosition(i))
            << ", \"velocity\": " << jsonPair(world.bodyVelocity(i))
            << ", \"angle\": " << jsonNumber(world.bodyAngle(i))
            << ", \"angular_velocity\": " << jsonNumber(world.bodyAngularVelocity(i)) << "}";
    }
    out << (first ? "}" : "\n    }") << "\n}\n";
}

double median(std::vector<double> v) {
    if (v.empty()) return 0.0;
    const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
    std::nth_element(v.begin(), mid, v.end());
    if (v.size() % 2) return *mid;
    return 0.5 * (*mid + *std::max_element(v.begin(), mid));
}

int interruptedBeforeRun(QTextStream& err) {
    err << "phasebox-cli: interrupted before the run began; nothing was written\n";
    err.flush();
    return kInterrupted;
}

bool writePlot(QChart* chart, const QString& path, QTextStream& err) {
    std::unique_ptr<QChart> owner(chart);
    QString error;
    if (writeChart(chart, path, QSize(1000, 600), &error)) return true;
    failWrite(err, error);
    return false;
}

// The probes of a run (CONTRACT §7): each sampled at every step for its statistics, whatever
// --every thins the CSV to.
struct ProbeSet {
    QStringList names;  // as given, the scene's saved instruments first
    std::vector<Probe> probes;
    std::vector<PeriodTracker> stats;
    std::vector<double> values;
    void sample(const World& world) {
        for (std::size_t i = 0; i < probes.size(); ++i) {
            values[i] = evaluateProbe(world, probes[i]);
            stats[i].add(world.time(), values[i]);
        }
    }
};

// What the step loop measured, for the report and the summary.
struct RunRecord {
    long long steps = 0;  // asked for
    long long done = 0;   // of the state shown
    bool diverged = false, interrupted = false;
    double wallSeconds = 0.0;
    double initialEnergy = 0.0;
    // Mean and max over every step; the median over an evenly thinned sample once a run passes
    // 2^21 steps (exact below that).
    BoundedSeries<double> stepMs{std::size_t(1) << 20};
    double stepMsSum = 0.0, stepMsMax = 0.0;
    long long stepsTimed = 0;
    // The joints' largest errors over the run, at the end of every step (CONTRACT §6).
    JointErrors worstJoint;
};

// The --json report but its "objects" (writeJsonReport adds them).
QJsonObject jsonReport(const World& world, const SimulationDesc& sim, double dt, const RunRecord& r,
                       const ProbeSet& probes) {
    const EnergyLedger& e = world.energy();
    const double stepsRun = static_cast<double>(std::max<long long>(1, r.stepsTimed));
    QJsonArray effects;
    for (const EffectCost& cost : world.effectCosts())
        effects.append(QJsonObject{{"name", QString::fromStdString(cost.name)},
                                   {"ms_per_step", cost.seconds * 1000.0 / stepsRun}});
    // The named stages of the step in the order they run (CONTRACT.md §7); a stage the
    // scene never needs (collide, with nothing to touch) is left out.
    QJsonArray stages;
    const StepProfile& profile = world.stepProfile();
    for (int i = 0; i < StepProfile::kStageCount; ++i)
        if (profile.ran(i))
            stages.append(
                QJsonObject{{"name", stageName(i)}, {"ms_per_step", profile.msPerStep(i)}});
    const double mean = r.stepsTimed == 0 ? 0.0 : r.stepMsSum / static_cast<double>(r.stepsTimed);
    QJsonObject report{
        {"integrator", QString::fromStdString(sim.integrator)},
        {"dt", dt},
        {"substeps", sim.substeps},
        {"steps", static_cast<double>(r.done)},
        {"sim_time", world.time()},
        {"wall_seconds", r.wallSeconds},
        {"step_ms",
         QJsonObject{{"median", median(r.stepMs.values())}, {"mean", mean}, {"max", r.stepMsMax}}},
        {"stages", stages},
        {"energy", QJsonObject{{"initial", r.initialEnergy},
                               {"kinetic", e.kinetic},
                               {"potential", e.potential},
                               {"work_nc", e.workNc},
                               {"drift", e.drift},
                               {"correction", e.correction},
                               {"max_abs_drift", e.maxAbsDrift}}},
        {"diverged", r.diverged},
        {"sleeping", world.sleepingBodies()},
        {"effects", effects},
        {"force_evaluations", static_cast<double>(world.forceEvaluations())},
    };
    if (!probes.probes.empty()) {
        // final is the probe in the state the report shows (after a divergence, the
        // restored one, as `objects`); the rest are over every step that ran.
        QJsonObject measured;
        for (std::size_t i = 0; i < probes.probes.size(); ++i) {
            const ProbeSummary st = probes.stats[i].summary();
            measured.insert(probes.names[i],
                            QJsonObject{{"final", evaluateProbe(world, probes.probes[i])},
                                        {"min", st.min},
                                        {"max", st.max},
                                        {"mean", st.mean},
                                        {"period", st.period ? QJsonValue(*st.period)
                                                             : QJsonValue(QJsonValue::Null)}});
        }
        report.insert("probes", measured);
    }
    if (world.jointSolver())
        report.insert("constraints", QJsonObject{{"max_error", r.worstJoint.position},
                                                 {"final_error", world.jointErrors().position},
                                                 {"max_angle_error", r.worstJoint.angle}});
    if (world.integrator().info().implicit) {
        // The implicit solve's work: Newton iterations, linear solves and (for large systems)
        // conjugate-gradient iterations per step, and the last relative residual.
        const IntegratorStats& st = world.integrator().stats();
        report.insert(
            "implicit_solver",
            QJsonObject{
                {"last_newton_iterations", st.lastNewtonIterations},
                {"linear_solves_per_step", static_cast<double>(st.linearSolves) / stepsRun},
                {"cg_iterations_per_step", static_cast<double>(st.linearIterations) / stepsRun},
                {"last_cg_iterations", st.lastLinearIterations},
                {"last_cg_residual", st.lastLinearResidual}});
    }
    if (r.diverged) {
        const Divergence& d = *world.divergence();
        report.insert("divergence", QJsonObject{{"time", d.time},
                                                {"object", QString::fromStdString(d.objectId)},
                                                {"what", QString::fromStdString(d.what)},
                                                {"restored_time", d.restoredTime},
                                                {"message", QString::fromStdString(d.message())}});
    }
    if (r.interrupted) report.insert("interrupted", true);
    return report;
}

// The summary on standard output when no output took it (CONTRACT §4).
void writeSummary(QTextStream& out, const QString& sceneName, const World& world,
                  const SimulationDesc& sim, double dt, const RunRecord& r, const ProbeSet& probes,
                  const std::vector<Tracked>& tracked) {
    const EnergyLedger& e = world.energy();
    const double stepsRun = static_cast<double>(std::max<long long>(1, r.stepsTimed));
    out << "scene:      " << sceneName << "\n"
        << "integrator: " << QString::fromStdString(sim.integrator) << ", dt = " << formatNumber(dt)
        << " s, " << sim.substeps << " sub-step(s)\n"
        << "ran:        " << r.done << " steps to t = " << formatNumber(world.time()) << " s in "
        << QString::number(r.wallSeconds, 'f', 3) << " s ("
        << QString::number(median(r.stepMs.values()), 'g', 3) << " ms per step, median)\n"
        << "energy:     initial " << QString::number(r.initialEnergy, 'g', 6) << " J; now kinetic "
        << QString::number(e.kinetic, 'g', 6) << ", potential "
        << QString::number(e.potential, 'g', 6) << ", work_nc " << QString::number(e.workNc, 'g', 6)
        << ", correction " << QString::number(e.correction, 'g', 6) << " J\n"
        << "drift:      " << QString::number(e.drift, 'g', 3) << " J (largest |drift| "
        << QString::number(e.maxAbsDrift, 'g', 3) << " J)\n";
    if (world.jointSolver())
        out << "joints:     largest error " << QString::number(r.worstJoint.position, 'g', 3)
            << " m, " << QString::number(r.worstJoint.angle, 'g', 3) << " rad; at the end "
            << QString::number(world.jointErrors().position, 'g', 3) << " m\n";
    out << "effects:   ";
    if (world.effectCosts().empty()) out << " none";
    for (const EffectCost& cost : world.effectCosts())
        out << " " << QString::fromStdString(cost.name) << " "
            << QString::number(cost.seconds * 1000.0 / stepsRun, 'g', 3) << " ms/step;";
    out << "\nstages:    ";
    const StepProfile& profile = world.stepProfile();
    for (int i = 0; i < StepProfile::kStageCount; ++i)
        if (profile.ran(i))
            out << " " << stageName(i) << " " << QString::number(profile.msPerStep(i), 'g', 3)
                << " ms/step;";
    out << "\n";
    for (std::size_t i = 0; i < probes.probes.size(); ++i) {
        const ProbeSummary st = probes.stats[i].summary();
        out << "probe " << probes.names[i] << ": final "
            << QString::number(evaluateProbe(world, probes.probes[i]), 'g', 6) << ", min "
            << QString::number(st.min, 'g', 6) << ", max " << QString::number(st.max, 'g', 6)
            << ", mean " << QString::number(st.mean, 'g', 6) << ", period "
            << (st.period ? QString::number(*st.period, 'g', 6) + QStringLiteral(" s")
                          : QStringLiteral("none"))
            << "\n";
    }
    for (const Tracked& t : tracked) {
        const ui::PhaseSample x = phaseOf(world, t, 0), y = phaseOf(world, t, 1);
        out << "  " << t.id << ": position (" << QString::number(x.coordinate, 'g', 6) << ", "
            << QString::number(y.coordinate, 'g', 6) << "), velocity ("
            << QString::number(x.velocity, 'g', 6) << ", " << QString::number(y.velocity, 'g', 6)
            << ")\n";
    }
}

// The objects of the CSV: --track's, else every particle not in a cloth and every rigid body.
QString trackedObjects(const World& world, const RunOptions& o, std::vector<Tracked>& tracked) {
    if (o.track) {
        for (const QString& id : *o.track) {
            const auto t = findObject(world, id);
            if (!t) return QStringLiteral("--track: unknown object id \"%1\"").arg(id);
            tracked.push_back(*t);
        }
    } else {
        for (int i = 0; i < static_cast<int>(world.particles().size()); ++i)
            if (world.particles()[i].cloth < 0)
                tracked.push_back({QString::fromStdString(world.particles()[i].id), false, i});
        for (int i = 0; i < static_cast<int>(world.rigidBodies().size()); ++i)
            tracked.push_back({QString::fromStdString(world.rigidBodies()[i].id), true, i});
    }
    return {};
}

// The series the plots draw, sampled as the run goes.
struct PlotSamples {
    bool energyPlot = false;
    std::optional<Tracked> phaseObject;
    int phaseCoordinate = 0;  // 0 x, 1 y, 2 angle
    // The charts decimate to a few thousand points, so 2·2^16 samples lose nothing visible.
    BoundedSeries<ui::EnergySample> energy{std::size_t(1) << 16};
    BoundedSeries<ui::PhaseSample> phase{std::size_t(1) << 16};
    bool any() const { return energyPlot || phaseObject; }
    void sample(const World& world) {
        if (energyPlot) {
            const EnergyLedger& e = world.energy();
            energy.push({world.time(), e.kinetic, e.potential, e.workNc, e.drift, e.correction});
        }
        if (phaseObject) phase.push(phaseOf(world, *phaseObject, phaseCoordinate));
    }
};

// --plot-phase's ID.COORD: the object and its coordinate, or the message refusing it.
QString phaseTarget(const World& world, const RunOptions& o, PlotSamples& plots) {
    const qsizetype dot = o.phaseTarget.lastIndexOf(QLatin1Char('.'));
    const QString id = o.phaseTarget.left(dot), coord = o.phaseTarget.mid(dot + 1);
    plots.phaseObject = dot > 0 ? findObject(world, id) : std::nullopt;
    if (!plots.phaseObject)
        return QStringLiteral(
                   "--plot-phase: unknown object \"%1\" (expected ID.COORD, e.g. ball.x)")
            .arg(o.phaseTarget);
    if (coord == QLatin1String("x"))
        plots.phaseCoordinate = 0;
    else if (coord == QLatin1String("y"))
        plots.phaseCoordinate = 1;
    else if (coord == QLatin1String("angle") && plots.phaseObject->isBox)
        plots.phaseCoordinate = 2;
    else
        return QStringLiteral("--plot-phase: unknown coordinate \"%1\"; known: x, y%2")
            .arg(coord, plots.phaseObject->isBox ? QStringLiteral(", angle") : QString());
    return {};
}

// The probes, refused before anything runs or is written. The lesson's saved instruments come
// first, as if given with --probe (one given again is not repeated).
QString parseProbes(const World& world, const SceneDesc& scene, const QStringList& given,
                    ProbeSet& probes) {
    for (const std::string& text : scene.instruments.readProbes())
        probes.names << QString::fromStdString(text);
    for (const QString& text : given)
        if (!probes.names.contains(text)) probes.names << text;
    for (const QString& text : std::as_const(probes.names)) {
        ProbeParse parsed = parseProbe(world, text.toStdString());
        if (!parsed) return QString::fromStdString(parsed.error);
        probes.probes.push_back(std::move(*parsed.probe));
    }
    probes.stats.resize(probes.probes.size());
    probes.values.resize(probes.probes.size());
    return {};
}

// Steps the world r.steps times, or until it diverges, a CSV write fails (a disk that filled, a
// reader gone: exit 3, not at the end of the run) or a signal comes. The CSV (when csv is not
// null) gets a row every `every` steps and at the last; an interrupted run's last row is its
// final state, as at the end of a full one.
void runSteps(World& world, RunRecord& r, ProbeSet& probes, PlotSamples& plots, CsvOutput* csv,
              int every, const std::vector<Tracked>& tracked) {
    r.initialEnergy = world.energy().initial;
    world.resetProfile();
    using Clock = std::chrono::steady_clock;
    const auto wallStart = Clock::now();
    for (long long k = 1; k <= r.steps; ++k) {
        const auto start = Clock::now();
        const bool ok = world.step();
        const double ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
        if (r.stepMs.due(k)) r.stepMs.push(ms);
        r.stepMsSum += ms;
        r.stepMsMax = std::max(r.stepMsMax, ms);
        ++r.stepsTimed;
        if (!ok) {
            r.diverged = true;
            break;
        }
        r.done = k;
        probes.sample(world);
        if (world.jointSolver()) {
            const JointErrors now = world.jointErrors();
            r.worstJoint.position = std::max(r.worstJoint.position, now.position);
            r.worstJoint.angle = std::max(r.worstJoint.angle, now.angle);
        }
        r.interrupted = k < r.steps && cli::interrupted();
        const bool last = k == r.steps || r.interrupted;
        if (csv && (k % every == 0 || last)) {
            writeCsvRow(csv->stream(), world, tracked, probes.values);
            if (csv->failed()) break;
        }
        if (plots.any() && (plots.energy.due(k) || last)) plots.sample(world);
        if (r.interrupted) break;
    }
    // A signal that came during the write that ended the loop.
    if (!r.diverged && r.done < r.steps && cli::interrupted()) r.interrupted = true;
    r.wallSeconds = std::chrono::duration<double>(Clock::now() - wallStart).count();
    // A runaway is confirmed a few steps after it began and the world goes back to where it
    // began: report the steps of the state that is shown, as sim_time does.
    if (r.diverged) r.done = world.stepCount();
}

}  // namespace

int runCommand(const QStringList& args, QTextStream& out, QTextStream& err) {
    if (asksForHelp(args)) {
        out << kRunUsage;
        return kSuccess;
    }
    RunOptions o;
    if (const QString error = parseOptions(args, o); !error.isEmpty()) return fail(err, error);
    if (const QString error =
            checkOutputs(o.scene, {{"--json", o.json ? QStringLiteral("-") : QString()},
                                   {"--csv", o.csv},
                                   {"--plot-energy", o.plotEnergy},
                                   {"--plot-phase", o.plotPhase}});
        !error.isEmpty())
        return fail(err, error);

    SceneLoadResult loaded = SceneIO::load(o.scene);
    if (!loaded.ok()) return fail(err, loaded.errorText());
    if (interrupted()) return interruptedBeforeRun(err);
    SceneDesc& scene = *loaded.scene;
    SimulationDesc& sim = scene.simulation;
    if (o.integrator) sim.integrator = o.integrator->toStdString();
    if (o.contactModel) sim.contactModel = *o.contactModel;
    if (o.dt) sim.dt = *o.dt;
    if (o.substeps) sim.substeps = *o.substeps;
    if (o.duration) sim.duration = *o.duration;
    if (o.tolerance) sim.tolerance = *o.tolerance;
    if (const std::string problem = substepWorkProblem(scene, sim.substeps); !problem.empty())
        return fail(err, QStringLiteral("--substeps: ") + QString::fromStdString(problem));

    BuildResult built;
    try {
        built = buildWorld(scene);
    } catch (const SceneError& e) {
        QStringList lines;
        for (const SceneIssue& issue : e.issues())
            lines << QStringLiteral("%1: %2: %3")
                         .arg(o.scene, QString::fromStdString(issue.path),
                              QString::fromStdString(issue.message));
        return fail(err, lines.join(QLatin1Char('\n')));
    }
    World& world = *built.world;
    world.setWorkers(o.threads);
    for (const std::string& name : built.unsupported)
        err << "phasebox-cli: warning: the effect \"" << QString::fromStdString(name)
            << "\" is not simulated yet and is ignored\n";
    if (const std::string warning = contactModelWarning(world); !warning.empty())
        err << "phasebox-cli: warning: " << QString::fromStdString(warning) << "\n";

    std::vector<Tracked> tracked;
    if (const QString error = trackedObjects(world, o, tracked); !error.isEmpty())
        return fail(err, error);
    PlotSamples plots;
    plots.energyPlot = !o.plotEnergy.isEmpty();
    if (!o.plotPhase.isEmpty())
        if (const QString error = phaseTarget(world, o, plots); !error.isEmpty())
            return fail(err, error);
    ProbeSet probes;
    if (const QString error = parseProbes(world, scene, o.probes, probes); !error.isEmpty())
        return fail(err, error);
    probes.sample(world);

    // A Ctrl-C, SIGTERM or SIGHUP while the scene loaded (the handlers are installed first
    // thing in main): nothing was computed, so nothing is written.
    if (interrupted()) return interruptedBeforeRun(err);
    // From here a signal stops the run between steps, and what was computed is written.
    CsvOutput csv;
    if (!o.csv.isEmpty()) {
        QString error;
        if (!csv.open(o.csv, out, &error)) return failWrite(err, error);
        writeCsvHeader(csv.stream(), tracked, probes.names);
        writeCsvRow(csv.stream(), world, tracked, probes.values);
    }

    const double dt = sim.dt;
    if (const QString problem = runLengthProblem(sim.duration, dt); !problem.isEmpty())
        return fail(err, problem);
    RunRecord r;
    r.steps = std::max<long long>(1, static_cast<long long>(std::ceil(sim.duration / dt - 1e-9)));
    if (plots.any()) plots.sample(world);
    runSteps(world, r, probes, plots, o.csv.isEmpty() ? nullptr : &csv, o.every, tracked);

    int status = kSuccess;
    if (!o.csv.isEmpty()) {
        QString error;
        if (!csv.commit(&error)) {
            status = failWrite(err, error);
            if (csv.interrupted()) status = kInterrupted;
        }
    }
    const QString title =
        QStringLiteral("%1 — %2, dt = %3 s")
            .arg(scene.name.empty() ? o.scene : QString::fromStdString(scene.name),
                 QString::fromStdString(sim.integrator), QString::number(dt, 'g', 4));
    if (!o.plotEnergy.isEmpty() &&
        !writePlot(ui::createEnergyChart(plots.energy.values(), {}, title), o.plotEnergy, err))
        status = kWriteFailed;
    if (plots.phaseObject) {
        static const char* names[3][2] = {
            {"x [m]", "vx [m/s]"}, {"y [m]", "vy [m/s]"}, {"angle [rad]", "omega [rad/s]"}};
        const QString who = plots.phaseObject->id + QLatin1Char(' ');
        if (!writePlot(
                ui::createPhaseChart(plots.phase.values(),
                                     who + QLatin1String(names[plots.phaseCoordinate][0]),
                                     who + QLatin1String(names[plots.phaseCoordinate][1]), title),
                o.plotPhase, err))
            status = kWriteFailed;
    }

    if (o.json) {
        writeJsonReport(out, jsonReport(world, sim, dt, r, probes), world);
    } else if (!OutputFile::isStandardOutput(o.csv) &&
               !OutputFile::isStandardOutput(o.plotEnergy) &&
               !OutputFile::isStandardOutput(o.plotPhase)) {
        writeSummary(out, scene.name.empty() ? o.scene : QString::fromStdString(scene.name), world,
                     sim, dt, r, probes, tracked);
    }
    out.flush();
    if (r.interrupted) {
        err << "phasebox-cli: interrupted at t = " << formatNumber(world.time()) << " s after "
            << r.done << " of " << r.steps << " steps; the results so far are written\n";
        err.flush();
        return status == kSuccess ? kInterrupted : status;
    }
    if (r.diverged) {
        err << "phasebox-cli: diverged: " << QString::fromStdString(world.divergence()->message());
        // The advisor at the restored state: which step this method needs (the largest stable
        // dt from the stiffest mode, penalty contacts included).
        if (const StabilityAdvice advice = adviseStability(world); !advice.currentStable)
            err << " Stability advisor: " << QString::fromStdString(advice.message);
        err << "\n";
        err.flush();
        return status == kSuccess ? kDiverged : status;
    }
    return status;
}

}  // namespace phasebox::cli
