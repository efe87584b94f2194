// The accuracy lab in the app: a study on the open scene in a worker thread, the diagram and
// tables it fills, the cheapest settings for a target error and applying them, and cancel. And
// that a class can read it: at 1024×700 and 1920×1080 the axis titles are whole and inside the
// chart, the dt labels do not overlap, "lower is better" is said, and an odd order is explained
// in words (RK4 at round-off, explicit Euler unstable on a stiff spring).

#include "MainWindowTestSupport.h"
#include "app/desktop/AccuracyDialog.h"
#include "app/desktop/MainWindow.h"
#include "app/document/Document.h"
#include "ui/plots/Charts.h"
#include "ui/plots/WorkPrecisionChart.h"

#include <QAction>
#include <QApplication>
#include <QCategoryAxis>
#include <QChart>
#include <QChartView>
#include <QGraphicsScene>
#include <QGraphicsSimpleTextItem>
#include <QGraphicsTextItem>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QLocale>
#include <QPushButton>
#include <QRegularExpression>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>
#include <QValueAxis>

#include <cmath>
#include <memory>
#include <vector>

using namespace phasebox;
using namespace phasebox::testing::parts;

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

void setLine(AccuracyDialog& dialog, int index, const QString& text) {
    dialog.findChildren<QLineEdit*>()[index]->setText(text);  // 0: dt list, 1: duration
}

bool runStudy(AccuracyDialog& dialog) {
    QSignalSpy finished(&dialog.study(), &AccuracyStudy::finished);
    return dialog.run() && finished.wait(120000) && !dialog.study().result().records.empty();
}

// The row of a table whose first cell is text.
int rowOf(QTableWidget* table, const QString& text) {
    for (int row = 0; row < table->rowCount(); ++row)
        if (table->item(row, 0) && table->item(row, 0)->text() == text) return row;
    return -1;
}

QTableWidget* table(AccuracyDialog& dialog, const char* name) {
    return dialog.findChild<QTableWidget*>(QString::fromLatin1(name));
}

// The title item showing text in the chart view's scene, if it shows it whole: Qt Charts elides
// a title that does not fit ("position error […"), so an item with the whole text is uncut.
QGraphicsTextItem* wholeTitle(QChartView* view, const QString& text) {
    for (QGraphicsItem* item : view->scene()->items())
        if (auto* t = dynamic_cast<QGraphicsTextItem*>(item);
            t && t->isVisible() && t->toPlainText() == text)
            return t;
    return nullptr;
}

// The tick labels of a chart's axis in that orientation, when it is a decade axis.
QStringList decadeLabels(QChart* chart, Qt::Orientation orientation) {
    auto* axis = qobject_cast<QCategoryAxis*>(chart->axes(orientation).value(0));
    return axis ? axis->categoriesLabels() : QStringList();
}

// Every label a power of ten as a reader writes it: 10, then a superscript exponent.
bool allPowersOfTen(const QStringList& labels) {
    static const QRegularExpression power(QStringLiteral("^10⁻?[⁰¹²³⁴⁵⁶⁷⁸⁹]+$"));
    for (const QString& label : labels)
        if (!power.match(label).hasMatch()) return false;
    return !labels.isEmpty();
}

void savePicture(QWidget* widget, const QString& name) {
    const QString dir = qEnvironmentVariable("PHASEBOX_SCREENSHOT_DIR");
    if (!dir.isEmpty()) widget->grab().save(QStringLiteral("%1/%2.png").arg(dir, name));
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
        AccuracyDialog* dialog = accuracyDialogOf(w);
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
        const auto euler =
            AccuracyDialog::observedOrder(dialog->study().result(), "explicit_euler");
        const auto rk4 = AccuracyDialog::observedOrder(dialog->study().result(), "rk4");
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

    void readableAtClassroomSizes() {
        MainWindow w;
        QVERIFY(w.openFile(QStringLiteral(":/scenes/spring-oscillator.phasebox.json"), true));
        w.action("accuracyLab")->trigger();
        AccuracyDialog* dialog = accuracyDialogOf(w);
        QVERIFY(runStudy(*dialog));  // every method, the default steps: the crowded case
        auto* view = dialog->findChild<QChartView*>(QStringLiteral("workPrecisionChart"));
        QVERIFY(view);
        QChart* chart = view->chart();
        auto* x = qobject_cast<QValueAxis*>(chart->axes(Qt::Horizontal).value(0));
        auto* y = qobject_cast<QValueAxis*>(chart->axes(Qt::Vertical).value(0));
        QVERIFY(x && y);
        QVERIFY(y->titleText().contains(QStringLiteral("lower is better")));
        QVERIFY(x->titleText().contains(QStringLiteral("left is faster")));
        QVERIFY(y->labelsFont().pointSizeF() >= 10.0);
        auto* caption = dialog->findChild<QLabel*>(QStringLiteral("chartCaption"));
        QVERIFY(caption && caption->text().contains(QStringLiteral("Lower is better")));

        for (const QSize size : {QSize(1024, 700), QSize(1920, 1080)}) {
            dialog->resize(size);
            QApplication::processEvents();
            QCOMPARE(dialog->size(), size);
            const QString at = QStringLiteral("%1x%2").arg(size.width()).arg(size.height());
            savePicture(dialog, QStringLiteral("accuracy-lab-") + at);
            QVERIFY2(view->height() >= 340 && view->width() >= 560, qPrintable(at));
            // Text at least 10 pt, and larger on the larger screen.
            QVERIFY(y->labelsFont().pointSizeF() >= (size.height() > 1000 ? 12.0 : 10.0));
            QVERIFY2(caption->isVisible() &&
                         caption->height() >= caption->heightForWidth(caption->width()),
                     qPrintable(at));

            // The axis titles and the chart's title are whole and inside the view.
            const QRect inside = view->viewport()->rect();
            for (const QString& title : {x->titleText(), y->titleText(), chart->title()}) {
                QGraphicsTextItem* item = wholeTitle(view, title);
                QVERIFY2(item, qPrintable(at + QStringLiteral(": cut: ") + title));
                const QRect r = view->mapFromScene(item->sceneBoundingRect()).boundingRect();
                QVERIFY2(inside.contains(r),
                         qPrintable(at + QStringLiteral(": outside: ") + title));
            }

            // The dt labels: in the plot, none over another, and each line's ends labelled
            // somewhere (at least the six dts' 1/60 and 1/1920 of some line).
            std::vector<QRectF> shown;
            QStringList texts;
            const QRectF plot = chart->mapToScene(chart->plotArea()).boundingRect();
            for (QGraphicsItem* item : view->scene()->items()) {
                auto* label = dynamic_cast<QGraphicsSimpleTextItem*>(item);
                if (!label || !label->isVisible() || label->parentItem() != chart) continue;
                const QRectF r = label->sceneBoundingRect();
                QVERIFY2(plot.contains(r), qPrintable(at + QStringLiteral(": ") + label->text()));
                for (const QRectF& other : shown)
                    QVERIFY2(!other.intersects(r),
                             qPrintable(at + QStringLiteral(": overlap at ") + label->text()));
                shown.push_back(r);
                texts << label->text();
            }
            QVERIFY2(
                texts.contains(QStringLiteral("1/60")) && texts.contains(QStringLiteral("1/1920")),
                qPrintable(at + QStringLiteral(": ") + texts.join(QLatin1Char(' '))));
            QVERIFY2(shown.size() >= 10, qPrintable(at));
        }
    }

    // The log axes read 10⁻⁶ in every language (not printf's 1e-06, nor German's 1E-06), and the
    // dt list takes the locale's decimal comma ("0,01; 0,005" in German) as well as '.'.
    void germanNumbersInTheLab() {
        const auto dts = [](const char* text) {
            return AccuracyDialog::parseDtList(QString::fromUtf8(text));
        };
        // The locale set below is put back however the test ends.
        struct English {
            English() { QLocale::setDefault(QLocale(QLocale::English, QLocale::UnitedStates)); }
            ~English() {
                ui::setChartLocale(std::nullopt);
                QLocale::setDefault(QLocale(QLocale::English, QLocale::UnitedStates));
            }
        } english_;
        QVERIFY(dts("0.01, 0.005; 1/120") == (std::vector<double>{0.01, 0.005, 1.0 / 120.0}));
        const std::vector<double> defaults = defaultAccuracyDts(1.0 / 60.0);
        const std::optional<std::vector<double>> english =
            AccuracyDialog::parseDtList(AccuracyDialog::dtListText(defaults));
        QVERIFY(english && english->size() == defaults.size());

        QLocale::setDefault(QLocale(QLocale::German, QLocale::Germany));
        ui::setChartLocale(QLocale());
        QVERIFY(dts("0,01; 0,005") == (std::vector<double>{0.01, 0.005}));
        QVERIFY(dts("0.01; 0.005") == (std::vector<double>{0.01, 0.005}));
        QVERIFY(dts("1/120; 0,0025") == (std::vector<double>{1.0 / 120.0, 0.0025}));
        // A comma is the decimal separator here, so it separates nothing: refused whole.
        QString bad;
        QVERIFY(!AccuracyDialog::parseDtList(QStringLiteral("0,01, 0,005"), &bad));
        QCOMPARE(bad, QStringLiteral("0,01, 0,005"));
        // A duration with a decimal comma runs, and so does one with a point.
        {
            MainWindow w;
            QVERIFY(w.openFile(QStringLiteral(":/scenes/spring-oscillator.phasebox.json"), true));
            w.action("accuracyLab")->trigger();
            AccuracyDialog& dialog = *accuracyDialogOf(w);
            setLine(dialog, 0, QStringLiteral("1/60; 0,008"));
            choose(dialog, {"symplectic_euler"});
            for (const QString& duration : {QStringLiteral("0,5"), QStringLiteral("0.25")}) {
                setLine(dialog, 1, duration);
                QVERIFY2(runStudy(dialog), qPrintable(duration));
                QCOMPARE(dialog.study().result().records.size(), std::size_t{2});
            }
        }
        // The field's own text reads back as the same steps as in English.
        const QString german = AccuracyDialog::dtListText(defaults);
        QVERIFY2(german.contains(QStringLiteral("; ")), qPrintable(german));
        QCOMPARE(AccuracyDialog::parseDtList(german), english);

        const std::vector<ui::WorkPrecisionPoint> points = {
            {QStringLiteral("rk4"), 1e-3, 1e-6, QStringLiteral("1/60")},
            {QStringLiteral("rk4"), 1e-2, 1e-9, QStringLiteral("1/120")}};
        std::unique_ptr<QChart> diagram(ui::createWorkPrecisionChart(points, QStringLiteral("t")));
        const QStringList errors = decadeLabels(diagram.get(), Qt::Vertical);
        QVERIFY2(allPowersOfTen(errors), qPrintable(errors.join(QLatin1Char(' '))));
        QCOMPARE(errors, (QStringList{QStringLiteral("10⁻⁹"), QStringLiteral("10⁻⁸"),
                                      QStringLiteral("10⁻⁷"), QStringLiteral("10⁻⁶")}));
        QVERIFY(allPowersOfTen(decadeLabels(diagram.get(), Qt::Horizontal)));
        const std::vector<QPointF> estimates = {{0.0, 2e-7}, {1.0, 3e-5}};
        std::unique_ptr<QChart> error(ui::createErrorChart(estimates, QStringLiteral("e")));
        QCOMPARE(decadeLabels(error.get(), Qt::Vertical),
                 (QStringList{QStringLiteral("10⁻⁷"), QStringLiteral("10⁻⁶"),
                              QStringLiteral("10⁻⁵"), QStringLiteral("10⁻⁴")}));
    }

    void roundOffFloorIsExplained() {
        // RK4 on the smooth oscillator at steps down to 1/30720: the error falls like dt⁴ to
        // 1e-15 m and then only wanders (the last slope is negative).
        MainWindow w;
        QVERIFY(w.openFile(QStringLiteral(":/scenes/spring-oscillator.phasebox.json"), true));
        w.action("accuracyLab")->trigger();
        AccuracyDialog* dialog = accuracyDialogOf(w);
        choose(*dialog, {"rk4"});
        setLine(*dialog, 0,
                QStringLiteral("1/60, 1/120, 1/240, 1/480, 1/960, 1/1920, 1/3840, 1/7680, "
                               "1/15360, 1/30720"));
        setLine(*dialog, 1, QStringLiteral("1.3"));
        QVERIFY(runStudy(*dialog));
        const AccuracyResult& result = dialog->study().result();
        // The data is what the explanation claims: the finest error is at the floor (below
        // 1e-9 of the positions' size) and did not fall as fast as dt⁴ from the step before.
        const AccuracyRecord& finest = result.records.back();
        const AccuracyRecord& before = result.records[result.records.size() - 2];
        QVERIFY(finest.positionError < 1e-9 * result.positionScale);
        QVERIFY(finest.order && *finest.order < 3.5);
        QVERIFY(before.positionError < 1e-12);

        QTableWidget* orders = table(*dialog, "ordersTable");
        const int row = rowOf(orders, QStringLiteral("rk4"));
        QVERIFY(row >= 0);
        const double measured = orders->item(row, 1)->text().toDouble();
        QVERIFY2(std::abs(measured - 4.0) < 0.3, qPrintable(orders->item(row, 1)->text()));
        QCOMPARE(orders->item(row, 2)->text(), QStringLiteral("4"));
        QVERIFY2(orders->item(row, 3)->text().contains(QStringLiteral("round-off floor reached")),
                 qPrintable(orders->item(row, 3)->text()));
        QVERIFY(orders->item(row, 3)->toolTip().contains(QStringLiteral("rounding errors")));
        // In words under the table too (a projector shows no tooltips).
        auto* detail = dialog->findChild<QLabel*>(QStringLiteral("orderExplanation"));
        QVERIFY(detail && detail->text().contains(QStringLiteral("rounding errors")));
        // The run at the floor says so beside its order.
        QTableWidget* runs = table(*dialog, "runsTable");
        const QString lastOrder = runs->item(runs->rowCount() - 1, 8)->text();
        QVERIFY2(lastOrder.contains(QStringLiteral("round-off floor reached")),
                 qPrintable(lastOrder));
        QVERIFY(!runs->item(1, 8)->text().contains(QStringLiteral("floor")));
        dialog->resize(1024, 700);
        QApplication::processEvents();
        savePicture(dialog, QStringLiteral("accuracy-lab-roundoff-1024x700"));
    }

    void instabilityIsExplained() {
        // Explicit Euler on the stiff spring (ω = 316 rad/s) blows up at every default step;
        // RK4 blows up at 1/60 only.
        MainWindow w;
        QVERIFY(w.openFile(QStringLiteral(":/scenes/stiff-spring-blowup.phasebox.json"), true));
        w.action("accuracyLab")->trigger();
        AccuracyDialog* dialog = accuracyDialogOf(w);
        choose(*dialog, {"explicit_euler", "rk4"});
        setLine(*dialog, 1, QStringLiteral("1"));
        QVERIFY(runStudy(*dialog));
        const AccuracyResult& result = dialog->study().result();
        for (const AccuracyRecord& r : result.records)
            if (r.integrator == "explicit_euler") QVERIFY(r.diverged);
        QTableWidget* orders = table(*dialog, "ordersTable");
        const int euler = rowOf(orders, QStringLiteral("explicit_euler"));
        QVERIFY(euler >= 0);
        QCOMPARE(orders->item(euler, 1)->text(), QStringLiteral("–"));
        QCOMPARE(orders->item(euler, 2)->text(), QStringLiteral("1"));
        QVERIFY2(orders->item(euler, 3)->text().contains(QStringLiteral("unstable")),
                 qPrintable(orders->item(euler, 3)->text()));
        QVERIFY(orders->item(euler, 3)->toolTip().contains(QStringLiteral("blew up")));
        const int rk4 = rowOf(orders, QStringLiteral("rk4"));
        QVERIFY(orders->item(rk4, 3)->text().contains(QStringLiteral("unstable at dt ≥ 1/60")));
        QTableWidget* runs = table(*dialog, "runsTable");
        QVERIFY(runs->item(0, 8)->text().contains(QStringLiteral("unstable at this dt")));
        dialog->resize(1024, 700);
        QApplication::processEvents();
        savePicture(dialog, QStringLiteral("accuracy-lab-unstable-1024x700"));
    }

    void cancelStopsTheStudy() {
        MainWindow w;
        QVERIFY(w.openFile(QStringLiteral(":/scenes/box-pyramid.phasebox.json"), true));
        AccuracyDialog* dialog = accuracyDialogOf(w);
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
