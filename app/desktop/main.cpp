// phasebox: the desktop app (CONTRACT.md §5).
//
//   phasebox [SCENE]
//   phasebox --screenshot FILE.png [--run-for S] [SCENE]
//   phasebox --canvas raster|opengl|auto   --presentation
//   phasebox --ruler A,B  --protractor V,A,B  --free-body --select ID

#include "app/desktop/DesktopOptions.h"
#include "app/desktop/MainWindow.h"

#include <QApplication>
#include <QTextStream>

int main(int argc, char** argv) {
    QApplication app(argc, argv);
    QApplication::setApplicationName(QStringLiteral("Phasebox"));
    QApplication::setOrganizationName(QStringLiteral("Phasebox"));
    QApplication::setApplicationVersion(QStringLiteral(PHASEBOX_VERSION));
    return phasebox::runDesktop(app);
}
