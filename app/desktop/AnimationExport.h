#pragma once
// File > Export Animation: the run drawn as an MP4 (H.264) or animated GIF clip (CONTRACT.md
// §8) with the canvas's view and drawing options, optionally with the energy and phase plots
// beside it, for a chosen time range, frame rate and size, with a progress bar and Cancel.
// The clip runs the scene from its setup with its settings (app/clips/ClipRenderer), so the
// live run goes on untouched; a failed or cancelled clip leaves no file and the app running.

#include "app/clips/ClipRenderer.h"

#include <QDialog>
#include <QObject>

QT_BEGIN_NAMESPACE
class QCheckBox;
class QDoubleSpinBox;
class QLineEdit;
class QSpinBox;
QT_END_NAMESPACE

namespace phasebox {

class Document;
class Recorder;
class SimulationController;
namespace ui {
class SceneView;
}

// The dialog's fields: the file, the time range, the frame rate, the size and the plots.
class AnimationExportDialog : public QDialog {
    Q_OBJECT

public:
    AnimationExportDialog(const QString& path, const ClipOptions& defaults, double maxSeconds,
                          QWidget* parent = nullptr);
    QString path() const;
    // The options as entered (the view and drawing options are the caller's).
    ClipOptions options(ClipOptions base) const;

private:
    void browse();

    QLineEdit* path_ = nullptr;
    QDoubleSpinBox* from_ = nullptr;
    QDoubleSpinBox* duration_ = nullptr;
    QSpinBox* fps_ = nullptr;
    QSpinBox* width_ = nullptr;
    QSpinBox* height_ = nullptr;
    QCheckBox* plots_ = nullptr;
};

class AnimationExport : public QObject {
    Q_OBJECT

public:
    AnimationExport(Document& document, ui::SceneView& canvas, Recorder& recorder,
                    SimulationController& controller, QWidget& window);

    // From 0 for the scene's duration at 30 fps, 1280 × 720, with the canvas's view and
    // drawing options and the phase plot's object.
    ClipOptions defaults() const;
    // Writes the clip with a progress dialog whose Cancel stops it (and removes the partial
    // file); the live run pauses meanwhile and then goes on. A problem with the options or the file
    // is in the result (WriteFailed) without anything written.
    ClipResult exportClip(const QString& path, const ClipOptions& options);
    // Asks for the file and options, exports, and reports a failure in a message box.
    void exportInteractively();

signals:
    // For the status bar: what was written, or that it was cancelled.
    void message(const QString& text);

private:
    Document& document_;
    ui::SceneView& canvas_;
    Recorder& recorder_;
    SimulationController& controller_;
    QWidget& window_;
    QString lastPath_;
};

}  // namespace phasebox
