#pragma once
// The options of `run`, `accuracy` and `render`, read with QCommandLineParser and reported in
// phasebox-cli's own words (CONTRACT.md §4). Qt's parser finds the options and their values;
// the commands check the values in command-line order, so the first fault named is the first
// one given. Qt's own messages ("Unknown option 'x'.") are mapped to ours, which the tests and
// scripts read. QCommandLineParser also takes `--dt=0.01` and `-dt 0.01` (docs/scene-format.md).

#include <QList>
#include <QString>
#include <QStringList>

namespace phasebox::cli {

// An option a command takes: its name without dashes ("dt") and how many values follow it: 0
// (a flag), 1, or 2 (`--plot-phase ID.COORD FILE`). missingValue is the message for an option
// at the end of the line without its values; empty for "--NAME needs a value".
struct OptionSpec {
    OptionSpec(const char* optionName, int valueCount = 1, const char* whenMissing = "")
        : name(QLatin1String(optionName)),
          values(valueCount),
          missingValue(QLatin1String(whenMissing)) {}
    QString name;
    int values = 1;
    QString missingValue;
};

// One option as given: its name with the dashes ("--dt") and its values.
struct GivenOption {
    QString name;
    QStringList values;
    const QString& value() const { return values.front(); }
    bool is(const char* option) const { return name == QLatin1String(option); }
};

struct CommandLine {
    QStringList positional;      // in command-line order
    QList<GivenOption> options;  // in command-line order, repeats kept
};

// Parses the arguments of `phasebox-cli COMMAND` (without the command). Returns an error message
// (for fail()) or an empty string: `unknown option "--x"; see phasebox-cli COMMAND --help`,
// `--dt needs a value`, `--json takes no value`. `--` is refused as an unknown option, as it
// always was, rather than ending the options: no scene name starts with a dash.
QString parseCommandLine(const QString& command, const QList<OptionSpec>& specs,
                         const QStringList& arguments, CommandLine& parsed);

// The command's one positional argument, its scene, into scene. Returns an error message for
// a second one (`unexpected argument "b" (the scene is "a")`) or none (`run needs a SCENE
// file`), else an empty string.
QString takeScene(const QString& command, const CommandLine& line, QString& scene);

// `--threads N` (CONTRACT §4), taken by run, accuracy and render: the number of workers, an
// integer from 1 to kMaxThreads. Every output but the timings is the same for every N; the
// step runs on one worker in this version, so N changes nothing yet. An error message, or
// an empty string.
inline constexpr int kMaxThreads = 1024;
QString threadsProblem(const QString& value);

// Whether the arguments ask for --help or -h (anywhere: the help wins over every fault).
bool asksForHelp(const QStringList& arguments);

}  // namespace phasebox::cli
