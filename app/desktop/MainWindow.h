#pragma once
// The main window in the classic Qt shape (createActions, createMenus, createDockWindows,
// readSettings/writeSettings, maybeSave): the canvas in the middle (with its measuring tools),
// docks for Parameters, Effects, Properties, Plots, Instruments, the Scene list and the scene's
// Notes. It only composes: each dock has a presenter (presenters/) that connects its ui/ widget to
// the Document (what is edited), the SimulationController (what runs) and the Recorder (what is
// plotted).

#include "app/document/Document.h"
#include "app/sim/ProbeRecorder.h"
#include "app/sim/Recorder.h"
#include "app/sim/SimulationController.h"
#include "ui/plots/PlotsPanel.h"

#include <QMainWindow>
#include <QPointer>
#include <QStringList>

#include <memory>

QT_BEGIN_NAMESPACE
class QAction;
class QDialog;
class QMessageBox;
class QDockWidget;
class QMenu;
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

class CanvasTools;
class TimelinePresenter;
class MeasureTools;
class AccuracyDialog;
class AnimationExport;
class Autosave;
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
    Recorder& recorder() { return recorder_; }
    ProbeRecorder& probeRecorder() { return probes_; }
    ui::SceneView* canvas() const { return canvas_; }
    CanvasTools* tools() const { return tools_; }
    // The ruler, protractor and free-body view.
    MeasureTools* measureTools() const { return measure_; }
    ui::ParametersPanel* parametersPanel() const { return parameters_; }
    ui::EffectsPanel* effectsPanel() const { return effects_; }
    ui::PropertiesPanel* propertiesPanel() const { return properties_; }
    ui::SceneBrowser* sceneBrowser() const { return browser_; }
    ui::PlotsPanel* plotsPanel() const { return plots_; }
    ui::InstrumentsPanel* instrumentsPanel() const { return instruments_; }
    InstrumentsPresenter* instruments() const { return instrumentsPresenter_; }
    ExactPresenter* exactSolution() const { return exactPresenter_; }
    // High contrast, line width and text size (View menu).
    AppearancePresenter* appearance() const { return appearance_; }
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
    Autosave* autosave() const { return autosave_.get(); }

    // Writes a plot as PNG, SVG or CSV, chosen by the file's extension.
    bool exportPlot(ui::PlotsPanel::Plot plot, const QString& path, QString* error);
    bool exportCanvas(const QString& path, QString* error);
    // The accuracy lab (created on first use).
    AccuracyDialog* accuracyDialog();
    void showAccuracyLab();
    // Help > User Guide (F1): docs/user-guide.md in a dialog. Help > Keyboard Shortcuts: every
    // action of the window that has a key, listed from the actions themselves.
    void showUserGuide();
    void showKeyboardShortcuts();
    // The language chosen in View > Language ("" = follow the system), read before the window
    // is made (its texts are translated as they are created); "" when the settings files may
    // not be read as they are (readSettings() repairs them and says so).
    static QString storedLanguage();

protected:
    void closeEvent(QCloseEvent* event) override;
    void showEvent(QShowEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dropEvent(QDropEvent* event) override;

private:
    void createActions();
    void createMenus();
    void createLanguageMenu(QMenu& menu);
    void prepareForKeyboard();
    void createToolBar();
    void createDockWindows();
    QDockWidget* addDock(QWidget* widget, const QString& title, const QString& name,
                         Qt::DockWidgetArea area);
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
    void onDiverged(const QString& message, const QString& details);
    // Gives the canvas at least kCanvasShare of the window's width (from the side docks).
    void keepCanvasWide();
    static constexpr double kCanvasShare = 0.5;

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
    QTextBrowser* notes_ = nullptr;  // the scene's name and description: what to try
    QList<QDockWidget*> docks_;

    QList<Presenter*> presenters_;  // every view's, for refreshNow()
    CanvasPresenter* canvasPresenter_ = nullptr;
    AppearancePresenter* appearance_ = nullptr;
    ParametersPresenter* parametersPresenter_ = nullptr;
    PlotsPresenter* plotsPresenter_ = nullptr;
    ExactPresenter* exactPresenter_ = nullptr;
    InstrumentsPresenter* instrumentsPresenter_ = nullptr;
    SceneBrowserPresenter* browserPresenter_ = nullptr;
    StatusPresenter* status_ = nullptr;
    TimelinePresenter* timelinePresenter_ = nullptr;

    AccuracyDialog* accuracy_ = nullptr;
    AnimationExport* animationExport_ = nullptr;  // File > Export Animation
    QDialog* guide_ = nullptr;
    QPointer<QDialog> shortcuts_;                 // deletes itself on close
    QPointer<QDockWidget> leftDock_, rightDock_;  // the docks keepCanvasWide() narrows
    QPointer<QMessageBox> divergenceBox_;         // the blow-up dialog while it is open
    // The docks' layout came from the settings (else the first show sets the columns' widths).
    bool layoutRestored_ = false;
    bool shownOnce_ = false;
    std::unique_ptr<Autosave> autosave_;  // the open scene, every minute, for crash recovery

    SceneFiles* files_ = nullptr;
    QByteArray normalState_;  // dock layout before presentation mode
    bool presentation_ = false;
};

}  // namespace phasebox
