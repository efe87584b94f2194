// phasebox: the desktop app (CONTRACT.md §5).
//
//   phasebox [SCENE]
//   phasebox --screenshot FILE.png [--run-for S] [SCENE]
//   phasebox --canvas raster|opengl|auto   --presentation
//   phasebox --ruler A,B  --protractor A,B,C  --free-body --select ID

#include "app/desktop/DesktopOptions.h"
#include "app/desktop/MainWindow.h"

#include <QApplication>
#include <QCoreApplication>
#include <QTextStream>

#include <string_view>

namespace {
void nameApplication() {
    QCoreApplication::setApplicationName(QStringLiteral("Phasebox"));
    QCoreApplication::setOrganizationName(QStringLiteral("Phasebox"));
    QCoreApplication::setApplicationVersion(QStringLiteral(PHASEBOX_VERSION));
}

// --help and --version need no display: they are answered before QApplication, which aborts
// where no window system is reachable (a terminal over ssh, a CI job).
bool asksForHelpOrVersion(int argc, char** argv) {
    for (int i = 1; i < argc; ++i) {
        const std::string_view a = argv[i];
        if (a == "--") break;
        if (a == "--help" || a == "-h" || a == "-?" || a == "--help-all" || a == "--version" ||
            a == "-v")
            return true;
    }
    return false;
}
}  // namespace

int main(int argc, char** argv) {
    if (asksForHelpOrVersion(argc, argv)) {
        QCoreApplication app(argc, argv);
        nameApplication();
        phasebox::DesktopOptions options;
        QString error;
        // Prints the help or the version and exits; returns only on an error before them.
        if (!phasebox::parseDesktopOptions(app.arguments(), options, &error)) {
            QTextStream(stderr) << "phasebox: error: " << error << "\n";
            return 2;
        }
        return 0;
    }
    QApplication app(argc, argv);
    nameApplication();
    return phasebox::runDesktop(app);
}
