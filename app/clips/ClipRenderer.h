#pragma once
// Draws a run as a clip (CONTRACT.md §8): N = round(duration·fps) frames at
// t = from + k/fps, each the state after the last step with t_step ≤ t, drawn by the canvas's
// own drawing code (SceneView::renderImage, the HUD line included) and, with plots, the energy
// and phase plots of Charts.h beside it, as the Plots dock shows them up to that moment. Used
// by `phasebox-cli render` and the app's File > Export Animation.
//
// The run starts from the scene's setup (what Reset returns to) with its settings: the same
// scene and settings give the same bits, so the clip is the run the app makes of them. Needs a
// QApplication (the canvas and Qt Charts draw through widgets; offscreen is enough).

#include "app/clips/ClipEncoder.h"
#include "ui/canvas/SceneRenderer.h"
#include "ui/canvas/ViewTransform.h"

#include <QSize>
#include <QString>

#include <functional>
#include <optional>

namespace phasebox {

struct SceneDesc;

struct ClipOptions {
    double from = 0.0;      // seconds of simulated time before the first frame
    double duration = 0.0;  // seconds of simulated time the clip shows (> 0)
    int fps = 30;
    QSize size{1280, 720};
    bool plots = false;  // the energy and phase plots beside the canvas
    // The canvas's view (its widget size included) and drawing options, as the app's canvas
    // has them; absent, the view frames everything that moves between from and from + duration.
    std::optional<ui::ViewTransform> view;
    ui::RenderOptions renderOptions;
    // The phase plot's object and coordinate (x, y or angle); empty: the particle (not of a
    // cloth) or body that travels farthest along x or y over the clip, along that axis.
    QString phaseObject, phaseCoordinate;
    // The world's worker threads (World::setWorkers; 0: every core). The frames are the same
    // for any number.
    int workers = 0;
};

// The clip's frame count, round(duration·fps).
int clipFrameCount(double duration, int fps);
// Largest values accepted for a clip, so that a typo cannot ask for days of encoding.
inline constexpr int kMaxClipFps = 120;
inline constexpr int kMaxClipSide = 7680;
inline constexpr int kMaxClipFrames = 100'000;
// Why options cannot make a clip in format (no frame, too many, a size the format refuses), or
// an empty string.
QString clipOptionsProblem(ClipFormat format, const ClipOptions& options);

struct ClipResult {
    enum Status { Written, Diverged, Cancelled, Interrupted, WriteFailed };
    Status status = Written;
    // Diverged: the world's report (the clip is written; after the runaway the frames show the
    // restored state). WriteFailed: "PATH: cannot write …" or the encoder's reason.
    QString message;
    int frames = 0;  // frames drawn
};

// progress(done, total) after each frame; returning false cancels. A cancelled, interrupted
// or failed clip leaves no file (an earlier file of that name stays whole). The scene must
// build (buildWorld does not throw).
ClipResult renderClip(const SceneDesc& scene, const ClipOptions& options, const QString& path,
                      const std::function<bool(int done, int total)>& progress = {});

}  // namespace phasebox
