#include "app/sim/ProbeRecorder.h"

#include "app/io/NumberFormat.h"
#include "app/io/OutputFile.h"
#include "physics/world/World.h"

#include <QTextStream>

#include <algorithm>
#include <cmath>
#include <limits>

namespace phasebox {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

template <typename T>
void keepEveryOther(std::vector<T>& v) {
    std::size_t out = 0;
    for (std::size_t i = 0; i < v.size(); i += 2) v[out++] = v[i];
    v.resize(out);
}

// A recorded value in a CSV or table: empty where the probe had none.
QString field(double value) {
    return std::isnan(value) ? QString() : formatNumber(value);
}
}  // namespace

ProbeRecorder::ProbeRecorder(QObject* parent) : QObject(parent) {}

std::optional<Probe> ProbeRecorder::parse(const World& world, const QString& text, QString* error) {
    ProbeParse parsed = parseProbe(world, text.toStdString());
    if (!parsed) {
        if (error) *error = QString::fromStdString(parsed.error);
        return std::nullopt;
    }
    return std::move(parsed.probe);
}

QStringList ProbeRecorder::probes() const {
    QStringList texts;
    for (const Column& c : columns_) texts << c.text;
    return texts;
}

int ProbeRecorder::indexOf(const QString& text) const {
    for (std::size_t i = 0; i < columns_.size(); ++i)
        if (columns_[i].text == text) return static_cast<int>(i);
    return -1;
}

void ProbeRecorder::setProbes(const QStringList& texts, const World& world) {
    std::vector<Column> columns;
    std::vector<bool> added;
    columns.reserve(static_cast<std::size_t>(texts.size()));
    bool changed = false;
    for (const QString& text : texts) {
        if (text.isEmpty() || std::any_of(columns.begin(), columns.end(),
                                          [&](const Column& c) { return c.text == text; }))
            continue;
        const int kept = indexOf(text);
        changed = changed || kept != static_cast<int>(columns.size());
        added.push_back(kept < 0);
        if (kept >= 0) {
            columns.push_back(std::move(columns_[kept]));
            continue;
        }
        Column column;
        column.text = text;
        column.values.assign(times_.size(), kNaN);
        columns.push_back(std::move(column));
    }
    changed = changed || columns.size() != columns_.size();
    columns_ = std::move(columns);
    bind(world);
    // A new probe's value now, in the current row when the world is at that row's time.
    const bool current = !times_.empty() && times_.back() == world.time();
    for (std::size_t i = 0; i < columns_.size(); ++i) {
        Column& c = columns_[i];
        if (!added[i] || !c.probe || !current) continue;
        c.values.back() = evaluateProbe(world, *c.probe);
        c.tracker.add(world.time(), c.values.back());
    }
    if (changed) emit probesChanged();
}

void ProbeRecorder::rebind(const World& world) {
    std::vector<bool> valid;
    for (const Column& c : columns_) valid.push_back(c.probe.has_value());
    bind(world);
    for (std::size_t i = 0; i < columns_.size(); ++i)
        if (columns_[i].probe.has_value() != valid[i]) {
            emit probesChanged();
            return;
        }
}

void ProbeRecorder::bind(const World& world) {
    world_ = &world;
    particles_ = world.particles().size();
    boxes_ = world.rigidBodies().size();
    joints_ = world.joints().size();
    for (Column& c : columns_) {
        c.error.clear();
        c.probe = parse(world, c.text, &c.error);
    }
}

bool ProbeRecorder::boundTo(const World& world) const {
    return world_ == &world && particles_ == world.particles().size() &&
           boxes_ == world.rigidBodies().size() && joints_ == world.joints().size();
}

void ProbeRecorder::record(const World& world) {
    if (!boundTo(world)) rebind(world);
    const double t = world.time();
    if (t < lastTime_) rewind(t);
    if (t == lastTime_) return;
    lastTime_ = t;
    // Every step feeds the period trackers; the series keep every stride_-th.
    const bool sampled = calls_++ % stride_ == 0;
    if (sampled) times_.push_back(t);
    for (Column& c : columns_) {
        const double value = c.probe ? evaluateProbe(world, *c.probe) : kNaN;
        c.tracker.add(t, value);
        if (sampled) c.values.push_back(value);
    }
    if (!sampled) return;
    pending_ = true;
    if (times_.size() >= maxSamples_) halve();
}

void ProbeRecorder::rewind(double t) {
    // The clock went back without a reset: a diverged step restored an earlier frame. What was
    // recorded from then on did not happen; the history before it stays.
    const auto kept = static_cast<std::size_t>(std::lower_bound(times_.begin(), times_.end(), t) -
                                               times_.begin());
    if (kept == 0) {
        clear();
        return;
    }
    times_.resize(kept);
    for (Column& c : columns_) {
        c.values.resize(kept);
        // Rebuilt from the kept samples: exact unless the series was halved.
        c.tracker = PeriodTracker();
        for (std::size_t r = 0; r < kept; ++r) c.tracker.add(times_[r], c.values[r]);
    }
    lastTime_ = times_.back();
    calls_ = 1;  // the next sample lands one stride after the last kept one
    pending_ = true;
}

void ProbeRecorder::flush() {
    if (!pending_) return;
    pending_ = false;
    emit samplesAdded();
}

void ProbeRecorder::clear() {
    times_.clear();
    for (Column& c : columns_) {
        c.values.clear();
        c.tracker = PeriodTracker();
    }
    lastTime_ = -1.0;
    stride_ = 1;
    calls_ = 0;
    pending_ = false;
    emit cleared();
}

void ProbeRecorder::setMaxSamples(std::size_t maxSamples) {
    maxSamples_ = std::max<std::size_t>(maxSamples, 2);
    while (times_.size() >= maxSamples_) halve();
}

void ProbeRecorder::halve() {
    keepEveryOther(times_);
    for (Column& c : columns_) keepEveryOther(c.values);
    stride_ *= 2;
    calls_ = 1;  // the next sample lands one new stride after the last kept one
}

std::vector<double> ProbeRecorder::crossings(int probe) const {
    const ProbeSummary s = summary(probe);
    if (s.samples < 2) return {};
    return upwardCrossings(times_, columns_[probe].values, 0.5 * (s.min + s.max));
}

std::vector<int> ProbeRecorder::columnIndices(const QStringList& columns) const {
    std::vector<int> indices;
    if (columns.isEmpty()) {
        for (int i = 0; i < probeCount(); ++i) indices.push_back(i);
        return indices;
    }
    for (const QString& text : columns)
        if (const int i = indexOf(text); i >= 0) indices.push_back(i);
    return indices;
}

QString ProbeRecorder::text(const QStringList& columns, QChar separator, int firstRow,
                            int lastRow) const {
    const std::vector<int> indices = columnIndices(columns);
    const int rows = static_cast<int>(times_.size());
    if (lastRow < 0 || lastRow >= rows) lastRow = rows - 1;
    const bool csv = separator == QLatin1Char(',');
    QString out = QStringLiteral("t");
    for (const int i : indices)
        out += separator + (csv ? csvField(columns_[i].text) : columns_[i].text);
    out += QLatin1Char('\n');
    for (int r = std::max(0, firstRow); r <= lastRow; ++r) {
        out += formatNumber(times_[r]);
        for (const int i : indices) out += separator + field(columns_[i].values[r]);
        out += QLatin1Char('\n');
    }
    return out;
}

bool ProbeRecorder::writeCsv(const QString& path, const QStringList& columns,
                             QString* error) const {
    // Through the app's one file writer: a failed export never leaves half a file behind.
    const std::vector<int> indices = columnIndices(columns);
    OutputFile file(path, tr("the CSV file"));
    if (file.open()) {
        QTextStream out(file.device());
        out << "t";
        for (const int i : indices) out << ',' << csvField(columns_[i].text);
        out << '\n';
        for (std::size_t r = 0; r < times_.size(); ++r) {
            out << formatNumber(times_[r]);
            for (const int i : indices) out << ',' << field(columns_[i].values[r]);
            out << '\n';
        }
        out.flush();
    }
    if (!file.commit()) {
        if (error) *error = file.error();
        return false;
    }
    return true;
}

}  // namespace phasebox
