// phasebox-cli entry point: a QCoreApplication, or a QApplication when a plot is written
// (Qt Charts draws through widgets). With no display the offscreen platform is used, so plots
// work on a headless machine.
//
// Standard output goes through OutputFile like every file the program writes, so that a
// failed write (a full disk, /dev/full, a file-size limit) is noticed and reported (exit 3)
// instead of lost. Standard error carries only "phasebox-cli:" lines (CONTRACT.md §4): Qt's
// own messages are dropped unless PHASEBOX_QT_MESSAGES is set, and then carry the prefix too.

#include "app/cli/Cli.h"
#include "app/io/OutputFile.h"

#include <QApplication>
#include <QCoreApplication>

#include <cstdio>
#include <cstdlib>
#include <memory>

namespace {

bool gShowQtMessages = false;

// Qt warns about things a command-line user cannot act on (XDG_RUNTIME_DIR, the offscreen
// platform's missing features); a script reading standard error must see only our lines.
void qtMessage(QtMsgType type, const QMessageLogContext&, const QString& message) {
    if (type == QtFatalMsg) {
        std::fprintf(stderr, "phasebox-cli: error: %s\n", qPrintable(message));
        std::abort();
    }
    if (!gShowQtMessages) return;
    std::fprintf(stderr, "phasebox-cli: qt: %s\n", qPrintable(message));
}

}  // namespace

int main(int argc, char** argv) {
    gShowQtMessages = !qEnvironmentVariableIsEmpty("PHASEBOX_QT_MESSAGES");
    qInstallMessageHandler(qtMessage);

    QStringList arguments;
    for (int i = 1; i < argc; ++i) arguments << QString::fromLocal8Bit(argv[i]);

    std::unique_ptr<QCoreApplication> app;
    if (phasebox::cli::needsGui(arguments)) {
        if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM") &&
            qEnvironmentVariableIsEmpty("DISPLAY") &&
            qEnvironmentVariableIsEmpty("WAYLAND_DISPLAY"))
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
    // Bad input stays bad input; any other outcome whose output was lost is a failed write.
    if (!standardOutput.commit() && status != phasebox::cli::kBadInput)
        status = phasebox::cli::failWrite(err, standardOutput.error());
    err.flush();
    return status;
}
