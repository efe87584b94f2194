#include "app/i18n/AdviceText.h"

#include "physics/diagnostics/StabilityAdvisor.h"
#include "physics/integrators/Integrator.h"
#include "physics/world/World.h"
#include "ui/panels/ShownNumber.h"

#include <QCoreApplication>
#include <QRegularExpression>
#include <QStringList>

#include <algorithm>
#include <cmath>

namespace phasebox::i18n {

namespace {
// The advisor's words, in the context lupdate gives them.
struct StabilityText {
    Q_DECLARE_TR_FUNCTIONS(StabilityText)
};

// The engine's numbers have three significant digits (std::ostream's default notation).
QString num(double v) {
    return ui::shownNumber(v, 'g', 3);
}

QString fromView(std::string_view text) {
    return QString::fromUtf8(text.data(), static_cast<qsizetype>(text.size()));
}

// The methods stable at this step other than the current one, as the engine lists them.
QString alternatives(const StabilityAdvice& advice, const std::string& method) {
    QStringList names;
    for (const StepLimit& limit : advice.recommended) {
        if (limit.integrator == method) continue;
        names << (std::isfinite(limit.maxDt)
                      ? StabilityText::tr("%1 (stable below %2 s)")
                            .arg(fromView(limit.integrator), num(limit.maxDt))
                      : fromView(limit.integrator));
    }
    return names.join(QStringLiteral(", "));
}

// The unstable current step: the same three cases and their numbers as adviseStability.
QString unstableText(const StabilityAdvice& advice, const SimulationSettings& settings,
                     const IntegratorInfo& info, double maxDt) {
    const double omega = advice.omegaMax;
    const double wh = omega * advice.dt;
    // The bound the advisor applied (the method's, or the penalty contacts' margin below it).
    const double bound = maxDt * omega;
    const QString method = QString::fromStdString(settings.integrator);
    const QString others = alternatives(advice, settings.integrator);
    const bool marginOnly =
        bound > 0.0 && bound < info.stabilityBound * (1.0 - 1e-9) && wh < info.stabilityBound;
    const QString substeps = QString::number(std::ceil(settings.dt / maxDt));
    if (bound > 0.0 && marginOnly) {
        const QString text =
            others.isEmpty()
                ? StabilityText::tr(
                      "%1 at a sub-step of %2 s has ω·h = %3 (below the linear limit %4 but above "
                      "%5, the margin for penalty contacts): a contact that begins within a step "
                      "can gain energy at every touch. Use dt/substeps below %6 s (%7 sub-steps).")
                : StabilityText::tr(
                      "%1 at a sub-step of %2 s has ω·h = %3 (below the linear limit %4 but above "
                      "%5, the margin for penalty contacts): a contact that begins within a step "
                      "can gain energy at every touch. Use dt/substeps below %6 s (%7 sub-steps), "
                      "or a method stable at this step: %8.");
        return text.arg(method, num(advice.dt), num(wh), num(info.stabilityBound), num(bound),
                        num(maxDt), substeps, others);
    }
    if (bound > 0.0) {
        const QString text =
            others.isEmpty()
                ? StabilityText::tr(
                      "%1 at a sub-step of %2 s has ω·h = %3 (stable below %4): it will blow up. "
                      "Use dt/substeps below %5 s (%6 sub-steps, more for a margin).")
                : StabilityText::tr(
                      "%1 at a sub-step of %2 s has ω·h = %3 (stable below %4): it will blow up. "
                      "Use dt/substeps below %5 s (%6 sub-steps, more for a margin), or a method "
                      "stable at this step: %7.");
        return text.arg(method, num(advice.dt), num(wh), num(bound), num(maxDt), substeps, others);
    }
    const double growth = info.energyGrowth ? info.energyGrowth(wh) : INFINITY;
    const QString text = others.isEmpty()
                             ? StabilityText::tr(
                                   "%1 at a sub-step of %2 s has ω·h = %3: it gains energy at "
                                   "every step (its stiffest mode by a factor of about %4 per "
                                   "sub-step).")
                             : StabilityText::tr(
                                   "%1 at a sub-step of %2 s has ω·h = %3: it gains energy at "
                                   "every step (its stiffest mode by a factor of about %4 per "
                                   "sub-step). Use a method stable at this step: %5.");
    return text.arg(method, num(advice.dt), num(wh), num(growth), others);
}
}  // namespace

QString adviceText(const StabilityAdvice& advice, const SimulationSettings& settings) {
    const QString engine = QString::fromStdString(advice.message)
                               .replace(QLatin1String("omega*h"), QStringLiteral("ω·h"));
    if (!(advice.omegaMax > 0.0)) return StabilityText::tr("nothing in the scene oscillates");
    if (advice.currentStable)
        return StabilityText::tr("%1 is stable at this step (ω·h = %2)")
            .arg(QString::fromStdString(settings.integrator), num(advice.omegaMax * advice.dt));
    const IntegratorInfo* info = findIntegrator(settings.integrator);
    const auto limit =
        std::find_if(advice.limits.begin(), advice.limits.end(),
                     [&](const StepLimit& l) { return l.integrator == settings.integrator; });
    if (!info || limit == advice.limits.end() || !std::isfinite(limit->maxDt)) return engine;
    return unstableText(advice, settings, *info, limit->maxDt);
}

QString contactWarningText(const std::string& warning) {
    if (warning.empty()) return {};
    const QString english = QString::fromStdString(warning);
    static const QRegularExpression stack(
        QStringLiteral("^Kinematic contacts cannot hold a stack \\(\"(.*)\" rests on \"(.*)\"\\): "
                       "they only stop bodies moving into each other and push them apart, so the "
                       "stack sinks into the floor\\. Use impulse contacts for stacks\\.$"));
    const QRegularExpressionMatch m = stack.match(english);
    if (!m.hasMatch()) return english;
    return StabilityText::tr(
               "Kinematic contacts cannot hold a stack (\"%1\" rests on \"%2\"): they only stop "
               "bodies moving into each other and push them apart, so the stack sinks into the "
               "floor. Use impulse contacts for stacks.")
        .arg(m.captured(1), m.captured(2));
}

}  // namespace phasebox::i18n
