#include "app/desktop/DesktopOptions.h"

#include "app/desktop/MainWindow.h"
#include "app/desktop/MeasureTools.h"
#include "app/desktop/presenters/AppearancePresenter.h"
#include "app/desktop/presenters/ComparePresenter.h"
#include "app/desktop/presenters/InstrumentsPresenter.h"
#include "app/document/Document.h"
#include "app/i18n/Language.h"
#include "app/io/OutputFile.h"
#include "app/sim/RunRecording.h"
#include "app/sim/SimulationController.h"
#include "physics/integrators/Integrator.h"
#include "physics/world/World.h"
#include "ui/canvas/SceneView.h"

#include <QAction>
#include <QApplication>
#include <QBuffer>
#include <QCommandLineParser>
#include <QMessageBox>
#include <QPainter>
#include <QPixmap>
#include <QTextStream>

#include <cmath>

namespace phasebox {

namespace {

// --compare-from and --compare-method: both or neither, a known method, a moment the run
// before the picture records.
bool parseCompareOptions(const QCommandLineParser& parser, DesktopOptions& options,
                         QString* error) {
    const bool from = parser.isSet(QStringLiteral("compare-from"));
    if (from != parser.isSet(QStringLiteral("compare-method"))) {
        *error = QStringLiteral("--compare-from and --compare-method go together");
        return false;
    }
    if (!from) return true;
    bool ok = false;
    options.compareFrom = parser.value(QStringLiteral("compare-from")).toDouble(&ok);
    if (!ok || !(options.compareFrom >= 0.0) || options.compareFrom >= options.runFor) {
        *error = QStringLiteral(
                     "--compare-from: expected seconds from 0 to less than --run-for, "
                     "got \"%1\"")
                     .arg(parser.value(QStringLiteral("compare-from")));
        return false;
    }
    options.compareMethod = parser.value(QStringLiteral("compare-method"));
    if (!findIntegrator(options.compareMethod.toStdString())) {
        QStringList names;
        for (const IntegratorInfo& info : integratorRegistry())
            names << QString::fromUtf8(info.name.data(), static_cast<qsizetype>(info.name.size()));
        *error = QStringLiteral("--compare-method: expected one of %1, got \"%2\"")
                     .arg(names.join(QStringLiteral(", ")), options.compareMethod);
        return false;
    }
    return true;
}

// The screenshot's comparison: back to compareFrom, on with compareMethod to where the run was.
int startComparison(MainWindow& window, const DesktopOptions& options, QString* error) {
    auto* compare = window.findChild<ComparePresenter*>();
    const RunRecording* recording = window.controller().runRecording();
    const double end = window.document().world().time();
    SimulationDesc settings = window.document().setup().simulation;
    settings.integrator = options.compareMethod.toStdString();
    if (!compare || !recording ||
        !window.controller().showFrame(recording->frameAtOrBefore(options.compareFrom)) ||
        !compare->start(settings)) {
        *error = QStringLiteral("--compare-from: the run cannot be compared from %1 s")
                     .arg(options.compareFrom);
        return 2;
    }
    return window.controller().advance(end - window.document().world().time()) ? 0 : 1;
}

}  // namespace

bool parseDesktopOptions(const QStringList& arguments, DesktopOptions& options, QString* error) {
    QCommandLineParser parser;
    parser.setApplicationDescription(
        QStringLiteral("Phasebox, a 2D physics sandbox for the classroom"));
    parser.addHelpOption();
    parser.addVersionOption();
    const QCommandLineOption screenshot(
        QStringLiteral("screenshot"),
        QStringLiteral("Save a picture of the window to FILE and exit."), QStringLiteral("FILE"));
    const QCommandLineOption runFor(
        QStringLiteral("run-for"),
        QStringLiteral("Simulate S seconds before the picture (default 0)."), QStringLiteral("S"),
        QStringLiteral("0"));
    const QCommandLineOption canvas(QStringLiteral("canvas"),
                                    QStringLiteral("Canvas backend: auto, raster or opengl."),
                                    QStringLiteral("BACKEND"), QStringLiteral("auto"));
    const QCommandLineOption presentation(
        QStringLiteral("presentation"),
        QStringLiteral("Start in presentation mode (full screen, large type)."));
    const QCommandLineOption select(
        QStringLiteral("select"),
        QStringLiteral("Select the object ID at start (the phase plot follows it)."),
        QStringLiteral("ID"));
    const QCommandLineOption probe(
        QStringLiteral("probe"),
        QStringLiteral("Graph the probe EXPR against time in the Instruments dock (repeatable; "
                       "CONTRACT §7: ID.x, system.total, distance(A,B), …)."),
        QStringLiteral("EXPR"));
    const QCommandLineOption ruler(
        QStringLiteral("ruler"),
        QStringLiteral("Put a ruler on the canvas from A to B, each an object id (the end follows "
                       "it) or a point X:Y in metres (repeatable)."),
        QStringLiteral("A,B"));
    const QCommandLineOption protractor(
        QStringLiteral("protractor"),
        QStringLiteral("Put a protractor on the canvas measuring the angle ABC: arms from the "
                       "vertex B (the middle one, as in the probe angle(A,B,C)) to A and C, each "
                       "an object id or X:Y (repeatable)."),
        QStringLiteral("A,B,C"));
    const QCommandLineOption freeBody(
        QStringLiteral("free-body"),
        QStringLiteral("Show the free-body view (of the object chosen with --select)."));
    const QCommandLineOption size(
        QStringLiteral("size"),
        QStringLiteral("Open the window W×H pixels large, e.g. 1024x700 (for --screenshot)."),
        QStringLiteral("WxH"));
    const QCommandLineOption language(
        QStringLiteral("language"),
        QStringLiteral("Show the app in LANG (%1) instead of the language chosen in View > "
                       "Language or the system's; nothing is stored.")
            .arg(i18n::languages().join(QStringLiteral(", "))),
        QStringLiteral("LANG"));
    const QCommandLineOption highContrast(
        QStringLiteral("high-contrast"),
        QStringLiteral("Use the high-contrast theme (View > High Contrast) for this run."));
    const QCommandLineOption lineScale(
        QStringLiteral("line-scale"),
        QStringLiteral("Scale the canvas's and the plots' lines by F (0.5 to 4)."),
        QStringLiteral("F"));
    const QCommandLineOption textScale(
        QStringLiteral("text-scale"),
        QStringLiteral("Scale the canvas's and the plots' text by F (0.5 to 4)."),
        QStringLiteral("F"));
    const QCommandLineOption compareFrom(
        QStringLiteral("compare-from"),
        QStringLiteral("With --screenshot: compare the run from S seconds (Compare from here)."),
        QStringLiteral("S"));
    const QCommandLineOption compareMethod(QStringLiteral("compare-method"),
                                           QStringLiteral("The method the comparison runs with."),
                                           QStringLiteral("NAME"));
    parser.addOptions({screenshot, runFor, canvas, presentation, select, probe, ruler, protractor,
                       freeBody, size, language, highContrast, lineScale, textScale, compareFrom,
                       compareMethod});
    parser.addPositionalArgument(QStringLiteral("scene"),
                                 QStringLiteral("Scene file to open (default: the demo)."));
    if (!parser.parse(arguments)) {
        *error = parser.errorText();
        return false;
    }
    if (parser.isSet(QStringLiteral("help")) || parser.isSet(QStringLiteral("version"))) {
        parser.process(arguments);  // prints and exits
    }
    bool ok = false;
    options.runFor = parser.value(runFor).toDouble(&ok);
    if (!ok || !std::isfinite(options.runFor) || options.runFor < 0.0 || options.runFor > 1e6) {
        *error = QStringLiteral("--run-for: expected a number of seconds >= 0, got \"%1\"")
                     .arg(parser.value(runFor));
        return false;
    }
    options.screenshot = parser.value(screenshot);
    options.canvas = parser.value(canvas).toLower();
    if (!QStringList{"auto", "raster", "opengl"}.contains(options.canvas)) {
        *error = QStringLiteral("--canvas: expected auto, raster or opengl, got \"%1\"")
                     .arg(options.canvas);
        return false;
    }
    options.presentation = parser.isSet(presentation);
    options.select = parser.value(select);
    options.probes = parser.values(probe);
    options.rulers = parser.values(ruler);
    options.protractors = parser.values(protractor);
    options.freeBody = parser.isSet(freeBody);
    if (parser.isSet(size)) {
        const QStringList wh = parser.value(size).toLower().split(QLatin1Char('x'));
        bool okW = false, okH = false;
        const int w = wh.size() == 2 ? wh[0].toInt(&okW) : 0;
        const int h = wh.size() == 2 ? wh[1].toInt(&okH) : 0;
        if (!okW || !okH || w < 320 || h < 240 || w > 16384 || h > 16384) {
            *error = QStringLiteral("--size: expected WxH in pixels (at least 320x240), got \"%1\"")
                         .arg(parser.value(size));
            return false;
        }
        options.size = QSize(w, h);
    }
    options.highContrast = parser.isSet(highContrast);
    for (const auto& [option, value] :
         {std::pair{&lineScale, &options.lineScale}, std::pair{&textScale, &options.textScale}}) {
        if (!parser.isSet(*option)) continue;
        bool scaleOk = false;
        *value = parser.value(*option).toDouble(&scaleOk);
        if (!scaleOk || !(*value >= 0.5 && *value <= 4.0)) {
            *error = QStringLiteral("--%1: expected a number from 0.5 to 4, got \"%2\"")
                         .arg(option->names().constFirst(), parser.value(*option));
            return false;
        }
    }
    options.language = parser.value(language).toLower();
    if (parser.isSet(language) && !i18n::languages().contains(options.language)) {
        *error = QStringLiteral("--language: expected one of %1, got \"%2\"")
                     .arg(i18n::languages().join(QStringLiteral(", ")), parser.value(language));
        return false;
    }
    const QStringList positional = parser.positionalArguments();
    if (positional.size() > 1) {
        *error = QStringLiteral("expected at most one scene file, got %1").arg(positional.size());
        return false;
    }
    options.scene = positional.isEmpty() ? QString() : positional.first();
    return parseCompareOptions(parser, options, error);
}

namespace {
// A part of the window, by its type and object name (MainWindow.h lists them).
template <typename T>
T& part(const MainWindow& window, const char* name) {
    T* found = window.findChild<T*>(QLatin1String(name));
    Q_ASSERT(found);
    return *found;
}
}  // namespace

int takeScreenshot(MainWindow& window, const DesktopOptions& options, QString* error) {
    // The picture must not replace the scene it shows (the same file under any name).
    if (!window.document().mayWriteOutput(options.screenshot, error)) return 2;
    window.show();
    QApplication::processEvents();
    int status = 0;
    if (options.runFor > 0.0 && !window.controller().advance(options.runFor)) status = 1;
    if (status == 0 && !options.compareMethod.isEmpty()) {
        status = startComparison(window, options, error);
        if (status == 2) return status;
    }
    window.refreshNow();
    QApplication::processEvents();
    if (options.presentation)  // the layout changed under the canvas
        part<ui::SceneView>(window, "canvas").fitToWorld();
    QApplication::processEvents();
    QPixmap picture = window.grab();
    // A blow-up's dialog is a window of its own: drawn over the picture where it stands, centred
    // on the window, as a user sees it.
    if (auto* box = window.findChild<QMessageBox*>(QStringLiteral("divergenceDialog"));
        box && box->isVisible()) {
        const QPixmap dialog = box->grab();
        QPainter painter(&picture);
        painter.drawPixmap((picture.width() - dialog.width()) / 2,
                           (picture.height() - dialog.height()) / 2, dialog);
    }
    QBuffer png;  // written by OutputFile, like every file the app writes
    png.open(QIODevice::WriteOnly);
    if (picture.isNull() || !picture.save(&png, "PNG")) {
        *error = QStringLiteral("could not draw %1").arg(options.screenshot);
        return 2;
    }
    if (!OutputFile::writeAll(options.screenshot, png.data(), error, QStringLiteral("the picture")))
        return 2;
    return status;
}

int runDesktop(QApplication& app) {
    DesktopOptions options;
    QString error;
    QTextStream err(stderr);
    if (!parseDesktopOptions(app.arguments(), options, &error)) {
        err << "phasebox: error: " << error << "\n";
        return 2;
    }
    // Refused before anything is opened: `--screenshot lesson.json lesson.json` (or a link to the
    // scene) would replace the scene with a picture.
    if (!options.screenshot.isEmpty() && !options.scene.isEmpty() &&
        !Document::mayWriteOutput(options.screenshot, options.scene, &error)) {
        err << "phasebox: error: --screenshot: " << error << "\n";
        return 2;
    }
    // Before the window: its texts are translated as they are made.
    i18n::install(i18n::resolve(options.language.isEmpty() ? MainWindow::storedLanguage()
                                                           : options.language));
    MainWindow window;
    const ui::CanvasBackend backend =
        options.canvas == QLatin1String("raster")   ? ui::CanvasBackend::Raster
        : options.canvas == QLatin1String("opengl") ? ui::CanvasBackend::OpenGL
                                                    : ui::CanvasBackend::Auto;
    part<ui::SceneView>(window, "canvas").setBackend(backend);
    if (options.size.isValid()) window.resize(options.size);
    if (options.highContrast || options.lineScale > 0.0 || options.textScale > 0.0) {
        auto& appearance = part<AppearancePresenter>(window, "appearancePresenter");
        ui::Appearance look = appearance.appearance();
        look.highContrast = look.highContrast || options.highContrast;
        if (options.lineScale > 0.0) look.lineScale = options.lineScale;
        if (options.textScale > 0.0) look.textScale = options.textScale;
        appearance.setAppearance(look);
    }
    const QString scene = options.scene.isEmpty() ? kDemoScene : options.scene;
    const bool headless = !options.screenshot.isEmpty();
    if (!window.openFile(scene, headless, &error)) {
        err << "phasebox: error: " << error << "\n";
        if (headless) return 2;
    }
    if (!options.select.isEmpty()) window.document().setSelection({options.select});
    for (const QString& probe : std::as_const(options.probes)) {
        // An unknown probe is refused with the list of known ones, as by phasebox-cli.
        if (!part<InstrumentsPresenter>(window, "instrumentsPresenter")
                 .plotProbe(probe, {}, &error)) {
            err << "phasebox: error: --probe: " << error << "\n";
            if (headless) return 2;
        }
    }
    auto& measure = part<MeasureTools>(window, "measureTools");
    for (const QString& ruler : std::as_const(options.rulers))
        if (!measure.addRuler(ruler, &error)) {
            err << "phasebox: error: " << error << "\n";
            if (headless) return 2;
        }
    for (const QString& protractor : std::as_const(options.protractors))
        if (!measure.addProtractor(protractor, &error)) {
            err << "phasebox: error: " << error << "\n";
            if (headless) return 2;
        }
    measure.setFreeBodyShown(options.freeBody);
    if (headless) {
        if (options.presentation) window.setPresentationMode(true);
        const int status = takeScreenshot(window, options, &error);
        if (status == 2) err << "phasebox: error: " << error << "\n";
        if (status == 1)
            err << "phasebox: the simulation diverged: "
                << QString::fromStdString(window.document().world().divergence()
                                              ? window.document().world().divergence()->message()
                                              : std::string())
                << "\n";
        return status;
    }
    if (options.presentation) window.setPresentationMode(true);
    window.show();
    window.offerRecovery();
    return app.exec();
}

}  // namespace phasebox
