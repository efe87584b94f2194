#include "app/desktop/WindowLayout.h"

#include <QApplication>
#include <QDockWidget>
#include <QEvent>
#include <QMainWindow>
#include <QTabBar>
#include <QTimer>
#include <QToolBar>

#include <algorithm>
#include <cmath>
#include <utility>

namespace phasebox {

WindowLayout::WindowLayout(QMainWindow& window, QWidget& canvas)
    : QObject(&window), window_(window), canvas_(canvas) {
    setObjectName(QStringLiteral("windowLayout"));
    window.installEventFilter(this);
}

QDockWidget* WindowLayout::addDock(QWidget* widget, const QString& title, const QString& name,
                                   Qt::DockWidgetArea area) {
    auto* dock = new QDockWidget(title, &window_);
    dock->setObjectName(name);
    dock->setWidget(widget);
    window_.addDockWidget(area, dock);
    docks_.append(dock);
    return dock;
}

void WindowLayout::setColumns(QDockWidget* left, QDockWidget* right) {
    leftDock_ = left;
    rightDock_ = right;
}

bool WindowLayout::restoreState(const QByteArray& state) {
    layoutRestored_ = window_.restoreState(state);
    return layoutRestored_;
}

QByteArray WindowLayout::stateToSave() const {
    return presentation_ ? normalState_ : window_.saveState();
}

bool WindowLayout::eventFilter(QObject* watched, QEvent* event) {
    if (watched == &window_) {
        if (event->type() == QEvent::Show)
            shown();
        else if (event->type() == QEvent::Resize)  // after the layout has settled at the size
            QTimer::singleShot(0, this, &WindowLayout::keepCanvasWide);
    }
    return QObject::eventFilter(watched, event);
}

void WindowLayout::shown() {
    // Tabbed docks show their whole titles, with scroll buttons when they do not fit, rather
    // than cut to "Eig…" (German and French titles are longer than the English ones).
    // A little less padding than the style's lets the left column's three tabs fit at 1024 x 700.
    for (QTabBar* bar : window_.findChildren<QTabBar*>()) {
        bar->setElideMode(Qt::ElideNone);
        bar->setUsesScrollButtons(true);
        if (qobject_cast<QMainWindow*>(bar->parentWidget()))
            bar->setStyleSheet(QStringLiteral("QTabBar::tab { padding: 4px 7px; }"));
    }
    // The columns' widths set while the window was built were clamped to a default-sized
    // window's; the first show gives them theirs, unless the settings brought the user's own.
    if (std::exchange(shownOnce_, true) || layoutRestored_ || !leftDock_ || !rightDock_) return;
    QTimer::singleShot(0, this, [this] {  // once the layout is live
        if (leftDock_ && rightDock_)
            window_.resizeDocks({leftDock_.data(), rightDock_.data()}, {280, 420}, Qt::Horizontal);
        keepCanvasWide();  // then a small window's canvas its share again
    });
}

// QMainWindow takes a smaller window's width from the central widget first, so at 1024 px the
// docks' 700 px left the canvas 300. When the canvas has less than kCanvasShare of the window,
// the side docks give up what it lacks, each in proportion to what it has above its minimum; a
// dock the user widened on a large window is left alone.
void WindowLayout::keepCanvasWide() {
    if (window_.isFullScreen()) return;
    const int lacking = static_cast<int>(kCanvasShare * window_.width()) - canvas_.width();
    if (lacking <= 0) return;
    QList<QDockWidget*> docks;
    QList<int> widths, slacks;
    int totalSlack = 0;
    for (QDockWidget* dock : {leftDock_.data(), rightDock_.data()}) {
        if (!dock || !dock->isVisible() || dock->isFloating()) continue;
        const int least = std::max(dock->minimumSizeHint().width(), dock->minimumWidth());
        docks << dock;
        widths << dock->width();
        slacks << std::max(0, dock->width() - least);
        totalSlack += slacks.back();
    }
    if (totalSlack <= 0) return;
    const int cut = std::min(lacking, totalSlack);
    for (qsizetype i = 0; i < docks.size(); ++i)
        widths[i] -= static_cast<int>(std::ceil(double(cut) * slacks[i] / totalSlack));
    window_.resizeDocks(docks, widths, Qt::Horizontal);
}

bool WindowLayout::setPresentation(bool on) {
    if (on == presentation_) return false;
    presentation_ = on;
    QFont font = QApplication::font();
    font.setPointSizeF(on ? font.pointSizeF() * 1.4 : font.pointSizeF() / 1.4);
    QApplication::setFont(font);
    if (on) {
        normalState_ = window_.saveState();
        // In front of a class the canvas, the plots and the instruments are what matter; every
        // other control stays on the keyboard (Simulation menu) and comes back with the layout on
        // exit.
        for (QDockWidget* dock : std::as_const(docks_))
            if (dock->objectName() != QLatin1String("plotsDock") &&
                dock->objectName() != QLatin1String("instrumentsDock"))
                dock->hide();
        for (QToolBar* bar : window_.findChildren<QToolBar*>()) bar->hide();
        window_.showFullScreen();
    } else {
        window_.showNormal();
        window_.restoreState(normalState_);
    }
    return true;
}

}  // namespace phasebox
