#pragma once
// One input of the command-line output fuzzer (fuzz_cli_outputs.cpp), checked end to end:
// the bytes are a phasebox-cli command line, one argument per line, run in-process through
// cli::run. Placeholders in it name output targets of every kind in a private workspace:
//   @scene @scene-link   the scene being read, and a hard link to it
//   @new.csv @new.png @new.svg @new   files that do not exist yet
//   @old.csv @old.png    existing files with known contents
//   @dir @notdir/x.csv @missing/x.csv   a folder, a path under a regular file, a missing folder
//   @full @full.png @null @null.csv     private device nodes (/dev/full and /dev/null copies)
// Shared with the replay in tests/cli/tst_fuzz_cli_corpus.cpp, so a reproducer kept in
// tests/fuzz/regressions-cli/ is checked in every CI run by the code that found it.
//
// The promises (CONTRACT.md §4, issue #20), the first one broken returned in words:
//   - the exit status is 0, 1, 2 or 3; standard error holds only "phasebox-cli: " lines;
//   - the scene file is never written (same bytes, still a regular file);
//   - a device stays a device and a folder a folder; no temporary file is left behind;
//   - an existing file is either kept whole or replaced by a complete new one, never cut;
//     after exit 2 (bad input, refused before anything runs) every file is as it was;
//   - after exit 0 every regular output named exists and a plot is a whole PNG or SVG.

#include "app/cli/Cli.h"
#include "tests/support/OutputTargets.h"

#include <QBuffer>
#include <QByteArray>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QString>
#include <QStringList>
#include <QTextStream>

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <map>

namespace phasebox::fuzz {

inline constexpr const char* kFuzzScene = R"({
  "format": "phasebox-scene", "version": 1, "name": "fuzz",
  "simulation": { "integrator": "symplectic_euler", "dt": 0.01, "duration": 0.05 },
  "effects": { "gravity": {} },
  "particles": [ { "id": "ball", "position": [1, 0] } ],
  "boxes": [ { "id": "crate", "position": [3, 0], "size": [1, 1] } ],
  "springs": [ { "a": "ball", "anchor": [0, 0], "stiffness": 4 } ]
})";
inline constexpr const char* kOldCsv = "an earlier CSV file\n";
inline constexpr const char* kOldPng = "an earlier picture";

class CliWorkspace {
public:
    explicit CliWorkspace(QString root) : root_(std::move(root)) {}

    QString path(const QString& name) const { return root_ + QLatin1Char('/') + name; }

    // Puts every target back as it was.
    bool reset() {
        QDir dir(root_);
        dir.removeRecursively();
        if (!QDir().mkpath(root_ + QStringLiteral("/dir"))) return false;
        if (!write(QStringLiteral("scene.json"), kFuzzScene) ||
            !write(QStringLiteral("old.csv"), kOldCsv) ||
            !write(QStringLiteral("old.png"), kOldPng) ||
            !write(QStringLiteral("notdir"), "a regular file"))
            return false;
        ::link(QFile::encodeName(path("scene.json")).constData(),
               QFile::encodeName(path("scene-link.json")).constData());
        // A private node where mknod is allowed, else a link to the system's device
        // (tests/support/OutputTargets.h): the device cases always run.
        for (const auto& [name, device] : kDevices)
            if (!testing::makeDevice(path(QLatin1String(name)), device)) return false;
        return true;
    }

    // An argument with its placeholder replaced. An output path that is not a placeholder is
    // put in the workspace as new.EXT (never the working folder), and numbers that would make
    // a run long are clamped: a slow but correct run is not what this fuzzer looks for.
    QString argument(const QString& raw, const QString& previous, bool isOutput) const {
        static const std::map<QString, QString> targets{{"@scene", "scene.json"},
                                                        {"@scene-link", "scene-link.json"},
                                                        {"@new.csv", "new.csv"},
                                                        {"@new.png", "new.png"},
                                                        {"@new.svg", "new.svg"},
                                                        {"@new", "new"},
                                                        {"@old.csv", "old.csv"},
                                                        {"@old.png", "old.png"},
                                                        {"@dir", "dir"},
                                                        {"@notdir/x.csv", "notdir/x.csv"},
                                                        {"@missing/x.csv", "missing/x.csv"},
                                                        {"@full", "full"},
                                                        {"@full.png", "full.png"},
                                                        {"@null", "null"},
                                                        {"@null.csv", "null.csv"}};
        if (const auto it = targets.find(raw); it != targets.end()) {
            return path(it->second);
        }
        if (isOutput && raw != QLatin1String("-")) {
            const QString suffix = QFileInfo(raw).suffix().left(8);
            return path(suffix.isEmpty() ? QStringLiteral("new")
                                         : QStringLiteral("new.") + suffix.toLower());
        }
        bool ok = false;
        const double v = raw.toDouble(&ok);
        if (ok) {
            if (previous == QLatin1String("--duration") && v > 0.2) return QStringLiteral("0.2");
            if (previous == QLatin1String("--dt") && v < 0.002) return QStringLiteral("0.002");
            if (previous == QLatin1String("--substeps") && v > 8) return QStringLiteral("8");
            if (previous.startsWith(QLatin1String("--toleranc")) && v < 1e-6)
                return QStringLiteral("1e-6");
        }
        if (previous == QLatin1String("--dt") && raw.contains(QLatin1Char(',')))
            return QStringLiteral("0.01,0.005");  // accuracy's list: kept short
        if (previous == QLatin1String("--integrators"))
            return raw.section(QLatin1Char(','), 0, 1);  // two methods at most
        return raw;
    }

    QByteArray read(const QString& name) const {
        QFile f(path(name));
        return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
    }
    bool exists(const QString& name) const { return QFileInfo::exists(path(name)); }
    // The devices reset() made, each still what it put there (not replaced by a file).
    const char* replacedDevice() const {
        for (const auto& [name, device] : kDevices)
            if (!testing::isStillDevice(path(QLatin1String(name)), device)) return name;
        return nullptr;
    }
    QStringList files() const {
        return QDir(root_).entryList(
            QDir::Files | QDir::System | QDir::Hidden | QDir::Dirs | QDir::NoDotAndDotDot,
            QDir::Name);
    }

private:
    bool write(const QString& name, const QByteArray& bytes) {
        QFile f(path(name));
        return f.open(QIODevice::WriteOnly) && f.write(bytes) == bytes.size();
    }

    static constexpr std::pair<const char*, testing::SystemDevice> kDevices[] = {
        {"full", testing::SystemDevice::Full},
        {"full.png", testing::SystemDevice::Full},
        {"null", testing::SystemDevice::Null},
        {"null.csv", testing::SystemDevice::Null}};
    QString root_;
};

// statusOut (when given) gets the exit status, for a replay to see which paths its seeds take.
inline QString checkCliOutputInput(const std::uint8_t* data, std::size_t size, CliWorkspace& ws,
                                   int* statusOut = nullptr) {
    if (!ws.reset()) return {};  // the workspace itself could not be made: not the program's fault
    const QStringList before = ws.files();
    QStringList args;
    QString previous, beforePrevious;
    QByteArray text(reinterpret_cast<const char*>(data), static_cast<qsizetype>(size));
    if (text.endsWith('\n')) text.chop(1);  // a last line break ends the last argument
    for (const QByteArray& line : text.split('\n')) {
        if (args.size() >= 24) break;
        const QString raw = QString::fromUtf8(line.left(200));
        if (args.isEmpty() && raw.isEmpty()) continue;
        const bool isOutput = previous == QLatin1String("--csv") ||
                              previous == QLatin1String("--plot-energy") ||
                              previous == QLatin1String("--plot") ||
                              beforePrevious == QLatin1String("--plot-phase") ||
                              (args.size() == 2 && args.first() == QLatin1String("scene"));
        args << ws.argument(raw, previous, isOutput);
        beforePrevious = previous;
        previous = raw;
    }
    if (args.isEmpty()) return {};
    // Each command runs for a fraction of a second: accuracy over two methods unless told.
    if (args.first() == QLatin1String("accuracy") && !args.contains(QLatin1String("--integrators")))
        args << QStringLiteral("--integrators") << QStringLiteral("rk4,symplectic_euler");

    QByteArray outBytes;
    QString errText;
    int status = -1;
    {
        QBuffer outBuffer(&outBytes);
        outBuffer.open(QIODevice::WriteOnly);
        QTextStream out(&outBuffer);
        QTextStream err(&errText);
        status = cli::run(args, out, err);
        out.flush();
        err.flush();
    }
    if (statusOut) *statusOut = status;
    const QString command = args.join(QLatin1Char(' '));
    // PHASEBOX_FUZZ_DEBUG=1 shows each command line and its outcome (to read a reproducer).
    if (qEnvironmentVariableIsSet("PHASEBOX_FUZZ_DEBUG"))
        std::fprintf(stderr, "fuzz_cli_outputs: %s -> %d\n%s", qPrintable(command), status,
                     qPrintable(errText));
    auto broken = [&](const QString& what) {
        return QStringLiteral("%1 (command: %2; status %3; stderr: %4)")
            .arg(what, command)
            .arg(status)
            .arg(errText.left(500));
    };
    if (status < 0 || status > 3) return broken(QStringLiteral("an exit status outside 0..3"));
    for (const QString& line : errText.split(QLatin1Char('\n'), Qt::SkipEmptyParts))
        if (!line.startsWith(QLatin1String("phasebox-cli: ")))
            return broken(QStringLiteral("a standard error line without the prefix: ") + line);
    if (ws.read(QStringLiteral("scene.json")) != kFuzzScene)
        return broken(QStringLiteral("the scene file was written"));
    if (const char* device = ws.replacedDevice())
        return broken(QStringLiteral("the device %1 was replaced").arg(QLatin1String(device)));
    if (!QFileInfo(ws.path(QStringLiteral("dir"))).isDir())
        return broken(QStringLiteral("the folder was replaced"));
    for (const QString& name : ws.files())
        if (!before.contains(name) && !name.startsWith(QLatin1String("new")))
            return broken(QStringLiteral("a stray file was left: ") + name);
    const QByteArray oldCsv = ws.read(QStringLiteral("old.csv"));
    const QByteArray oldPng = ws.read(QStringLiteral("old.png"));
    if (status == cli::kBadInput) {
        if (ws.files() != before) return broken(QStringLiteral("bad input, yet a file was made"));
        if (oldCsv != kOldCsv || oldPng != kOldPng)
            return broken(QStringLiteral("bad input, yet an earlier file changed"));
        return {};
    }
    // Written or not, an earlier file is whole: its old bytes, or a complete new output.
    if (oldCsv != kOldCsv && !oldCsv.endsWith('\n'))
        return broken(QStringLiteral("old.csv was cut short"));
    if (oldPng != kOldPng && !oldPng.startsWith("\x89PNG") && !oldPng.contains("</svg>"))
        return broken(QStringLiteral("old.png was cut short"));
    if (oldPng.startsWith("\x89PNG") && !oldPng.contains("IEND"))
        return broken(QStringLiteral("old.png is not a whole PNG"));
    if (status == cli::kSuccess) {
        // The last of each output option is the one that counts.
        std::map<QString, QString> outputs;
        for (qsizetype i = 0; i + 1 < args.size(); ++i) {
            const QString& option = args[i];
            if (option == QLatin1String("--csv") || option == QLatin1String("--plot-energy") ||
                option == QLatin1String("--plot"))
                outputs[option] = args[i + 1];
            if (option == QLatin1String("--plot-phase") && i + 2 < args.size())
                outputs[option] = args[i + 2];
        }
        for (const auto& [option, file] : outputs) {
            const QFileInfo info(file);
            if (file == QLatin1String("-") || !file.startsWith(ws.path(QString())) ||
                (info.exists() && !info.isFile()))
                continue;
            if (!info.exists() || info.size() == 0)
                return broken(QStringLiteral("exit 0, but %1 was not written").arg(file));
        }
    }
    return {};
}

}  // namespace phasebox::fuzz
