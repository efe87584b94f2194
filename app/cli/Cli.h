#pragma once
// phasebox-cli (CONTRACT.md §4). Exit status: 0 success, 1 the simulation diverged,
// 2 bad input (usage, unreadable or invalid scene, an output that is the scene itself),
// 3 an output could not be written, 130 interrupted (SIGINT, SIGTERM or SIGHUP).

#include <QList>
#include <QPair>
#include <QStringList>
#include <QTextStream>

namespace phasebox::cli {

enum ExitCode { kSuccess = 0, kDiverged = 1, kBadInput = 2, kWriteFailed = 3, kInterrupted = 130 };

// Runs one command line (without the program name). Output goes to out, messages to err.
int run(const QStringList& arguments, QTextStream& out, QTextStream& err);

// True when the command line asks for a plot, which needs a QApplication.
bool needsGui(const QStringList& arguments);

// Commands, one file each.
int integratorsCommand(const QStringList& args, QTextStream& out, QTextStream& err);
int infoCommand(const QStringList& args, QTextStream& out, QTextStream& err);
int runCommand(const QStringList& args, QTextStream& out, QTextStream& err);
int sceneCommand(const QStringList& args, QTextStream& out, QTextStream& err);
int accuracyCommand(const QStringList& args, QTextStream& out, QTextStream& err);
int renderCommand(const QStringList& args, QTextStream& out, QTextStream& err);

// "phasebox-cli: error: " + each line of message, on err; returns kBadInput.
int fail(QTextStream& err, const QString& message);
// The same for an output that could not be written; returns kWriteFailed.
int failWrite(QTextStream& err, const QString& message);

// The files a command will write, each with the option that names it (empty paths are not
// given; {"--json", "-"} for a report on standard output). Returns an error message (for
// kBadInput) when one is the scene being read (standard output included), a loop of symbolic
// links, or when two name the same file or both standard output ("-", /dev/stdout, the file
// `>` opened); else an empty string. Checked before anything runs.
QString checkOutputs(const QString& scene, const QList<QPair<QString, QString>>& outputs);
// One output path: refused when empty or a loop of symbolic links; else an empty string.
QString checkOutputPath(const QString& option, const QString& path);

// An output option (--csv, --plot-*) met while parsing: refused when empty or given twice.
QString noteOutputOption(const QString& option, const QString& path, QStringList& seen);

// A run longer than this is refused before it starts: at dt = 1/60 it is 190 days of simulated
// time, and a tiny --dt with a long --duration would otherwise run for years.
constexpr double kMaxRunSteps = 1e9;
// The message refusing a run of duration at dt when it takes more than kMaxRunSteps steps;
// empty when it does not. `run` and `accuracy` (each of its dt) refuse alike.
QString runLengthProblem(double duration, double dt);

}  // namespace phasebox::cli
