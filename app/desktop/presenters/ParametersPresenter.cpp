#include "app/desktop/presenters/ParametersPresenter.h"

#include "app/document/Document.h"
#include "app/i18n/AdviceText.h"
#include "app/sim/SimulationController.h"
#include "physics/diagnostics/StabilityAdvisor.h"
#include "physics/integrators/Integrator.h"
#include "physics/scene/SceneSchema.h"
#include "ui/panels/ParametersPanel.h"
#include "ui/panels/ShownNumber.h"

#include <QAction>
#include <QSettings>

#include <algorithm>
#include <cmath>

namespace phasebox {

ParametersPresenter::ParametersPresenter(ui::ParametersPanel& panel, Document& document,
                                         SimulationController& controller, QObject* parent)
    : Presenter(parent), panel_(panel), document_(document), controller_(controller) {
    connect(&document_, &Document::sceneReset, this, &ParametersPresenter::refresh);
    // An edit may bring a lighter body, and with it another automatic penalty stiffness.
    connect(&document_, &Document::sceneEdited, this, [this] {
        panel_.setContactStiffness(document_.world().penaltyStiffness(),
                                   !document_.setup().simulation.contactStiffness.has_value());
        updateAdvice();
    });
    connect(&document_, &Document::simulationSettingsChanged, this,
            &ParametersPresenter::showSettings);

    connect(&panel_, &ui::ParametersPanel::integratorChanged, this, [this](const QString& name) {
        change([&](auto& s) { s.integrator = name.toStdString(); });
    });
    connect(&panel_, &ui::ParametersPanel::dtChanged, this,
            [this](double dt) { change([&](auto& s) { s.dt = dt; }); });
    connect(&panel_, &ui::ParametersPanel::substepsChanged, this,
            [this](int n) { change([&](auto& s) { s.substeps = n; }); });
    connect(&panel_, &ui::ParametersPanel::toleranceChanged, this,
            [this](double tolerance) { change([&](auto& s) { s.tolerance = tolerance; }); });
    connect(&panel_, &ui::ParametersPanel::newtonIterationsChanged, this,
            [this](int n) { change([&](auto& s) { s.newtonIterations = n; }); });
    connect(&panel_, &ui::ParametersPanel::speedChanged, this, &ParametersPresenter::setSpeed);
    connect(&panel_, &ui::ParametersPanel::contactModelChanged, this,
            [this](ContactModel model) { change([&](auto& s) { s.contactModel = model; }); });
    connect(&panel_, &ui::ParametersPanel::contactStiffnessChanged, this, [this](double k) {
        change([&](auto& s) {
            s.contactStiffness = k > 0.0 ? std::optional<double>(k) : std::nullopt;
        });
    });
    connect(&panel_, &ui::ParametersPanel::contactDampingChanged, this,
            [this](double c) { change([&](auto& s) { s.contactDamping = c; }); });
    connect(&panel_, &ui::ParametersPanel::sleepChanged, this,
            [this](bool sleep) { change([&](auto& s) { s.sleep = sleep; }); });
}

void ParametersPresenter::createActions(QWidget& window) {
    auto add = [&](const char* name, const QString& text, QKeyCombination key, auto slot) {
        QAction* action = addWindowAction(window, name, text, key);
        connect(action, &QAction::triggered, this, slot);
        return action;
    };
    QAction* play = add("play", tr("&Play"), Qt::Key_Space, [this] { controller_.togglePlay(); });
    play->setCheckable(true);
    play->setToolTip(tr("Play or pause the simulation (Space)"));
    connect(&controller_, &SimulationController::runningChanged, play, [play](bool running) {
        play->setChecked(running);
        play->setText(running ? tr("&Pause") : tr("&Play"));
    });
    QAction* step = add("step", tr("S&tep"), Qt::Key_S, [this] { controller_.singleStep(); });
    step->setToolTip(tr("Advance one step (S)"));
    QAction* reset =
        add("reset", tr("&Reset"), Qt::CTRL | Qt::Key_R, [this] { controller_.reset(); });
    reset->setToolTip(tr("Back to the setup (Ctrl+R)"));
    panel_.setActions(play, step, reset);
    add("nextIntegrator", tr("Next Integrator"), Qt::Key_BracketRight,
        [this] { cycleIntegrator(1); });
    add("previousIntegrator", tr("Previous Integrator"), Qt::Key_BracketLeft,
        [this] { cycleIntegrator(-1); });
    add("doubleDt", tr("Double dt"), Qt::CTRL | Qt::Key_Period, [this] { scaleDt(2.0); });
    add("halveDt", tr("Halve dt"), Qt::CTRL | Qt::Key_Comma, [this] { scaleDt(0.5); });
    add("moreSubsteps", tr("More Sub-steps"), Qt::ALT | Qt::Key_Up, [this] { changeSubsteps(1); });
    add("fewerSubsteps", tr("Fewer Sub-steps"), Qt::ALT | Qt::Key_Down,
        [this] { changeSubsteps(-1); });
    add("faster", tr("Faster"), Qt::CTRL | Qt::Key_Up, [this] { changeSpeed(1); });
    add("slower", tr("Slower"), Qt::CTRL | Qt::Key_Down, [this] { changeSpeed(-1); });
}

void ParametersPresenter::readSettings(const QSettings& settings) {
    // A hand-edited or damaged file may hold anything: not a number, nan, inf, a negative or
    // huge speed. Those give the default, as a missing key does.
    bool ok = false;
    const double speed = settings.value(QStringLiteral("simulation/speed"), 1.0).toDouble(&ok);
    setSpeed(ok && std::isfinite(speed) && speed >= SimulationController::kMinSpeed &&
                     speed <= SimulationController::kMaxSpeed
                 ? speed
                 : 1.0);
}

void ParametersPresenter::writeSettings(QSettings& settings) const {
    settings.setValue(QStringLiteral("simulation/speed"), controller_.speed());
}

void ParametersPresenter::refresh() {
    panel_.setSpeed(controller_.speed());
    showSettings();
}

void ParametersPresenter::showSettings() {
    const SimulationDesc& simulation = document_.setup().simulation;
    panel_.setSimulation(simulation);
    panel_.setContactStiffness(document_.world().penaltyStiffness(),
                               !simulation.contactStiffness.has_value());
    updateAdvice();
}

void ParametersPresenter::updateAdvice() {
    const StabilityAdvice advice = adviseStability(document_.world(), 200);
    // The contact model's warning (kinematic contacts under a stack) stands beside the step's.
    const QString contactWarning = i18n::contactWarningText(advice.contactWarning);
    if (advice.omegaMax <= 0.0) {
        panel_.setAdvice(contactWarning, !contactWarning.isEmpty());
        return;
    }
    // The largest stable step of every method, as the advisor computed them.
    QStringList details{tr("Largest stable sub-step (stiffest mode ω = %1 rad/s):")
                            .arg(ui::shownNumber(advice.omegaMax, 'g', 4))};
    for (const StepLimit& limit : advice.limits) {
        const QString name = QString::fromLatin1(limit.integrator.data(),
                                                 static_cast<qsizetype>(limit.integrator.size()));
        const QString step = std::isinf(limit.maxDt) ? tr("any")
                             : limit.maxDt == 0.0
                                 ? tr("none")
                                 : tr("%1 s").arg(ui::shownNumber(limit.maxDt, 'g', 3));
        details << QStringLiteral("%1: %2").arg(name, step);
    }
    // The advisor writes English for a terminal (omega*h); the panel in the window's language
    // and the lecture's notation.
    QString text = i18n::adviceText(advice, document_.world().settings());
    if (!contactWarning.isEmpty())
        text = advice.currentStable ? contactWarning : text + QLatin1Char('\n') + contactWarning;
    panel_.setAdvice(text, !advice.currentStable || !contactWarning.isEmpty(),
                     details.join(QLatin1Char('\n')));
}

bool ParametersPresenter::change(const std::function<void(SimulationDesc&)>& edit) {
    SimulationDesc simulation = document_.setup().simulation;
    edit(simulation);
    QString error;
    const bool ok = document_.applySimulationSettings(simulation, &error);
    if (!ok) {
        emit message(error);
        panel_.setSimulation(document_.setup().simulation);
    }
    document_.finishInteraction();
    return ok;
}

void ParametersPresenter::cycleIntegrator(int direction) {
    const auto& registry = integratorRegistry();
    const std::string current = document_.setup().simulation.integrator;
    const auto it = std::find_if(registry.begin(), registry.end(),
                                 [&](const auto& info) { return info.name == current; });
    const int n = static_cast<int>(registry.size());
    const int index = it == registry.end() ? 0 : static_cast<int>(it - registry.begin());
    const std::string next(registry[static_cast<std::size_t>((index + direction + n) % n)].name);
    if (change([&](auto& s) { s.integrator = next; }))
        emit message(tr("Integrator: %1").arg(QString::fromStdString(next)));
}

void ParametersPresenter::scaleDt(double factor) {
    const schema::Editor& limits = schema::simulationField(schema::key::dt).editor;
    const double dt = std::clamp(document_.setup().simulation.dt * factor, limits.min, limits.max);
    if (change([&](auto& s) { s.dt = dt; })) emit message(tr("dt = %1 s").arg(dt, 0, 'g', 4));
}

void ParametersPresenter::changeSubsteps(int delta) {
    const int substeps = std::clamp(document_.setup().simulation.substeps + delta, 1, 1000);
    if (change([&](auto& s) { s.substeps = substeps; }))
        emit message(tr("%1 sub-steps").arg(substeps));
}

void ParametersPresenter::applyStudyChoice(const QString& integrator, double dt, double tolerance) {
    const bool ok = change([&](auto& s) {
        s.integrator = integrator.toStdString();
        s.dt = dt;
        s.tolerance = tolerance;
    });
    if (ok) emit message(tr("Applied %1 at dt %2 s").arg(integrator).arg(dt, 0, 'g', 4));
}

void ParametersPresenter::changeSpeed(int direction) {
    const auto& speeds = ui::ParametersPanel::speeds();
    const double current = controller_.speed();
    const auto nearest =
        std::min_element(speeds.begin(), speeds.end(), [current](double a, double b) {
            return std::abs(std::log(a / current)) < std::abs(std::log(b / current));
        });
    const int index = std::clamp(static_cast<int>(nearest - speeds.begin()) + direction, 0,
                                 static_cast<int>(speeds.size()) - 1);
    setSpeed(speeds[static_cast<std::size_t>(index)]);
}

void ParametersPresenter::setSpeed(double factor) {
    controller_.setSpeed(factor);
    panel_.setSpeed(controller_.speed());
    emit speedChanged(controller_.speed());
}

}  // namespace phasebox
