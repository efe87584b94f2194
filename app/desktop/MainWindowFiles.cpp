// MainWindow: files, settings and closing (the settings files are checked by SettingsGuard).

#include "app/desktop/MainWindow.h"

#include "app/desktop/MeasureTools.h"
#include "app/desktop/SceneFiles.h"
#include "app/desktop/SettingsGuard.h"
#include "app/desktop/WindowLayout.h"
#include "app/desktop/WorkerMenu.h"
#include "app/desktop/presenters/AppearancePresenter.h"
#include "app/desktop/presenters/CanvasPresenter.h"
#include "app/desktop/presenters/InstrumentsPresenter.h"
#include "app/desktop/presenters/ParametersPresenter.h"
#include "app/desktop/presenters/PlotsPresenter.h"
#include "app/desktop/presenters/StatusPresenter.h"
#include "app/document/Autosave.h"
#include "app/i18n/Language.h"
#include "ui/canvas/SceneView.h"

#include <QApplication>
#include <QCloseEvent>
#include <QDebug>
#include <QDockWidget>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFileInfo>
#include <QMessageBox>
#include <QMimeData>
#include <QSettings>
#include <QTimer>

namespace phasebox {

bool MainWindow::openFile(const QString& path, bool quiet, QString* error) {
    return files_->open(path, quiet, error);
}

bool MainWindow::saveFile(const QString& path, QString* error) {
    return files_->saveTo(path, error);
}

bool MainWindow::revert() {
    const QString path = document_.filePath();
    if (path.isEmpty()) return false;
    if (document_.isModified() && isVisible() &&
        !QApplication::platformName().startsWith(QLatin1String("offscreen"))) {
        const auto answer =
            QMessageBox::question(this, tr("Revert"),
                                  tr("Drop your changes and reopen %1 as it was last saved?")
                                      .arg(QFileInfo(path).fileName()),
                                  QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Cancel);
        if (answer != QMessageBox::Discard) return false;
    }
    controller_.pause();
    return openFile(path);
}

void MainWindow::offerRecovery() {
    files_->offerRecovery(autosave_->recoveryDir());
}

bool MainWindow::exportPlot(ui::PlotsPanel::Plot plot, const QString& path, QString* error) {
    return plotsPresenter_->exportPlot(plot, path, error);
}

bool MainWindow::exportCanvas(const QString& path, QString* error) {
    return canvasPresenter_->exportPicture(path, error);
}

void MainWindow::connectLessonInstruments() {
    document_.setInstrumentsSource([this] { return currentInstruments(); });
    // After the presenters have set theirs (they connected first).
    connect(&document_, &Document::instrumentsLoaded, this, [this] {
        const InstrumentsDesc& in = document_.loadedInstruments();
        if (in.view) {
            const ViewDesc& v = *in.view;
            canvas_->showWidth(QPointF(v.center[0], v.center[1]), v.width);
        }
        // No plots named: the energy and phase plots, as a new window shows them.
        plots_->showLowerPlot(ui::PlotsPanel::Plot::Phase);
        if (in.plots.empty()) return;
        QDockWidget* dock = findChild<QDockWidget*>(QStringLiteral("plotsDock"));
        for (const std::string& name : in.plots) {
            if (name == kPlotNames[0]) continue;
            plots_->showLowerPlot(name == kPlotNames[2] ? ui::PlotsPanel::Plot::Error
                                                        : ui::PlotsPanel::Plot::Phase);
        }
        if (dock) {
            dock->show();
            dock->raise();
        }
    });
}

InstrumentsDesc MainWindow::currentInstruments() const {
    InstrumentsDesc in;
    instrumentsPresenter_->collectInstruments(in);
    measure_->collectInstruments(in);
    // The view and the plots are written only when chosen, so that a scene without
    // instruments saves as it was (version 1 stays version 1).
    if (canvas_->isChosenView()) {
        const ui::ViewTransform view = canvas_->view();
        in.view = ViewDesc{{view.centre().x(), view.centre().y()}, canvas_->shownWidth()};
    }
    if (plots_->lowerPlot() == ui::PlotsPanel::Plot::Error)
        in.plots = {std::string(kPlotNames[0]), std::string(kPlotNames[2])};
    return in;
}

void MainWindow::newScene() {
    if (!maybeSave()) return;
    controller_.pause();
    document_.newScene();
}

void MainWindow::openIfSaved(const QString& path) {
    if (maybeSave()) openFile(path);
}

bool MainWindow::maybeSave() {
    if (!document_.isModified()) return true;
    const auto answer =
        QMessageBox::warning(this, tr("Phasebox"), tr("The scene has unsaved changes. Save them?"),
                             QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel);
    if (answer == QMessageBox::Save) return files_->save();
    return answer == QMessageBox::Discard;
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event) {
    const auto urls = event->mimeData()->urls();
    if (urls.size() == 1 && urls.first().isLocalFile() &&
        SceneFiles::isSceneFile(urls.first().toLocalFile()))
        event->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent* event) {
    const auto urls = event->mimeData()->urls();
    if (urls.isEmpty() || !maybeSave()) return;
    openFile(urls.first().toLocalFile());
    event->acceptProposedAction();
}

QString MainWindow::storedLanguage() {
    QStringList problems;
    if (!guardSettingsFiles(&problems, false)) return {};  // readSettings() repairs and says so
    const QSettings settings;
    return i18n::storedLanguage(settings);
}

void MainWindow::readSettings() {
    QStringList problems;
    const bool safe = guardSettingsFiles(&problems);
    for (const QString& problem : problems) qWarning().noquote() << "phasebox:" << problem;
    if (!problems.isEmpty())
        QTimer::singleShot(0, this, [this, problems] { status_->showMessage(problems.join(' ')); });
    if (!safe) {  // a file that could not be removed or moved aside: nothing is read from it
        resize(1400, 880);
        return;
    }
    const QSettings settings;
    // No saved geometry (the first start), one that is not ours (Qt's is under 100 bytes, its
    // dock state a few kilobytes) or one that no longer fits: a size that shows it all.
    const QByteArray geometry = settings.value(QStringLiteral("window/geometry")).toByteArray();
    if (geometry.size() > 4096 || !restoreGeometry(geometry) || width() < 320 || height() < 240 ||
        width() > 16384 || height() > 16384)
        resize(1400, 880);
    if (const QByteArray state = settings.value(QStringLiteral("window/state")).toByteArray();
        state.size() <= 256 * 1024)
        layout_->restoreState(state);
    files_->readSettings(settings);
    parametersPresenter_->readSettings(settings);
    canvasPresenter_->readSettings(settings);
    appearance_->readSettings(settings);
    workerMenu_->readSettings(settings);
}

void MainWindow::writeSettings() {
    QSettings settings;
    settings.setValue(QStringLiteral("window/geometry"), saveGeometry());
    settings.setValue(QStringLiteral("window/state"), layout_->stateToSave());
    files_->writeSettings(settings);
    parametersPresenter_->writeSettings(settings);
    canvasPresenter_->writeSettings(settings);
    appearance_->writeSettings(settings);
}

void MainWindow::closeEvent(QCloseEvent* event) {
    if (!maybeSave()) {
        event->ignore();
        return;
    }
    controller_.pause();
    writeSettings();
    autosave_->discard();  // a clean exit: nothing to recover next time
    event->accept();
}

}  // namespace phasebox
