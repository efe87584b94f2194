#include "app/sim/DivergenceReport.h"

#include "app/i18n/AdviceText.h"
#include "physics/diagnostics/StabilityAdvisor.h"
#include "physics/world/World.h"
#include "ui/panels/BuiltinText.h"
#include "ui/panels/ShownNumber.h"

#include <QCoreApplication>
#include <QStringList>

#include <cmath>
#include <limits>

namespace phasebox {

namespace {
// The report's words, in the context lupdate gives them.
struct DivergenceText {
    Q_DECLARE_TR_FUNCTIONS(DivergenceText)
};

QString seconds(double t) {
    return ui::shownNumber(t, 'g', 3) + QStringLiteral(" s");
}

// The engine's "what" (DivergenceGuard) in a user's words.
QString whatHappened(const std::string& what) {
    if (what.find("non-finite") != std::string::npos)
        return DivergenceText::tr(
            "a position or speed grew so large that it is no longer a number");
    if (what.find("energy growing") != std::string::npos)
        return DivergenceText::tr("its energy grew without bound");
    if (what.find("tolerance") != std::string::npos)
        return DivergenceText::tr("the adaptive method could not keep its error small enough");
    return QString::fromStdString(what);
}

QString label(std::string_view name) {
    const IntegratorInfo* info = findIntegrator(name);
    if (info) return ui::integratorText(info->label);
    return QString::fromUtf8(name.data(), static_cast<qsizetype>(name.size()));
}
}  // namespace

QString describeObject(const World& world, const QString& id) {
    const std::string key = id.toStdString();
    for (const Particle& p : world.particles()) {
        if (p.id != key) continue;
        if (p.cloth >= 0) {
            const Cloth& cloth = world.cloths()[static_cast<std::size_t>(p.cloth)];
            const int node = static_cast<int>(&p - world.particles().data()) - cloth.firstParticle;
            const int column = node % cloth.nx, row = node / cloth.nx;
            return DivergenceText::tr(
                       "cloth '%1', the node in row %2 from the top, column %3 from the left")
                .arg(QString::fromStdString(cloth.id))
                .arg(row + 1)
                .arg(column + 1);
        }
        return DivergenceText::tr("particle '%1'").arg(id);
    }
    for (const RigidBody& b : world.rigidBodies()) {
        if (b.id != key) continue;
        switch (b.shape) {
            case RigidShape::Disk:
                return DivergenceText::tr("disk '%1'").arg(id);
            case RigidShape::Polygon:
                return DivergenceText::tr("polygon '%1'").arg(id);
            case RigidShape::Rectangle:
                break;
        }
        return DivergenceText::tr("box '%1'").arg(id);
    }
    return id.isEmpty() ? QString() : QStringLiteral("'%1'").arg(id);
}

DivergenceReport describeDivergence(World& world) {
    DivergenceReport report;
    const SimulationSettings& settings = world.settings();
    if (!world.divergence()) {
        report.text = DivergenceText::tr(
            "The simulation became unstable. Try a smaller time step, more sub-steps "
            "or Implicit Euler.");
        return report;
    }
    const Divergence& d = *world.divergence();
    QStringList lines;
    lines << DivergenceText::tr(
                 "The simulation became unstable at t = %1: %2. It was paused and put back to "
                 "t = %3.")
                 .arg(seconds(d.time), whatHappened(d.what), seconds(d.restoredTime));
    const QString where = describeObject(world, QString::fromStdString(d.objectId));
    if (!where.isEmpty()) lines << DivergenceText::tr("It started at %1.").arg(where);

    // What to try, from the stability advisor at the restored state: the step this method
    // needs, the sub-steps that give it, a method stable at this step, softer springs.
    const StabilityAdvice advice = adviseStability(world, 500);
    QStringList tries;
    double maxDt = std::numeric_limits<double>::infinity();
    for (const StepLimit& limit : advice.limits)
        if (limit.integrator == settings.integrator) maxDt = limit.maxDt;
    // A chain pulled straight between two fixed points: first what removes the cause.
    if (!d.straightFrom.empty())
        tries << DivergenceText::tr(
                     "start the chain from joint '%1' to joint '%2' with some sag: it is pulled "
                     "straight between two fixed points, where it cannot sag without stretching, "
                     "and the forces that keep it straight grow without bound as it moves")
                     .arg(QString::fromStdString(d.straightFrom),
                          QString::fromStdString(d.straightTo))
              << DivergenceText::tr("or free one end of that chain");
    if (!advice.currentStable && maxDt > 0.0 && std::isfinite(maxDt)) {
        // A margin below the limit: a step right at it is barely stable.
        const double target = 0.8 * maxDt;
        const int substeps = static_cast<int>(std::ceil(settings.dt / target));
        tries << DivergenceText::tr("a smaller time step: dt below %1").arg(seconds(target))
              << DivergenceText::tr("%1 sub-steps per step (same dt, each step cut into %1 pieces)")
                     .arg(substeps);
    } else {
        tries
            << DivergenceText::tr("a smaller time step (half of dt = %1)").arg(seconds(settings.dt))
            << DivergenceText::tr("%1 sub-steps per step").arg(std::max(2, 2 * settings.substeps));
    }
    if (settings.integrator != "implicit_euler")
        tries << DivergenceText::tr(
                     "%1, which stays stable at any time step (it damps fast motion)")
                     .arg(label("implicit_euler"));
    if (!world.springs().empty())
        tries << DivergenceText::tr("softer springs or cloth (a lower stiffness)");
    if (settings.contactModel == ContactModel::Penalty)
        tries << DivergenceText::tr("impulse contacts instead of penalty contacts");
    lines << QString() << DivergenceText::tr("What to try:");
    for (const QString& t : std::as_const(tries)) lines << QStringLiteral("• ") + t;
    report.text = lines.join(QLatin1Char('\n'));

    QStringList details{QString::fromStdString(d.message())};
    if (!advice.message.empty())
        details
            << DivergenceText::tr("Stability advisor: %1").arg(i18n::adviceText(advice, settings));
    report.details = details.join(QLatin1Char('\n'));
    return report;
}

}  // namespace phasebox
