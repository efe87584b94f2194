#pragma once
// What the MainWindow suites share: the window's parts, found in its object tree by their
// object names (MainWindow.h lists them); a drag as a hand makes it, where a pixel of the canvas
// is in the world, and the document's scene as text.

#include "app/desktop/AccuracyDialog.h"
#include "app/desktop/AccuracyLab.h"
#include "app/desktop/CanvasTools.h"
#include "app/desktop/MainWindow.h"
#include "app/desktop/MeasureTools.h"
#include "app/desktop/presenters/AppearancePresenter.h"
#include "app/desktop/presenters/ExactPresenter.h"
#include "app/desktop/presenters/InstrumentsPresenter.h"
#include "app/document/Autosave.h"
#include "app/io/SceneIO.h"
#include "app/sim/ProbeRecorder.h"
#include "app/sim/Recorder.h"
#include "ui/canvas/SceneView.h"
#include "ui/instruments/InstrumentsPanel.h"
#include "ui/panels/EffectsPanel.h"
#include "ui/panels/ParametersPanel.h"
#include "ui/panels/PropertiesPanel.h"
#include "ui/panels/SceneBrowser.h"
#include "ui/plots/PlotsPanel.h"

#include <QByteArray>
#include <QPoint>
#include <QPointF>
#include <QTest>
#include <QWidget>

namespace phasebox::testing {

namespace parts {
// The part of the window of that type and object name; a missing one ends the test run.
template <typename T>
T* part(const MainWindow& w, const char* name) {
    T* found = w.findChild<T*>(QLatin1String(name));
    if (!found) qFatal("the window has no %s named %s", T::staticMetaObject.className(), name);
    return found;
}

inline ui::SceneView* canvasOf(const MainWindow& w) {
    return part<ui::SceneView>(w, "canvas");
}
inline CanvasTools* toolsOf(const MainWindow& w) {
    return part<CanvasTools>(w, "canvasTools");
}
// The ruler, protractor and free-body view.
inline MeasureTools* measureToolsOf(const MainWindow& w) {
    return part<MeasureTools>(w, "measureTools");
}
inline ui::ParametersPanel* parametersPanelOf(const MainWindow& w) {
    return part<ui::ParametersPanel>(w, "parametersPanel");
}
inline ui::EffectsPanel* effectsPanelOf(const MainWindow& w) {
    return part<ui::EffectsPanel>(w, "effectsPanel");
}
inline ui::PropertiesPanel* propertiesPanelOf(const MainWindow& w) {
    return part<ui::PropertiesPanel>(w, "propertiesPanel");
}
inline ui::SceneBrowser* sceneBrowserOf(const MainWindow& w) {
    return part<ui::SceneBrowser>(w, "sceneBrowser");
}
inline ui::PlotsPanel* plotsPanelOf(const MainWindow& w) {
    return part<ui::PlotsPanel>(w, "plotsPanel");
}
inline ui::InstrumentsPanel* instrumentsPanelOf(const MainWindow& w) {
    return part<ui::InstrumentsPanel>(w, "instruments");
}
inline InstrumentsPresenter* instrumentsOf(const MainWindow& w) {
    return part<InstrumentsPresenter>(w, "instrumentsPresenter");
}
inline ExactPresenter* exactSolutionOf(const MainWindow& w) {
    return part<ExactPresenter>(w, "exactPresenter");
}
// High contrast, line width and text size (View menu).
inline AppearancePresenter* appearanceOf(const MainWindow& w) {
    return part<AppearancePresenter>(w, "appearancePresenter");
}
inline Recorder& recorderOf(const MainWindow& w) {
    return *part<Recorder>(w, "recorder");
}
inline ProbeRecorder& probeRecorderOf(const MainWindow& w) {
    return *part<ProbeRecorder>(w, "probeRecorder");
}
inline Autosave* autosaveOf(const MainWindow& w) {
    return part<Autosave>(w, "autosave");
}
// The Accuracy Lab's dialog (made on first use).
inline AccuracyDialog* accuracyDialogOf(const MainWindow& w) {
    return part<AccuracyLab>(w, "accuracyLabController")->dialog();
}
}  // namespace parts

inline QByteArray serialized(MainWindow& w) {
    return SceneIO::serialize(w.document().setup());
}

// A press, a few moves and a release, as a hand would drag.
inline void drag(QWidget* widget, QPoint from, QPoint to) {
    QTest::mousePress(widget, Qt::LeftButton, {}, from);
    for (int k = 1; k <= 4; ++k) QTest::mouseMove(widget, from + (to - from) * k / 4);
    QTest::mouseRelease(widget, Qt::LeftButton, {}, to);
}

inline QPointF worldAt(MainWindow& w, QPoint pixel) {
    return parts::canvasOf(w)->toWorld(QPointF(pixel));
}

}  // namespace phasebox::testing
