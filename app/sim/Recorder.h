#pragma once
// Time series of a run, for the plots and for CSV export: the energy ledger at every step,
// markers where the integrator or dt changed, and the phase-space trace of one coordinate of
// one object.
//
// Memory is bounded: past maxSamples() the series are halved by keeping every other sample,
// and from then on only every second step is recorded (then every fourth, …), so a long run
// keeps its whole history at a coarser, still uniform spacing.

#include "physics/contacts/ContactModel.h"
#include "ui/plots/Charts.h"

#include <QObject>
#include <QPointF>
#include <QString>

#include <cstddef>
#include <string>
#include <vector>

namespace phasebox {

class World;

class Recorder : public QObject {
    Q_OBJECT

public:
    explicit Recorder(QObject* parent = nullptr);

    // Appends the world's current state (call after each step). A clock that went backwards
    // (a reset) starts the series over; a second call at the same time adds nothing.
    void record(const World& world);
    // Emits samplesAdded() if anything was recorded since the last flush: a controller records
    // every step but notifies once per frame.
    void flush();
    void clear();

    const std::vector<ui::EnergySample>& energySamples() const { return energy_; }
    const std::vector<ui::PlotMarker>& markers() const { return markers_; }
    const std::vector<ui::PhaseSample>& phaseSamples() const { return phase_; }
    const std::vector<double>& phaseTimes() const { return phaseTimes_; }

    // The live local error estimate (World::estimateLocalError) against time, one sample per
    // displayed frame while running; halved like the other series when it grows too long.
    void recordError(double t, double error);
    const std::vector<QPointF>& errorSamples() const { return errors_; }

    // The object and coordinate of the phase plot: "x", "y" (particles and boxes) or "angle"
    // (boxes), against vx, vy or omega. Changing it clears the phase series.
    void setPhaseTarget(const QString& objectId, const QString& coordinate);
    QString phaseObject() const { return QString::fromStdString(phaseObject_); }
    QString phaseCoordinate() const { return phaseCoordinate_; }
    // "vx", "vy" or "omega": the velocity paired with the coordinate.
    QString phaseVelocityName() const;

    // The samples after t, taken out when a run goes on from an earlier moment, and put back
    // when that is undone (SimulationController::resumeFromShownFrame).
    struct Tail {
        std::vector<ui::EnergySample> energy;
        std::vector<ui::PlotMarker> markers;
        std::vector<ui::PhaseSample> phase;
        std::vector<double> phaseTimes;
        std::vector<QPointF> errors;
        double lastTime = -1.0;
    };
    Tail takeAfter(double t);
    void putBack(Tail&& tail);

    void setMaxSamples(std::size_t maxSamples);
    std::size_t maxSamples() const { return maxSamples_; }
    // Steps per recorded sample (1 until the first halving).
    long long stride() const { return stride_; }

    // CSV (CONTRACT.md §4, §6): header t,kinetic,potential,work_nc,drift,correction, one row
    // per sample (the CLI's columns, without its constraint_error).
    bool writeEnergyCsv(const QString& path, QString* error) const;
    // Header t,ID.COORD,ID.VELOCITY (e.g. t,ball.x,ball.vx).
    bool writePhaseCsv(const QString& path, QString* error) const;
    // Header t,local_error.
    bool writeErrorCsv(const QString& path, QString* error) const;

    static constexpr std::size_t kDefaultMaxSamples = 200'000;

signals:
    void samplesAdded();
    void cleared();

private:
    void checkSettings(const World& world);
    bool samplePhase(const World& world, ui::PhaseSample& sample);
    void halve();

    std::vector<ui::EnergySample> energy_;
    std::vector<ui::PlotMarker> markers_;
    std::vector<ui::PhaseSample> phase_;
    std::vector<double> phaseTimes_;
    std::vector<QPointF> errors_;

    std::string phaseObject_;
    QString phaseCoordinate_ = QStringLiteral("x");
    int phaseIndex_ = -1;  // cached index into the world's particles or boxes
    bool phaseIsBox_ = false;

    std::string lastIntegrator_;
    double lastDt_ = 0.0;
    ContactModel lastContactModel_ = ContactModel::Impulse;
    double lastTime_ = -1.0;
    bool haveSettings_ = false;
    std::size_t maxSamples_ = kDefaultMaxSamples;
    long long stride_ = 1;
    long long calls_ = 0;  // records since the series started, for the stride
    bool pending_ = false;
};

}  // namespace phasebox
