#pragma once
// The accuracy lab (Tools → Accuracy Lab): runs the AccuracyStudy on the open scene's setup in
// a worker thread and shows what accuracy costs in time — the work-precision diagram, the
// table of runs, each method's observed order against theory — and answers "what is the
// cheapest way to an error of …?", which can be applied to the scene.

#include "app/accuracy/AccuracyStudy.h"

#include <QDialog>
#include <QFont>

#include <optional>
#include <vector>

QT_BEGIN_NAMESPACE
class QChartView;
class QLabel;
class QLineEdit;
class QListWidget;
class QProgressBar;
class QPushButton;
class QTableWidget;
QT_END_NAMESPACE

namespace phasebox {

class AccuracyDialog : public QDialog {
    Q_OBJECT

public:
    explicit AccuracyDialog(QWidget* parent = nullptr);

    // The scene the next study runs on (a copy is taken when it starts).
    void setScene(const SceneDesc& scene);
    // The open scene's file, which an export must not replace.
    void setSceneFile(const QString& path) { sceneFile_ = path; }
    // The document's scene now: a study's result applies only to the scene it studied, so
    // Apply is disabled while they differ in anything but the simulation settings (which are
    // what Apply changes).
    void setCurrentScene(const SceneDesc& scene);
    bool studiedSceneIsCurrent() const { return studiedIsCurrent_; }
    // Starts a study with the dialog's choices; false when one is running or the choices are
    // invalid (the reason is shown).
    bool run();
    void cancel();
    AccuracyStudy& study() { return study_; }

    // The dt list as typed: steps in (0, 1] s, each a number or a fraction (1/120), '.' always
    // a decimal point and the window's locale's decimal separator too ("0,01" in German);
    // separated by ';', and by ',' where that is not the decimal separator. nullopt for any part
    // that is no such step, *bad then holding it.
    static std::optional<std::vector<double>> parseDtList(const QString& text,
                                                          QString* bad = nullptr);
    // Steps as the field shows them, in the window's locale, with that locale's separator.
    static QString dtListText(const std::vector<double>& dts);

    // The cheapest finished run whose error is at most target (least CPU time), if any.
    std::optional<AccuracyRecord> cheapestFor(double targetError) const;
    // The order measured for an integrator on the steps in its asymptotic range (above the
    // round-off floor, below any unstable step: assessOrders), as the orders table shows it.
    static std::optional<double> observedOrder(const AccuracyResult& result,
                                               const std::string& integrator);
    // The orders table's explanation for an integrator of the last study (its tooltip).
    QString orderExplanation(const QString& integrator) const;

    bool exportTo(const QString& path, QString* error) const;  // .png, .svg or .csv
    QString summaryText() const;

signals:
    // "Apply" on the cheapest settings: the main window changes the scene's integrator and dt
    // (and tolerance for the adaptive methods).
    void applyRequested(const QString& integrator, double dt, double tolerance);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    QFont chartFont() const;  // the dialog's font, larger as the diagram grows
    void onFinished();
    void updateCheapest();
    void fillTable(const AccuracyResult& result);
    void exportInteractively(const QString& format);

    SceneDesc scene_;
    SceneDesc studied_;  // the scene of the last study started
    bool studiedIsCurrent_ = true;
    AccuracyStudy study_;
    QListWidget* integrators_ = nullptr;
    QLineEdit* dts_ = nullptr;
    QLineEdit* duration_ = nullptr;
    QPushButton* runButton_ = nullptr;
    QPushButton* cancelButton_ = nullptr;
    QProgressBar* progress_ = nullptr;
    QChartView* chart_ = nullptr;
    QTableWidget* table_ = nullptr;
    QTableWidget* orders_ = nullptr;
    QLabel* orderDetail_ = nullptr;  // the explanation of the orders table's current row
    QLabel* summary_ = nullptr;
    QLineEdit* target_ = nullptr;
    QLabel* cheapest_ = nullptr;
    QPushButton* apply_ = nullptr;
    std::optional<AccuracyRecord> chosen_;
    QFont chartFont_;  // what the diagram's text was last sized from
    QString sceneFile_;
};

}  // namespace phasebox
