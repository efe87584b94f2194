#include "app/desktop/MainWindow.h"

#include "app/desktop/AccuracyDialog.h"
#include "app/desktop/AnimationExport.h"
#include "app/desktop/CanvasTools.h"
#include "app/desktop/HelpDialogs.h"
#include "app/desktop/MeasureTools.h"
#include "app/desktop/SceneFiles.h"
#include "app/desktop/SceneLibraryMenu.h"
#include "app/desktop/presenters/AppearancePresenter.h"
#include "app/desktop/presenters/CanvasPresenter.h"
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
#include "app/i18n/Language.h"
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
#include <QActionGroup>
#include <QApplication>
#include <QDockWidget>
#include <QFileInfo>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QScrollArea>
#include <QSettings>
#include <QStatusBar>
#include <QTabBar>
#include <QTextBrowser>
#include <QTimer>

#include <QToolBar>
#include <QUndoStack>
#include <QVBoxLayout>
#include <utility>

#include <algorithm>
#include <cmath>
#include <tuple>

namespace phasebox {

namespace {
// Adds the window's actions by name to a menu or tool bar; "" is a separator.
void addNamedActions(QWidget* to, const MainWindow& window,
                     std::initializer_list<const char*> names) {
    for (const char* name : names) {
        QAction* a = *name ? window.action(name) : new QAction(to);
        a->setSeparator(!*name);
        to->addAction(a);
    }
}
}  // namespace

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent), controller_(document_) {
    setObjectName(QStringLiteral("MainWindow"));
    setAcceptDrops(true);
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
    tools_ = new CanvasTools(document_, *canvas_, this);

    createActions();
    createDockWindows();
    createMenus();
    createToolBar();
    connect(&document_, &Document::sceneReset, this, &MainWindow::updateTitle);
    // The blow-up dialog speaks of a run that New, Open, Reset and Revert have ended.
    connect(&document_, &Document::sceneReset, this, [this] {
        if (divergenceBox_) divergenceBox_->close();
    });
    connect(&document_, &Document::modifiedChanged, this, &MainWindow::updateTitle);
    connect(&document_, &Document::filePathChanged, this, &MainWindow::updateTitle);
    const auto revertable = [this] {
        action("revert")->setEnabled(!document_.filePath().isEmpty());
    };
    connect(&document_, &Document::modifiedChanged, this, revertable);
    connect(&document_, &Document::filePathChanged, this, revertable);
    revertable();
    connect(&controller_, &SimulationController::diverged, this, &MainWindow::onDiverged);
    connectLessonInstruments();
    readSettings();
    autosave_ = std::make_unique<Autosave>(document_);
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
        showAccuracyLab();
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
         [this] { showUserGuide(); })
        ->setToolTip(tr("How to use Phasebox: the window, building scenes, measuring, files"));
    make("keyboardShortcuts", tr("&Keyboard Shortcuts"), QKeySequence(),
         [this] { showKeyboardShortcuts(); });
}

void MainWindow::createMenus() {
    QMenu* file = menuBar()->addMenu(tr("&File"));
    addNamedActions(file, *this, {"new", "open"});
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
    addNamedActions(file, *this, {"", "save", "saveAs", "revert"});
    QMenu* exports = file->addMenu(tr("&Export"));
    exports->addAction(action("exportCanvas"));
    plotsPresenter_->addExportActions(*exports);
    instrumentsPresenter_->addExportActions(*exports);
    addNamedActions(file, *this, {"exportAnimation"});
    connect(animationExport_, &AnimationExport::message, status_, &StatusPresenter::showMessage);
    addNamedActions(file, *this, {"", "quit"});
    addNamedActions(menuBar()->addMenu(tr("&Edit")), *this,
                    {"undo", "redo", "", "cut", "copy", "paste", "delete"});
    addNamedActions(menuBar()->addMenu(tr("&Simulation")), *this,
                    {"play", "step", "reset", "", "frameBack", "frameForward", "jumpToStart", "",
                     "nextIntegrator", "previousIntegrator", "doubleDt", "halveDt", "moreSubsteps",
                     "fewerSubsteps", "faster", "slower"});
    QMenu* tools = menuBar()->addMenu(tr("&Tools"));
    tools->addActions(canvasPresenter_->toolActions());
    addNamedActions(tools, *this,
                    {"", "clearMeasurements", "", "showInstruments", "stopwatch", "stopwatchLap",
                     "", "accuracyLab"});
    QMenu* view = menuBar()->addMenu(tr("&View"));
    for (QDockWidget* dock : docks_) view->addAction(dock->toggleViewAction());
    addNamedActions(view, *this,
                    {"", "fit", "follow", "trails", "velocityArrows", "forceArrows", "freeBody",
                     "labels", "viewExact", "grid", "errorEstimate", "presentation", ""});
    appearance_->addToMenu(*view);
    createLanguageMenu(*view->addMenu(tr("&Language")));
    QMenu* help = menuBar()->addMenu(tr("&Help"));
    addNamedActions(help, *this, {"userGuide", "keyboardShortcuts", ""});
    help->addAction(tr("&About Phasebox"), this, [this] {
        QMessageBox::about(this, tr("About Phasebox"),
                           tr("<b>Phasebox %1</b><p>A 2D physics sandbox for the classroom: drop "
                              "particles, springs, cloth and boxes into a scene, switch the "
                              "integrator while it runs, and watch what accuracy costs.</p>")
                               .arg(QStringLiteral(PHASEBOX_VERSION)));
    });
}

// The language is chosen here and stored; it applies from the next start, since every text of
// the window is translated once, when it is made.
void MainWindow::createLanguageMenu(QMenu& menu) {
    menu.setObjectName(QStringLiteral("languageMenu"));
    auto* group = new QActionGroup(&menu);
    const QString stored = storedLanguage();
    QStringList codes{QString()};
    codes << i18n::languages();
    for (const QString& code : std::as_const(codes)) {
        QAction* a =
            menu.addAction(code.isEmpty() ? tr("&System Language") : i18n::nativeName(code));
        a->setCheckable(true);
        a->setChecked(code == stored);
        a->setData(code);
        a->setObjectName(QStringLiteral("language_") +
                         (code.isEmpty() ? QStringLiteral("system") : code));
        group->addAction(a);
        connect(a, &QAction::triggered, this, [this, code] {
            QSettings settings;
            i18n::storeLanguage(settings, code);
            const QString next = i18n::resolve(code);
            if (next == i18n::installedLanguage()) return;
            const QString message =
                tr("Phasebox will speak %1 from its next start.").arg(i18n::nativeName(next));
            if (QGuiApplication::platformName() == QLatin1String("offscreen"))
                status_->showMessage(message);
            else
                QMessageBox::information(this, tr("Language"), message);
        });
    }
}

void MainWindow::createToolBar() {
    QToolBar* bar = addToolBar(tr("Main"));
    bar->setObjectName(QStringLiteral("mainToolBar"));
    addNamedActions(bar, *this, {"new", "open", "save", "", "play", "step", "reset", ""});
    bar->addActions(canvasPresenter_->toolActions());
    bar->addWidget(canvasPresenter_->polygonSidesBox());
    bar->addWidget(canvasPresenter_->jointTypeBox());
}

QDockWidget* MainWindow::addDock(QWidget* widget, const QString& title, const QString& name,
                                 Qt::DockWidgetArea area) {
    auto* dock = new QDockWidget(title, this);
    dock->setObjectName(name);
    dock->setWidget(widget);
    addDockWidget(area, dock);
    docks_.append(dock);
    return dock;
}

template <typename P>
P* MainWindow::addPresenter(P* presenter) {
    presenters_.append(presenter);
    connect(presenter, &Presenter::message, status_, &StatusPresenter::showMessage);
    return presenter;
}

void MainWindow::createDockWindows() {
    parameters_ = new ui::ParametersPanel(this);
    effects_ = new ui::EffectsPanel(this);
    properties_ = new ui::PropertiesPanel(this);
    browser_ = new ui::SceneBrowser(this);
    plots_ = new ui::PlotsPanel(this);
    instruments_ = new ui::InstrumentsPanel(this);
    instruments_->setObjectName(QStringLiteral("instruments"));
    notes_ = new QTextBrowser(this);
    notes_->setObjectName(QStringLiteral("notes"));
    QDockWidget* p =
        addDock(parameters_, tr("Parameters"), "parametersDock", Qt::LeftDockWidgetArea);
    QDockWidget* e = addDock(effects_, tr("Effects"), "effectsDock", Qt::LeftDockWidgetArea);
    // The scene's objects beside the parameters, and three tabs below: four in one row do not
    // fit the left column at 1024 x 700 in German, Spanish or French.
    tabifyDockWidget(p, addDock(browser_, tr("Scene"), "sceneDock", Qt::LeftDockWidgetArea));
    p->raise();
    e->raise();
    // The properties of the selection and the lesson's notes share the left column's lower
    // half with the effects (raised when an object is chosen): the right column is the plots'
    // and instruments' whole height, which at 1024 x 700 is what keeps them legible.
    QDockWidget* pr =
        addDock(properties_, tr("Properties"), "propertiesDock", Qt::LeftDockWidgetArea);
    tabifyDockWidget(e, pr);
    QDockWidget* pl = addDock(plots_, tr("Plots"), "plotsDock", Qt::RightDockWidgetArea);
    // The instruments share the plots' place: both are things to watch while it runs.
    // The instruments' pages are laid out in short rows that fit the dock at 1024 x 700; in a
    // narrower one they scroll sideways rather than take the canvas's width.
    auto* instrumentsScroll = new QScrollArea(this);
    instrumentsScroll->setObjectName(QStringLiteral("instrumentsScroll"));
    instrumentsScroll->setWidget(instruments_);
    instrumentsScroll->setWidgetResizable(true);
    instrumentsScroll->setFrameShape(QFrame::NoFrame);
    QDockWidget* in =
        addDock(instrumentsScroll, tr("Instruments"), "instrumentsDock", Qt::RightDockWidgetArea);
    tabifyDockWidget(pl, in);
    pl->raise();
    QDockWidget* notes = addDock(notes_, tr("Notes"), "notesDock", Qt::LeftDockWidgetArea);
    tabifyDockWidget(pr, notes);
    notes->raise();
    // The parameters take the height of their fields; the rest is the lower tabs'.
    resizeDocks({p, e}, {parameters_->sizeHint().height() + 30, 2000}, Qt::Vertical);
    resizeDocks({p}, {280}, Qt::Horizontal);
    resizeDocks({pl}, {420}, Qt::Horizontal);
    leftDock_ = p;
    rightDock_ = pl;

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
    addPresenter(appearance_ = new AppearancePresenter(*canvasPresenter_, this));
    appearance_->createActions(*this);
    connect(appearance_, &AppearancePresenter::changed, this, &MainWindow::refreshNow,
            Qt::QueuedConnection);
    addPresenter(measure_ = new MeasureTools(document_, *tools_, *canvas_, controller_, this));
    measure_->createActions(*this);
    addPresenter(parametersPresenter_ =
                     new ParametersPresenter(*parameters_, document_, controller_, this));
    parametersPresenter_->createActions(*this);
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
    addPresenter(exactPresenter_ = new ExactPresenter(*canvas_, *plots_, document_, controller_,
                                                      recorder_, this));
    exactPresenter_->createActions(*this);
    connect(exactPresenter_, &ExactPresenter::phaseReferenceChanged, plotsPresenter_,
            &PlotsPresenter::refresh);
    addPresenter(instrumentsPresenter_ = new InstrumentsPresenter(*instruments_, document_,
                                                                  controller_, probes_, this));
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

void MainWindow::showEvent(QShowEvent* event) {
    QMainWindow::showEvent(event);
    // Tabbed docks show their whole titles, with scroll buttons when they do not fit, rather
    // than cut to "Eig…" (German and French titles are longer than the English ones).
    // A little less padding than the style's lets the left column's three tabs fit at 1024 x 700.
    for (QTabBar* bar : findChildren<QTabBar*>()) {
        bar->setElideMode(Qt::ElideNone);
        bar->setUsesScrollButtons(true);
        if (qobject_cast<QMainWindow*>(bar->parentWidget()))
            bar->setStyleSheet(QStringLiteral("QTabBar::tab { padding: 4px 7px; }"));
    }
    // The columns' widths set while the window was built were clamped to a default-sized
    // window's; the first show gives them theirs, unless the settings brought the user's own.
    if (std::exchange(shownOnce_, true) || layoutRestored_ || !leftDock_ || !rightDock_) return;
    QTimer::singleShot(0, this, [this] {  // once the layout is live
        if (leftDock_ && rightDock_)
            resizeDocks({leftDock_.data(), rightDock_.data()}, {280, 420}, Qt::Horizontal);
        keepCanvasWide();  // then a small window's canvas its share again
    });
}

void MainWindow::resizeEvent(QResizeEvent* event) {
    QMainWindow::resizeEvent(event);
    // After the layout has settled at the new size.
    QTimer::singleShot(0, this, &MainWindow::keepCanvasWide);
}

// QMainWindow takes a smaller window's width from the central widget first, so at 1024 px the
// docks' 700 px left the canvas 300. When the canvas has less than kCanvasShare of the window,
// the side docks give up what it lacks, each in proportion to what it has above its minimum; a
// dock the user widened on a large window is left alone.
void MainWindow::keepCanvasWide() {
    if (!canvas_ || isFullScreen()) return;
    const int lacking = static_cast<int>(kCanvasShare * width()) - canvas_->width();
    if (lacking <= 0) return;
    QList<QDockWidget*> docks;
    QList<int> widths, slacks;
    int totalSlack = 0;
    for (QDockWidget* dock : {leftDock_.data(), rightDock_.data()}) {
        if (!dock || !dock->isVisible() || dock->isFloating()) continue;
        const int least = std::max(dock->minimumSizeHint().width(), dock->minimumWidth());
        docks << dock;
        widths << dock->width();
        slacks << std::max(0, dock->width() - least);
        totalSlack += slacks.back();
    }
    if (totalSlack <= 0) return;
    const int cut = std::min(lacking, totalSlack);
    for (qsizetype i = 0; i < docks.size(); ++i)
        widths[i] -= static_cast<int>(std::ceil(double(cut) * slacks[i] / totalSlack));
    resizeDocks(docks, widths, Qt::Horizontal);
}

void MainWindow::onDiverged(const QString& message, const QString& details) {
    // The status bar: what happened and where, the first two lines.
    status_->showMessage(
        message.split(QLatin1Char('\n'), Qt::SkipEmptyParts).mid(0, 2).join(QLatin1Char(' ')));
    refreshNow();
    if (!isVisible()) return;
    // Window-modal and open(), not exec(): the window stays responsive behind it, and a later
    // blow-up updates the one dialog instead of stacking another.
    if (!divergenceBox_) {
        divergenceBox_ = new QMessageBox(QMessageBox::Warning, tr("The simulation became unstable"),
                                         QString(), QMessageBox::Ok, this);
        divergenceBox_->setObjectName(QStringLiteral("divergenceDialog"));
        divergenceBox_->setAttribute(Qt::WA_DeleteOnClose);
    }
    divergenceBox_->setText(message);
    divergenceBox_->setDetailedText(details);
    divergenceBox_->open();
}

AccuracyDialog* MainWindow::accuracyDialog() {
    if (!accuracy_) {
        accuracy_ = new AccuracyDialog(this);
        connect(accuracy_, &AccuracyDialog::applyRequested, parametersPresenter_,
                &ParametersPresenter::applyStudyChoice);
        // Apply only to the scene it studied: every edit, New, Open and Revert is checked.
        for (auto signal : {&Document::sceneEdited, &Document::sceneReset})
            connect(&document_, signal, accuracy_,
                    [this] { accuracy_->setCurrentScene(document_.setup()); });
    }
    return accuracy_;
}

void MainWindow::showAccuracyLab() {
    AccuracyDialog* dialog = accuracyDialog();
    if (!dialog->study().isRunning()) dialog->setScene(document_.setup());
    dialog->setSceneFile(document_.filePath());
    dialog->show();
    dialog->raise();
}

void MainWindow::setPresentationMode(bool on) {
    if (on == presentation_) return;
    presentation_ = on;
    action("presentation")->setChecked(on);
    canvasPresenter_->setPresentation(on);
    QFont font = QApplication::font();
    font.setPointSizeF(on ? font.pointSizeF() * 1.4 : font.pointSizeF() / 1.4);
    QApplication::setFont(font);
    if (on) {
        normalState_ = saveState();
        // In front of a class the canvas, the plots and the instruments are what matter; every
        // other control stays on the keyboard (Simulation menu) and comes back with the layout on
        // exit.
        for (QDockWidget* dock : docks_)
            if (dock->objectName() != QLatin1String("plotsDock") &&
                dock->objectName() != QLatin1String("instrumentsDock"))
                dock->hide();
        for (QToolBar* bar : findChildren<QToolBar*>()) bar->hide();
        showFullScreen();
    } else {
        showNormal();
        restoreState(normalState_);
    }
    // The canvas changed size with the layout: frame the scene again once it has settled.
    QTimer::singleShot(0, canvas_, [this] { canvas_->fitToWorld(); });
    plotsPresenter_->setPresentation(on);
}

void MainWindow::showUserGuide() {
    if (!guide_) guide_ = createUserGuideDialog(this);
    guide_->show();
    guide_->raise();
    guide_->activateWindow();
}

void MainWindow::showKeyboardShortcuts() {
    // Made anew each time from the actions as they are now.
    delete shortcuts_;
    shortcuts_ = createShortcutsDialog(*this);
    shortcuts_->setAttribute(Qt::WA_DeleteOnClose);
    shortcuts_->show();
    shortcuts_->raise();
    shortcuts_->activateWindow();
}

}  // namespace phasebox
