#pragma once
// The desktop app's command line (CONTRACT.md §5) and its screenshot mode, apart from main()
// so that tests can drive them.

#include <QSize>
#include <QString>
#include <QStringList>

class QApplication;

namespace phasebox {

class MainWindow;

struct DesktopOptions {
    QString scene;        // empty: the built-in demo
    QString screenshot;   // non-empty: save a picture of the window and exit
    double runFor = 0.0;  // simulated seconds before the picture
    QString canvas;       // "auto", "raster" or "opengl"
    bool presentation = false;
    QString select;             // an object to select at start (its phase space is plotted)
    QStringList probes;         // probes to graph at start, one graph each (the Instruments dock)
    QStringList rulers;         // "A,B": a ruler between two objects or X:Y points
    QStringList protractors;    // "A,B,C": a protractor with its vertex at B
    bool freeBody = false;      // the free-body view on (of the --select object)
    QSize size;                 // valid: the window's size in pixels (--size WxH)
    bool highContrast = false;  // --high-contrast
    double lineScale = 0.0;     // --line-scale; 0 = the stored one
    double textScale = 0.0;     // --text-scale; 0 = the stored one
    QString language;  // --language: en, de, es, fr; empty = the stored choice or the system's
    // --compare-from S --compare-method NAME (with --screenshot and a longer --run-for): the run
    // is recorded for runFor seconds, then compared from S with NAME up to runFor again.
    double compareFrom = -1.0;
    QString compareMethod;
};

inline const QString kDemoScene = QStringLiteral(":/scenes/demo.phasebox.json");

// Parses the arguments; on a usage error returns false with the message in *error.
bool parseDesktopOptions(const QStringList& arguments, DesktopOptions& options, QString* error);

// Simulates options.runFor seconds in the window, refreshes every view and saves a picture of
// the whole window. Returns 0, 1 when the simulation diverged (the picture is still written,
// showing the restored state and the message), 2 when the picture cannot be written.
int takeScreenshot(MainWindow& window, const DesktopOptions& options, QString* error);

// The whole app: parse, open the window (or take the screenshot), run the event loop.
int runDesktop(QApplication& app);

}  // namespace phasebox
