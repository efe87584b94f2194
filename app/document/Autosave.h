#pragma once
// Crash recovery: every interval, the open scene's setup goes to a recovery file when it has
// changed since the last autosave; a clean exit removes it, so a recovery file found at start
// means the last session ended without one (a crash, a killed process, a power cut).
//
// The recovery file is an ordinary scene file written through SceneIO::save (OutputFile: a crash
// during the autosave leaves the previous autosave intact), next to a small JSON sidecar that
// remembers which file the scene came from and when it was written. Once the document is clean
// again (saved, or undone back to its saved state) the recovery file is removed: the file on
// disk is then the newest copy, and offering an older one at the next start would mislead.

#include <QDateTime>
#include <QObject>
#include <QString>
#include <QStringList>
#include <QTimer>

#include <optional>

namespace phasebox {

class Document;

// What the next start finds after a session that did not end cleanly.
struct RecoveryInfo {
    QString recoveryFile;  // the autosaved scene (load it with Document::load or SceneIO::load)
    QString originalPath;  // the file the scene came from; empty for a scene never saved
    QDateTime savedAt;     // when the autosave was written (UTC)
};

class Autosave : public QObject {
    Q_OBJECT

public:
    static constexpr int kDefaultIntervalMs = 60'000;

    // Starts the timer at once. The directory is created on the first write. The document
    // must outlive the autosave.
    Autosave(Document& document, QString recoveryDir = defaultRecoveryDir(),
             int intervalMs = kDefaultIntervalMs, QObject* parent = nullptr);
    ~Autosave() override;

    // QStandardPaths::AppDataLocation + "/recovery".
    static QString defaultRecoveryDir();
    // The recovery file and its sidecar in a directory.
    static QString recoveryFilePath(const QString& recoveryDir);
    static QString sidecarFilePath(const QString& recoveryDir);
    // The recovery left by an earlier session, or nothing. A sidecar that is missing or
    // unreadable still yields the scene (a lost path must not lose the work): originalPath is
    // then empty and savedAt the file's modification time.
    // Nothing is read that could block or has no end: a recovery file or sidecar that is not
    // a regular file (a FIFO, a device, a link to /dev/zero, a folder) is removed (a link, not
    // its target) and never opened, with one line for each in *problems; a sidecar over 64 KiB
    // is not ours and is ignored.
    static std::optional<RecoveryInfo> findRecovery(
        const QString& recoveryDir = defaultRecoveryDir(), QStringList* problems = nullptr);
    // Removes a recovery file and its sidecar (after the user declined or took the recovery).
    static bool removeRecovery(const QString& recoveryDir);

    QString recoveryDir() const { return dir_; }
    QString recoveryFile() const { return recoveryFilePath(dir_); }
    int intervalMs() const { return timer_.interval(); }
    // The last failure of an autosave, or empty.
    QString lastError() const { return lastError_; }

    // What the timer does: writes the recovery file when the document has changed since the
    // last autosave and is not clean. True when a file was written.
    bool autosaveNow();
    // On a clean exit: stops the timer and removes the recovery file and its sidecar.
    void discard();

signals:
    void autosaved(const QString& recoveryFile);
    // The autosave could not be written (disk full, folder not writable); the work is not
    // protected until a later one succeeds, and the app should say so.
    void autosaveFailed(const QString& message);

private:
    void documentChanged();
    void documentCleanChanged(bool modified);

    Document& document_;
    QString dir_;
    QTimer timer_;
    bool changedSinceAutosave_ = false;
    QString lastError_;
};

}  // namespace phasebox
