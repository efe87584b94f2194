// The accuracy lab in the app: a study on the open scene in a worker thread, the diagram and
// tables it fills, the cheapest settings for a target error and applying them, and cancel.

#include "app/desktop/AccuracyDialog.h"
#include "app/desktop/MainWindow.h"
#include "app/document/Document.h"

#include <QAction>
#include <QChart>
#include <QChartView>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

#include <cmath>

using namespace phasebox;

namespace {
// Leaves only these integrators checked.
void choose(AccuracyDialog& dialog, const QStringList& names) {
    auto* list = dialog.findChild<QListWidget*>();
    for (int i = 0; i < list->count(); ++i) {
        QListWidgetItem* item = list->item(i);
        item->setCheckState(names.contains(item->data(Qt::UserRole).toString()) ? Qt::Checked
                                                                                : Qt::Unchecked);
    }
}
}  // namespace

class TestAccuracyDialog : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void studyFillsTheDiagramAndTheCheapestSettingsApply() {
        MainWindow w;
        QVERIFY(w.openFile(QStringLiteral(":/scenes/spring-oscillator.phasebox.json"), true));
        w.action("accuracyLab")->trigger();
        AccuracyDialog* dialog = w.accuracyDialog();
        QVERIFY(dialog->isVisible());
        choose(*dialog, {"explicit_euler", "rk4"});
        // Not a whole number of periods (T = 1 s and 2 s), where errors partly cancel.
        dialog->findChildren<QLineEdit*>()[1]->setText(QStringLiteral("1.3"));  // duration
        QSignalSpy finished(&dialog->study(), &AccuracyStudy::finished);
        QVERIFY(dialog->run());
        QVERIFY(finished.wait(120000));
        const auto& records = dialog->study().result().records;
        QCOMPARE(records.size(), std::size_t(12));  // 2 methods × the default 6 steps
        QVERIFY(dialog->summaryText().contains(QStringLiteral("Reference")));

        // The table has a row per run; the orders table says 1 and 4 within 0.2.
        QTableWidget* runs = nullptr;
        for (QTableWidget* t : dialog->findChildren<QTableWidget*>())
            if (t->columnCount() == 9) runs = t;
        QVERIFY(runs);
        QCOMPARE(runs->rowCount(), 12);
        const auto euler = AccuracyDialog::observedOrder(records, "explicit_euler");
        const auto rk4 = AccuracyDialog::observedOrder(records, "rk4");
        QVERIFY(euler && std::abs(*euler - 1.0) < 0.2);
        QVERIFY(rk4 && std::abs(*rk4 - 4.0) < 0.2);

        // The cheapest run for a target: within the target, and no run within it is cheaper.
        const double target = 1e-4;
        const auto best = dialog->cheapestFor(target);
        QVERIFY(best.has_value());
        QVERIFY(best->positionError <= target);
        for (const AccuracyRecord& r : records)
            if (r.positionError <= target) QVERIFY(r.cpuSeconds >= best->cpuSeconds);
        // Explicit Euler cannot reach 1e-4 here at these steps; RK4 can, at its coarsest step.
        QCOMPARE(best->integrator, std::string("rk4"));

        // A study applies only to the scene it studied: an edit of the scene disables Apply,
        // undoing the edit enables it again (simulation settings are what Apply changes, so
        // they do not count).
        auto* applyButton = [&]() -> QPushButton* {
            for (QPushButton* b : dialog->findChildren<QPushButton*>())
                if (b->text().contains(QStringLiteral("Apply"))) return b;
            return nullptr;
        }();
        QVERIFY(applyButton);
        QVERIFY(applyButton->isEnabled());
        const QString id = QString::fromStdString(w.document().setup().particles.front().id);
        QVERIFY(w.document().setProperty(id, QStringLiteral("mass"), 2.0));
        QVERIFY(!dialog->studiedSceneIsCurrent());
        QVERIFY(!applyButton->isEnabled());
        w.document().undoStack()->undo();
        QVERIFY(dialog->studiedSceneIsCurrent());
        QVERIFY(applyButton->isEnabled());

        // Apply sets the scene's integrator and dt.
        emit dialog->applyRequested(QString::fromStdString(best->integrator), best->dt, 1e-6);
        QCOMPARE(QString::fromStdString(w.document().setup().simulation.integrator),
                 QStringLiteral("rk4"));
        QCOMPARE(w.document().setup().simulation.dt, best->dt);

        // Exports.
        QTemporaryDir dir;
        QString error;
        QVERIFY2(dialog->exportTo(dir.filePath("wp.png"), &error), qPrintable(error));
        QVERIFY(!QImage(dir.filePath("wp.png")).isNull());
        QVERIFY2(dialog->exportTo(dir.filePath("wp.csv"), &error), qPrintable(error));
        QFile csv(dir.filePath("wp.csv"));
        QVERIFY(csv.open(QIODevice::ReadOnly));
        QVERIFY(csv.readLine().startsWith(
            "integrator,dt,steps,force_evals,cpu_seconds,position_error,energy_drift,order"));
    }

    void cancelStopsTheStudy() {
        MainWindow w;
        QVERIFY(w.openFile(QStringLiteral(":/scenes/box-pyramid.phasebox.json"), true));
        AccuracyDialog* dialog = w.accuracyDialog();
        dialog->setScene(w.document().setup());
        dialog->findChildren<QLineEdit*>()[1]->setText(QStringLiteral("10"));
        QSignalSpy finished(&dialog->study(), &AccuracyStudy::finished);
        QVERIFY(dialog->run());
        QTest::qWait(300);
        dialog->cancel();
        QVERIFY(finished.wait(30000));
        QVERIFY(dialog->study().result().cancelled);
        QVERIFY(static_cast<int>(dialog->study().result().records.size()) <
                dialog->study().result().plannedRuns);
        QVERIFY(dialog->study().result().contacts);
    }
};

QTEST_MAIN(TestAccuracyDialog)
#include "tst_accuracy_dialog.moc"
