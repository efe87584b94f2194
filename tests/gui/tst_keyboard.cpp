// The window with the keyboard alone: a scene built on the canvas (a tool's key, the arrow keys
// moving the keyboard cursor, Enter placing the object), an object chosen with Tab, moved with
// the arrow keys and opened with Enter, the scene run with the Step key, and a probe read off
// the Instruments dock's readouts as a screen reader reads them (QAccessible), and the canvas
// describing the selection. No mouse event is sent.

#include "MainWindowTestSupport.h"
#include "app/desktop/MainWindow.h"
#include "ui/canvas/SceneView.h"
#include "ui/panels/PropertiesPanel.h"

#include <QAccessible>
#include <QAction>
#include <QApplication>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTableWidget>
#include <QTest>

#include <cmath>

using namespace phasebox;
using namespace phasebox::testing::parts;

namespace {

void press(int key, Qt::KeyboardModifiers modifiers = Qt::NoModifier) {
    QWidget* target = QApplication::focusWidget();
    QVERIFY(target);
    QTest::keyClick(target, static_cast<Qt::Key>(key), modifiers);
}

// Tab until the canvas has the focus, as a keyboard user gets there.
bool tabToCanvas(MainWindow& window) {
    for (int i = 0; i < 400; ++i) {
        if (QApplication::focusWidget() == canvasOf(window)) return true;
        QWidget* from = QApplication::focusWidget() ? QApplication::focusWidget() : &window;
        QTest::keyClick(from, Qt::Key_Tab);
    }
    return QApplication::focusWidget() == canvasOf(window);
}

// A table's cell as a screen reader gets it.
QString accessibleCell(QTableWidget* table, int row, int column) {
    QAccessibleInterface* iface = QAccessible::queryAccessibleInterface(table);
    if (!iface || !iface->tableInterface()) return {};
    QAccessibleInterface* cell = iface->tableInterface()->cellAt(row, column);
    return cell ? cell->text(QAccessible::Name) : QString();
}

}  // namespace

class TestKeyboard : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }
    void buildRunAndReadWithTheKeyboardAlone();
    void everyDrawingToolPlacesAtTheCursor();
};

void TestKeyboard::buildRunAndReadWithTheKeyboardAlone() {
    MainWindow window;
    window.resize(1024, 700);
    window.show();
    QApplication::setActiveWindow(&window);
    QVERIFY(QTest::qWaitForWindowActive(&window));
    QTest::keySequence(&window, QKeySequence::New);
    const std::size_t particlesBefore = window.document().setup().particles.size();
    QCOMPARE(particlesBefore, std::size_t(0));

    // A particle where the keyboard cursor is, three steps above where it starts.
    QVERIFY(tabToCanvas(window));
    const QPointF cursor = canvasOf(window)->keyboardCursor();
    press(Qt::Key_2);  // Add particle
    QVERIFY(window.action(QStringLiteral("toolParticle"))->isChecked());
    for (int i = 0; i < 3; ++i) press(Qt::Key_Up);
    press(Qt::Key_Right, Qt::ShiftModifier);  // a fine step
    press(Qt::Key_Return);
    QCOMPARE(window.document().setup().particles.size(), std::size_t(1));
    const ParticleDesc placed = window.document().setup().particles.at(0);
    QCOMPARE(placed.position[0], cursor.x() + 0.01);
    QVERIFY(std::abs(placed.position[1] - (cursor.y() + 0.3)) < 1e-9);

    // Select tool; Tab walks to the particle; Right moves it by a step.
    press(Qt::Key_1);
    QVERIFY(QApplication::focusWidget() == canvasOf(window));
    const QString id = QString::fromStdString(placed.id.empty() ? "p0" : placed.id);
    for (int i = 0; i < 4 && window.document().selection() != QStringList{id}; ++i)
        press(Qt::Key_Tab);
    QCOMPARE(window.document().selection(), QStringList{id});
    QCOMPARE(QApplication::focusWidget(), canvasOf(window));
    press(Qt::Key_Right);
    QVERIFY(std::abs(window.document().setup().particles.at(0).position[0] -
                     (placed.position[0] + 0.1)) < 1e-9);
    QVERIFY(canvasOf(window)->accessibleDescription().contains(id));

    // Enter opens its properties: the focus goes to the Properties panel's first field.
    press(Qt::Key_Return);
    QVERIFY(QApplication::focusWidget());
    QVERIFY(propertiesPanelOf(window)->isAncestorOf(QApplication::focusWidget()));

    // Run 30 steps (Simulation > Step, S), then read its height off the readouts.
    for (int i = 0; i < 30; ++i) press(Qt::Key_S);
    const double t = window.document().world().time();
    QVERIFY(t > 0.4);
    QTest::keySequence(&window, QKeySequence(Qt::CTRL | Qt::Key_I));  // Tools > Instruments
    window.refreshNow();
    auto* table = window.findChild<QTableWidget*>(QStringLiteral("readoutTable"));
    QVERIFY(table);
    QVERIFY(table->rowCount() > 0);
    QString position;
    for (int row = 0; row < table->rowCount(); ++row)
        if (accessibleCell(table, row, 0).startsWith(QStringLiteral("position")))
            position = accessibleCell(table, row, 1);
    QVERIFY2(!position.isEmpty(), "no position row in the readouts");
    // Free fall from rest: y = y0 − g t²/2, within what the readout's digits show.
    const double expectedY = placed.position[1] - 0.5 * 9.81 * t * t;
    QString pair = position;
    pair.remove(QLatin1Char('(')).remove(QLatin1Char(')')).replace(QChar(0x2212), QLatin1Char('-'));
    const QStringList numbers = pair.split(QRegularExpression(QStringLiteral("[;,]\\s")));
    QVERIFY2(numbers.size() >= 2, qPrintable(position));
    const double readY = QLocale().toDouble(numbers.last().trimmed());
    QVERIFY2(std::abs(readY - expectedY) < 0.05,
             qPrintable(QStringLiteral("%1 against %2").arg(position).arg(expectedY)));
    QVERIFY(canvasOf(window)->accessibleDescription().contains(QStringLiteral("velocity")));
}

// Each drawing tool's key, then Enter: its object appears at the keyboard cursor (a spring and a
// joint from the selected particle to the cursor).
void TestKeyboard::everyDrawingToolPlacesAtTheCursor() {
    MainWindow window;
    window.resize(1024, 700);
    window.show();
    QApplication::setActiveWindow(&window);
    QVERIFY(QTest::qWaitForWindowActive(&window));
    QTest::keySequence(&window, QKeySequence::New);
    QVERIFY(tabToCanvas(window));
    const auto count = [&window] {
        const SceneDesc& s = window.document().setup();
        return s.particles.size() + s.boxes.size() + s.disks.size() + s.polygons.size() +
               s.planes.size() + s.springs.size() + s.cloths.size() + s.joints.size();
    };
    press(Qt::Key_2);  // a particle to hang things from, then select it
    press(Qt::Key_Return);
    QCOMPARE(window.document().setup().particles.size(), std::size_t(1));
    const std::string& id = window.document().setup().particles[0].id;
    const QString particle = id.empty() ? QStringLiteral("p0") : QString::fromStdString(id);
    // Tool keys 5 box, 6 disk, 7 polygon, 4 cloth, then 3 spring and 0 joint from the particle
    // (selected again: a placed object becomes the selection) to the cursor, and 8 a plane last
    // (its edge runs through the cursor's height); the cursor moves 1.5 m right before each so
    // that no two objects overlap.
    for (const int key :
         {Qt::Key_5, Qt::Key_6, Qt::Key_7, Qt::Key_4, Qt::Key_3, Qt::Key_0, Qt::Key_8}) {
        if (key == Qt::Key_3 || key == Qt::Key_0) window.document().setSelection({particle});
        press(key);
        QCOMPARE(QApplication::focusWidget(), canvasOf(window));
        for (int i = 0; i < 15; ++i) press(Qt::Key_Right);
        const std::size_t before = count();
        press(Qt::Key_Return);
        QVERIFY2(count() == before + 1, qPrintable(QStringLiteral("tool key %1: %2")
                                                       .arg(key)
                                                       .arg(window.statusBar()->currentMessage())));
    }
    const SceneDesc& s = window.document().setup();
    QCOMPARE(s.boxes.size(), std::size_t(1));
    QCOMPARE(s.disks.size(), std::size_t(1));
    QCOMPARE(s.polygons.size(), std::size_t(1));
    QCOMPARE(s.planes.size(), std::size_t(2));  // the new scene's ground and this one
    QCOMPARE(s.cloths.size(), std::size_t(1));
    QCOMPARE(s.springs.size(), std::size_t(1));
    QCOMPARE(s.joints.size(), std::size_t(1));
}

QTEST_MAIN(TestKeyboard)
#include "tst_keyboard.moc"
