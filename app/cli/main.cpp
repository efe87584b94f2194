// phasebox-cli entry point: a QCoreApplication, or a QApplication when a plot is written
// (Qt Charts draws through widgets) on the offscreen platform whatever the environment says: the
// program shows no window, and a DISPLAY that cannot be reached (or a platform plugin that is
// missing) would otherwise abort a plot command.
//
// Standard output goes through OutputFile like every file the program writes, so that a
// failed write (a full disk, /dev/full, a file-size limit) is noticed and reported (exit 3)
// instead of lost. Standard error carries only "phasebox-cli:" lines (CONTRACT.md §4): Qt's
// own messages are dropped unless PHASEBOX_QT_MESSAGES is set, and then carry the prefix too.

#include "app/cli/Cli.h"
#include "app/cli/Interrupt.h"
#include "app/io/OutputFile.h"

#include <QApplication>
#include <QCoreApplication>

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <memory>

namespace {

bool gShowQtMessages = false;

// Qt warns about things a command-line user cannot act on (XDG_RUNTIME_DIR, the offscreen
// platform's missing features); a script reading standard error must see only our lines.
void qtMessage(QtMsgType type, const QMessageLogContext&, const QString& message) {
    // Every line carries the prefix: Qt's messages may span several.
    QString text = message;
    if (type == QtFatalMsg) {
        text.replace(QLatin1Char('\n'), QStringLiteral("\nphasebox-cli: error: "));
        std::fprintf(stderr, "phasebox-cli: error: %s\n", qPrintable(text));
        std::abort();
    }
    if (!gShowQtMessages) return;
    text.replace(QLatin1Char('\n'), QStringLiteral("\nphasebox-cli: qt: "));
    std::fprintf(stderr, "phasebox-cli: qt: %s\n", qPrintable(text));
}

}  // namespace

int main(int argc, char** argv) {
    // First of all: a Ctrl-C, SIGTERM or SIGHUP while Qt starts or the scene loads is a request
    // to stop, not a silent death (CONTRACT.md §4: "from the moment the command starts").
    phasebox::cli::installInterruptHandlers();
#if defined(__unix__) || defined(__APPLE__)
    // A reader that goes away (`| head`) makes a write fail with EPIPE, reported as a failed
    // write (exit 3), instead of killing the program silently with SIGPIPE.
    std::signal(SIGPIPE, SIG_IGN);
#endif
    gShowQtMessages = !qEnvironmentVariableIsEmpty("PHASEBOX_QT_MESSAGES");
    qInstallMessageHandler(qtMessage);

    QStringList arguments;
    for (int i = 1; i < argc; ++i) arguments << QString::fromLocal8Bit(argv[i]);

    std::unique_ptr<QCoreApplication> app;
    if (phasebox::cli::needsGui(arguments)) {
        qputenv("QT_QPA_PLATFORM", "offscreen");
        app = std::make_unique<QApplication>(argc, argv);
    } else {
        app = std::make_unique<QCoreApplication>(argc, argv);
    }
    QCoreApplication::setApplicationName(QStringLiteral("phasebox-cli"));

    QTextStream err(stderr);
    phasebox::OutputFile standardOutput(QStringLiteral("-"));
    if (!standardOutput.open()) {
        phasebox::cli::failWrite(err, standardOutput.error());
        return phasebox::cli::kWriteFailed;
    }
    int status = 0;
    {
        QTextStream out(standardOutput.device());
        status = phasebox::cli::run(arguments, out, err);
        out.flush();
    }
    // Bad input stays bad input; any other outcome whose output was lost is a failed write,
    // unless a signal abandoned it (a reader that took nothing: interrupted, 130).
    if (!standardOutput.commit() && status != phasebox::cli::kBadInput) {
        if (standardOutput.interrupted()) {
            phasebox::cli::fail(err, standardOutput.error());
            status = phasebox::cli::kInterrupted;
        } else {
            status = phasebox::cli::failWrite(err, standardOutput.error());
        }
    }
    // A command that finished although a signal asked it to stop (info, scene) says so.
    if (status == phasebox::cli::kSuccess && phasebox::cli::interrupted()) {
        err << "phasebox-cli: interrupted\n";
        status = phasebox::cli::kInterrupted;
    }
    err.flush();
    return status;
}
