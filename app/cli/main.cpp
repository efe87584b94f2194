// phasebox-cli entry point: a QCoreApplication, or a QApplication when a plot is written
// (Qt Charts draws through widgets). With no display the offscreen platform is used, so plots
// work on a headless machine.

#include "app/cli/Cli.h"

#include <QApplication>
#include <QCoreApplication>

#include <cstdio>
#include <memory>

int main(int argc, char** argv) {
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

    QTextStream out(stdout);
    QTextStream err(stderr);
    const int status = phasebox::cli::run(arguments, out, err);
    out.flush();
    err.flush();
    return status;
}
