// The window for a keyboard and a screen reader: Tab walks every control of the window (with each
// tabbed dock raised in turn), every control it reaches has an accessible name, and every visible
// control is reached, so none is left to the mouse. Also the high-contrast theme and the line and
// text scales (View menu), which repaint the window, the canvas and the plots.

#include "MainWindowTestSupport.h"
#include "app/desktop/MainWindow.h"
#include "app/desktop/presenters/AppearancePresenter.h"
#include "ui/canvas/SceneView.h"
#include "ui/panels/AccessibleNames.h"

#include <QAbstractItemView>
#include <QAction>
#include <QApplication>
#include <QDockWidget>
#include <QStandardPaths>
#include <QTest>
#include <QTextBrowser>

#include <algorithm>

using namespace phasebox;
using namespace phasebox::testing::parts;

namespace {

// Presses Tab until the focus comes back to where it started (at most limit presses); a widget
// that keeps Tab for itself (the canvas walks its objects with it) is pressed through. Returns
// the widgets that held the focus, in order.
QList<QWidget*> tabWalk(QWidget* start, int limit = 600) {
    QList<QWidget*> seen;
    start->setFocus(Qt::TabFocusReason);
    QApplication::processEvents();
    QWidget* first = QApplication::focusWidget();
    if (!first) return seen;
    seen << first;
    bool left = false;
    for (int i = 0; i < limit; ++i) {
        QTest::keyClick(QApplication::focusWidget(), Qt::Key_Tab);
        QWidget* now = QApplication::focusWidget();
        if (!now) break;
        if (now != first) left = true;
        if (now == first && left) break;
        if (!seen.contains(now)) seen << now;
    }
    return seen;
}

// What a user can focus and act on: visible, enabled, taking Tab focus.
QList<QWidget*> visibleControls(QWidget* window) {
    QList<QWidget*> out;
    for (QWidget* w : window->findChildren<QWidget*>()) {
        if (!w->isVisible() || !w->isEnabled() || !(w->focusPolicy() & Qt::TabFocus)) continue;
        if (w->focusProxy()) continue;  // its proxy is the control
        if (w->visibleRegion().isEmpty()) continue;
        out << w;
    }
    return out;
}

QString describe(QWidget* w) {
    return QStringLiteral("%1 \"%2\" (%3)")
        .arg(QString::fromLatin1(w->metaObject()->className()), w->objectName(),
             w->parentWidget() ? w->parentWidget()->objectName() : QString());
}

}  // namespace

class TestAccessibility : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }
    void tabReachesEveryControlAndEachHasAName();
    void highContrastAndScalesRepaintTheWindow();
};

void TestAccessibility::tabReachesEveryControlAndEachHasAName() {
    MainWindow window;
    window.resize(1024, 700);
    window.show();
    QApplication::setActiveWindow(&window);
    QVERIFY(QTest::qWaitForWindowActive(&window));
    QVERIFY(window.openFile(QStringLiteral(":/scenes/demo.phasebox.json"), true));
    QApplication::processEvents();

    QStringList unnamed, unreached;
    int walked = 0;
    const QList<QDockWidget*> docks = window.findChildren<QDockWidget*>();
    for (QDockWidget* dock : docks) {
        if (dock->isHidden()) continue;
        dock->raise();
        QApplication::processEvents();
        const QList<QWidget*> walk = tabWalk(canvasOf(window));
        walked = std::max(walked, static_cast<int>(walk.size()));
        for (QWidget* w : walk) {
            if (qEnvironmentVariableIsSet("PHASEBOX_LIST_NAMES"))
                qInfo().noquote() << describe(w) << "->" << ui::accessibleNameOf(w);
            if (ui::accessibleNameOf(w).isEmpty() && !unnamed.contains(describe(w)))
                unnamed << describe(w);
        }
        for (QWidget* w : visibleControls(&window))
            if (!walk.contains(w) && !unreached.contains(describe(w))) unreached << describe(w);
    }
    QVERIFY2(walked > 20, qPrintable(QString::number(walked)));
    QVERIFY2(unnamed.isEmpty(),
             qPrintable(QStringLiteral("controls without an accessible name:\n") +
                        unnamed.join(QLatin1Char('\n'))));
    QVERIFY2(unreached.isEmpty(), qPrintable(QStringLiteral("controls Tab does not reach:\n") +
                                             unreached.join(QLatin1Char('\n'))));
    QVERIFY(!ui::accessibleNameOf(canvasOf(window)).isEmpty());
    QVERIFY(!canvasOf(window)->accessibleDescription().isEmpty());
}

void TestAccessibility::highContrastAndScalesRepaintTheWindow() {
    MainWindow window;
    window.resize(1024, 700);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    AppearancePresenter* look = appearanceOf(window);
    QVERIFY(look);
    QVERIFY(!look->appearance().highContrast);
    const QColor normalWindow = QApplication::palette().color(QPalette::Window);
    window.action(QStringLiteral("highContrast"))->trigger();
    QVERIFY(look->appearance().highContrast);
    QCOMPARE(QApplication::palette().color(QPalette::Window), QColor(Qt::black));
    QCOMPARE(canvasOf(window)->renderOptions().background, QColor(Qt::black));
    QCOMPARE(canvasOf(window)->renderOptions().colors.selection, ui::okabeIto::yellow);
    window.action(QStringLiteral("lineScale200"))->trigger();
    window.action(QStringLiteral("textScale150"))->trigger();
    QCOMPARE(look->appearance().lineScale, 2.0);
    QCOMPARE(look->appearance().textScale, 1.5);
    QCOMPARE(canvasOf(window)->renderOptions().lineWidthScale, 2.0);
    QCOMPARE(canvasOf(window)->renderOptions().fontScale, 1.5);
    // Presentation mode multiplies the user's scales.
    window.setPresentationMode(true);
    QCOMPARE(canvasOf(window)->renderOptions().lineWidthScale, 4.0);
    window.setPresentationMode(false);
    window.action(QStringLiteral("highContrast"))->trigger();
    window.action(QStringLiteral("lineScale100"))->trigger();
    window.action(QStringLiteral("textScale100"))->trigger();
    QCOMPARE(QApplication::palette().color(QPalette::Window), normalWindow);
    QCOMPARE(canvasOf(window)->renderOptions().background, ui::RenderOptions{}.background);
    QCOMPARE(look->appearance(), ui::Appearance{});
}

QTEST_MAIN(TestAccessibility)
#include "tst_accessibility.moc"
