#pragma once
// The status bar: the last message on the left; on the right the live error estimate, the
// clock, the real-time factor and the cost of a step.

#include "app/desktop/presenters/Presenter.h"

QT_BEGIN_NAMESPACE
class QLabel;
class QStatusBar;
class QTimer;
QT_END_NAMESPACE

namespace phasebox {

class Document;
class SimulationController;

class StatusPresenter : public Presenter {
    Q_OBJECT

public:
    StatusPresenter(QStatusBar& bar, Document& document, SimulationController& controller,
                    QObject* parent = nullptr);

    void refresh() override;
    // Shows a message for kMessageMs, or until the next one or a new scene (every presenter's
    // message() comes here): "Distance 1.001 m" must not outlive the ruler it measured.
    void showMessage(const QString& text);
    static constexpr int kMessageMs = 10000;

private:
    void reportUnsupportedEffects();
    // A new scene (New, Open, Reset, Revert): no message of the scene before stays.
    void onSceneReset();

    Document& document_;
    SimulationController& controller_;
    QLabel* message_ = nullptr;
    QTimer* expiry_ = nullptr;  // clears message_
    QLabel* error_ = nullptr;
    QLabel* time_ = nullptr;
    QLabel* speed_ = nullptr;
    QLabel* cost_ = nullptr;
};

}  // namespace phasebox
