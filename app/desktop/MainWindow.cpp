#include "app/desktop/MainWindow.h"

#include "app/desktop/AccuracyDialog.h"
#include "app/desktop/CanvasTools.h"
#include "app/document/Autosave.h"
#include "app/document/PropertyTable.h"
#include "app/io/SceneIO.h"
#include "physics/core/World.h"
#include "physics/diagnostics/StabilityAdvisor.h"
#include "physics/integrators/Integrator.h"
#include "ui/canvas/SceneView.h"
#include "ui/panels/EffectsPanel.h"
#include "ui/panels/ParametersPanel.h"
#include "ui/panels/PropertiesPanel.h"
#include "ui/panels/SceneBrowser.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QDir>
#include <QDockWidget>
#include <QLocale>
#include <QFileInfo>
#include <QLabel>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QTextBrowser>
#include <QStatusBar>
#include <QTimer>
#include <QToolBar>
#include <QUndoStack>

#include <algorithm>
#include <cmath>

namespace phasebox {

namespace {
// Plots are rebuilt at most this often while running: a chart of a few thousand points costs a
// few milliseconds, which every frame would take from the simulation.
constexpr qint64 kPlotIntervalMs = 250;

QString formatSeconds(double seconds) { return QString::number(seconds, 'g', 4) + QStringLiteral(" s"); }
}  // namespace

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent), controller_(document_) {
    setObjectName(QStringLiteral("MainWindow"));
    setAcceptDrops(true);
    controller_.setRecorder(&recorder_);

    canvas_ = new ui::SceneView(this);
    canvas_->setObjectName(QStringLiteral("canvas"));
    setCentralWidget(canvas_);
    tools_ = new CanvasTools(document_, *canvas_, this);

    createActions();
    createDocks();
    createMenus();
    createToolBar();

    statusTime_ = new QLabel(this);
    statusSpeed_ = new QLabel(this);
    statusCost_ = new QLabel(this);
    statusMessage_ = new QLabel(this);
    statusMessage_->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    statusBar()->addWidget(statusMessage_, 1);
    statusError_ = new QLabel(this);
    statusError_->setToolTip(tr("Step doubling at the current state: the error one step of this "
                                "method makes now. Raise dt and watch it grow."));
    for (QLabel* label : {statusError_, statusTime_, statusSpeed_, statusCost_})
        statusBar()->addPermanentWidget(label);
    connect(tools_, &CanvasTools::message, statusMessage_, &QLabel::setText);
    connect(tools_, &CanvasTools::toolChanged, this, [this](CanvasTools::Tool tool) {
        const QList<QAction*> actions = toolGroup_->actions();
        actions[static_cast<int>(tool)]->setChecked(true);
    });

    connectDocument();
    readSettings();
    autosave_ = std::make_unique<Autosave>(document_);
    connect(autosave_.get(), &Autosave::autosaveFailed, this, [this](const QString& message) {
        statusMessage_->setText(tr("Autosave failed: %1").arg(message));
    });
    sincePlots_.start();
    document_.newScene();
}

MainWindow::~MainWindow() = default;

void MainWindow::offerRecovery() {
    const auto recovery = Autosave::findRecovery(autosave_->recoveryDir());
    if (!recovery) return;
    const QString from = recovery->originalPath.isEmpty() ? tr("an unsaved scene")
                                                          : QDir::toNativeSeparators(recovery->originalPath);
    const auto answer = QMessageBox::question(
        this, tr("Recover the last scene?"),
        tr("Phasebox did not close properly last time. An autosave of %1 from %2 is available. "
           "Open it?")
            .arg(from, QLocale().toString(recovery->savedAt.toLocalTime(), QLocale::ShortFormat)),
        QMessageBox::Open | QMessageBox::Discard, QMessageBox::Open);
    if (answer == QMessageBox::Open) {
        const SceneLoadResult loaded = SceneIO::load(recovery->recoveryFile);
        QString error;
        if (loaded.ok() && document_.loadFromDesc(*loaded.scene, recovery->originalPath, &error)) {
            statusMessage_->setText(tr("Recovered from the autosave: save it to keep it."));
            return;
        }
        QMessageBox::warning(this, tr("Could not recover"),
                             loaded.ok() ? error : loaded.errorText());
        return;  // the recovery file stays for another try
    }
    Autosave::removeRecovery(autosave_->recoveryDir());
}

QAction* MainWindow::action(const QString& name) const {
    return findChild<QAction*>(name, Qt::FindDirectChildrenOnly);
}

// ---- actions, menus, docks --------------------------------------------------------------------

void MainWindow::createActions() {
    auto make = [this](const QString& name, const QString& text, const QKeySequence& shortcut,
                       auto slot) {
        auto* a = new QAction(text, this);
        a->setObjectName(name);
        if (!shortcut.isEmpty()) a->setShortcut(shortcut);
        connect(a, &QAction::triggered, this, slot);
        addAction(a);  // shortcuts work even with the menu bar hidden (presentation mode)
        return a;
    };
    make("new", tr("&New"), QKeySequence::New, [this] { newScene(); });
    make("open", tr("&Open…"), QKeySequence::Open, [this] { open(); });
    make("save", tr("&Save"), QKeySequence::Save, [this] { save(); });
    make("saveAs", tr("Save &As…"), QKeySequence::SaveAs, [this] { saveAs(); });
    make("exportCanvas", tr("Export &Canvas as PNG…"), QKeySequence(), [this] { exportCanvasInteractively(); });
    make("quit", tr("&Quit"), QKeySequence::Quit, [this] { close(); });

    QAction* undo = document_.undoStack()->createUndoAction(this, tr("&Undo"));
    undo->setObjectName(QStringLiteral("undo"));
    undo->setShortcut(QKeySequence::Undo);
    addAction(undo);
    QAction* redo = document_.undoStack()->createRedoAction(this, tr("&Redo"));
    redo->setObjectName(QStringLiteral("redo"));
    redo->setShortcut(QKeySequence::Redo);
    addAction(redo);
    make("delete", tr("&Delete"), QKeySequence::Delete, [this] {
        QString error;
        if (!document_.deleteObjects(document_.selection(), &error) && !error.isEmpty())
            statusMessage_->setText(error);
    });

    QAction* play = make("play", tr("&Play"), QKeySequence(Qt::Key_Space), [this] { controller_.togglePlay(); });
    play->setCheckable(true);
    play->setToolTip(tr("Play or pause the simulation (Space)"));
    make("step", tr("S&tep"), QKeySequence(Qt::Key_S), [this] { controller_.singleStep(); })
        ->setToolTip(tr("Advance one step (S)"));
    make("reset", tr("&Reset"), QKeySequence(Qt::CTRL | Qt::Key_R), [this] {
        controller_.reset();
        recorder_.clear();
    })->setToolTip(tr("Back to the setup (Ctrl+R)"));
    make("nextIntegrator", tr("Next Integrator"), QKeySequence(Qt::Key_BracketRight), [this] { cycleIntegrator(1); });
    make("previousIntegrator", tr("Previous Integrator"), QKeySequence(Qt::Key_BracketLeft),
         [this] { cycleIntegrator(-1); });
    make("doubleDt", tr("Double dt"), QKeySequence(Qt::Key_Period), [this] { scaleDt(2.0); });
    make("halveDt", tr("Halve dt"), QKeySequence(Qt::Key_Comma), [this] { scaleDt(0.5); });
    make("moreSubsteps", tr("More Sub-steps"), QKeySequence(Qt::ALT | Qt::Key_Up), [this] { changeSubsteps(1); });
    make("fewerSubsteps", tr("Fewer Sub-steps"), QKeySequence(Qt::ALT | Qt::Key_Down), [this] { changeSubsteps(-1); });
    make("faster", tr("Faster"), QKeySequence(Qt::CTRL | Qt::Key_Up), [this] { changeSpeed(1); });
    make("slower", tr("Slower"), QKeySequence(Qt::CTRL | Qt::Key_Down), [this] { changeSpeed(-1); });

    make("fit", tr("&Fit Scene"), QKeySequence(Qt::Key_F), [this] { canvas_->fitToWorld(); });
    make("accuracyLab", tr("&Accuracy Lab…"), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_A),
         [this] { showAccuracyLab(); })
        ->setToolTip(tr("Error against CPU time for every integrator, on this scene"));
    QAction* presentation = make("presentation", tr("&Presentation Mode"), QKeySequence(Qt::Key_F11),
                                 [this](bool on) { setPresentationMode(on); });
    presentation->setCheckable(true);
    auto option = [this, &make](const QString& name, const QString& text, const QKeySequence& key,
                                bool ui::RenderOptions::*member) {
        QAction* a = make(name, text, key, [this, member](bool on) {
            ui::RenderOptions options = canvas_->renderOptions();
            options.*member = on;
            canvas_->setRenderOptions(options);
            if (member == &ui::RenderOptions::trails) canvas_->trails().clear();
        });
        a->setCheckable(true);
        a->setChecked(canvas_->renderOptions().*member);
    };
    option("trails", tr("&Trails"), QKeySequence(Qt::Key_T), &ui::RenderOptions::trails);
    option("velocityArrows", tr("&Velocity Arrows"), QKeySequence(Qt::Key_V), &ui::RenderOptions::velocityArrows);
    option("labels", tr("Object &Labels"), QKeySequence(Qt::Key_L), &ui::RenderOptions::labels);
    option("grid", tr("Metre &Grid"), QKeySequence(Qt::Key_G), &ui::RenderOptions::grid);
    QAction* estimate = make("errorEstimate", tr("Live &Error Estimate"), QKeySequence(Qt::Key_E),
                             [this](bool on) { controller_.setEstimateErrors(on); updatePlots(); });
    estimate->setCheckable(true);
    estimate->setChecked(true);

    toolGroup_ = new QActionGroup(this);
    const struct {
        CanvasTools::Tool tool;
        const char* name;
        Qt::Key key;
    } tools[] = {{CanvasTools::Tool::Select, "toolSelect", Qt::Key_1},
                 {CanvasTools::Tool::Particle, "toolParticle", Qt::Key_2},
                 {CanvasTools::Tool::Spring, "toolSpring", Qt::Key_3},
                 {CanvasTools::Tool::Cloth, "toolCloth", Qt::Key_4},
                 {CanvasTools::Tool::Box, "toolBox", Qt::Key_5},
                 {CanvasTools::Tool::Plane, "toolPlane", Qt::Key_6},
                 {CanvasTools::Tool::Pin, "toolPin", Qt::Key_7}};
    for (const auto& t : tools) {
        QAction* a = make(QString::fromLatin1(t.name), CanvasTools::toolName(t.tool), QKeySequence(t.key),
                          [this, tool = t.tool] { tools_->setTool(tool); });
        a->setCheckable(true);
        a->setToolTip(CanvasTools::toolName(t.tool) + QStringLiteral(" (") +
                      QKeySequence(t.key).toString() + QStringLiteral("): ") + CanvasTools::toolHelp(t.tool));
        a->setChecked(t.tool == CanvasTools::Tool::Select);
        toolGroup_->addAction(a);
    }
}

void MainWindow::createMenus() {
    QMenu* file = menuBar()->addMenu(tr("&File"));
    file->addAction(action("new"));
    file->addAction(action("open"));
    recentMenu_ = file->addMenu(tr("Open &Recent"));
    examplesMenu_ = file->addMenu(tr("&Examples"));
    examplesMenu_->setObjectName(QStringLiteral("examplesMenu"));
    lessonsMenu_ = file->addMenu(tr("&Lessons"));
    lessonsMenu_->setObjectName(QStringLiteral("lessonsMenu"));
    for (const auto& [menu, folder] : {std::pair{examplesMenu_, QStringLiteral(":/scenes")},
                                       std::pair{lessonsMenu_, QStringLiteral(":/lessons")}}) {
        for (const QString& path : builtInScenes(folder)) {
            const SceneLoadResult loaded = SceneIO::load(path);
            const QString title = loaded.ok() && !loaded.scene->name.empty()
                                      ? QString::fromStdString(loaded.scene->name)
                                      : QFileInfo(path).completeBaseName();
            QAction* a = menu->addAction(title, this, [this, path = path] { openExample(path); });
            if (loaded.ok()) a->setToolTip(QString::fromStdString(loaded.scene->description));
            a->setData(path);
        }
        menu->setToolTipsVisible(true);
        menu->setEnabled(!menu->isEmpty());
    }
    file->addSeparator();
    file->addAction(action("save"));
    file->addAction(action("saveAs"));
    QMenu* exports = file->addMenu(tr("&Export"));
    exports->addAction(action("exportCanvas"));
    for (const auto& [plot, name] : {std::pair{ui::PlotsPanel::Plot::Energy, tr("Energy Plot")},
                                     std::pair{ui::PlotsPanel::Plot::Phase, tr("Phase Plot")},
                                     std::pair{ui::PlotsPanel::Plot::Error, tr("Error Plot")}})
        for (const QString& format : {QStringLiteral("png"), QStringLiteral("svg"), QStringLiteral("csv")})
            exports->addAction(tr("%1 as %2…").arg(name, format.toUpper()), this,
                               [this, plot = plot, format] { exportPlotInteractively(plot, format); });
    file->addSeparator();
    file->addAction(action("quit"));

    QMenu* edit = menuBar()->addMenu(tr("&Edit"));
    edit->addAction(action("undo"));
    edit->addAction(action("redo"));
    edit->addSeparator();
    edit->addAction(action("delete"));

    QMenu* simulation = menuBar()->addMenu(tr("&Simulation"));
    for (const char* name : {"play", "step", "reset"}) simulation->addAction(action(name));
    simulation->addSeparator();
    for (const char* name : {"nextIntegrator", "previousIntegrator", "doubleDt", "halveDt",
                             "moreSubsteps", "fewerSubsteps", "faster", "slower"})
        simulation->addAction(action(name));

    QMenu* tools = menuBar()->addMenu(tr("&Tools"));
    tools->addActions(toolGroup_->actions());
    tools->addSeparator();
    tools->addAction(action("accuracyLab"));

    viewMenu_ = menuBar()->addMenu(tr("&View"));
    for (QDockWidget* dock : docks_) viewMenu_->addAction(dock->toggleViewAction());
    viewMenu_->addSeparator();
    for (const char* name : {"fit", "trails", "velocityArrows", "labels", "grid", "errorEstimate", "presentation"})
        viewMenu_->addAction(action(name));

    QMenu* help = menuBar()->addMenu(tr("&Help"));
    help->addAction(tr("&About Phasebox"), this, [this] {
        QMessageBox::about(this, tr("About Phasebox"),
                           tr("<b>Phasebox %1</b><p>A 2D physics sandbox for the classroom: drop "
                              "particles, springs, cloth and boxes into a scene, switch the "
                              "integrator while it runs, and watch what accuracy costs.</p>")
                               .arg(QStringLiteral(PHASEBOX_VERSION)));
    });
}

void MainWindow::createToolBar() {
    QToolBar* bar = addToolBar(tr("Main"));
    bar->setObjectName(QStringLiteral("mainToolBar"));
    for (const char* name : {"new", "open", "save"}) bar->addAction(action(name));
    bar->addSeparator();
    for (const char* name : {"play", "step", "reset"}) bar->addAction(action(name));
    bar->addSeparator();
    bar->addActions(toolGroup_->actions());
}

void MainWindow::createDocks() {
    auto dock = [this](QWidget* widget, const QString& title, const QString& name, Qt::DockWidgetArea area) {
        auto* d = new QDockWidget(title, this);
        d->setObjectName(name);
        d->setWidget(widget);
        addDockWidget(area, d);
        docks_.append(d);
        return d;
    };
    parameters_ = new ui::ParametersPanel(this);
    parameters_->setActions(action("play"), action("step"), action("reset"));
    effects_ = new ui::EffectsPanel(this);
    properties_ = new ui::PropertiesPanel(this);
    browser_ = new ui::SceneBrowser(this);
    plots_ = new ui::PlotsPanel(this);
    QDockWidget* p = dock(parameters_, tr("Parameters"), "parametersDock", Qt::LeftDockWidgetArea);
    QDockWidget* e = dock(effects_, tr("Effects"), "effectsDock", Qt::LeftDockWidgetArea);
    dock(browser_, tr("Scene"), "sceneDock", Qt::LeftDockWidgetArea);
    notes_ = new QTextBrowser(this);
    notes_->setObjectName(QStringLiteral("notes"));
    notes_->setOpenExternalLinks(true);
    QDockWidget* pr = dock(properties_, tr("Properties"), "propertiesDock", Qt::RightDockWidgetArea);
    QDockWidget* pl = dock(plots_, tr("Plots"), "plotsDock", Qt::RightDockWidgetArea);
    tabifyDockWidget(e, findChild<QDockWidget*>(QStringLiteral("sceneDock")));
    e->raise();
    splitDockWidget(pr, pl, Qt::Vertical);
    QDockWidget* notes = dock(notes_, tr("Notes"), "notesDock", Qt::RightDockWidgetArea);
    tabifyDockWidget(pr, notes);
    notes->raise();
    resizeDocks({pr, pl}, {220, 600}, Qt::Vertical);
    resizeDocks({p}, {280}, Qt::Horizontal);
    resizeDocks({pl}, {420}, Qt::Horizontal);

    connect(parameters_, &ui::ParametersPanel::integratorChanged, this, [this](const QString& name) {
        SimulationDesc s = document_.setup().simulation;
        s.integrator = name.toStdString();
        applySimulation(s);
    });
    connect(parameters_, &ui::ParametersPanel::dtChanged, this, [this](double dt) {
        SimulationDesc s = document_.setup().simulation;
        s.dt = dt;
        applySimulation(s);
    });
    connect(parameters_, &ui::ParametersPanel::substepsChanged, this, [this](int n) {
        SimulationDesc s = document_.setup().simulation;
        s.substeps = n;
        applySimulation(s);
    });
    connect(parameters_, &ui::ParametersPanel::toleranceChanged, this, [this](double tol) {
        SimulationDesc s = document_.setup().simulation;
        s.tolerance = tol;
        applySimulation(s);
    });
    connect(parameters_, &ui::ParametersPanel::newtonIterationsChanged, this, [this](int n) {
        SimulationDesc s = document_.setup().simulation;
        s.newtonIterations = n;
        applySimulation(s);
    });
    connect(parameters_, &ui::ParametersPanel::speedChanged, &controller_, &SimulationController::setSpeed);

    connect(effects_, &ui::EffectsPanel::effectToggled, this, [this](const QString& name, bool on) {
        QString error;
        if (!document_.setEffectEnabled(name, on, &error)) {
            statusMessage_->setText(error);
            updateEffectsRows();
            return;
        }
        if (on) switchedOffEffects_.erase(name);
        else switchedOffEffects_.insert(name);
        updateEffectsRows();
    });
    connect(effects_, &ui::EffectsPanel::addEffectRequested, this, [this](const QString& name) {
        QString error;
        if (!document_.addEffect(name, &error)) statusMessage_->setText(error);
        switchedOffEffects_.erase(name);
        updateEffectsRows();
    });

    connect(properties_, &ui::PropertiesPanel::propertyEdited, this, [this](const QString& key, double value) {
        QString error;
        const bool ok = key == QLatin1String("pinned") || key == QLatin1String("static")
                            ? document_.setPinned(propertiesObject_, value != 0.0, &error)
                            : document_.setProperty(propertiesObject_, key, value, &error);
        if (ok) properties_->clearError();
        else properties_->showError(error);
        document_.finishInteraction();
    });

    connect(browser_, &ui::SceneBrowser::selectionChanged, &document_, &Document::setSelection);
    connect(browser_, &ui::SceneBrowser::deleteRequested, action("delete"), &QAction::trigger);

    connect(plots_, &ui::PlotsPanel::clearRequested, &recorder_, &Recorder::clear);
    connect(plots_, &ui::PlotsPanel::phaseCoordinateRequested, this, [this](const QString& coordinate) {
        const QString object = recorder_.phaseObject();
        const ObjectRef ref = findObject(document_.setup(), object.toStdString());
        if (object.isEmpty() || (coordinate == QLatin1String("angle") && ref.kind != ObjectKind::Box)) {
            statusMessage_->setText(object.isEmpty() ? tr("Click an object first.")
                                                     : tr("Only boxes have an angle."));
            plots_->setPhaseCoordinate(recorder_.phaseCoordinate());
            return;
        }
        recorder_.setPhaseTarget(object, coordinate);
        recorder_.record(document_.world());
        updatePlots();
    });
    connect(plots_, &ui::PlotsPanel::exportRequested, this, &MainWindow::exportPlotInteractively);
    connect(plots_, &ui::PlotsPanel::pausedChanged, this, [this](bool paused) {
        if (!paused) updatePlots();
    });
}

// ---- the document and the controller ----------------------------------------------------------

void MainWindow::connectDocument() {
    connect(&document_, &Document::sceneReset, this, &MainWindow::onSceneReplaced);
    connect(&document_, &Document::sceneEdited, this, &MainWindow::onSceneEdited);
    connect(&document_, &Document::simulationSettingsChanged, this, &MainWindow::onSimulationSettingsChanged);
    connect(&document_, &Document::selectionChanged, this, &MainWindow::onSelectionChanged);
    connect(&document_, &Document::modifiedChanged, this, &MainWindow::updateTitle);
    connect(&document_, &Document::filePathChanged, this, &MainWindow::updateTitle);
    connect(&controller_, &SimulationController::stepped, this, &MainWindow::onStepped);
    connect(&controller_, &SimulationController::statsChanged, this, &MainWindow::updateStatus);
    connect(&controller_, &SimulationController::diverged, this, &MainWindow::onDiverged);
    connect(&controller_, &SimulationController::runningChanged, this, [this](bool running) {
        QAction* play = action("play");
        play->setChecked(running);
        play->setText(running ? tr("&Pause") : tr("&Play"));
        updateStatus();
    });
}

void MainWindow::onSceneReplaced() {
    const SceneDesc& scene = document_.setup();
    notes_->setHtml(QStringLiteral("<h3>%1</h3><p>%2</p>")
                        .arg(QString::fromStdString(scene.name).toHtmlEscaped(),
                             QString::fromStdString(scene.description).toHtmlEscaped()));
    if (!scene.description.empty()) findChild<QDockWidget*>(QStringLiteral("notesDock"))->raise();
    canvas_->setWorld(&document_.world());
    canvas_->trails().clear();
    canvas_->fitToWorld();
    recorder_.clear();
    recorder_.record(document_.world());
    switchedOffEffects_.clear();
    onSceneEdited();
    onSimulationSettingsChanged();
    onSelectionChanged();
    updateTitle();
}

void MainWindow::onSceneEdited() {
    canvas_->setWorld(&document_.world());
    browser_->setScene(document_.setup());
    browser_->setSelection(document_.selection());
    updateEffectsRows();
    updateProperties(true);
    updateAdvice();
    updateCanvas();
    updateStatus();
    if (!document_.unsupportedEffects().isEmpty())
        statusMessage_->setText(tr("Not simulated yet by this version: %1")
                                    .arg(document_.unsupportedEffects().join(QStringLiteral(", "))));
}

void MainWindow::onSimulationSettingsChanged() {
    parameters_->setSimulation(document_.setup().simulation);
    updateAdvice();
    updateStatus();
}

void MainWindow::onSelectionChanged() {
    const QStringList selection = document_.selection();
    browser_->setSelection(selection);
    ui::RenderOptions options = canvas_->renderOptions();
    options.selectedIds.clear();
    for (const QString& id : selection) options.selectedIds.insert(id.toStdString());
    canvas_->setRenderOptions(options);
    updateProperties(true);
    if (properties_->hasObject()) findChild<QDockWidget*>(QStringLiteral("propertiesDock"))->raise();
    // The phase plot follows the first selected particle or box.
    const QString first = selection.isEmpty() ? QString() : selection.first();
    const ObjectRef ref = findObject(document_.setup(), first.toStdString());
    const bool isNode = first.contains(QLatin1Char('['));
    if (ref.kind == ObjectKind::Particle || ref.kind == ObjectKind::Box || isNode) {
        const QString coordinate = defaultPhaseCoordinate(first);
        recorder_.setPhaseTarget(first, coordinate);
        plots_->setPhaseCoordinate(coordinate);
        recorder_.record(document_.world());
    }
    updatePlots();
}

QString MainWindow::defaultPhaseCoordinate(const QString& id) const {
    // The coordinate that moves: the larger live velocity component, or at rest the direction
    // gravity will move it.
    const World& w = document_.world();
    const std::string name = id.toStdString();
    Vec2 v = Vec2::Zero();
    for (std::size_t i = 0; i < w.particles().size(); ++i)
        if (w.particles()[i].id == name) v = w.particleVelocity(static_cast<int>(i));
    for (std::size_t i = 0; i < w.boxes().size(); ++i)
        if (w.boxes()[i].id == name) v = w.boxVelocity(static_cast<int>(i));
    if (v.squaredNorm() == 0.0) {
        const auto& gravity = document_.setup().effects.gravity;
        if (gravity) v = Vec2(gravity->g[0], gravity->g[1]);
    }
    return std::abs(v.y()) > std::abs(v.x()) ? QStringLiteral("y") : QStringLiteral("x");
}

void MainWindow::onStepped() {
    updateCanvas();
    updateProperties(false);
    if (sincePlots_.elapsed() >= kPlotIntervalMs) updatePlots();
    updateStatus();
}

void MainWindow::onDiverged(const QString& message) {
    lastMessage_ = message;
    statusMessage_->setText(message);
    refreshNow();
    if (!QApplication::platformName().startsWith(QLatin1String("offscreen")) && isVisible())
        QMessageBox::warning(this, tr("The simulation diverged"), message);
}

void MainWindow::refreshNow() {
    updateCanvas();
    updateProperties(false);
    updatePlots();
    updateStatus();
    const World& w = document_.world();
    effects_->setCosts(w.effectCosts(), std::max<long long>(1, w.stepCount()), w.integratorSeconds());
}

void MainWindow::updateCanvas() {
    tools_->refreshGrabOverlay();
    canvas_->setHudText(tr("t = %1 s   %2, dt %3 s")
                            .arg(document_.world().time(), 0, 'f', 2)
                            .arg(QString::fromStdString(document_.setup().simulation.integrator))
                            .arg(document_.setup().simulation.dt, 0, 'g', 4));
    canvas_->update();
}

void MainWindow::updatePlots() {
    sincePlots_.restart();
    const auto& s = document_.setup().simulation;
    plots_->setEnergy(recorder_.energySamples(), recorder_.markers(),
                      tr("Energy (%1, dt %2 s)")
                          .arg(QString::fromStdString(s.integrator))
                          .arg(s.dt, 0, 'g', 4));
    plots_->setError(recorder_.errorSamples(),
                     tr("Local error per step (%1, dt %2 s)")
                         .arg(QString::fromStdString(s.integrator))
                         .arg(s.dt / s.substeps, 0, 'g', 4),
                     errorPlotNote());
    const QString object = recorder_.phaseObject();
    if (object.isEmpty()) {
        plots_->setPhase({}, {}, {}, tr("Phase space"));
    } else {
        const QString coordinate = object + QLatin1Char('.') + recorder_.phaseCoordinate();
        const QString velocity = object + QLatin1Char('.') + recorder_.phaseVelocityName();
        plots_->setPhase(recorder_.phaseSamples(), coordinate, velocity,
                         tr("Phase space of %1").arg(coordinate));
    }
}

QString MainWindow::errorPlotNote() const {
    if (!controller_.estimatesErrors()) return tr("The live error estimate is off (View menu).");
    if (controller_.msPerStep() > SimulationController::kMaxEstimateStepMs)
        return tr("No live error estimate: a step takes %1 ms, and the estimate would cost three more.")
            .arg(controller_.msPerStep(), 0, 'g', 3);
    return tr("Press Play: the error one step makes is estimated as the simulation runs.");
}

void MainWindow::updateStatus() {
    const World& w = document_.world();
    const double error = controller_.lastErrorEstimate();
    statusError_->setText(std::isfinite(error) ? tr("local error ≈ %1 m").arg(error, 0, 'g', 2) : QString());
    statusTime_->setText(tr("t = %1").arg(formatSeconds(w.time())));
    statusSpeed_->setText(controller_.isRunning()
                              ? tr("real-time factor %1 (speed %2×)")
                                    .arg(controller_.realTimeFactor(), 0, 'f', 2)
                                    .arg(controller_.speed())
                              : tr("paused (speed %1×)").arg(controller_.speed()));
    statusCost_->setText(tr("%1 ms per step").arg(controller_.msPerStep(), 0, 'g', 3));
    if (w.stepCount() > 0)
        effects_->setCosts(w.effectCosts(), std::max<long long>(1, w.stepCount()), w.integratorSeconds());
}

void MainWindow::updateEffectsRows() {
    std::vector<ui::EffectRow> rows;
    for (const QString& name : Document::effectNames()) {
        const bool on = document_.isEffectEnabled(name);
        if (on || switchedOffEffects_.count(name)) rows.push_back({name, on, true, on ? 0.0 : -1.0, {}});
    }
    const World& w = document_.world();
    if (!w.springs().empty())
        rows.push_back({QStringLiteral("springs"), true, false, 0.0, tr("Runs because the scene has springs")});
    if (w.contacts())
        rows.push_back({QStringLiteral("contacts"), true, false, 0.0,
                        tr("Runs because the scene holds things that can touch")});
    rows.push_back({ui::EffectsPanel::kIntegratorRow, true, false, 0.0,
                    tr("The integrator's own arithmetic")});
    effects_->setEffects(rows);
}

void MainWindow::updateProperties(bool rebuild) {
    const QStringList selection = document_.selection();
    QString id = selection.size() == 1 ? selection.first() : QString();
    const ObjectRef ref = findObject(document_.setup(), id.toStdString());
    if (ref.isValid()) id = QString::fromStdString(objectId(document_.setup(), ref));
    if (!ref.isValid()) {
        propertiesObject_.clear();
        properties_->clearObject();
        return;
    }
    std::vector<ui::PropertyField> fields;
    for (const PropertyRow& row : propertiesOf(document_.setup(), id))
        fields.push_back({row.key, row.label, row.unit, row.value, row.minimum, row.maximum,
                          row.decimals, row.isBool});
    if (rebuild || id != propertiesObject_) {
        propertiesObject_ = id;
        properties_->setObject(objectKindName(ref.kind) + QStringLiteral(" ") + id, fields);
    } else {
        properties_->updateValues(fields);
    }
}

void MainWindow::updateAdvice() {
    const StabilityAdvice advice = adviseStability(document_.world(), 200);
    if (advice.omegaMax <= 0.0) {
        parameters_->setAdvice({}, false);
        return;
    }
    parameters_->setAdvice(QString::fromStdString(advice.message), !advice.currentStable);
}

void MainWindow::updateTitle() {
    const QString path = document_.filePath();
    const QString name = path.isEmpty() || path.startsWith(QLatin1Char(':'))
                             ? QString::fromStdString(document_.setup().name)
                             : QFileInfo(path).fileName();
    setWindowTitle((name.isEmpty() ? tr("Untitled") : name) + QStringLiteral("[*] — Phasebox"));
    setWindowModified(document_.isModified());
}

// ---- keyboard control of the parameters -------------------------------------------------------

void MainWindow::applySimulation(const SimulationDesc& simulation) {
    QString error;
    if (!document_.applySimulationSettings(simulation, &error)) {
        statusMessage_->setText(error);
        parameters_->setSimulation(document_.setup().simulation);
    }
    document_.finishInteraction();
}

void MainWindow::cycleIntegrator(int direction) {
    const auto& registry = integratorRegistry();
    const std::string current = document_.setup().simulation.integrator;
    auto it = std::find_if(registry.begin(), registry.end(), [&](const auto& info) { return info.name == current; });
    const int n = static_cast<int>(registry.size());
    const int index = it == registry.end() ? 0 : static_cast<int>(it - registry.begin());
    SimulationDesc s = document_.setup().simulation;
    s.integrator = std::string(registry[static_cast<std::size_t>((index + direction + n) % n)].name);
    applySimulation(s);
    statusMessage_->setText(tr("Integrator: %1").arg(QString::fromStdString(s.integrator)));
}

void MainWindow::scaleDt(double factor) {
    SimulationDesc s = document_.setup().simulation;
    s.dt = std::clamp(s.dt * factor, 1e-5, 1.0);
    applySimulation(s);
    statusMessage_->setText(tr("dt = %1").arg(formatSeconds(s.dt)));
}

void MainWindow::changeSubsteps(int delta) {
    SimulationDesc s = document_.setup().simulation;
    s.substeps = std::clamp(s.substeps + delta, 1, 1000);
    applySimulation(s);
    statusMessage_->setText(tr("%1 sub-steps").arg(s.substeps));
}

void MainWindow::changeSpeed(int direction) {
    const auto& speeds = ui::ParametersPanel::speeds();
    const double current = controller_.speed();
    auto it = std::min_element(speeds.begin(), speeds.end(), [current](double a, double b) {
        return std::abs(std::log(a / current)) < std::abs(std::log(b / current));
    });
    const int index = std::clamp(static_cast<int>(it - speeds.begin()) + direction, 0,
                                 static_cast<int>(speeds.size()) - 1);
    controller_.setSpeed(speeds[static_cast<std::size_t>(index)]);
    parameters_->setSpeed(controller_.speed());
    updateStatus();
}

AccuracyDialog* MainWindow::accuracyDialog() {
    if (!accuracy_) {
        accuracy_ = new AccuracyDialog(this);
        connect(accuracy_, &AccuracyDialog::applyRequested, this,
                [this](const QString& integrator, double dt, double tolerance) {
                    SimulationDesc s = document_.setup().simulation;
                    s.integrator = integrator.toStdString();
                    s.dt = dt;
                    s.tolerance = tolerance;
                    applySimulation(s);
                    statusMessage_->setText(tr("Applied %1 at dt %2 s").arg(integrator).arg(dt, 0, 'g', 4));
                });
    }
    return accuracy_;
}

void MainWindow::showAccuracyLab() {
    AccuracyDialog* dialog = accuracyDialog();
    if (!dialog->study().isRunning()) dialog->setScene(document_.setup());
    dialog->show();
    dialog->raise();
}

void MainWindow::setPresentationMode(bool on) {
    if (on == presentation_) return;
    presentation_ = on;
    action("presentation")->setChecked(on);
    ui::RenderOptions options = canvas_->renderOptions();
    options.lineWidthScale = on ? 2.0 : 1.0;
    options.fontScale = on ? 1.8 : 1.0;
    options.labels = on || action("labels")->isChecked();
    canvas_->setRenderOptions(options);
    plots_->setPresentation(on);
    QFont font = QApplication::font();
    font.setPointSizeF(on ? font.pointSizeF() * 1.4 : font.pointSizeF() / 1.4);
    QApplication::setFont(font);
    if (on) {
        normalState_ = saveState();
        // In front of a class the canvas and the plots are what matter; every other control
        // stays on the keyboard (Simulation menu) and comes back with the layout on exit.
        for (QDockWidget* dock : docks_)
            if (dock->objectName() != QLatin1String("plotsDock")) dock->hide();
        for (QToolBar* bar : findChildren<QToolBar*>()) bar->hide();
        showFullScreen();
    } else {
        showNormal();
        restoreState(normalState_);
    }
    // The canvas changed size with the layout: frame the scene again once it has settled.
    QTimer::singleShot(0, canvas_, [this] { canvas_->fitToWorld(); });
    updatePlots();
}

}  // namespace phasebox
