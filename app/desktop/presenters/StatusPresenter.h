#pragma once
// The status bar: the last message on the left; on the right the live error estimate, the
// clock, the real-time factor and the cost of a step.

#include "app/desktop/presenters/Presenter.h"

QT_BEGIN_NAMESPACE
class QLabel;
class QStatusBar;
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
    // Shows a message until the next one (every presenter's message() comes here).
    void showMessage(const QString& text);

private:
    void reportUnsupportedEffects();

    Document& document_;
    SimulationController& controller_;
    QLabel* message_ = nullptr;
    QLabel* error_ = nullptr;
    QLabel* time_ = nullptr;
    QLabel* speed_ = nullptr;
    QLabel* cost_ = nullptr;
};

}  // namespace phasebox
