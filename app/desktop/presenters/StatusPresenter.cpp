#include "app/desktop/presenters/StatusPresenter.h"

#include "app/document/Document.h"
#include "app/sim/SimulationController.h"
#include "physics/world/World.h"
#include "ui/panels/ShownNumber.h"

#include <QLabel>
#include <QStatusBar>
#include <QTimer>

#include <cmath>

namespace phasebox {

StatusPresenter::StatusPresenter(QStatusBar& bar, Document& document,
                                 SimulationController& controller, QObject* parent)
    : Presenter(parent), document_(document), controller_(controller) {
    message_ = new QLabel(&bar);
    message_->setObjectName(QStringLiteral("statusMessage"));
    message_->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    bar.addWidget(message_, 1);
    expiry_ = new QTimer(this);
    expiry_->setObjectName(QStringLiteral("statusMessageExpiry"));
    expiry_->setSingleShot(true);
    expiry_->setInterval(kMessageMs);
    connect(expiry_, &QTimer::timeout, message_, &QLabel::clear);
    error_ = new QLabel(&bar);
    error_->setToolTip(
        tr("Step doubling at the current state: the error one step of this "
           "method makes now. Raise dt and watch it grow."));
    time_ = new QLabel(&bar);
    speed_ = new QLabel(&bar);
    cost_ = new QLabel(&bar);
    for (QLabel* label : {error_, time_, speed_, cost_}) bar.addPermanentWidget(label);

    connect(&document_, &Document::sceneReset, this, &StatusPresenter::onSceneReset);
    connect(&document_, &Document::sceneEdited, this, &StatusPresenter::reportUnsupportedEffects);
    connect(&document_, &Document::simulationSettingsChanged, this, &StatusPresenter::refresh);
    connect(&controller_, &SimulationController::stepped, this, &StatusPresenter::refresh);
    connect(&controller_, &SimulationController::statsChanged, this, &StatusPresenter::refresh);
    connect(&controller_, &SimulationController::runningChanged, this, &StatusPresenter::refresh);
    connect(&controller_, &SimulationController::frameShown, this, &StatusPresenter::refresh);
}

void StatusPresenter::showMessage(const QString& text) {
    message_->setText(text);
    if (text.isEmpty())
        expiry_->stop();
    else
        expiry_->start();
}

void StatusPresenter::onSceneReset() {
    showMessage(QString());
    reportUnsupportedEffects();
}

void StatusPresenter::reportUnsupportedEffects() {
    refresh();
    const QStringList unsupported = document_.unsupportedEffects();
    if (!unsupported.isEmpty())
        showMessage(tr("Not simulated yet by this version: %1")
                        .arg(unsupported.join(QStringLiteral(", "))));
}

void StatusPresenter::refresh() {
    const double error = controller_.lastErrorEstimate();
    error_->setText(std::isfinite(error)
                        ? tr("local error ≈ %L1 m").arg(ui::shownNumber(error, 'g', 2))
                        : QString());
    time_->setText(tr("t = %L1 s").arg(ui::shownNumber(document_.world().time(), 'g', 4)));
    speed_->setText(controller_.isRunning() ? tr("real-time factor %L1 (speed %L2×)")
                                                  .arg(controller_.realTimeFactor(), 0, 'f', 2)
                                                  .arg(controller_.speed())
                                            : tr("paused (speed %L1×)").arg(controller_.speed()));
    // The cost is the live run's mean: a recorded frame keeps no timing of its own.
    const QString cost = ui::shownNumber(controller_.msPerStep(), 'g', 3);
    cost_->setText(controller_.shownFrame() >= 0 ? tr("%L1 ms per step (live run)").arg(cost)
                                                 : tr("%L1 ms per step").arg(cost));
}

}  // namespace phasebox
