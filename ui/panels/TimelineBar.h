#pragma once
// The timeline under the canvas: the run's recorded frames on a slider, buttons to jump to the
// start and to step a frame back or forth, the time shown, and the recording's memory against
// its budget (settable). It shows what it is given and emits what the user asks for; the app
// moves the simulation.

#include <QWidget>

#include <cstddef>

QT_BEGIN_NAMESPACE
class QAction;
class QLabel;
class QSlider;
class QSpinBox;
class QToolButton;
QT_END_NAMESPACE

namespace phasebox::ui {

class TimelineBar : public QWidget {
    Q_OBJECT

public:
    explicit TimelineBar(QWidget* parent = nullptr);

    // count recorded frames, the one shown (count − 1: the live end) and its time, and the
    // time of the last frame.
    void setFrames(int count, int shown, double shownTime, double endTime);
    void setMemory(std::size_t usedBytes, std::size_t budgetBytes);
    int shownFrame() const;
    // The button beside the time for one of the app's actions (Compare from Here, Leave
    // Compare): it shows and triggers whichever is set (nullptr hides it). While it shows, the
    // memory figure is hidden.
    void setCompareAction(QAction* action);

signals:
    // The user dragged or clicked the slider to this frame.
    void frameRequested(int index);
    // The budget field changed (bytes).
    void budgetRequested(std::size_t bytes);
    void startRequested();
    void stepRequested(int delta);

private:
    QToolButton* start_;
    QToolButton* back_;
    QToolButton* forward_;
    QSlider* slider_;
    QLabel* time_;
    QToolButton* compare_;
    QLabel* memory_;
    QSpinBox* budget_;
};

}  // namespace phasebox::ui
