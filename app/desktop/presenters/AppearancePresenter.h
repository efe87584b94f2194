#pragma once
// The window's look for a projector or for low vision (ui/canvas/Appearance.h): View > High
// Contrast, Line Width and Text Size. The high-contrast theme repaints the whole window (its
// palette), the canvas and the plots; the two scales apply to the canvas and the plots only,
// whatever the system's font. Kept in the settings; `--high-contrast`, `--line-scale` and
// `--text-scale` set them for one run.

#include "app/desktop/presenters/Presenter.h"
#include "ui/canvas/Appearance.h"

#include <QList>

QT_BEGIN_NAMESPACE
class QMenu;
class QSettings;
QT_END_NAMESPACE

namespace phasebox {

class CanvasPresenter;

class AppearancePresenter : public Presenter {
    Q_OBJECT

public:
    AppearancePresenter(CanvasPresenter& canvas, QObject* parent = nullptr);

    void refresh() override;
    // The actions: highContrast (Ctrl+Shift+H) and the scale choices, each group exclusive.
    void createActions(QWidget& window);
    // View > High Contrast, Line Width, Text Size.
    void addToMenu(QMenu& view);
    const ui::Appearance& appearance() const { return appearance_; }
    // Applies an appearance (scales clamped to kMin/kMaxAppearanceScale) and checks its actions.
    void setAppearance(const ui::Appearance& appearance);
    void readSettings(const QSettings& settings);
    void writeSettings(QSettings& settings) const;

signals:
    // The plots must be drawn again to take the new look.
    void changed();

private:
    void syncActions();

    CanvasPresenter& canvas_;
    ui::Appearance appearance_;
    QAction* highContrast_ = nullptr;
    QList<QAction*> lineScales_;
    QList<QAction*> textScales_;
};

}  // namespace phasebox
