#include "app/cli/CommandLine.h"

#include <QCommandLineParser>
#include <QHash>

#include <algorithm>

namespace phasebox::cli {

namespace {

const OptionSpec* findSpec(const QList<OptionSpec>& specs, const QString& name) {
    const auto it = std::find_if(specs.begin(), specs.end(),
                                 [&](const OptionSpec& s) { return s.name == name; });
    return it == specs.end() ? nullptr : &*it;
}

// The option's name in an argument: "--dt=0.1" and "-dt" are "dt"; empty for a positional one.
QString optionName(const QString& argument) {
    if (argument.size() < 2 || !argument.startsWith(QLatin1Char('-'))) return {};
    const qsizetype dashes = argument.startsWith(QLatin1String("--")) ? 2 : 1;
    return argument.mid(dashes).section(QLatin1Char('='), 0, 0);
}

QString needsValues(const OptionSpec& spec) {
    return spec.missingValue.isEmpty() ? QStringLiteral("--%1 needs a value").arg(spec.name)
                                       : spec.missingValue;
}

// QCommandLineParser takes one value an option; a second (the FILE of --plot-phase) is taken
// out here, in command-line order, and handed back with the first. The walk stops, with the
// message, at `--` (which Qt reads as the end of the options) and at an option without its
// values; forQt then holds the arguments up to there.
QString takeSecondValues(const QString& command, const QList<OptionSpec>& specs,
                         const QStringList& arguments, QStringList& forQt,
                         QStringList& secondValues) {
    for (qsizetype i = 0; i < arguments.size(); ++i) {
        const QString& argument = arguments[i];
        forQt << argument;
        if (argument == QLatin1String("--"))
            return QStringLiteral("unknown option \"--\"; see phasebox-cli %1 --help").arg(command);
        const OptionSpec* spec = findSpec(specs, optionName(argument));
        if (!spec || spec->values == 0) continue;
        if (!argument.contains(QLatin1Char('='))) {
            if (i + 1 >= arguments.size()) return needsValues(*spec);
            forQt << arguments[++i];
        }
        if (spec->values < 2) continue;
        if (i + 1 >= arguments.size()) return needsValues(*spec);
        secondValues << arguments[++i];
    }
    return {};
}

// Qt's message for a fault it found, in ours: the unknown option as it was spelled, an option
// without its value, a flag given a value.
QString mappedError(const QString& command, const QList<OptionSpec>& specs,
                    const QStringList& arguments, const QCommandLineParser& parser) {
    if (!parser.unknownOptionNames().isEmpty()) {
        const QString unknown = parser.unknownOptionNames().front();
        const auto spelled =
            std::find_if(arguments.begin(), arguments.end(),
                         [&](const QString& a) { return optionName(a) == unknown; });
        return QStringLiteral("unknown option \"%1\"; see phasebox-cli %2 --help")
            .arg(spelled == arguments.end() ? unknown : *spelled, command);
    }
    // "Missing value after '--dt'." or "Unexpected value after '--json'.": the option is quoted.
    const QString text = parser.errorText();
    const qsizetype open = text.indexOf(QLatin1Char('\''));
    const qsizetype close = text.lastIndexOf(QLatin1Char('\''));
    if (open >= 0 && close > open) {
        const QString name = optionName(text.mid(open + 1, close - open - 1));
        if (const OptionSpec* spec = findSpec(specs, name))
            return spec->values == 0 ? QStringLiteral("--%1 takes no value").arg(name)
                                     : needsValues(*spec);
    }
    return text;
}

}  // namespace

QString takeScene(const QString& command, const CommandLine& line, QString& scene) {
    if (line.positional.size() > 1)
        return QStringLiteral("unexpected argument \"%1\" (the scene is \"%2\")")
            .arg(line.positional[1], line.positional[0]);
    if (line.positional.isEmpty()) return QStringLiteral("%1 needs a SCENE file").arg(command);
    scene = line.positional.front();
    return {};
}

bool asksForHelp(const QStringList& arguments) {
    return arguments.contains(QStringLiteral("--help")) || arguments.contains(QStringLiteral("-h"));
}

QString parseCommandLine(const QString& command, const QList<OptionSpec>& specs,
                         const QStringList& arguments, CommandLine& parsed) {
    QStringList forQt{QStringLiteral("phasebox-cli ") + command};  // Qt skips the program name
    QStringList secondValues;
    // A fault in the values' count stops the walk; an unknown option before it is named first.
    const QString countFault = takeSecondValues(command, specs, arguments, forQt, secondValues);
    QCommandLineParser parser;
    for (const OptionSpec& spec : specs)
        parser.addOption(spec.values == 0
                             ? QCommandLineOption(spec.name)
                             : QCommandLineOption(spec.name, QString(), QStringLiteral("VALUE")));
    // -dt is --dt (Qt's default would read it as -d -t), and no option has a one-letter name.
    parser.setSingleDashWordOptionMode(QCommandLineParser::ParseAsLongOptions);
    const bool parsedWell = parser.parse(forQt);
    if (!parser.unknownOptionNames().isEmpty())
        return mappedError(command, specs, arguments, parser);
    if (!countFault.isEmpty()) return countFault;
    if (!parsedWell) return mappedError(command, specs, arguments, parser);

    // Qt lists the options found in command-line order, each repeat again; the k-th time an
    // option is named, its value is the k-th of values(name).
    QHash<QString, qsizetype> seen;
    qsizetype second = 0;
    for (const QString& name : parser.optionNames()) {
        const OptionSpec* spec = findSpec(specs, name);
        GivenOption given{QStringLiteral("--") + name, {}};
        if (spec->values > 0) given.values << parser.values(name).at(seen[name]++);
        if (spec->values > 1) given.values << secondValues.at(second++);
        parsed.options << given;
    }
    parsed.positional = parser.positionalArguments();
    return {};
}

QString threadsProblem(const QString& value) {
    bool ok = false;
    const int n = value.toInt(&ok);
    if (!ok) return QStringLiteral("--threads: must be an integer (got \"%1\")").arg(value);
    if (n < 1 || n > kMaxThreads)
        return QStringLiteral("--threads: must be >= 1 and <= %1 (got %2)").arg(kMaxThreads).arg(n);
    return {};
}

}  // namespace phasebox::cli
