#pragma once
// Runs the real phasebox-cli binary (PHASEBOX_CLI, set by tests/CMakeLists.txt) for the cli
// suites: its exit status, standard output and error, and how long it took.

#include <QByteArray>
#include <QFile>
#include <QProcess>
#include <QStringList>
#include <QTemporaryDir>

#include <chrono>

namespace phasebox::testing {

struct CliResult {
    int status = -1;  // the exit code; −1 if it crashed or timed out
    QByteArray out, err;
    double seconds = 0.0;
};

// A run that has not finished after timeoutMs is killed and reported with status −1.
inline CliResult runCli(const QStringList& args, int timeoutMs = 120000) {
    QProcess p;
    const auto start = std::chrono::steady_clock::now();
    p.start(QStringLiteral(PHASEBOX_CLI), args);
    CliResult r;
    if (!p.waitForFinished(timeoutMs)) {
        p.kill();
        p.waitForFinished();
        return r;
    }
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    r.status = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1;
    r.out = p.readAllStandardOutput();
    r.err = p.readAllStandardError();
    return r;
}

// Writes text to a file called name in dir and returns its path (a scene for the command line).
inline QString writeFile(const QTemporaryDir& dir, const QString& name, const QByteArray& bytes) {
    const QString path = dir.filePath(name);
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly) || f.write(bytes) != bytes.size())
        qFatal("cannot write %s", qPrintable(path));
    return path;
}

}  // namespace phasebox::testing
