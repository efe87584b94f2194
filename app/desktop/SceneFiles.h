#pragma once
// Opening and saving scene files for the main window: the file dialogs, the messages of a bad
// file or a failed save, and File → Open Recent. The Document reads and writes (SceneIO).

#include <QObject>
#include <QString>

QT_BEGIN_NAMESPACE
class QMenu;
class QSettings;
class QWidget;
QT_END_NAMESPACE

namespace phasebox {

class Document;
class RecentFiles;
class SimulationController;

class SceneFiles : public QObject {
    Q_OBJECT

public:
    SceneFiles(QWidget& window, Document& document, SimulationController& controller,
               QMenu& recentMenu);

    // Pauses and opens a scene file; a bad file shows the loader's message (in a dialog unless
    // quiet) and leaves the open scene untouched.
    bool open(const QString& path, bool quiet = false, QString* error = nullptr);
    // Asks for a file to open (in the folder of the last one).
    void openInteractively();
    // To the scene's own file, or asks for one (saveAs) when it has none or is built in.
    bool save();
    bool saveAs();
    bool saveTo(const QString& path, QString* error = nullptr);
    // A name a scene file can have: *.json, *.phasebox.json.
    static bool isSceneFile(const QString& path);
    // After a crash: offers the scene autosaved in recoveryDir by the last session (if any)
    // and opens it; declined, the autosave is removed.
    void offerRecovery(const QString& recoveryDir);

    void readSettings(const QSettings& settings);
    void writeSettings(QSettings& settings) const;

signals:
    void message(const QString& text);
    // An entry of Open Recent was chosen (the window asks to save the scene first).
    void recentFileChosen(const QString& path);

private:
    bool warnUnsaved(bool ok, const QString& error);

    QWidget& window_;
    Document& document_;
    SimulationController& controller_;
    RecentFiles* recent_ = nullptr;
};

}  // namespace phasebox
