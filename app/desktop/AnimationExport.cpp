#include "app/desktop/AnimationExport.h"

#include "app/document/Document.h"
#include "app/sim/Recorder.h"
#include "app/sim/SimulationController.h"
#include "physics/scene/SceneDesc.h"
#include "ui/canvas/SceneView.h"

#include <QCheckBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QProgressDialog>
#include <QPushButton>
#include <QSpinBox>
#include <QStandardPaths>

namespace phasebox {

AnimationExportDialog::AnimationExportDialog(const QString& path, const ClipOptions& defaults,
                                             double maxSeconds, QWidget* parent)
    : QDialog(parent) {
    setWindowTitle(tr("Export Animation"));
    setObjectName(QStringLiteral("animationExportDialog"));
    auto* form = new QFormLayout(this);
    path_ = new QLineEdit(path, this);
    path_->setObjectName(QStringLiteral("clipPath"));
    path_->setAccessibleName(tr("Clip file"));
    path_->setToolTip(tr("A .mp4 file (H.264 video) or a .gif file (animated GIF)"));
    auto* browse = new QPushButton(tr("&Browse…"), this);
    connect(browse, &QPushButton::clicked, this, &AnimationExportDialog::browse);
    auto* fileRow = new QHBoxLayout;
    fileRow->addWidget(path_, 1);
    fileRow->addWidget(browse);
    path_->setMinimumWidth(fontMetrics().horizontalAdvance(QLatin1Char('x')) * 40);
    // A row of several widgets gets its label by hand: the form sets no buddy for a layout.
    auto* fileLabel = new QLabel(tr("&File:"), this);
    fileLabel->setBuddy(path_);
    form->addRow(fileLabel, fileRow);

    const auto seconds = [&](const char* name, const QString& accessible, double value,
                             double minimum) {
        auto* box = new QDoubleSpinBox(this);
        box->setObjectName(QLatin1String(name));
        box->setAccessibleName(accessible);
        box->setDecimals(3);
        box->setRange(minimum, maxSeconds);
        box->setSuffix(tr(" s"));
        box->setValue(value);
        return box;
    };
    from_ = seconds("clipFrom", tr("Start time"), defaults.from, 0.0);
    from_->setToolTip(tr("Simulated time of the first frame"));
    form->addRow(tr("Fro&m:"), from_);
    duration_ = seconds("clipDuration", tr("Duration"), defaults.duration, 0.001);
    duration_->setToolTip(tr("Simulated seconds the clip shows"));
    form->addRow(tr("&Duration:"), duration_);
    fps_ = new QSpinBox(this);
    fps_->setObjectName(QStringLiteral("clipFps"));
    fps_->setAccessibleName(tr("Frames per second"));
    fps_->setRange(1, kMaxClipFps);
    fps_->setValue(defaults.fps);
    fps_->setSuffix(tr(" fps"));
    form->addRow(tr("Frame &rate:"), fps_);
    width_ = new QSpinBox(this);
    height_ = new QSpinBox(this);
    for (auto [box, name, accessible, value] :
         {std::tuple{width_, "clipWidth", tr("Width in pixels"), defaults.size.width()},
          std::tuple{height_, "clipHeight", tr("Height in pixels"), defaults.size.height()}}) {
        box->setObjectName(QLatin1String(name));
        box->setAccessibleName(accessible);
        box->setRange(16, kMaxClipSide);
        box->setValue(value);
        box->setSuffix(tr(" px"));
    }
    auto* sizeRow = new QHBoxLayout;
    sizeRow->addWidget(width_);
    sizeRow->addWidget(new QLabel(QStringLiteral("×"), this));
    sizeRow->addWidget(height_);
    auto* sizeLabel = new QLabel(tr("&Size:"), this);
    sizeLabel->setBuddy(width_);
    form->addRow(sizeLabel, sizeRow);
    plots_ = new QCheckBox(tr("&Plots beside the canvas (energy and phase space)"), this);
    plots_->setObjectName(QStringLiteral("clipPlots"));
    plots_->setChecked(defaults.plots);
    form->addRow(plots_);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    buttons->button(QDialogButtonBox::Ok)->setText(tr("&Export"));
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    form->addRow(buttons);
}

QString AnimationExportDialog::path() const {
    return path_->text().trimmed();
}

ClipOptions AnimationExportDialog::options(ClipOptions base) const {
    base.from = from_->value();
    base.duration = duration_->value();
    base.fps = fps_->value();
    base.size = QSize(width_->value(), height_->value());
    base.plots = plots_->isChecked();
    return base;
}

void AnimationExportDialog::browse() {
    const QString chosen = QFileDialog::getSaveFileName(
        this, tr("Export Animation"), path(), tr("MP4 video (*.mp4);;Animated GIF (*.gif)"));
    if (!chosen.isEmpty()) path_->setText(chosen);
}

AnimationExport::AnimationExport(Document& document, ui::SceneView& canvas, Recorder& recorder,
                                 SimulationController& controller, QWidget& window)
    : QObject(&window),
      document_(document),
      canvas_(canvas),
      recorder_(recorder),
      controller_(controller),
      window_(window) {
    setObjectName(QStringLiteral("animationExport"));
}

ClipOptions AnimationExport::defaults() const {
    ClipOptions o;
    o.duration = document_.setup().simulation.duration;
    o.view = canvas_.view();
    o.renderOptions = canvas_.renderOptions();
    // What the canvas shows of the moment, not of the clip: hover and selection highlights.
    o.renderOptions.hoveredId.clear();
    o.phaseObject = recorder_.phaseObject();
    o.phaseCoordinate = recorder_.phaseCoordinate();
    return o;
}

ClipResult AnimationExport::exportClip(const QString& path, const ClipOptions& options) {
    ClipResult refused;
    refused.status = ClipResult::WriteFailed;
    const std::optional<ClipFormat> format = clipFormatOf(path);
    if (!format) {
        refused.message = tr("%1: unknown clip format; known: %2")
                              .arg(QFileInfo(path).fileName(), clipFormatList());
        return refused;
    }
    if (const QString problem = clipOptionsProblem(*format, options); !problem.isEmpty()) {
        refused.message = problem;
        return refused;
    }
    if (!document_.mayWriteOutput(path, &refused.message)) return refused;
    // The clip has its own world; the live run would only take time from it while the
    // progress dialog lets events through, so it waits and goes on afterwards.
    const bool wasRunning = controller_.isRunning();
    if (wasRunning) controller_.pause();
    const int frames = clipFrameCount(options.duration, options.fps);
    QProgressDialog progress(tr("Exporting %1…").arg(QFileInfo(path).fileName()), tr("Cancel"), 0,
                             frames, &window_);
    progress.setObjectName(QStringLiteral("animationProgress"));
    progress.setWindowModality(Qt::WindowModal);
    progress.setMinimumDuration(0);
    progress.setAutoReset(false);
    progress.setValue(0);
    const ClipResult result =
        renderClip(document_.setup(), options, path, [&progress](int done, int) {
            progress.setValue(done);  // a window-modal dialog processes events here
            return !progress.wasCanceled();
        });
    if (wasRunning) controller_.play();
    switch (result.status) {
        case ClipResult::Written:
            emit message(tr("Wrote %1 (%2 frames)").arg(path).arg(result.frames));
            break;
        case ClipResult::Diverged:
            emit message(tr("Wrote %1; the run diverged: %2").arg(path, result.message));
            break;
        case ClipResult::Cancelled:
        case ClipResult::Interrupted:
            emit message(tr("Export cancelled; nothing was written"));
            break;
        case ClipResult::WriteFailed:
            break;
    }
    return result;
}

void AnimationExport::exportInteractively() {
    QString path = lastPath_;
    if (path.isEmpty()) {
        const QString dir = QStandardPaths::writableLocation(QStandardPaths::MoviesLocation);
        path = QDir(dir).filePath(QStringLiteral("scene.mp4"));
    }
    AnimationExportDialog dialog(path, defaults(), 1e6, &window_);
    if (dialog.exec() != QDialog::Accepted) return;
    lastPath_ = dialog.path();
    const ClipResult result = exportClip(dialog.path(), dialog.options(defaults()));
    if (result.status == ClipResult::WriteFailed)
        QMessageBox::warning(&window_, tr("Export failed"), result.message);
}

}  // namespace phasebox
