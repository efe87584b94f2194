#pragma once
// What the MainWindow suites (tst_mainwindow, tst_mainwindow_tools) share: a drag as a hand
// makes it, where a pixel of the canvas is in the world, and the document's scene as text.

#include "app/desktop/MainWindow.h"
#include "app/io/SceneIO.h"
#include "ui/canvas/SceneView.h"

#include <QByteArray>
#include <QPoint>
#include <QPointF>
#include <QTest>
#include <QWidget>

namespace phasebox::testing {

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
    return w.canvas()->toWorld(QPointF(pixel));
}

}  // namespace phasebox::testing
