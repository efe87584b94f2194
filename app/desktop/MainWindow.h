#pragma once
// The main window in the classic Qt shape (createActions, createMenus, createDockWindows,
// readSettings/writeSettings, maybeSave): the canvas in the middle (with its measuring tools),
// docks for Parameters, Effects, Properties, Plots, Instruments, the Scene list and the scene's
// Notes. It only composes: each dock has a presenter (presenters/) that connects its ui/ widget to
// the Document (what is edited), the SimulationController (what runs) and the Recorder (what is
// plotted); the docks' layout and presentation mode are WindowLayout's, the Accuracy Lab is
// AccuracyLab's, the Help menu's dialogs HelpWindows', View > Language LanguageMenu's and the
// blow-up dialog DivergenceNotice's. Its parts are reached through Qt's object tree by their
// object names: the widgets "canvas", "parametersPanel", "effectsPanel", "propertiesPanel",
// "sceneBrowser", "plotsPanel", "instruments" and "notes"; "canvasTools", "measureTools",
// "appearancePresenter", "exactPresenter", "instrumentsPresenter", "accuracyLabController",
// "recorder", "probeRecorder" and "autosave"; the actions by their names (action()).

#include "app/document/Document.h"
#include "app/sim/ProbeRecorder.h"
#include "app/sim/Recorder.h"
#include "app/sim/SimulationController.h"
#include "ui/plots/PlotsPanel.h"

#include <QMainWindow>
#include <QStringList>

#include <memory>

QT_BEGIN_NAMESPACE
class QAction;
class QDockWidget;
class QTextBrowser;
QT_END_NAMESPACE

namespace phasebox {

namespace ui {
class SceneView;
class TimelineBar;
class ParametersPanel;
class EffectsPanel;
class PropertiesPanel;
class SceneBrowser;
class InstrumentsPanel;
}  // namespace ui

class AccuracyLab;
class AnimationExport;
class Autosave;
class CanvasTools;
class DivergenceNotice;
class HelpWindows;
class WorkerMenu;
class MeasureTools;
class TimelinePresenter;
class WindowLayout;
class Presenter;
class SceneFiles;
class AppearancePresenter;
class CanvasPresenter;
class ParametersPresenter;
class ExactPresenter;
class PlotsPresenter;
class InstrumentsPresenter;
class SceneBrowserPresenter;
class StatusPresenter;

class MainWindow : public QMainWindow {
    Q_OBJECT

public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    Document& document() { return document_; }
    SimulationController& controller() { return controller_; }
    QAction* action(const QString& name) const;

    // Opens a scene file; a bad file shows the loader's message (in a dialog unless quiet) and
    // leaves the open scene untouched.
    bool openFile(const QString& path, bool quiet = false, QString* error = nullptr);
    bool saveFile(const QString& path, QString* error = nullptr);
    // File > Revert: reopens the scene's file as it is on disk (a built-in lesson as it ships),
    // dropping the edits, the run and every plot and instrument; asks first when there are
    // unsaved edits (not under the offscreen platform). False when there is no file or it fails.
    bool revert();
    // Brings every view up to date at once (plots included), for pictures and tests.
    void refreshNow();
    void setPresentationMode(bool on);
    // After a crash: offers the scene autosaved by the last session (if any) and opens it.
    void offerRecovery();

    // Writes a plot as PNG, SVG or CSV, chosen by the file's extension.
    bool exportPlot(ui::PlotsPanel::Plot plot, const QString& path, QString* error);
    bool exportCanvas(const QString& path, QString* error);
    // The language chosen in View > Language ("" = follow the system), read before the window
    // is made (its texts are translated as they are created); "" when the settings files may
    // not be read as they are (readSettings() repairs them and says so).
    static QString storedLanguage();

protected:
    void closeEvent(QCloseEvent* event) override;
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dropEvent(QDropEvent* event) override;

private:
    void createActions();
    void createMenus();
    void prepareForKeyboard();
    void createToolBar();
    void createDockWindows();
    // Keeps the presenter for refreshNow() and shows its messages in the status bar.
    template <typename P>
    P* addPresenter(P* presenter);
    void readSettings();
    void writeSettings();
    bool maybeSave();

    // A lesson's instruments (CONTRACT §7): the view and the plots here, the rest in the
    // instruments' presenter and the measuring tools; collected for Save and the autosave.
    void connectLessonInstruments();
    InstrumentsDesc currentInstruments() const;

    void newScene();
    void openIfSaved(const QString& path);
    void updateTitle();

    Document document_;
    Recorder recorder_;
    ProbeRecorder probes_;  // what the instruments read
    SimulationController controller_;

    ui::SceneView* canvas_ = nullptr;
    ui::TimelineBar* timeline_ = nullptr;  // under the canvas
    CanvasTools* tools_ = nullptr;
    MeasureTools* measure_ = nullptr;
    ui::ParametersPanel* parameters_ = nullptr;
    ui::EffectsPanel* effects_ = nullptr;
    ui::PropertiesPanel* properties_ = nullptr;
    ui::SceneBrowser* browser_ = nullptr;
    ui::PlotsPanel* plots_ = nullptr;
    ui::InstrumentsPanel* instruments_ = nullptr;
    QTextBrowser* notes_ = nullptr;   // the scene's name and description: what to try
    WindowLayout* layout_ = nullptr;  // the docks, their widths and presentation mode

    QList<Presenter*> presenters_;  // every view's, for refreshNow()
    CanvasPresenter* canvasPresenter_ = nullptr;
    AppearancePresenter* appearance_ = nullptr;
    WorkerMenu* workerMenu_ = nullptr;  // Simulation > Worker Threads
    ParametersPresenter* parametersPresenter_ = nullptr;
    PlotsPresenter* plotsPresenter_ = nullptr;
    ExactPresenter* exactPresenter_ = nullptr;
    InstrumentsPresenter* instrumentsPresenter_ = nullptr;
    SceneBrowserPresenter* browserPresenter_ = nullptr;
    StatusPresenter* status_ = nullptr;
    TimelinePresenter* timelinePresenter_ = nullptr;

    AccuracyLab* accuracyLab_ = nullptr;
    AnimationExport* animationExport_ = nullptr;  // File > Export Animation
    HelpWindows* help_ = nullptr;
    DivergenceNotice* divergence_ = nullptr;  // the blow-up dialog
    std::unique_ptr<Autosave> autosave_;      // the open scene, every minute, for crash recovery

    SceneFiles* files_ = nullptr;
};

}  // namespace phasebox
