#pragma once
// Time series of the probes the instruments watch (CONTRACT §7): the graphs, the period timer
// and the data table read them from here, one column per probe beside one column of times.
//
// Recording follows the Recorder: a sample after every step (SimulationController calls
// record()), listeners told once per displayed frame (flush()), and memory bounded by halving:
// past maxSamples() every other sample is dropped and from then on every second step is kept
// (then every fourth, …), so a long run keeps its whole history at a coarser, uniform spacing.
// Each probe also has a PeriodTracker fed at every step, decimated or not, so its period is the
// one `phasebox-cli run --probe` reports for the same run.
//
// A probe is parsed once against the world (physics/world/Probes.h) and evaluated by index, so
// the world's objects must not change under it: rebind() parses every probe again after the
// document rebuilt its world (an edit, a load, a reset). A probe whose object is gone (deleted,
// renamed) stays, marked invalid with the reason, and records NaN until it is valid again.
// record() also rebinds by itself when it is handed another world, as a last line of defence.

#include "physics/world/Probes.h"

#include <QObject>
#include <QString>
#include <QStringList>

#include <cstddef>
#include <optional>
#include <vector>

namespace phasebox {

class World;

class ProbeRecorder : public QObject {
    Q_OBJECT

public:
    explicit ProbeRecorder(QObject* parent = nullptr);

    // The probes to record, by text. A probe already recorded keeps its samples; a new one starts
    // now (NaN in the rows before, its value in the current row when the world is at its time).
    // Invalid texts are kept as invalid columns (isValid() false, error() says why).
    void setProbes(const QStringList& texts, const World& world);
    QStringList probes() const;
    int probeCount() const { return static_cast<int>(columns_.size()); }
    int indexOf(const QString& text) const;
    // Parses every probe again against the (rebuilt) world.
    void rebind(const World& world);
    // Parses one text against the world: nullopt and *error when it is not a probe.
    static std::optional<Probe> parse(const World& world, const QString& text, QString* error);

    // Appends the world's current values (call after each step). A clock that went backwards (a
    // diverged step restored to an earlier frame) drops what was recorded from that time on (all
    // of it when the clock went back to the start); a second call at the same time adds nothing.
    void record(const World& world);
    // Emits samplesAdded() if anything was recorded since the last flush.
    void flush();
    // Forgets every sample (the probes stay).
    void clear();

    const std::vector<double>& times() const { return times_; }
    const std::vector<double>& values(int probe) const { return columns_[probe].values; }
    QString probeText(int probe) const { return columns_[probe].text; }
    bool isValid(int probe) const { return columns_[probe].probe.has_value(); }
    QString error(int probe) const { return columns_[probe].error; }
    // The parsed probe (its kind, for units); nullopt when invalid.
    const std::optional<Probe>& parsed(int probe) const { return columns_[probe].probe; }
    // min, max, mean, final and period over every step since the probe was added or cleared.
    ProbeSummary summary(int probe) const { return columns_[probe].tracker.summary(); }
    // The upward crossings of the summary's mid-level (min + max)/2 in the recorded series: the
    // crossings the period is measured from (every one of them while no halving has happened).
    std::vector<double> crossings(int probe) const;

    void setMaxSamples(std::size_t maxSamples);
    std::size_t maxSamples() const { return maxSamples_; }
    long long stride() const { return stride_; }
    static constexpr std::size_t kDefaultMaxSamples = 200'000;

    // CSV (written by OutputFile) with the header t,PROBE,… (quoted where a probe holds a comma, as
    // CONTRACT §7's
    // `--probe` columns are) and a row per sample; a probe without a value in a row leaves its
    // field empty. columns are probe texts (all recorded ones when empty).
    bool writeCsv(const QString& path, const QStringList& columns, QString* error) const;
    // The same rows as text separated by separator (a tab for a spreadsheet's paste); rows in
    // [firstRow, lastRow], all when lastRow < 0.
    QString text(const QStringList& columns, QChar separator, int firstRow = 0,
                 int lastRow = -1) const;

signals:
    void samplesAdded();
    void cleared();
    // The set of probes or their validity changed.
    void probesChanged();

private:
    struct Column {
        QString text;
        std::optional<Probe> probe;
        QString error;
        std::vector<double> values;
        PeriodTracker tracker;
    };

    void bind(const World& world);
    bool boundTo(const World& world) const;
    void halve();
    void rewind(double t);
    std::vector<int> columnIndices(const QStringList& columns) const;

    std::vector<Column> columns_;
    std::vector<double> times_;
    // The world the probes were parsed against, and its object counts, to notice a rebuilt one.
    const World* world_ = nullptr;
    std::size_t particles_ = 0, boxes_ = 0, joints_ = 0;

    double lastTime_ = -1.0;
    std::size_t maxSamples_ = kDefaultMaxSamples;
    long long stride_ = 1;
    long long calls_ = 0;
    bool pending_ = false;
};

}  // namespace phasebox
