#pragma once
// Two clocks on simulated time. The period timer measures the period of any probe as
// `phasebox-cli run --probe` does (CONTRACT §7): the mean interval between upward crossings of
// the mid-level (min + max)/2, each crossing interpolated within its step; it lists the
// crossings it used, so a student can check the number by hand. The stopwatch is started,
// stopped, lapped and reset by hand, and reads the simulation's clock.

#include <QString>
#include <QWidget>

#include <optional>
#include <vector>

QT_BEGIN_NAMESPACE
class QLabel;
class QToolButton;
class QTableWidget;
QT_END_NAMESPACE

namespace phasebox::ui {

class ProbePicker;

class TimerView : public QWidget {
    Q_OBJECT

public:
    explicit TimerView(QWidget* parent = nullptr);

    ProbePicker* picker() const { return picker_; }

    // The measured period (nullopt: not yet two crossings), a line on how it was measured, and
    // the crossing times.
    void setPeriod(std::optional<double> period, const QString& detail,
                   const std::vector<double>& crossings);
    std::optional<double> period() const { return period_; }
    QString periodText() const;
    int crossingCount() const;

    void setStopwatch(double elapsed, bool running, const std::vector<double>& laps);
    QString stopwatchText() const;
    int lapCount() const;

signals:
    void probeEntered(const QString& probe);
    void startStopClicked();
    void lapClicked();
    void resetClicked();

private:
    ProbePicker* picker_ = nullptr;
    QLabel* periodLabel_ = nullptr;
    QLabel* frequency_ = nullptr;
    QLabel* detail_ = nullptr;
    QTableWidget* crossings_ = nullptr;
    std::optional<double> period_;

    QLabel* stopwatch_ = nullptr;
    QToolButton* startStop_ = nullptr;
    QToolButton* lap_ = nullptr;
    QTableWidget* laps_ = nullptr;
};

}  // namespace phasebox::ui
