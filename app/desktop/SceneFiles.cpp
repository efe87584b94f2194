#include "app/desktop/SceneFiles.h"

#include "app/desktop/SceneLibraryMenu.h"
#include "app/document/Autosave.h"
#include "app/document/Document.h"
#include "app/io/SceneIO.h"
#include "app/sim/SimulationController.h"
#include "ui/panels/DisplayText.h"

#include <QDebug>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QLocale>
#include <QMessageBox>
#include <QWidget>

namespace phasebox {

namespace {
QString sceneFilter() {
    return QObject::tr("Phasebox scenes (*.phasebox.json *.json);;All files (*)");
}
bool isBuiltIn(const QString& path) {
    return path.startsWith(QLatin1Char(':'));
}
}  // namespace

SceneFiles::SceneFiles(QWidget& window, Document& document, SimulationController& controller,
                       QMenu& recentMenu)
    : QObject(&window), window_(window), document_(document), controller_(controller) {
    recent_ = new RecentFiles(
        recentMenu, [this](const QString& path) { emit recentFileChosen(path); }, this);
}

bool SceneFiles::isSceneFile(const QString& path) {
    return path.endsWith(QLatin1String(".json"), Qt::CaseInsensitive);  // .phasebox.json too
}

bool SceneFiles::open(const QString& path, bool quiet, QString* errorOut) {
    QString error;
    controller_.pause();
    if (!document_.load(path, &error)) {
        if (errorOut) *errorOut = error;
        emit message(tr("Could not open %1").arg(QFileInfo(path).fileName()));
        if (!quiet)
            QMessageBox::warning(&window_, tr("Could not open the scene"),
                                 tr("%1\n\nThe open scene is unchanged.").arg(error));
        return false;
    }
    if (!isBuiltIn(path)) recent_->add(path);
    emit message(tr("Opened %1").arg(QFileInfo(path).fileName()));
    return true;
}

void SceneFiles::openInteractively() {
    const QStringList recent = recent_->paths();
    const QString dir = recent.isEmpty() ? QDir::homePath() : QFileInfo(recent.first()).path();
    const QString path =
        QFileDialog::getOpenFileName(&window_, tr("Open Scene"), dir, sceneFilter());
    if (!path.isEmpty()) open(path);
}

bool SceneFiles::save() {
    const QString path = document_.filePath();
    if (path.isEmpty() || isBuiltIn(path)) return saveAs();
    QString error;
    return warnUnsaved(saveTo(path, &error), error);
}

bool SceneFiles::saveAs() {
    QString suggestion = document_.filePath();
    if (suggestion.isEmpty() || isBuiltIn(suggestion)) {
        const std::string& name = document_.setup().name;
        suggestion = QDir::home().filePath(
            (name.empty() ? QStringLiteral("scene") : QString::fromStdString(name)) +
            QStringLiteral(".phasebox.json"));
    }
    QString path =
        QFileDialog::getSaveFileName(&window_, tr("Save Scene As"), suggestion, sceneFilter());
    if (path.isEmpty()) return false;
    if (!isSceneFile(path)) path += QStringLiteral(".phasebox.json");
    QString error;
    return warnUnsaved(saveTo(path, &error), error);
}

bool SceneFiles::warnUnsaved(bool ok, const QString& error) {
    if (!ok) QMessageBox::warning(&window_, tr("Could not save"), error);
    return ok;
}

bool SceneFiles::saveTo(const QString& path, QString* error) {
    QString message;
    if (!document_.save(path, &message)) {
        if (error) *error = tr("%1\n\nThe file on disk (if any) is unchanged.").arg(message);
        emit this->message(tr("Saving failed: %1").arg(message));
        return false;
    }
    recent_->add(path);
    emit this->message(tr("Saved %1").arg(QDir::toNativeSeparators(path)));
    return true;
}

void SceneFiles::offerRecovery(const QString& recoveryDir) {
    QStringList problems;
    const auto recovery = Autosave::findRecovery(recoveryDir, &problems);
    for (const QString& problem : std::as_const(problems)) {
        qWarning().noquote() << "phasebox:" << problem;
        emit message(problem);
    }
    if (!recovery) return;
    const QString from =
        recovery->originalPath.isEmpty()
            ? tr("an unsaved scene")
            : ui::shownText(QDir::toNativeSeparators(recovery->originalPath), 1000);
    const QString when = QLocale().toString(recovery->savedAt.toLocalTime(), QLocale::ShortFormat);
    const auto answer = QMessageBox::question(
        &window_, tr("Recover the last scene?"),
        tr("Phasebox did not close properly last time. An autosave of %1 from %2 is available. "
           "Open it?")
            .arg(from, when),
        QMessageBox::Open | QMessageBox::Discard, QMessageBox::Open);
    if (answer != QMessageBox::Open) {
        Autosave::removeRecovery(recoveryDir);
        return;
    }
    const SceneLoadResult loaded = SceneIO::load(recovery->recoveryFile);
    QString error;
    if (loaded.ok() && document_.loadFromDesc(*loaded.scene, recovery->originalPath, &error))
        emit message(tr("Recovered from the autosave: save it to keep it."));
    else  // the recovery file stays for another try
        QMessageBox::warning(&window_, tr("Could not recover"),
                             loaded.ok() ? error : loaded.errorText());
}

void SceneFiles::readSettings(const QSettings& settings) {
    recent_->readSettings(settings);
}

void SceneFiles::writeSettings(QSettings& settings) const {
    recent_->writeSettings(settings);
}

}  // namespace phasebox
