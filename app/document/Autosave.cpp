#include "app/document/Autosave.h"

#include "app/document/Document.h"
#include "app/io/InputFile.h"
#include "app/io/OutputFile.h"
#include "app/io/SceneIO.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QStandardPaths>
#include <QUndoStack>

#include <utility>

namespace phasebox {

namespace {
const char* const kRecoveryFileName = "recovery.phasebox.json";
const char* const kSidecarFileName = "recovery.info.json";
}  // namespace

Autosave::Autosave(Document& document, QString recoveryDir, int intervalMs, QObject* parent)
    : QObject(parent), document_(document), dir_(std::move(recoveryDir)) {
    // Every edit, undo and redo moves the undo stack's index; that is what "changed" means.
    // The live simulation running is not a change: Save writes the setup, and so does this.
    connect(document_.undoStack(), &QUndoStack::indexChanged, this, &Autosave::documentChanged);
    connect(&document_, &Document::modifiedChanged, this, &Autosave::documentCleanChanged);
    // A load or a new scene replaces the setup without a command.
    connect(&document_, &Document::sceneReset, this, &Autosave::documentChanged);
    changedSinceAutosave_ = document_.isModified();
    timer_.setInterval(intervalMs);
    connect(&timer_, &QTimer::timeout, this, &Autosave::autosaveNow);
    timer_.start();
}

Autosave::~Autosave() = default;

QString Autosave::defaultRecoveryDir() {
    return QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) +
           QStringLiteral("/recovery");
}

QString Autosave::recoveryFilePath(const QString& recoveryDir) {
    return QDir(recoveryDir).filePath(QLatin1String(kRecoveryFileName));
}

QString Autosave::sidecarFilePath(const QString& recoveryDir) {
    return QDir(recoveryDir).filePath(QLatin1String(kSidecarFileName));
}

void Autosave::documentChanged() {
    changedSinceAutosave_ = true;
}

void Autosave::documentCleanChanged(bool modified) {
    if (modified) return;
    // Saved (or undone back to the saved state): the file on disk is the newest copy.
    removeRecovery(dir_);
    changedSinceAutosave_ = false;
}

bool Autosave::autosaveNow() {
    if (!document_.isModified()) {
        changedSinceAutosave_ = false;
        return false;
    }
    if (!changedSinceAutosave_) return false;
    if (!QDir().mkpath(dir_)) {
        lastError_ = dir_ + QStringLiteral(": cannot create the recovery folder");
        emit autosaveFailed(lastError_);
        return false;
    }
    QString error;
    if (!SceneIO::save(document_.sceneToSave(), recoveryFile(), &error)) {
        lastError_ = error;
        emit autosaveFailed(lastError_);
        return false;
    }
    // The sidecar second: a recovery file without one is still found (findRecovery), while a
    // sidecar without the scene would be useless.
    const QJsonObject info{
        {QStringLiteral("original_path"), document_.filePath()},
        {QStringLiteral("saved_at"), QDateTime::currentDateTimeUtc().toString(Qt::ISODateWithMs)},
    };
    if (!OutputFile::writeAll(sidecarFilePath(dir_), QJsonDocument(info).toJson(), &error)) {
        lastError_ = error;
        emit autosaveFailed(lastError_);
        // The scene itself is safe; only its origin is lost.
    } else {
        lastError_.clear();
    }
    changedSinceAutosave_ = false;
    emit autosaved(recoveryFile());
    return true;
}

void Autosave::discard() {
    timer_.stop();
    removeRecovery(dir_);
    changedSinceAutosave_ = false;
}

bool Autosave::removeRecovery(const QString& recoveryDir) {
    bool ok = true;
    for (const QString& path : {recoveryFilePath(recoveryDir), sidecarFilePath(recoveryDir)})
        if (QFileInfo::exists(path)) ok = QFile::remove(path) && ok;
    return ok;
}

namespace {
// Removes path when it exists and is not a regular file (never opening it); says so.
bool removeIfIrregular(const QString& path, QStringList* problems) {
    const QString kind = inputfile::irregularKind(path);
    if (kind.isEmpty()) return false;
    const bool removed = QFileInfo(path).isDir() ? QDir().rmdir(path) : QFile::remove(path);
    if (problems)
        *problems << QStringLiteral("%1: it is %2, not a recovery file; %3")
                         .arg(path, kind,
                              removed ? QStringLiteral("removed") : QStringLiteral("ignored"));
    return true;
}
}  // namespace

std::optional<RecoveryInfo> Autosave::findRecovery(const QString& recoveryDir,
                                                   QStringList* problems) {
    const QString scenePath = recoveryFilePath(recoveryDir);
    const QString sidecarPath = sidecarFilePath(recoveryDir);
    removeIfIrregular(scenePath, problems);
    const bool irregularSidecar = removeIfIrregular(sidecarPath, problems);
    const QFileInfo scene(scenePath);
    if (!scene.isFile()) return std::nullopt;
    RecoveryInfo info;
    info.recoveryFile = scene.filePath();
    info.savedAt = scene.lastModified().toUTC();
    // A sidecar is a few hundred bytes; a larger one is not ours and is not read.
    QByteArray bytes;
    QString error;
    if (!irregularSidecar && QFileInfo::exists(sidecarPath) &&
        inputfile::readAll(sidecarPath, 64 * 1024, &bytes, &error,
                           QStringLiteral("recovery file"))) {
        const QJsonObject object = QJsonDocument::fromJson(bytes).object();
        info.originalPath = object.value(QStringLiteral("original_path")).toString();
        const QDateTime savedAt = QDateTime::fromString(
            object.value(QStringLiteral("saved_at")).toString(), Qt::ISODateWithMs);
        if (savedAt.isValid()) info.savedAt = savedAt.toUTC();
    } else if (!error.isEmpty() && problems) {
        *problems << error;
    }
    return info;
}

}  // namespace phasebox
