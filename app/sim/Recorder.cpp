#include "app/sim/Recorder.h"

#include "app/io/NumberFormat.h"
#include "app/io/OutputFile.h"
#include "physics/world/World.h"
#include "ui/panels/ShownNumber.h"

#include <QTextStream>

#include <algorithm>
#include <iterator>

namespace phasebox {

namespace {
// Keeps elements 0, 2, 4, … of v.
template <typename T>
void keepEveryOther(std::vector<T>& v) {
    std::size_t out = 0;
    for (std::size_t i = 0; i < v.size(); i += 2) v[out++] = v[i];
    v.resize(out);
}

// Writes lines through OutputFile: a failed export never leaves half a file behind.
template <typename WriteRows>
bool writeCsv(const QString& path, QString* error, const QString& header, WriteRows&& rows) {
    OutputFile file(path, QObject::tr("the CSV file"));
    if (file.open()) {
        QTextStream out(file.device());
        out << header << '\n';
        rows(out);
        out.flush();
    }
    if (!file.commit()) {
        if (error) *error = file.error();
        return false;
    }
    return true;
}
}  // namespace

Recorder::Recorder(QObject* parent) : QObject(parent) {}

void Recorder::clear() {
    energy_.clear();
    markers_.clear();
    phase_.clear();
    phaseTimes_.clear();
    errors_.clear();
    haveSettings_ = false;
    lastTime_ = -1.0;
    stride_ = 1;
    calls_ = 0;
    pending_ = false;
    emit cleared();
}

void Recorder::setMaxSamples(std::size_t maxSamples) {
    maxSamples_ = std::max<std::size_t>(maxSamples, 2);
    while (energy_.size() >= maxSamples_ || phase_.size() >= maxSamples_) halve();
}

void Recorder::setPhaseTarget(const QString& objectId, const QString& coordinate) {
    phaseObject_ = objectId.toStdString();
    phaseCoordinate_ = coordinate;
    phaseIndex_ = -1;
    phase_.clear();
    phaseTimes_.clear();
}

QString Recorder::phaseVelocityName() const {
    if (phaseCoordinate_ == QLatin1String("y")) return QStringLiteral("vy");
    if (phaseCoordinate_ == QLatin1String("angle")) return QStringLiteral("omega");
    return QStringLiteral("vx");
}

void Recorder::recordError(double t, double error) {
    if (!errors_.empty() && t < errors_.back().x()) errors_.clear();  // a new run
    errors_.emplace_back(t, error);
    if (errors_.size() > maxSamples_) {
        std::size_t kept = 0;
        for (std::size_t k = 0; k < errors_.size(); k += 2) errors_[kept++] = errors_[k];
        errors_.resize(kept);
    }
    pending_ = true;
}

void Recorder::record(const World& world) {
    const double t = world.time();
    if (t < lastTime_) clear();  // the world was reset: a new run
    if (t == lastTime_) {
        // A phase target chosen at this instant (before Play, or while paused) starts its curve
        // at this state, not after the next step.
        ui::PhaseSample sample;
        if (phase_.empty() && samplePhase(world, sample)) {
            phase_.push_back(sample);
            phaseTimes_.push_back(t);
            pending_ = true;
        }
        return;
    }
    lastTime_ = t;
    // Every step is checked for a change of method, sampled or not, so a marker is never lost
    // to the stride.
    checkSettings(world);
    if (calls_++ % stride_ != 0) return;

    const EnergyLedger& e = world.energy();
    energy_.push_back({t, e.kinetic, e.potential, e.workNc, e.drift, e.correction});
    ui::PhaseSample sample;
    if (samplePhase(world, sample)) {
        phase_.push_back(sample);
        phaseTimes_.push_back(t);
    }
    pending_ = true;
    if (energy_.size() >= maxSamples_ || phase_.size() >= maxSamples_) halve();
}

void Recorder::flush() {
    if (!pending_) return;
    pending_ = false;
    emit samplesAdded();
}

namespace {

// Moves the elements of series after index first into tail (in order).
template <typename T>
void moveTail(std::vector<T>& series, std::size_t first, std::vector<T>& tail) {
    first = std::min(first, series.size());
    tail.assign(std::make_move_iterator(series.begin() + static_cast<std::ptrdiff_t>(first)),
                std::make_move_iterator(series.end()));
    series.resize(first);
}

template <typename T, typename Time>
std::size_t firstAfter(const std::vector<T>& series, double t, Time time) {
    return static_cast<std::size_t>(
        std::find_if(series.begin(), series.end(), [&](const T& s) { return time(s) > t; }) -
        series.begin());
}

}  // namespace

Recorder::Tail Recorder::takeAfter(double t) {
    Tail tail;
    tail.lastTime = lastTime_;
    moveTail(energy_, firstAfter(energy_, t, [](const ui::EnergySample& s) { return s.t; }),
             tail.energy);
    moveTail(markers_, firstAfter(markers_, t, [](const ui::PlotMarker& m) { return m.t; }),
             tail.markers);
    const std::size_t phaseFirst = firstAfter(phaseTimes_, t, [](double s) { return s; });
    moveTail(phase_, phaseFirst, tail.phase);
    moveTail(phaseTimes_, phaseFirst, tail.phaseTimes);
    moveTail(errors_, firstAfter(errors_, t, [](const QPointF& p) { return p.x(); }), tail.errors);
    lastTime_ = std::min(lastTime_, t);
    pending_ = true;
    return tail;
}

void Recorder::putBack(Tail&& tail) {
    const auto append = [](auto& series, auto& more) {
        series.insert(series.end(), std::make_move_iterator(more.begin()),
                      std::make_move_iterator(more.end()));
    };
    append(energy_, tail.energy);
    append(markers_, tail.markers);
    append(phase_, tail.phase);
    append(phaseTimes_, tail.phaseTimes);
    append(errors_, tail.errors);
    lastTime_ = std::max(lastTime_, tail.lastTime);
    tail = {};
    pending_ = true;
}

void Recorder::halve() {
    keepEveryOther(energy_);
    keepEveryOther(phase_);
    keepEveryOther(phaseTimes_);
    stride_ *= 2;
    // The next sample lands one new stride after the last kept one.
    calls_ = 1;
}

void Recorder::checkSettings(const World& world) {
    const SimulationSettings& s = world.settings();
    const bool method = s.integrator != lastIntegrator_ || s.dt != lastDt_;
    const bool contacts = s.contactModel != lastContactModel_;
    if (haveSettings_ && (method || contacts)) {
        // The marker is where the new settings began: the start of this step.
        QString label = QStringLiteral("%1, dt %2")
                            .arg(QString::fromStdString(s.integrator))
                            .arg(ui::shownNumber(s.dt, 'g', 4));
        if (contacts) {
            const std::string_view model = contactModelName(s.contactModel);
            const QString contactLabel =
                QStringLiteral("%1 contacts")
                    .arg(QString::fromLatin1(model.data(), static_cast<qsizetype>(model.size())));
            label = method ? label + QStringLiteral(", ") + contactLabel : contactLabel;
        }
        markers_.push_back({world.time() - s.dt, label});
    }
    haveSettings_ = true;
    lastContactModel_ = s.contactModel;
    lastIntegrator_ = s.integrator;
    lastDt_ = s.dt;
}

bool Recorder::samplePhase(const World& world, ui::PhaseSample& sample) {
    if (phaseObject_.empty()) return false;
    // The world is rebuilt by edits, so the cached index is checked against the id each time
    // (one string compare per step) and searched again only when it no longer matches.
    const auto& particles = world.particles();
    const auto& boxes = world.rigidBodies();
    const bool cached =
        phaseIndex_ >= 0 && (phaseIsBox_ ? phaseIndex_ < static_cast<int>(boxes.size()) &&
                                               boxes[phaseIndex_].id == phaseObject_
                                         : phaseIndex_ < static_cast<int>(particles.size()) &&
                                               particles[phaseIndex_].id == phaseObject_);
    if (!cached) {
        phaseIndex_ = -1;
        const auto find = [this](const auto& objects) {
            for (int i = 0; i < static_cast<int>(objects.size()); ++i)
                if (objects[i].id == phaseObject_) return i;
            return -1;
        };
        phaseIsBox_ = false;
        phaseIndex_ = find(particles);
        if (phaseIndex_ < 0) {
            phaseIsBox_ = true;
            phaseIndex_ = find(boxes);
        }
        if (phaseIndex_ < 0) return false;
    }
    const int i = phaseIndex_;
    if (phaseCoordinate_ == QLatin1String("angle")) {
        if (!phaseIsBox_) return false;
        sample = {world.bodyAngle(i), world.bodyAngularVelocity(i)};
        return true;
    }
    const int axis = phaseCoordinate_ == QLatin1String("y") ? 1 : 0;
    const Vec2 x = phaseIsBox_ ? world.bodyPosition(i) : world.particlePosition(i);
    const Vec2 v = phaseIsBox_ ? world.bodyVelocity(i) : world.particleVelocity(i);
    sample = {x[axis], v[axis]};
    return true;
}

bool Recorder::writeEnergyCsv(const QString& path, QString* error) const {
    // total: the mechanical energy the plot's top line shows (kinetic + potential).
    return writeCsv(path, error,
                    QStringLiteral("t,kinetic,potential,work_nc,drift,correction,total"),
                    [&](QTextStream& out) {
                        for (const ui::EnergySample& s : energy_)
                            out << formatNumber(s.t) << ',' << formatNumber(s.kinetic) << ','
                                << formatNumber(s.potential) << ',' << formatNumber(s.workNc) << ','
                                << formatNumber(s.drift) << ',' << formatNumber(s.correction) << ','
                                << formatNumber(s.kinetic + s.potential) << '\n';
                    });
}

bool Recorder::writePhaseCsv(const QString& path, QString* error) const {
    const QString id = phaseObject();
    const QString header = QStringLiteral("t,") +
                           csvField(id + QLatin1Char('.') + phaseCoordinate_) + QLatin1Char(',') +
                           csvField(id + QLatin1Char('.') + phaseVelocityName());
    return writeCsv(path, error, header, [&](QTextStream& out) {
        for (std::size_t k = 0; k < phase_.size(); ++k)
            out << formatNumber(phaseTimes_[k]) << ',' << formatNumber(phase_[k].coordinate) << ','
                << formatNumber(phase_[k].velocity) << '\n';
    });
}

bool Recorder::writeErrorCsv(const QString& path, QString* error) const {
    return writeCsv(path, error, QStringLiteral("t,local_error"), [&](QTextStream& out) {
        for (const QPointF& p : errors_)
            out << formatNumber(p.x()) << ',' << formatNumber(p.y()) << '\n';
    });
}

}  // namespace phasebox
