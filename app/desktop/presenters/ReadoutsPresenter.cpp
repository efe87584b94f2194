#include "app/desktop/presenters/ReadoutsPresenter.h"

#include "app/document/Document.h"
#include "app/sim/ProbeRecorder.h"
#include "physics/world/World.h"
#include "ui/instruments/InstrumentsPanel.h"
#include "ui/instruments/ProbeFormat.h"
#include "ui/instruments/ReadoutView.h"
#include "ui/panels/ShownNumber.h"

#include <cmath>
#include <optional>

namespace phasebox {

namespace {
// What kind of object an id names in the world, for the readouts' heading.
QString objectKind(const World& world, const std::string& id) {
    for (const Particle& p : world.particles())
        if (p.id == id)
            return p.cloth >= 0 ? ReadoutsPresenter::tr("cloth node")
                   : p.pinned   ? ReadoutsPresenter::tr("pinned particle")
                                : ReadoutsPresenter::tr("particle");
    for (const RigidBody& b : world.rigidBodies()) {
        if (b.id != id) continue;
        const QString shape = b.shape == RigidShape::Disk      ? ReadoutsPresenter::tr("disk")
                              : b.shape == RigidShape::Polygon ? ReadoutsPresenter::tr("polygon")
                                                               : ReadoutsPresenter::tr("box");
        return b.isStatic ? ReadoutsPresenter::tr("static %1").arg(shape) : shape;
    }
    return {};
}
}  // namespace

ReadoutsPresenter::ReadoutsPresenter(ui::InstrumentsPanel& panel, Document& document,
                                     ProbeRecorder& probes, QObject* parent)
    : InstrumentBase(panel, document, probes, parent) {}

void ReadoutsPresenter::refresh() {
    ui::ReadoutView* view = panel_.readouts();
    const World& world = document_.world();
    std::vector<std::string> objects;
    QString joint;
    for (const QString& id : document_.selection()) {
        const std::string name = id.toStdString();
        if (!objectKind(world, name).isEmpty())
            objects.push_back(name);
        else if (joint.isEmpty() && isJointId(world, name))
            joint = id;
    }
    if (objects.empty() && joint.isEmpty()) {
        view->showHint(
            tr("Click an object on the canvas to read its position, velocity, "
               "energy and momentum; Shift-click a second and a third for the "
               "distance and the angle between them."));
        return;
    }
    QList<ui::ReadoutRow> rows;
    // A row of one or two probes; left out when the first does not parse (angle of a particle).
    const auto addRow = [&](const QString& label, const QStringList& texts) {
        ui::ReadoutRow row;
        row.label = label;
        for (const QString& text : texts) {
            const std::optional<Probe> probe = ProbeRecorder::parse(world, text, nullptr);
            if (!probe) return;
            if (row.unit.isEmpty()) row.unit = ui::probeUnit(probe->kind);
            row.values << evaluateProbe(world, *probe);
            row.probes << text;
        }
        rows << row;
    };
    QString subject;
    if (!objects.empty()) {
        const QString id = QString::fromStdString(objects.front());
        subject = QStringLiteral("%1 (%2)").arg(id, objectKind(world, objects.front()));
        const auto p = [&id](const char* field) { return id + QLatin1Char('.') + field; };
        addRow(tr("position (x, y)"), {p("x"), p("y")});
        addRow(tr("velocity (vx, vy)"), {p("vx"), p("vy")});
        addRow(tr("speed"), {p("speed")});
        addRow(tr("angle"), {p("angle")});
        addRow(tr("angular velocity ω"), {p("omega")});
        addRow(tr("kinetic energy"), {p("kinetic")});
        addRow(tr("momentum (px, py)"), {p("px"), p("py")});
        addRow(tr("angular momentum L"), {p("L")});
        addRow(tr("contact force"), {QStringLiteral("contact_force(%1)").arg(id)});
    }
    if (objects.size() >= 2) {
        const QString a = QString::fromStdString(objects[0]),
                      b = QString::fromStdString(objects[1]);
        subject = QStringLiteral("%1, %2").arg(a, b);
        addRow(tr("distance %1–%2").arg(a, b), {QStringLiteral("distance(%1,%2)").arg(a, b)});
        if (objects.size() >= 3) {
            const QString c = QString::fromStdString(objects[2]);
            subject += QStringLiteral(", ") + c;
            addRow(tr("angle %1–%2–%3").arg(a, b, c),
                   {QStringLiteral("angle(%1,%2,%3)").arg(a, b, c)});
        }
    }
    if (!joint.isEmpty()) {
        if (subject.isEmpty()) subject = tr("%1 (joint)").arg(joint);
        addRow(tr("constraint force of %1").arg(joint), {QStringLiteral("force(%1)").arg(joint)});
        // Hinges, rods and ropes: the pendulum's angle (the row is left out for the others).
        addRow(tr("angle of %1").arg(joint), {joint + QStringLiteral(".angle")});
    }
    // A recorded frame the timeline shows says so (the world is in its state, at its time),
    // with the timeline's three decimals, which tell frames of a 1/60 s step apart.
    using Source = ui::ReadoutView::Source;
    const Source source = !std::isnan(shownTime()) ? Source::Recorded
                          : document_.hasRun()     ? Source::Live
                                                   : Source::Setup;
    const QString state = source == Source::Recorded
                              ? tr("recorded, t = %1 s").arg(ui::shownNumber(world.time(), 'f', 3))
                          : source == Source::Live
                              ? tr("live, t = %1 s").arg(ui::shownNumber(world.time(), 'f', 2))
                              : tr("setup");
    view->setReadout(subject, state, source, rows);
}

}  // namespace phasebox
