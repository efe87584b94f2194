#pragma once
// The main window's docks and columns: the docks as they are added, the widths of the left and
// right columns on the first show, a canvas kept at least kCanvasShare of the window's width,
// and presentation mode (full screen, larger text, only the canvas, plots and instruments).
// It follows the window's show and resize events itself (an event filter), so that MainWindow
// only composes.

#include <QByteArray>
#include <QList>
#include <QObject>
#include <QPointer>
#include <QString>

QT_BEGIN_NAMESPACE
class QDockWidget;
class QMainWindow;
class QWidget;
QT_END_NAMESPACE

namespace phasebox {

class WindowLayout : public QObject {
    Q_OBJECT

public:
    // The canvas is the window's central area (or in it); the layout is the window's child.
    WindowLayout(QMainWindow& window, QWidget& canvas);

    QDockWidget* addDock(QWidget* widget, const QString& title, const QString& name,
                         Qt::DockWidgetArea area);
    const QList<QDockWidget*>& docks() const { return docks_; }
    // The docks whose widths the first show sets (280 and 420 px) and keepCanvasWide() narrows.
    void setColumns(QDockWidget* left, QDockWidget* right);

    // The docks' layout from the settings; true when it applied (then the first show keeps
    // the user's widths). stateToSave() is the layout to store: in presentation mode, the one
    // before it.
    bool restoreState(const QByteArray& state);
    QByteArray stateToSave() const;

    // Presentation mode: full screen and text 1.4 times larger, the other docks and the tool
    // bars hidden; leaving it brings the layout back. False when it was already so.
    bool setPresentation(bool on);
    bool presentation() const { return presentation_; }

    static constexpr double kCanvasShare = 0.5;

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void shown();
    // Gives the canvas at least kCanvasShare of the window's width (from the side docks).
    void keepCanvasWide();

    QMainWindow& window_;
    QWidget& canvas_;
    QList<QDockWidget*> docks_;
    QPointer<QDockWidget> leftDock_, rightDock_;
    // The docks' layout came from the settings (else the first show sets the columns' widths).
    bool layoutRestored_ = false;
    bool shownOnce_ = false;
    QByteArray normalState_;  // dock layout before presentation mode
    bool presentation_ = false;
};

}  // namespace phasebox
