// phasebox-cli accuracy: error against CPU time per integrator and dt (CONTRACT.md §4).

#include "app/accuracy/AccuracyStudy.h"
#include "app/cli/Cli.h"
#include "app/cli/CommandLine.h"
#include "app/cli/Interrupt.h"
#include "app/io/ChartFile.h"
#include "app/io/NumberFormat.h"
#include "app/io/OutputFile.h"
#include "app/io/SceneIO.h"
#include "physics/integrators/Integrator.h"
#include "physics/scene/BuildWorld.h"
#include "ui/plots/Charts.h"
#include "ui/plots/WorkPrecisionChart.h"

#include <QChart>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <stdexcept>
#include <vector>

#if defined(__unix__) || defined(__APPLE__)
#include <unistd.h>
#endif

namespace phasebox::cli {

namespace {

constexpr double kUnbounded = std::numeric_limits<double>::infinity();

const char* kAccuracyUsage =
    "usage: phasebox-cli accuracy SCENE [--integrators LIST|all] [--dt LIST] [--duration S]\n"
    "                                   [--tolerances LIST] [--csv FILE] [--plot FILE] [--json]\n"
    "                                   [--threads N]\n"
    "\n"
    "Runs the scene to its end time with each integrator at each dt, compares the positions\n"
    "at the end with a reference (the exact solution for oscillators, free fall and Kepler\n"
    "orbits, else rk45 at tolerance 1e-12) and times each run (CPU time of the run alone, best\n"
    "of up to 5 for runs under 50 ms).\n"
    "\n"
    "  --integrators LIST  comma-separated names, or all (default)\n"
    "  --dt LIST           comma-separated steps; default the scene's dt x 1, 1/2, ... 1/32.\n"
    "                      Every run uses one sub-step, so dt is the integrator's step\n"
    "  --duration S        end time; default the scene's duration\n"
    "  --tolerances LIST   what the adaptive methods (adaptive_euler, rk45) sweep instead of\n"
    "                      dt; default 1e-2 ... 1e-7 for adaptive_euler, 1e-5 ... 1e-10 for\n"
    "                      rk45. Their dt column is the frame step they land on (the first\n"
    "                      dt), their steps column their internal steps\n"
    "  --csv FILE          integrator,dt,steps,force_evals,cpu_seconds,position_error,\n"
    "                      energy_drift,order,tolerance,diverged; '-' = stdout\n"
    "  --json              one JSON object: scene, reference, contacts, note, records\n"
    "  --plot FILE         the work-precision diagram (.png or .svg)\n"
    "  --threads N         workers, 1 to 1024 (the same records for every N)\n"
    "\n"
    "order = ln(error_prev/error) / ln(dt_prev/dt) against the previous dt of the same\n"
    "integrator; empty for adaptive methods and for scenes with contacts (contact events make\n"
    "every method first-order).\n"
    "exit status: 0 even when some runs diverged: a divergence is a result here, shown as\n"
    "position_error = inf (null in JSON); 2 bad input (usage, unknown integrator, dt <= 0 or\n"
    "> 1, unreadable or invalid scene).\n";

struct AccuracyCliOptions {
    QString scene;
    AccuracyOptions study;
    QString csv, plot;
    bool json = false;
};

QStringList splitList(const QString& text) {
    QStringList items;
    for (const QString& item : text.split(QLatin1Char(','), Qt::SkipEmptyParts))
        if (!item.trimmed().isEmpty()) items << item.trimmed();
    return items;
}

// Numbers in (0, upper]; returns an error message or an empty string.
QString parseNumbers(const QString& option, const QString& text, double upper,
                     std::vector<double>& out) {
    const QStringList items = splitList(text);
    if (items.isEmpty()) return QStringLiteral("%1 needs at least one number").arg(option);
    for (const QString& item : items) {
        bool ok = false;
        const double value = item.toDouble(&ok);
        if (!ok || !std::isfinite(value))
            return QStringLiteral("%1: must be a number (got \"%2\")").arg(option, item);
        if (!(value > 0.0) || !(value <= upper))
            return std::isinf(upper) ? QStringLiteral("%1: must be > 0 (got %2)").arg(option, item)
                                     : QStringLiteral("%1: must be > 0 and <= %2 (got %3)")
                                           .arg(option, formatNumber(upper), item);
        out.push_back(value);
    }
    return {};
}

QString parseOptions(const QStringList& args, AccuracyCliOptions& o) {
    CommandLine line;
    if (const QString error = parseCommandLine(QStringLiteral("accuracy"),
                                               {{"json", 0},
                                                {"integrators"},
                                                {"dt"},
                                                {"duration"},
                                                {"tolerances"},
                                                {"csv"},
                                                {"plot"},
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
        if (a == QLatin1String("--threads")) {
            if (!(error = threadsProblem(v)).isEmpty()) return error;
        } else if (a == QLatin1String("--integrators")) {
            o.study.integrators.clear();
            if (v.trimmed() == QLatin1String("all")) continue;
            const QStringList names = splitList(v);
            if (names.isEmpty()) return QStringLiteral("--integrators needs a name or all");
            for (const QString& name : names) {
                if (!findIntegrator(name.toStdString()))
                    return QStringLiteral("--integrators: unknown integrator \"%1\"; known: %2")
                        .arg(name, QString::fromStdString(knownIntegratorNames()));
                o.study.integrators.push_back(name.toStdString());
            }
        } else if (a == QLatin1String("--dt")) {
            o.study.dts.clear();
            if (!(error = parseNumbers(a, v, 1.0, o.study.dts)).isEmpty()) return error;
        } else if (a == QLatin1String("--tolerances")) {
            o.study.tolerances.clear();
            if (!(error = parseNumbers(a, v, kUnbounded, o.study.tolerances)).isEmpty())
                return error;
            // As in a scene (CONTRACT §1): a double cannot meet a tighter tolerance.
            for (const double tolerance : o.study.tolerances)
                if (tolerance < SceneLimits::kMinTolerance)
                    return QStringLiteral("--tolerances: must be >= 1e-14 (got %1)")
                        .arg(formatNumber(tolerance));
        } else if (a == QLatin1String("--duration")) {
            std::vector<double> d;
            if (!(error = parseNumbers(a, v, kUnbounded, d)).isEmpty()) return error;
            if (d.size() != 1)
                return QStringLiteral("--duration takes one number (got \"%1\")").arg(v);
            // The scene's own bound, named as the option's: the study would otherwise refuse
            // it as the scene's simulation.duration, an option the user never gave.
            static_assert(SceneLimits::kMaxDuration == 1e6);
            if (d.front() > SceneLimits::kMaxDuration)
                return QStringLiteral("--duration: must be > 0 and <= 1e6 (got %1)").arg(v);
            o.study.duration = d.front();
        } else if (a == QLatin1String("--csv")) {
            if (!(error = noteOutputOption(a, v, outputsSeen)).isEmpty()) return error;
            o.csv = v;
        } else if (a == QLatin1String("--plot")) {
            if (!(error = noteOutputOption(a, v, outputsSeen)).isEmpty()) return error;
            const QString suffix = QFileInfo(v).suffix().toLower();
            if (suffix != QLatin1String("png") && suffix != QLatin1String("svg"))
                return QStringLiteral("%1: the plot must be a .png or .svg file").arg(v);
            o.plot = v;
        }
    }
    if (QString error = takeScene(QStringLiteral("accuracy"), line, o.scene); !error.isEmpty())
        return error;
    return {};
}

QString optionalNumber(const std::optional<double>& value) {
    return value ? formatNumber(*value) : QString();
}

void writeCsv(QTextStream& s, const AccuracyResult& result) {
    // The contract's columns in the contract's order; tolerance and diverged are extensions.
    s << "integrator,dt,steps,force_evals,cpu_seconds,position_error,energy_drift,order,tolerance,"
         "diverged\n";
    for (const AccuracyRecord& r : result.records) {
        s << csvField(QString::fromStdString(r.integrator)) << ',' << formatNumber(r.dt) << ','
          << r.steps << ',' << r.forceEvals << ',' << formatNumber(r.cpuSeconds) << ','
          << formatNumber(r.positionError) << ',' << formatNumber(r.energyDrift) << ','
          << optionalNumber(r.order) << ',' << optionalNumber(r.tolerance) << ','
          << (r.diverged ? "true" : "false") << '\n';
    }
}

QJsonValue finiteOrNull(double value) {
    return std::isfinite(value) ? QJsonValue(value) : QJsonValue();
}
QJsonValue optionalOrNull(const std::optional<double>& v) {
    return v ? QJsonValue(*v) : QJsonValue();
}

QJsonObject toJson(const AccuracyResult& result, const QString& sceneName, const QString& file) {
    QJsonArray records;
    for (const AccuracyRecord& r : result.records) {
        QJsonObject o{{"integrator", QString::fromStdString(r.integrator)},
                      {"dt", r.dt},
                      {"steps", static_cast<qint64>(r.steps)},
                      {"force_evals", static_cast<qint64>(r.forceEvals)},
                      {"cpu_seconds", r.cpuSeconds},
                      {"position_error", finiteOrNull(r.positionError)},
                      {"energy_drift", finiteOrNull(r.energyDrift)},
                      {"order", optionalOrNull(r.order)},
                      {"tolerance", optionalOrNull(r.tolerance)},
                      {"diverged", r.diverged},
                      {"repeats", r.repeats}};
        if (r.diverged) o.insert("divergence", QString::fromStdString(r.divergence));
        records.append(o);
    }
    QJsonObject report{
        {"scene", sceneName},
        {"file", file},
        {"duration", result.endTime},
        {"reference", QString::fromStdString(result.reference)},
        {"contacts", result.contacts},
        {"note",
         result.note.empty() ? QJsonValue() : QJsonValue(QString::fromStdString(result.note))},
        {"records", records}};
    QJsonArray warnings;
    for (const std::string& warning : result.warnings)
        warnings.append(QString::fromStdString(warning));
    report.insert("warnings", warnings);
    report.insert("end_time_moved", result.endTimeMoved);
    if (!result.error.empty())
        report.insert("reference_error", QString::fromStdString(result.error));
    return report;
}

// "1/120" when dt is the reciprocal of a whole number (the usual frame rates), else 3 digits.
QString dtLabel(double dt) {
    const double n = 1.0 / dt;
    if (n >= 2.0 && std::abs(n - std::round(n)) < 1e-6 * n)
        return QStringLiteral("1/%1").arg(static_cast<qint64>(std::llround(n)));
    return QString::number(dt, 'g', 3);
}

// "1e-4" for powers of ten, else 2 digits.
QString toleranceLabel(double tol) {
    const double exponent = std::log10(tol);
    if (std::abs(exponent - std::round(exponent)) < 1e-9)
        return QStringLiteral("1e%1").arg(static_cast<int>(std::lround(exponent)));
    return QString::number(tol, 'g', 2);
}

void writeTable(QTextStream& out, const AccuracyResult& result, const QString& sceneName) {
    out << "scene:      " << sceneName << "\n"
        << "reference:  " << QString::fromStdString(result.reference)
        << ", positions at t = " << formatNumber(result.endTime) << " s\n"
        << "timing:     CPU time of each run alone, best of up to 5 for runs under 50 ms\n";
    if (!result.note.empty()) out << "note:       " << QString::fromStdString(result.note) << "\n";
    if (result.endTimeMoved)
        out << "end time:   moved from the scene's duration to where the motion is fastest "
               "(at a turning point every method looks better than it is)\n";
    for (const std::string& warning : result.warnings)
        out << "warning:    " << QString::fromStdString(warning) << "\n";
    out << "\n"
        << QStringLiteral("%1 %2 %3 %4 %5 %6 %7 %8 %9\n")
               .arg(QStringLiteral("integrator"), -18)
               .arg(QStringLiteral("dt"), -10)
               .arg(QStringLiteral("tolerance"), -9)
               .arg(QStringLiteral("steps"), 9)
               .arg(QStringLiteral("force evals"), 11)
               .arg(QStringLiteral("cpu [s]"), 10)
               .arg(QStringLiteral("pos. error"), 11)
               .arg(QStringLiteral("max |drift|"), 11)
               .arg(QStringLiteral("order"), 6);
    for (const AccuracyRecord& r : result.records) {
        const QString error =
            r.diverged ? QStringLiteral("diverged") : QString::number(r.positionError, 'e', 3);
        out << QStringLiteral("%1 %2 %3 %4 %5 %6 %7 %8 %9\n")
                   .arg(QString::fromStdString(r.integrator), -18)
                   .arg(QString::number(r.dt, 'g', 4), -10)
                   .arg(r.tolerance ? toleranceLabel(*r.tolerance) : QStringLiteral("-"), -9)
                   .arg(r.steps, 9)
                   .arg(r.forceEvals, 11)
                   .arg(QString::number(r.cpuSeconds, 'e', 2), 10)
                   .arg(error, 11)
                   .arg(QString::number(r.energyDrift, 'e', 2), 11)
                   .arg(r.order ? QString::number(*r.order, 'f', 2) : QStringLiteral("-"), 6);
    }
}

void writeProgress(int done, int total) {
    std::fprintf(stderr, "\rphasebox-cli: accuracy: %d/%d runs", done, total);
    if (done == total) std::fputc('\n', stderr);
    std::fflush(stderr);
}

bool stderrIsTerminal() {
#if defined(__unix__) || defined(__APPLE__)
    return ::isatty(STDERR_FILENO) != 0;
#else
    return false;
#endif
}

}  // namespace

int accuracyCommand(const QStringList& args, QTextStream& out, QTextStream& err) {
    if (asksForHelp(args)) {
        out << kAccuracyUsage;
        return kSuccess;
    }
    AccuracyCliOptions o;
    if (const QString error = parseOptions(args, o); !error.isEmpty()) return fail(err, error);
    if (const QString error =
            checkOutputs(o.scene, {{"--json", o.json ? QStringLiteral("-") : QString()},
                                   {"--csv", o.csv},
                                   {"--plot", o.plot}});
        !error.isEmpty())
        return fail(err, error);
    const SceneLoadResult loaded = SceneIO::load(o.scene);
    if (!loaded.ok()) return fail(err, loaded.errorText());
    const SceneDesc& scene = *loaded.scene;
    const QString sceneName = scene.name.empty() ? o.scene : QString::fromStdString(scene.name);
    // Each dt's run is refused as `run` refuses it: a tiny --dt would otherwise run unbounded. The
    // default list is the scene's dt, which `run` takes, and smaller by at most 32.
    const double duration = o.study.duration > 0.0 ? o.study.duration : scene.simulation.duration;
    for (const double dt : o.study.dts)
        if (const QString problem = runLengthProblem(duration, dt); !problem.isEmpty())
            return fail(err, problem);

    AccuracyResult result;
    try {
        // Progress only where a person watches; scripts and pipes get clean output.
        const AccuracyProgress progress =
            stderrIsTerminal() ? AccuracyProgress(writeProgress) : AccuracyProgress();
        // Ctrl-C, SIGTERM or SIGHUP (also one that came while the scene loaded) cancels the
        // study at its next check; the finished runs are written and the exit status is 130.
        result = runAccuracyStudy(scene, o.study, progress, &interruptFlag());
    } catch (const SceneError& e) {
        QStringList lines;
        for (const SceneIssue& issue : e.issues())
            lines << QStringLiteral("%1: %2: %3")
                         .arg(o.scene, QString::fromStdString(issue.path),
                              QString::fromStdString(issue.message));
        return fail(err, lines.join(QLatin1Char('\n')));
    } catch (const std::invalid_argument& e) {
        return fail(err, QString::fromStdString(e.what()));
    }

    int status = kSuccess;
    const bool table = o.csv.isEmpty() && !o.json;
    if (!result.error.empty())
        err << "phasebox-cli: warning: " << QString::fromStdString(result.error)
            << "; position errors are nan\n";
    if (!result.note.empty() && !table)
        err << "phasebox-cli: note: " << QString::fromStdString(result.note) << "\n";
    if (!table)
        for (const std::string& warning : result.warnings)
            err << "phasebox-cli: warning: " << QString::fromStdString(warning) << "\n";
    int diverged = 0;
    for (const AccuracyRecord& r : result.records) diverged += r.diverged;
    if (diverged > 0)
        err << "phasebox-cli: note: " << diverged << " of " << result.records.size()
            << " runs diverged (position_error = inf); that is a result, the exit status stays 0\n";
    err.flush();

    if (!o.csv.isEmpty()) {
        if (OutputFile::isStandardOutput(o.csv)) {
            writeCsv(out, result);
        } else {
            OutputFile file(o.csv, QStringLiteral("the CSV file"));
            if (file.open()) {
                QTextStream s(file.device());
                writeCsv(s, result);
                s.flush();
            }
            if (!file.commit()) status = failWrite(err, file.error());
        }
    }
    if (o.json) {
        QJsonObject report = toJson(result, sceneName, o.scene);
        if (result.cancelled) report.insert("interrupted", true);
        out << QJsonDocument(report).toJson(QJsonDocument::Indented);
    }
    if (table) writeTable(out, result, sceneName);
    out.flush();

    if (!o.plot.isEmpty()) {
        std::vector<ui::WorkPrecisionPoint> points;
        for (const AccuracyRecord& r : result.records)
            points.push_back({QString::fromStdString(r.integrator), r.cpuSeconds, r.positionError,
                              r.tolerance ? toleranceLabel(*r.tolerance) : dtLabel(r.dt)});
        QString title = QStringLiteral("%1: error against CPU time, t = %2 s, reference %3")
                            .arg(sceneName, formatNumber(result.endTime),
                                 QString::fromStdString(result.reference));
        if (result.contacts) title += QStringLiteral(" (contacts: every method first-order)");
        const std::unique_ptr<QChart> chart(ui::createWorkPrecisionChart(points, title));
        QString error;
        if (!writeChart(chart.get(), o.plot, QSize(1100, 720), &error))
            status = failWrite(err, error);
    }
    if (result.cancelled) {
        err << "phasebox-cli: interrupted after " << result.records.size() << " of "
            << result.plannedRuns << " runs; the finished runs are written\n";
        err.flush();
        return status == kSuccess ? kInterrupted : status;
    }
    return status;
}

}  // namespace phasebox::cli
