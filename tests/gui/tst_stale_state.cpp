// Nothing stale (issue #37): after New, Open, Reset and Revert from a run that diverged, the
// text of every visible widget (window and dock titles, labels, buttons, fields, tables, the
// status bar, plot titles, axis titles and legends) equals that of a freshly started window
// showing the same scene. Whatever a panel kept of the run before shows up as a difference.

#include "app/desktop/MainWindow.h"
#include "app/document/Document.h"
#include "app/io/SceneIO.h"
#include "app/sim/SimulationController.h"
#include "physics/world/World.h"

#include <QAbstractAxis>
#include <QAbstractButton>
#include <QAbstractItemView>
#include <QAbstractSpinBox>
#include <QAction>
#include <QApplication>
#include <QChart>
#include <QChartView>
#include <QComboBox>
#include <QDockWidget>
#include <QFile>
#include <QGroupBox>
#include <QLabel>
#include <QLegendMarker>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QSet>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTabBar>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QTextEdit>

using namespace phasebox;

namespace {

// A name for a widget that two windows share: its chain of object names.
QString pathOf(const QWidget* w, const QWidget* root) {
    QStringList names;
    for (const QWidget* p = w; p && p != root; p = p->parentWidget())
        names.prepend(p->objectName().isEmpty() ? QString::fromLatin1(p->metaObject()->className())
                                                : p->objectName());
    return names.join(QLatin1Char('/'));
}

QStringList chartTexts(const QChart* chart) {
    QStringList out{QStringLiteral("title=") + chart->title()};
    for (const QAbstractAxis* axis : chart->axes())
        out << QStringLiteral("axis=") + axis->titleText();
    for (const QLegendMarker* marker : chart->legend()->markers())
        out << QStringLiteral("legend=") + marker->label();
    return out;
}

QStringList modelTexts(const QAbstractItemModel* model) {
    QStringList out;
    if (!model) return out;
    const int rows = std::min(model->rowCount(), 200), columns = model->columnCount();
    for (int c = 0; c < columns; ++c)
        out << QStringLiteral("header=") + model->headerData(c, Qt::Horizontal).toString();
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < columns; ++c) out << model->index(r, c).data().toString();
    return out;
}

// Every visible widget's text, "path: text".
void collectVisible(MainWindow& w, QSet<QString>& out) {
    w.refreshNow();
    QApplication::processEvents();
    out << QStringLiteral("window: ") + w.windowTitle();
    for (QWidget* widget : w.findChildren<QWidget*>()) {
        if (!widget->isVisibleTo(&w)) continue;
        QStringList texts;
        if (auto* l = qobject_cast<QLabel*>(widget)) texts << l->text();
        if (auto* b = qobject_cast<QAbstractButton*>(widget)) texts << b->text();
        if (auto* e = qobject_cast<QLineEdit*>(widget)) texts << e->text();
        if (auto* c = qobject_cast<QComboBox*>(widget)) texts << c->currentText();
        if (auto* s = qobject_cast<QAbstractSpinBox*>(widget)) texts << s->text();
        if (auto* g = qobject_cast<QGroupBox*>(widget)) texts << g->title();
        if (auto* d = qobject_cast<QDockWidget*>(widget)) texts << d->windowTitle();
        if (auto* t = qobject_cast<QTabBar*>(widget))
            for (int i = 0; i < t->count(); ++i) texts << t->tabText(i);
        if (auto* t = qobject_cast<QTextEdit*>(widget)) texts << t->toPlainText();
        if (auto* t = qobject_cast<QPlainTextEdit*>(widget)) texts << t->toPlainText();
        if (auto* v = qobject_cast<QAbstractItemView*>(widget)) texts << modelTexts(v->model());
        if (auto* c = qobject_cast<QChartView*>(widget)) texts << chartTexts(c->chart());
        if (auto* s = qobject_cast<QStatusBar*>(widget)) texts << s->currentMessage();
        for (const QString& t : std::as_const(texts))
            if (!t.isEmpty()) out << pathOf(widget, &w) + QStringLiteral(": ") + t;
    }
}

// The texts of every panel a user can bring up: each dock raised in turn, and in it each tab
// of every tab widget (the tabs' own order is kept afterwards), sorted.
QStringList visibleTexts(MainWindow& w) {
    QSet<QString> out;
    for (QDockWidget* dock : w.findChildren<QDockWidget*>()) {
        if (dock->isHidden()) continue;
        dock->raise();
        for (QTabWidget* tabs : dock->findChildren<QTabWidget*>()) {
            const int current = tabs->currentIndex();
            for (int i = 0; i < tabs->count(); ++i) {
                tabs->setCurrentIndex(i);
                collectVisible(w, out);
            }
            tabs->setCurrentIndex(current);
        }
        collectVisible(w, out);
    }
    QStringList sorted(out.begin(), out.end());
    sorted.sort();
    return sorted;
}

// The lines of a that b lacks and the reverse, for the failure message.
QString difference(const QStringList& a, const QStringList& b) {
    QStringList lines;
    for (const QString& t : a)
        if (!b.contains(t)) lines << QStringLiteral("  after:  ") + t;
    for (const QString& t : b)
        if (!a.contains(t)) lines << QStringLiteral("  fresh:  ") + t;
    return lines.join(QLatin1Char('\n'));
}

struct Window {
    MainWindow w;
    Window() {
        w.resize(1400, 900);
        w.show();
    }
};

}  // namespace

class TestStaleState : public QObject {
    Q_OBJECT

    QTemporaryDir dir_;
    QString blowup_;  // a stiff spring under symplectic Euler: diverges within frames
    QString other_;

    // Opens the diverging scene, selects its ball (the phase plot and readouts name it),
    // pulls it with the mouse spring, runs until the world stops it as diverged.
    void divergeIn(Window& window) {
        QVERIFY(window.w.openFile(blowup_, true));
        window.w.document().setSelection({QStringLiteral("ball")});
        QVERIFY(!window.w.controller().advance(2.0));
        QVERIFY(window.w.document().world().divergence().has_value());
        window.w.refreshNow();
    }

    void expectSame(Window& after, Window& fresh, const char* what) {
        const QStringList a = visibleTexts(after.w), f = visibleTexts(fresh.w);
        QVERIFY2(a == f, qPrintable(QStringLiteral("%1 differs from a fresh window:\n%2")
                                        .arg(QLatin1String(what), difference(a, f))));
    }

private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        const SceneLoadResult blowup =
            SceneIO::load(QStringLiteral(":/scenes/stiff-spring-blowup.phasebox.json"));
        QVERIFY(blowup.ok());
        SceneDesc scene = *blowup.scene;
        scene.simulation.integrator = "symplectic_euler";
        scene.instruments.graphs = {{"ball.y", ""}};
        scene.instruments.probes = {"ball.speed"};
        blowup_ = dir_.filePath(QStringLiteral("blowup.phasebox.json"));
        QString error;
        QVERIFY2(SceneIO::save(scene, blowup_, &error), qPrintable(error));
        other_ = QStringLiteral(":/scenes/box-pyramid.phasebox.json");
    }

    void newAfterADivergedRun() {
        Window fresh;
        Window window;
        divergeIn(window);
        window.w.action(QStringLiteral("new"))->trigger();
        expectSame(window, fresh, "New");
    }

    void openAfterADivergedRun() {
        Window fresh;
        QVERIFY(fresh.w.openFile(other_, true));
        Window window;
        divergeIn(window);
        QVERIFY(window.w.openFile(other_, true));
        expectSame(window, fresh, "Open");
    }

    void resetAfterADivergedRun() {
        Window fresh;
        QVERIFY(fresh.w.openFile(blowup_, true));
        fresh.w.document().setSelection({QStringLiteral("ball")});
        fresh.w.action(QStringLiteral("reset"))->trigger();
        Window window;
        divergeIn(window);
        window.w.action(QStringLiteral("reset"))->trigger();
        expectSame(window, fresh, "Reset");
    }

    void revertAfterADivergedRun() {
        Window fresh;
        QVERIFY(fresh.w.openFile(blowup_, true));
        Window window;
        divergeIn(window);
        window.w.action(QStringLiteral("revert"))->trigger();
        expectSame(window, fresh, "Revert");
    }
};

QTEST_MAIN(TestStaleState)
#include "tst_stale_state.moc"
