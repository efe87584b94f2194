#pragma once
// Runs the real phasebox-cli binary (PHASEBOX_CLI, set by tests/CMakeLists.txt) for the cli
// suites: its exit status, standard output and error, and how long it took.

#include <QByteArray>
#include <QFile>
#include <QProcess>
#include <QStringList>
#include <QTemporaryDir>

#include <chrono>
#include <vector>

#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

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

// The same, for a run whose cost is measured: the child's own peak resident memory (from
// wait4's rusage, so only the CLI and not the test is counted). Standard output and error go
// to files in dir, read back afterwards.
struct MeasuredResult : CliResult {
    long long maxRssKb = -1;
    // The child's CPU time (user + system, all its threads): its cost, whatever else the
    // machine runs (CI runs two suites at once, which doubled the wall time of a 19 s run).
    double cpuSeconds = 0.0;
};

inline MeasuredResult runCliMeasured(const QStringList& args, const QString& dir,
                                     int timeoutMs = 120000) {
    MeasuredResult r;
    const QByteArray program = QByteArrayLiteral(PHASEBOX_CLI);
    std::vector<QByteArray> argv8{program};
    for (const QString& a : args) argv8.push_back(a.toLocal8Bit());
    std::vector<char*> argv;
    for (QByteArray& a : argv8) argv.push_back(a.data());
    argv.push_back(nullptr);
    const QByteArray outPath = (dir + QStringLiteral("/measured.out")).toLocal8Bit();
    const QByteArray errPath = (dir + QStringLiteral("/measured.err")).toLocal8Bit();
    const auto start = std::chrono::steady_clock::now();
    const pid_t pid = ::fork();
    if (pid == 0) {
        const int out = ::open(outPath.constData(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        const int err = ::open(errPath.constData(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        ::dup2(out, 1);
        ::dup2(err, 2);
        ::execv(argv[0], argv.data());
        ::_exit(127);
    }
    int status = 0;
    rusage usage{};
    for (;;) {
        const pid_t done = ::wait4(pid, &status, WNOHANG, &usage);
        if (done == pid) break;
        if (std::chrono::steady_clock::now() - start > std::chrono::milliseconds(timeoutMs)) {
            ::kill(pid, SIGKILL);
            ::wait4(pid, &status, 0, &usage);
            return r;
        }
        ::usleep(10000);
    }
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    r.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.maxRssKb = usage.ru_maxrss;
    const auto toSeconds = [](const timeval& t) { return double(t.tv_sec) + 1e-6 * t.tv_usec; };
    r.cpuSeconds = toSeconds(usage.ru_utime) + toSeconds(usage.ru_stime);
    QFile out(QString::fromLocal8Bit(outPath)), err(QString::fromLocal8Bit(errPath));
    if (out.open(QIODevice::ReadOnly)) r.out = out.readAll();
    if (err.open(QIODevice::ReadOnly)) r.err = err.readAll();
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
