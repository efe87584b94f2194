#pragma once
// The main window in the classic Qt shape (createActions, createMenus, createDocks,
// readSettings/writeSettings, maybeSave): the canvas in the middle, docks for Parameters,
// Effects, Properties, Plots and the Scene list. It composes ui/ widgets and wires them to the
// Document (what is edited), the SimulationController (what runs) and the Recorder (what is
// plotted); it holds no physics of its own.

#include "app/document/Document.h"
#include "app/sim/Recorder.h"
#include "app/sim/SimulationController.h"
#include "ui/plots/PlotsPanel.h"

#include <QElapsedTimer>
#include <QMainWindow>
#include <QStringList>

#include <memory>
#include <set>

QT_BEGIN_NAMESPACE
class QAction;
class QActionGroup;
class QDockWidget;
class QLabel;
class QMenu;
class QTextBrowser;
QT_END_NAMESPACE

namespace phasebox {

namespace ui {
class SceneView;
class ParametersPanel;
class EffectsPanel;
class PropertiesPanel;
class SceneBrowser;
}  // namespace ui

class CanvasTools;
class AccuracyDialog;
class Autosave;

// The built-in scenes of a resource folder (":/scenes" for the examples, ":/lessons"), by
// file name.
QStringList builtInScenes(const QString& folder);

class MainWindow : public QMainWindow {
    Q_OBJECT

public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    Document& document() { return document_; }
    SimulationController& controller() { return controller_; }
    Recorder& recorder() { return recorder_; }
    ui::SceneView* canvas() const { return canvas_; }
    CanvasTools* tools() const { return tools_; }
    ui::ParametersPanel* parametersPanel() const { return parameters_; }
    ui::EffectsPanel* effectsPanel() const { return effects_; }
    ui::PropertiesPanel* propertiesPanel() const { return properties_; }
    ui::SceneBrowser* sceneBrowser() const { return browser_; }
    ui::PlotsPanel* plotsPanel() const { return plots_; }
    QAction* action(const QString& name) const;

    // Opens a scene file; a bad file shows the loader's message (in a dialog unless quiet) and
    // leaves the open scene untouched.
    bool openFile(const QString& path, bool quiet = false, QString* error = nullptr);
    bool saveFile(const QString& path, QString* error = nullptr);
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

protected:
    void closeEvent(QCloseEvent* event) override;
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dropEvent(QDropEvent* event) override;

private:
    void createActions();
    void createMenus();
    void createToolBar();
    void createDocks();
    void connectDocument();
    void readSettings();
    void writeSettings();
    bool maybeSave();

    void newScene();
    void open();
    bool save();
    bool saveAs();
    void openExample(const QString& path);
    void addRecentFile(const QString& path);
    void updateRecentFilesMenu();
    void exportPlotInteractively(ui::PlotsPanel::Plot plot, const QString& format);
    void exportCanvasInteractively();

    // Views following the document.
    void onSceneReplaced();
    void onSceneEdited();
    void onSimulationSettingsChanged();
    void onSelectionChanged();
    void onStepped();
    void onDiverged(const QString& message);
    void updateTitle();
    void updateStatus();
    void updateEffectsRows();
    void updateProperties(bool rebuild);
    void updatePlots();
    void updateAdvice();
    QString errorPlotNote() const;
    QString defaultPhaseCoordinate(const QString& id) const;
    void updateCanvas();

    // Keyboard control of the parameters.
    void cycleIntegrator(int direction);
    void scaleDt(double factor);
    void changeSubsteps(int delta);
    void changeSpeed(int direction);
    void applySimulation(const SimulationDesc& simulation);

    Document document_;
    Recorder recorder_;
    SimulationController controller_;

    ui::SceneView* canvas_ = nullptr;
    CanvasTools* tools_ = nullptr;
    ui::ParametersPanel* parameters_ = nullptr;
    ui::EffectsPanel* effects_ = nullptr;
    ui::PropertiesPanel* properties_ = nullptr;
    ui::SceneBrowser* browser_ = nullptr;
    ui::PlotsPanel* plots_ = nullptr;
    QTextBrowser* notes_ = nullptr;
    AccuracyDialog* accuracy_ = nullptr;
    std::unique_ptr<Autosave> autosave_;  // the open scene, every minute, for crash recovery  // the scene's name and description: what to try
    QList<QDockWidget*> docks_;

    QMenu* recentMenu_ = nullptr;
    QMenu* examplesMenu_ = nullptr;
    QMenu* lessonsMenu_ = nullptr;
    QMenu* viewMenu_ = nullptr;
    QActionGroup* toolGroup_ = nullptr;
    QLabel* statusTime_ = nullptr;
    QLabel* statusSpeed_ = nullptr;
    QLabel* statusCost_ = nullptr;
    QLabel* statusError_ = nullptr;
    QLabel* statusMessage_ = nullptr;

    QStringList recentFiles_;
    std::set<QString> switchedOffEffects_;  // shown unchecked in the Effects dock
    QString propertiesObject_;              // the id the Properties dock shows
    QElapsedTimer sincePlots_;
    QByteArray normalState_;  // dock layout before presentation mode
    bool presentation_ = false;
    QString lastMessage_;
};

}  // namespace phasebox
