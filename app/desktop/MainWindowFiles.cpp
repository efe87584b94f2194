// MainWindow: files, examples, exports, settings and closing.

#include "app/desktop/MainWindow.h"

#include "app/document/Autosave.h"
#include "app/io/SceneIO.h"
#include "ui/canvas/SceneView.h"
#include "ui/plots/Charts.h"

#include <QAction>
#include <QChart>
#include <QChartView>
#include <QCloseEvent>
#include <QDir>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QMenu>
#include <QMessageBox>
#include <QMimeData>
#include <QSettings>
#include <QStandardPaths>

#include <memory>

namespace phasebox {

namespace {
constexpr int kMaxRecentFiles = 8;
const QString kSceneFilter = QObject::tr("Phasebox scenes (*.phasebox.json *.json);;All files (*)");

bool isSceneFile(const QString& path) {
    return path.endsWith(QLatin1String(".phasebox.json"), Qt::CaseInsensitive) ||
           path.endsWith(QLatin1String(".json"), Qt::CaseInsensitive);
}
}  // namespace

QStringList builtInScenes(const QString& folder) {
    QStringList paths;
    const QDir dir(folder);
    for (const QString& name : dir.entryList({QStringLiteral("*.json")}, QDir::Files, QDir::Name))
        paths.append(dir.filePath(name));
    return paths;
}

// ---- files -----------------------------------------------------------------------------------

void MainWindow::newScene() {
    if (!maybeSave()) return;
    controller_.pause();
    document_.newScene();
}

void MainWindow::open() {
    if (!maybeSave()) return;
    const QString dir = recentFiles_.isEmpty() ? QDir::homePath() : QFileInfo(recentFiles_.first()).path();
    const QString path = QFileDialog::getOpenFileName(this, tr("Open Scene"), dir, kSceneFilter);
    if (!path.isEmpty()) openFile(path);
}

bool MainWindow::openFile(const QString& path, bool quiet, QString* errorOut) {
    QString error;
    controller_.pause();
    if (!document_.load(path, &error)) {
        if (errorOut) *errorOut = error;
        statusMessage_->setText(tr("Could not open %1").arg(QFileInfo(path).fileName()));
        if (!quiet)
            QMessageBox::warning(this, tr("Could not open the scene"),
                                 tr("%1\n\nThe open scene is unchanged.").arg(error));
        return false;
    }
    if (!path.startsWith(QLatin1Char(':'))) addRecentFile(path);
    statusMessage_->setText(tr("Opened %1").arg(QFileInfo(path).fileName()));
    return true;
}

void MainWindow::openExample(const QString& path) {
    if (!maybeSave()) return;
    openFile(path);
}

bool MainWindow::save() {
    const QString path = document_.filePath();
    if (path.isEmpty() || path.startsWith(QLatin1Char(':'))) return saveAs();
    QString error;
    if (saveFile(path, &error)) return true;
    QMessageBox::warning(this, tr("Could not save"), error);
    return false;
}

bool MainWindow::saveAs() {
    QString suggestion = document_.filePath();
    if (suggestion.isEmpty() || suggestion.startsWith(QLatin1Char(':')))
        suggestion = QDir::home().filePath(
            (document_.setup().name.empty() ? QStringLiteral("scene")
                                            : QString::fromStdString(document_.setup().name)) +
            QStringLiteral(".phasebox.json"));
    QString path = QFileDialog::getSaveFileName(this, tr("Save Scene As"), suggestion, kSceneFilter);
    if (path.isEmpty()) return false;
    if (!isSceneFile(path)) path += QStringLiteral(".phasebox.json");
    QString error;
    if (saveFile(path, &error)) return true;
    QMessageBox::warning(this, tr("Could not save"), error);
    return false;
}

bool MainWindow::saveFile(const QString& path, QString* error) {
    QString message;
    if (!document_.save(path, &message)) {
        if (error) *error = tr("%1\n\nThe file on disk (if any) is unchanged.").arg(message);
        statusMessage_->setText(tr("Saving failed: %1").arg(message));
        return false;
    }
    addRecentFile(path);
    statusMessage_->setText(tr("Saved %1").arg(QDir::toNativeSeparators(path)));
    return true;
}

bool MainWindow::maybeSave() {
    if (!document_.isModified()) return true;
    const auto answer = QMessageBox::warning(
        this, tr("Phasebox"), tr("The scene has unsaved changes. Save them?"),
        QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel);
    if (answer == QMessageBox::Save) return save();
    return answer == QMessageBox::Discard;
}

void MainWindow::addRecentFile(const QString& path) {
    const QString absolute = QFileInfo(path).absoluteFilePath();
    recentFiles_.removeAll(absolute);
    recentFiles_.prepend(absolute);
    while (recentFiles_.size() > kMaxRecentFiles) recentFiles_.removeLast();
    updateRecentFilesMenu();
}

void MainWindow::updateRecentFilesMenu() {
    recentMenu_->clear();
    for (const QString& path : recentFiles_)
        recentMenu_->addAction(QFileInfo(path).fileName(), this, [this, path] {
            if (maybeSave()) openFile(path);
        })->setToolTip(path);
    recentMenu_->setEnabled(!recentFiles_.isEmpty());
}

// ---- drag and drop ---------------------------------------------------------------------------

void MainWindow::dragEnterEvent(QDragEnterEvent* event) {
    const auto urls = event->mimeData()->urls();
    if (urls.size() == 1 && urls.first().isLocalFile() && isSceneFile(urls.first().toLocalFile()))
        event->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent* event) {
    const auto urls = event->mimeData()->urls();
    if (urls.isEmpty() || !maybeSave()) return;
    openFile(urls.first().toLocalFile());
    event->acceptProposedAction();
}

// ---- exports ---------------------------------------------------------------------------------

bool MainWindow::exportPlot(ui::PlotsPanel::Plot plot, const QString& path, QString* error) {
    if (path.endsWith(QLatin1String(".csv"), Qt::CaseInsensitive)) {
        switch (plot) {
            case ui::PlotsPanel::Plot::Energy: return recorder_.writeEnergyCsv(path, error);
            case ui::PlotsPanel::Plot::Phase: return recorder_.writePhaseCsv(path, error);
            case ui::PlotsPanel::Plot::Error: return recorder_.writeErrorCsv(path, error);
        }
    }
    // The picture is made from the recorded samples in a chart of its own, not grabbed from
    // the screen, so it is complete even while the plots are paused or the dock is hidden.
    const auto& sim = document_.setup().simulation;
    std::unique_ptr<QChart> chart;
    if (plot == ui::PlotsPanel::Plot::Energy) {
        chart.reset(ui::createEnergyChart(recorder_.energySamples(), recorder_.markers(),
                                          tr("Energy (%1, dt %2 s)")
                                              .arg(QString::fromStdString(sim.integrator))
                                              .arg(sim.dt, 0, 'g', 4)));
    } else if (plot == ui::PlotsPanel::Plot::Error) {
        chart.reset(ui::createErrorChart(recorder_.errorSamples(),
                                         tr("Local error per step (%1, dt %2 s)")
                                             .arg(QString::fromStdString(sim.integrator))
                                             .arg(sim.dt / sim.substeps, 0, 'g', 4)));
    } else {
        const QString object = recorder_.phaseObject();
        if (object.isEmpty()) {
            if (error) *error = tr("no object chosen for the phase plot: click one on the canvas");
            return false;
        }
        const QString coordinate = object + QLatin1Char('.') + recorder_.phaseCoordinate();
        chart.reset(ui::createPhaseChart(recorder_.phaseSamples(), coordinate,
                                         object + QLatin1Char('.') + recorder_.phaseVelocityName(),
                                         tr("Phase space of %1 (%2)")
                                             .arg(coordinate, QString::fromStdString(sim.integrator))));
    }
    return ui::exportChart(chart.get(), path, QSize(1200, 800), error);
}

bool MainWindow::exportCanvas(const QString& path, QString* error) {
    const QImage image = canvas_->renderImage(canvas_->size().expandedTo(QSize(800, 600)));
    if (image.save(path, "PNG")) return true;
    if (error) *error = tr("could not write %1").arg(path);
    return false;
}

void MainWindow::exportPlotInteractively(ui::PlotsPanel::Plot plot, const QString& format) {
    const QString base = plot == ui::PlotsPanel::Plot::Energy  ? QStringLiteral("energy")
                         : plot == ui::PlotsPanel::Plot::Phase ? QStringLiteral("phase")
                                                               : QStringLiteral("error");
    const QString dir = QStandardPaths::writableLocation(QStandardPaths::PicturesLocation);
    const QString path = QFileDialog::getSaveFileName(
        this, tr("Export Plot"), QDir(dir).filePath(base + QLatin1Char('.') + format),
        format.toUpper() + QStringLiteral(" (*.") + format + QLatin1Char(')'));
    if (path.isEmpty()) return;
    QString error;
    if (!exportPlot(plot, path, &error)) QMessageBox::warning(this, tr("Export failed"), error);
    else statusMessage_->setText(tr("Wrote %1").arg(QDir::toNativeSeparators(path)));
}

void MainWindow::exportCanvasInteractively() {
    const QString dir = QStandardPaths::writableLocation(QStandardPaths::PicturesLocation);
    const QString path = QFileDialog::getSaveFileName(this, tr("Export Canvas"),
                                                      QDir(dir).filePath(QStringLiteral("scene.png")),
                                                      tr("PNG (*.png)"));
    if (path.isEmpty()) return;
    QString error;
    if (!exportCanvas(path, &error)) QMessageBox::warning(this, tr("Export failed"), error);
}

// ---- settings and closing --------------------------------------------------------------------

void MainWindow::readSettings() {
    QSettings settings;
    const QByteArray geometry = settings.value(QStringLiteral("window/geometry")).toByteArray();
    if (geometry.isEmpty()) resize(1400, 880);
    else restoreGeometry(geometry);
    restoreState(settings.value(QStringLiteral("window/state")).toByteArray());
    recentFiles_ = settings.value(QStringLiteral("recentFiles")).toStringList();
    updateRecentFilesMenu();
    const double speed = settings.value(QStringLiteral("simulation/speed"), 1.0).toDouble();
    controller_.setSpeed(speed);
    ui::RenderOptions options = canvas_->renderOptions();
    options.trails = settings.value(QStringLiteral("view/trails"), false).toBool();
    options.velocityArrows = settings.value(QStringLiteral("view/velocityArrows"), false).toBool();
    options.labels = settings.value(QStringLiteral("view/labels"), false).toBool();
    canvas_->setRenderOptions(options);
    action("trails")->setChecked(options.trails);
    action("velocityArrows")->setChecked(options.velocityArrows);
    action("labels")->setChecked(options.labels);
}

void MainWindow::writeSettings() {
    QSettings settings;
    settings.setValue(QStringLiteral("window/geometry"), saveGeometry());
    settings.setValue(QStringLiteral("window/state"), presentation_ ? normalState_ : saveState());
    settings.setValue(QStringLiteral("recentFiles"), recentFiles_);
    settings.setValue(QStringLiteral("simulation/speed"), controller_.speed());
    settings.setValue(QStringLiteral("view/trails"), canvas_->renderOptions().trails);
    settings.setValue(QStringLiteral("view/velocityArrows"), canvas_->renderOptions().velocityArrows);
    settings.setValue(QStringLiteral("view/labels"), canvas_->renderOptions().labels);
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
