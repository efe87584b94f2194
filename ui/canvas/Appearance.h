#pragma once
// How the window looks in front of a class: a high-contrast theme, and line and text scales for
// the canvas and the plots that do not depend on the system's font (a projector across a room
// needs thicker lines, not a larger menu bar). The colours of both themes keep every pair that
// matters apart for the common colour blindnesses: they come from the Okabe–Ito palette, whose
// eight colours stay distinct under protanopia, deuteranopia and tritanopia, and where two
// lines could still be confused they differ in dash or width as well, never in hue alone.

#include "ui/canvas/SceneRenderer.h"

#include <QColor>
#include <QPalette>

namespace phasebox::ui {

struct Appearance {
    bool highContrast = false;
    double lineScale = 1.0;  // line widths of the canvas and the plots
    double textScale = 1.0;  // text of the canvas and the plots
    bool operator==(const Appearance&) const = default;
};

// The scales a user may choose (View > Line Width, Text Size), from 1 to 3.
inline constexpr double kAppearanceScales[] = {1.0, 1.5, 2.0, 3.0};
inline constexpr double kMinAppearanceScale = 0.5;
inline constexpr double kMaxAppearanceScale = 4.0;

// The Okabe–Ito colours (Okabe & Ito 2008, "Color Universal Design").
namespace okabeIto {
inline const QColor black{0x00, 0x00, 0x00};
inline const QColor orange{0xe6, 0x9f, 0x00};
inline const QColor skyBlue{0x56, 0xb4, 0xe9};
inline const QColor bluishGreen{0x00, 0x9e, 0x73};
inline const QColor yellow{0xf0, 0xe4, 0x42};
inline const QColor blue{0x00, 0x72, 0xb2};
inline const QColor vermillion{0xd5, 0x5e, 0x00};
inline const QColor reddishPurple{0xcc, 0x79, 0xa7};
}  // namespace okabeIto

// The canvas's colours and background in either theme.
SceneColors sceneColors(bool highContrast);
QColor canvasBackground(bool highContrast);
// White text on black, yellow selection and focus: the whole window in the high-contrast theme.
QPalette highContrastPalette();

// The plots' look, for every chart made after the call (Charts.h): the app sets it from its
// View menu; the command line never does, so the plots it writes keep the default.
void setChartAppearance(const Appearance& appearance);
const Appearance& chartAppearance();

}  // namespace phasebox::ui
