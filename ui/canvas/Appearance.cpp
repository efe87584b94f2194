#include "ui/canvas/Appearance.h"

namespace phasebox::ui {

namespace {
Appearance& currentChartAppearance() {
    static Appearance appearance;
    return appearance;
}
}  // namespace

SceneColors sceneColors(bool highContrast) {
    if (!highContrast) return SceneColors{};
    // On black: light or saturated strokes, the selection in yellow (the focus colour of the
    // high-contrast palette), every object outlined bright enough for a washed-out projector.
    SceneColors c;
    c.grid = QColor(0x30, 0x30, 0x30);
    c.axis = QColor(0x80, 0x80, 0x80);
    c.particle = okabeIto::skyBlue;
    c.pinnedParticle = QColor(0xe0, 0xe0, 0xe0);
    c.dynamicBox = okabeIto::orange;
    c.staticBox = QColor(0x90, 0x90, 0x90);
    c.plane = QColor(0x38, 0x38, 0x38);
    c.planeBorder = QColor(0xff, 0xff, 0xff);
    c.springCompressed = okabeIto::skyBlue;
    c.springRest = QColor(0xc0, 0xc0, 0xc0);
    c.springStretched = okabeIto::vermillion;
    c.cloth = QColor(0xd0, 0xd0, 0xd0);
    c.anchor = QColor(0xff, 0xff, 0xff);
    c.joint = QColor(0xe8, 0xe8, 0xe8);
    c.rope = okabeIto::orange;
    c.track = okabeIto::skyBlue;
    c.velocity = okabeIto::bluishGreen;
    c.force = okabeIto::reddishPurple;
    c.selection = okabeIto::yellow;
    c.hover = QColor(0xff, 0xf7, 0xa8);
    c.text = QColor(0xff, 0xff, 0xff);
    c.backdrop = QColor(0x00, 0x00, 0x00, 0xd8);
    return c;
}

QColor canvasBackground(bool highContrast) {
    return highContrast ? QColor(0x00, 0x00, 0x00) : RenderOptions{}.background;
}

QPalette highContrastPalette() {
    const QColor black(0x00, 0x00, 0x00), white(0xff, 0xff, 0xff), grey(0xa0, 0xa0, 0xa0);
    QPalette p;
    for (const QPalette::ColorGroup group : {QPalette::Active, QPalette::Inactive}) {
        p.setColor(group, QPalette::Window, black);
        p.setColor(group, QPalette::WindowText, white);
        p.setColor(group, QPalette::Base, black);
        p.setColor(group, QPalette::AlternateBase, QColor(0x20, 0x20, 0x20));
        p.setColor(group, QPalette::Text, white);
        p.setColor(group, QPalette::Button, QColor(0x18, 0x18, 0x18));
        p.setColor(group, QPalette::ButtonText, white);
        p.setColor(group, QPalette::BrightText, okabeIto::yellow);
        p.setColor(group, QPalette::Highlight, okabeIto::yellow);
        p.setColor(group, QPalette::HighlightedText, black);
        p.setColor(group, QPalette::ToolTipBase, black);
        p.setColor(group, QPalette::ToolTipText, white);
        p.setColor(group, QPalette::PlaceholderText, grey);
        p.setColor(group, QPalette::Link, okabeIto::skyBlue);
        p.setColor(group, QPalette::LinkVisited, okabeIto::reddishPurple);
        p.setColor(group, QPalette::Light, white);
        p.setColor(group, QPalette::Midlight, grey);
        p.setColor(group, QPalette::Mid, grey);
        p.setColor(group, QPalette::Dark, grey);
        p.setColor(group, QPalette::Shadow, white);
    }
    p.setColor(QPalette::Disabled, QPalette::Window, black);
    p.setColor(QPalette::Disabled, QPalette::Base, black);
    p.setColor(QPalette::Disabled, QPalette::Button, QColor(0x18, 0x18, 0x18));
    for (const QPalette::ColorRole role :
         {QPalette::WindowText, QPalette::Text, QPalette::ButtonText, QPalette::Highlight})
        p.setColor(QPalette::Disabled, role, grey);
    return p;
}

void setChartAppearance(const Appearance& appearance) {
    currentChartAppearance() = appearance;
}

const Appearance& chartAppearance() {
    return currentChartAppearance();
}

}  // namespace phasebox::ui
