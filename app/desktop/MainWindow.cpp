#include "app/desktop/MainWindow.h"

#include "app/desktop/AccuracyLab.h"
#include "app/desktop/AnimationExport.h"
#include "app/desktop/CanvasTools.h"
#include "app/desktop/DivergenceNotice.h"
#include "app/desktop/HelpDialogs.h"
#include "app/desktop/LanguageMenu.h"
#include "app/desktop/MeasureTools.h"
#include "app/desktop/SceneFiles.h"
#include "app/desktop/SceneLibraryMenu.h"
#include "app/desktop/WindowLayout.h"
#include "app/desktop/WorkerMenu.h"
#include "app/desktop/presenters/AppearancePresenter.h"
#include "app/desktop/presenters/CanvasPresenter.h"
#include "app/desktop/presenters/ComparePresenter.h"
#include "app/desktop/presenters/EffectsPresenter.h"
#include "app/desktop/presenters/ExactPresenter.h"
#include "app/desktop/presenters/InstrumentsPresenter.h"
#include "app/desktop/presenters/NotesPresenter.h"
#include "app/desktop/presenters/ParametersPresenter.h"
#include "app/desktop/presenters/PlotsPresenter.h"
#include "app/desktop/presenters/PropertiesPresenter.h"
#include "app/desktop/presenters/SceneBrowserPresenter.h"
#include "app/desktop/presenters/StatusPresenter.h"
#include "app/desktop/presenters/TimelinePresenter.h"
#include "app/document/Autosave.h"
#include "ui/canvas/SceneView.h"
#include "ui/instruments/InstrumentsPanel.h"
#include "ui/panels/AccessibleNames.h"
#include "ui/panels/BuiltinText.h"
#include "ui/panels/DisplayText.h"
#include "ui/panels/EffectsPanel.h"
#include "ui/panels/ParametersPanel.h"
#include "ui/panels/PropertiesPanel.h"
#include "ui/panels/SceneBrowser.h"
#include "ui/panels/TimelineBar.h"

#include <QAbstractItemView>
#include <QAction>
#include <QDockWidget>
#include <QFileInfo>
#include <QMenu>
#include <QMenuBar>
#include <QScrollArea>
#include <QScrollBar>
#include <QStatusBar>
#include <QTextBrowser>
#include <QTimer>
#include <QToolBar>
#include <QUndoStack>
#include <QVBoxLayout>

#include <tuple>

namespace phasebox {

namespace {
// Names a part of the window, so that it can be found in the window's object tree.
template <typename T>
T* named(T* object, const char* name) {
    object->setObjectName(QLatin1String(name));
    return object;
}
}  // namespace

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent), controller_(document_) {
    setObjectName(QStringLiteral("MainWindow"));
    setAcceptDrops(true);
    // The recorders in the window's object tree, where the views' tests find them.
    named(&recorder_, "recorder")->setParent(this);
    named(&probes_, "probeRecorder")->setParent(this);
    controller_.setRecorder(&recorder_);
    controller_.setProbeRecorder(&probes_);
    // The canvas over its timeline.
    auto* centre = new QWidget(this);
    auto* column = new QVBoxLayout(centre);
    column->setContentsMargins(0, 0, 0, 0);
    column->setSpacing(0);
    canvas_ = new ui::SceneView(centre);
    canvas_->setObjectName(QStringLiteral("canvas"));
    column->addWidget(canvas_, 1);
    timeline_ = new ui::TimelineBar(centre);
    column->addWidget(timeline_);
    setCentralWidget(centre);
    tools_ = named(new CanvasTools(document_, *canvas_, this), "canvasTools");
    layout_ = new WindowLayout(*this, *canvas_);
    help_ = new HelpWindows(*this);

    createActions();
    createDockWindows();
    createMenus();
    createToolBar();
    connect(&document_, &Document::sceneReset, this, &MainWindow::updateTitle);
    connect(&document_, &Document::modifiedChanged, this, &MainWindow::updateTitle);
    connect(&document_, &Document::filePathChanged, this, &MainWindow::updateTitle);
    const auto revertable = [this] {
        action("revert")->setEnabled(!document_.filePath().isEmpty());
    };
    connect(&document_, &Document::modifiedChanged, this, revertable);
    connect(&document_, &Document::filePathChanged, this, revertable);
    revertable();
    divergence_ = new DivergenceNotice(*this, document_);
    connect(&controller_, &SimulationController::diverged, this,
            [this](const QString& message, const QString& details) {
                status_->showMessage(DivergenceNotice::statusLine(message));
                refreshNow();
                divergence_->show(message, details);
            });
    connectLessonInstruments();
    readSettings();
    autosave_ = std::make_unique<Autosave>(document_);
    named(autosave_.get(), "autosave")->setParent(this);  // removed from the tree when it goes
    connect(autosave_.get(), &Autosave::autosaveFailed, this, [this](const QString& message) {
        status_->showMessage(tr("Autosave failed: %1").arg(message));
    });
    document_.newScene();
    prepareForKeyboard();
}

MainWindow::~MainWindow() = default;

// Tab moves between controls everywhere: lists and tables keep the arrow keys for their rows,
// the notes their scrolling keys. The canvas is named for screen readers, and every control
// without a name gets the one its label or tooltip gives it (ui/panels/AccessibleNames.h).
void MainWindow::prepareForKeyboard() {
    for (auto* view : findChildren<QAbstractItemView*>()) view->setTabKeyNavigation(false);
    notes_->setTabChangesFocus(true);
    canvas_->setAccessibleName(tr("Scene canvas"));
    ui::nameControls(this);
}

QAction* MainWindow::action(const QString& name) const {
    return findChild<QAction*>(name, Qt::FindDirectChildrenOnly);
}

// ---- actions, menus, docks --------------------------------------------------------------------

void MainWindow::createActions() {
    auto make = [this](const char* name, const QString& text, const QKeySequence& key, auto slot) {
        QAction* a = addWindowAction(*this, name, text, key);
        connect(a, &QAction::triggered, this, slot);
        return a;
    };
    make("new", tr("&New"), QKeySequence::New, [this] { newScene(); });
    make("open", tr("&Open…"), QKeySequence::Open, [this] {
        if (maybeSave()) files_->openInteractively();
    });
    make("save", tr("&Save"), QKeySequence::Save, [this] { files_->save(); });
    animationExport_ = new AnimationExport(document_, *canvas_, recorder_, controller_, *this);
    make("exportAnimation", tr("Export &Animation…"), QKeySequence(), [this] {
        animationExport_->exportInteractively();
    })->setToolTip(tr("The run as an MP4 or animated GIF clip, optionally with the plots"));
    make("revert", tr("Re&vert"), QKeySequence(), [this] {
        revert();
    })->setToolTip(tr("Reopen the scene's file as it was last saved, dropping the edits"));
    // Ctrl+Shift+S everywhere: QKeySequence::SaveAs is empty on platforms without a desktop theme.
    make("saveAs", tr("Save &As…"), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_S),
         [this] { files_->saveAs(); });
    make("quit", tr("&Quit"), QKeySequence::Quit, [this] { close(); });
    QUndoStack* stack = document_.undoStack();
    for (const auto& [a, name, key] :
         {std::tuple{stack->createUndoAction(this, tr("&Undo")), "undo", QKeySequence::Undo},
          std::tuple{stack->createRedoAction(this, tr("&Redo")), "redo", QKeySequence::Redo}}) {
        a->setObjectName(name);
        a->setShortcut(key);
        addAction(a);
    }
    make("delete", tr("&Delete"), QKeySequence::Delete,
         [this] { browserPresenter_->deleteSelection(); });
    make("copy", tr("&Copy"), QKeySequence::Copy, [this] { browserPresenter_->copySelection(); });
    make("cut", tr("Cu&t"), QKeySequence::Cut, [this] { browserPresenter_->cutSelection(); });
    make("paste", tr("&Paste"), QKeySequence::Paste, [this] { browserPresenter_->paste(); });
    make("accuracyLab", tr("&Accuracy Lab…"), Qt::CTRL | Qt::SHIFT | Qt::Key_A, [this] {
        accuracyLab_->show();
    })->setToolTip(tr("Error against CPU time for every integrator, on this scene"));
    make("presentation", tr("&Presentation Mode"), Qt::Key_F11, [this](bool on) {
        setPresentationMode(on);
    })->setCheckable(true);
    QAction* estimate =
        make("errorEstimate", tr("Live &Error Estimate"), Qt::Key_E, [this](bool on) {
            controller_.setEstimateErrors(on);
            plotsPresenter_->refresh();
        });
    estimate->setCheckable(true);
    estimate->setChecked(true);
    // F1 where the platform has no binding for HelpContents (it has one on every desktop).
    make("userGuide", tr("&User Guide"),
         QKeySequence::keyBindings(QKeySequence::HelpContents).value(0, QKeySequence(Qt::Key_F1)),
         [this] { help_->showUserGuide(); })
        ->setToolTip(tr("How to use Phasebox: the window, building scenes, measuring, files"));
    make("keyboardShortcuts", tr("&Keyboard Shortcuts"), QKeySequence(),
         [this] { help_->showKeyboardShortcuts(); });
}

void MainWindow::createMenus() {
    QMenu* file = menuBar()->addMenu(tr("&File"));
    addWindowActions(*file, *this, {"new", "open"});
    files_ = new SceneFiles(*this, document_, controller_, *file->addMenu(tr("Open &Recent")));
    connect(files_, &SceneFiles::message, status_, &StatusPresenter::showMessage);
    connect(files_, &SceneFiles::recentFileChosen, this, &MainWindow::openIfSaved);
    for (const auto& [title, name, folder] :
         {std::tuple{tr("&Examples"), "examplesMenu", ":/scenes"},
          std::tuple{tr("&Lessons"), "lessonsMenu", ":/lessons"}}) {
        QMenu* menu = file->addMenu(title);
        menu->setObjectName(name);
        fillSceneLibraryMenu(*menu, folder, [this](const QString& path) { openIfSaved(path); });
    }
    addWindowActions(*file, *this, {"", "save", "saveAs", "revert"});
    QMenu* exports = file->addMenu(tr("&Export"));
    exports->addAction(action("exportCanvas"));
    plotsPresenter_->addExportActions(*exports);
    instrumentsPresenter_->addExportActions(*exports);
    addWindowActions(*file, *this, {"exportAnimation"});
    connect(animationExport_, &AnimationExport::message, status_, &StatusPresenter::showMessage);
    addWindowActions(*file, *this, {"", "quit"});
    addWindowActions(*menuBar()->addMenu(tr("&Edit")), *this,
                     {"undo", "redo", "", "cut", "copy", "paste", "delete"});
    QMenu* simulation = menuBar()->addMenu(tr("&Simulation"));
    addWindowActions(*simulation, *this,
                     {"play", "step", "reset", "", "frameBack", "frameForward", "jumpToStart",
                      "compareFromHere", "leaveCompare", "", "nextIntegrator", "previousIntegrator",
                      "doubleDt", "halveDt", "moreSubsteps", "fewerSubsteps", "faster", "slower"});
    simulation->addSeparator();
    workerMenu_ = new WorkerMenu(*simulation->addMenu(tr("&Worker Threads")), document_);
    connect(workerMenu_, &WorkerMenu::message, status_, &StatusPresenter::showMessage);
    QMenu* tools = menuBar()->addMenu(tr("&Tools"));
    tools->addActions(canvasPresenter_->toolActions());
    addWindowActions(*tools, *this,
                     {"", "clearMeasurements", "", "showInstruments", "stopwatch", "stopwatchLap",
                      "", "accuracyLab"});
    QMenu* view = menuBar()->addMenu(tr("&View"));
    for (QDockWidget* dock : layout_->docks()) view->addAction(dock->toggleViewAction());
    addWindowActions(*view, *this,
                     {"", "fit", "follow", "trails", "velocityArrows", "forceArrows", "freeBody",
                      "labels", "viewExact", "grid", "errorEstimate", "presentation", ""});
    appearance_->addToMenu(*view);
    auto* language = new LanguageMenu(*view->addMenu(tr("&Language")), storedLanguage(), *this);
    connect(language, &LanguageMenu::message, status_, &StatusPresenter::showMessage);
    QMenu* help = menuBar()->addMenu(tr("&Help"));
    addWindowActions(*help, *this, {"userGuide", "keyboardShortcuts", ""});
    help->addAction(tr("&About Phasebox"), help_, &HelpWindows::showAbout);
}

void MainWindow::createToolBar() {
    QToolBar* bar = addToolBar(tr("Main"));
    bar->setObjectName(QStringLiteral("mainToolBar"));
    addWindowActions(*bar, *this, {"new", "open", "save", "", "play", "step", "reset", ""});
    bar->addActions(canvasPresenter_->toolActions());
    bar->addWidget(canvasPresenter_->polygonSidesBox());
    bar->addWidget(canvasPresenter_->jointTypeBox());
}

template <typename P>
P* MainWindow::addPresenter(P* presenter) {
    presenters_.append(presenter);
    connect(presenter, &Presenter::message, status_, &StatusPresenter::showMessage);
    return presenter;
}

void MainWindow::createDockWindows() {
    parameters_ = named(new ui::ParametersPanel(this), "parametersPanel");
    effects_ = named(new ui::EffectsPanel(this), "effectsPanel");
    properties_ = named(new ui::PropertiesPanel(this), "propertiesPanel");
    browser_ = named(new ui::SceneBrowser(this), "sceneBrowser");
    plots_ = named(new ui::PlotsPanel(this), "plotsPanel");
    instruments_ = named(new ui::InstrumentsPanel(this), "instruments");
    notes_ = named(new QTextBrowser(this), "notes");
    QDockWidget* p =
        layout_->addDock(parameters_, tr("Parameters"), "parametersDock", Qt::LeftDockWidgetArea);
    QDockWidget* e =
        layout_->addDock(effects_, tr("Effects"), "effectsDock", Qt::LeftDockWidgetArea);
    // The scene's objects beside the parameters, and three tabs below: four in one row do not
    // fit the left column at 1024 x 700 in German, Spanish or French.
    tabifyDockWidget(p,
                     layout_->addDock(browser_, tr("Scene"), "sceneDock", Qt::LeftDockWidgetArea));
    p->raise();
    e->raise();
    // The properties of the selection and the lesson's notes share the left column's lower
    // half with the effects (raised when an object is chosen): the right column is the plots'
    // and instruments' whole height, which at 1024 x 700 is what keeps them legible.
    QDockWidget* pr =
        layout_->addDock(properties_, tr("Properties"), "propertiesDock", Qt::LeftDockWidgetArea);
    tabifyDockWidget(e, pr);
    QDockWidget* pl = layout_->addDock(plots_, tr("Plots"), "plotsDock", Qt::RightDockWidgetArea);
    // The instruments share the plots' place: both are things to watch while it runs.
    // The instruments' pages are laid out in short rows that fit the dock at 1024 x 700; in a
    // narrower one they scroll sideways rather than take the canvas's width. The dock is never
    // narrower than the rows at the window's first font: a small window's canvas takes its share
    // from the docks down to their minimum (WindowLayout), which a scroll area's alone is nothing.
    auto* instrumentsScroll = new QScrollArea(this);
    instrumentsScroll->setObjectName(QStringLiteral("instrumentsScroll"));
    instrumentsScroll->setWidget(instruments_);
    instrumentsScroll->setWidgetResizable(true);
    instrumentsScroll->setFrameShape(QFrame::NoFrame);
    instrumentsScroll->setMinimumWidth(instruments_->minimumSizeHint().width() +
                                       instrumentsScroll->verticalScrollBar()->sizeHint().width());
    QDockWidget* in = layout_->addDock(instrumentsScroll, tr("Instruments"), "instrumentsDock",
                                       Qt::RightDockWidgetArea);
    tabifyDockWidget(pl, in);
    pl->raise();
    QDockWidget* notes = layout_->addDock(notes_, tr("Notes"), "notesDock", Qt::LeftDockWidgetArea);
    tabifyDockWidget(pr, notes);
    notes->raise();
    // The parameters take the height of their fields; the rest is the lower tabs'.
    resizeDocks({p, e}, {parameters_->sizeHint().height() + 30, 2000}, Qt::Vertical);
    resizeDocks({p}, {280}, Qt::Horizontal);
    resizeDocks({pl}, {420}, Qt::Horizontal);
    layout_->setColumns(p, pl);

    // The status bar's first: every presenter's messages go to it.
    status_ = new StatusPresenter(*statusBar(), document_, controller_, this);
    presenters_.append(status_);
    addPresenter(canvasPresenter_ =
                     new CanvasPresenter(*canvas_, *tools_, document_, controller_, this));
    canvasPresenter_->createActions(*this);
    connect(canvasPresenter_, &CanvasPresenter::propertiesWanted, this, [this, pr] {
        pr->show();
        pr->raise();
        for (QWidget* w : properties_->findChildren<QWidget*>())
            if (w->isVisible() && w->isEnabled() && (w->focusPolicy() & Qt::TabFocus)) {
                w->setFocus(Qt::TabFocusReason);
                break;
            }
    });
    addPresenter(appearance_ = named(new AppearancePresenter(*canvasPresenter_, this),
                                     "appearancePresenter"));
    appearance_->createActions(*this);
    connect(appearance_, &AppearancePresenter::changed, this, &MainWindow::refreshNow,
            Qt::QueuedConnection);
    addPresenter(measure_ = named(new MeasureTools(document_, *tools_, *canvas_, controller_, this),
                                  "measureTools"));
    measure_->createActions(*this);
    addPresenter(parametersPresenter_ =
                     new ParametersPresenter(*parameters_, document_, controller_, this));
    parametersPresenter_->createActions(*this);
    accuracyLab_ = new AccuracyLab(*this, document_, *parametersPresenter_);
    // After the presenter's reset (Document::reset), which records the setup's first sample.
    connect(action("reset"), &QAction::triggered, &recorder_, &Recorder::clear);
    connect(parametersPresenter_, &ParametersPresenter::speedChanged, status_,
            &StatusPresenter::refresh);
    addPresenter(new EffectsPresenter(*effects_, document_, controller_, this));
    connect(addPresenter(new PropertiesPresenter(*properties_, document_, controller_, this)),
            &PropertiesPresenter::objectShown, pr, &QDockWidget::raise);
    addPresenter(browserPresenter_ = new SceneBrowserPresenter(*browser_, document_, this));
    connect(addPresenter(new NotesPresenter(*notes_, document_, this)),
            &NotesPresenter::notesToRead, notes, &QDockWidget::raise);
    addPresenter(timelinePresenter_ = new TimelinePresenter(*timeline_, controller_, this));
    timelinePresenter_->createActions(*this);
    addPresenter(plotsPresenter_ =
                     new PlotsPresenter(*plots_, document_, controller_, recorder_, this));
    addPresenter(exactPresenter_ = named(
                     new ExactPresenter(*canvas_, *plots_, document_, controller_, recorder_, this),
                     "exactPresenter"));
    exactPresenter_->createActions(*this);
    addPresenter(new ComparePresenter(*canvas_, *timeline_, *plots_, *plotsPresenter_, document_,
                                      controller_, recorder_, this))
        ->createActions(*this);
    connect(exactPresenter_, &ExactPresenter::phaseReferenceChanged, plotsPresenter_,
            &PlotsPresenter::refresh);
    addPresenter(instrumentsPresenter_ = named(
                     new InstrumentsPresenter(*instruments_, document_, controller_, probes_, this),
                     "instrumentsPresenter"));
    instrumentsPresenter_->createActions(*this);
    connect(instrumentsPresenter_, &InstrumentsPresenter::instrumentsWanted, in, [in] {
        in->show();
        in->raise();
    });
    // A ruler or protractor on the canvas is a probe the dock's graphs, timer and table offer.
    connect(measure_, &MeasureTools::probesChanged, instrumentsPresenter_,
            [this] { instrumentsPresenter_->setInstrumentProbes(measure_->probes()); });
}

// ---- views following the document ------------------------------------------------------------

void MainWindow::refreshNow() {
    for (Presenter* presenter : presenters_) presenter->refresh();
}

void MainWindow::updateTitle() {
    const QString path = document_.filePath();
    const QString name = path.isEmpty() || path.startsWith(QLatin1Char(':'))
                             ? ui::sceneText(document_.setup().name)
                             : QFileInfo(path).fileName();
    setWindowTitle((name.isEmpty() ? tr("Untitled") : ui::shownText(name)) +
                   QStringLiteral("[*] — Phasebox"));
    setWindowModified(document_.isModified());
}

void MainWindow::setPresentationMode(bool on) {
    if (on == layout_->presentation()) return;
    action("presentation")->setChecked(on);
    canvasPresenter_->setPresentation(on);
    layout_->setPresentation(on);
    // The canvas changed size with the layout: frame the scene again once it has settled.
    QTimer::singleShot(0, canvas_, [this] { canvas_->fitToWorld(); });
    plotsPresenter_->setPresentation(on);
}

}  // namespace phasebox
