#pragma once
// The ghost of a recorded run (Compare from here): another World, in the state the recorded run
// had at the live run's time, drawn over the scene through the same SceneRenderer in dimmed,
// translucent colours, so that both runs are seen at once and the live one stays the solid one.
// What does not move (planes, static bodies, pinned particles) is left out: it is drawn once.

#include "ui/canvas/SceneRenderer.h"

#include <QString>

namespace phasebox::ui {

// The live options turned into the ghost's: no grid, scale bar, labels, arrows, trails or
// highlights; every moving thing in a translucent grey.
RenderOptions ghostOptions(const RenderOptions& live);

void drawGhost(QPainter& painter, const ViewTransform& view, QSize viewportPixels,
               const World& ghost, const RenderOptions& live);

// One line naming the ghost, in the canvas's bottom right corner.
void drawGhostCaption(QPainter& painter, QSize viewportPixels, const QString& caption,
                      const RenderOptions& live);

}  // namespace phasebox::ui
