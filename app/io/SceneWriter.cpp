#include "app/io/OutputFile.h"
#include "app/io/SceneIO.h"
#include "physics/scene/SceneSchema.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <string_view>
#include <utility>
#include <vector>

// Writing scene format v1: a small JSON writer of our own, because QJsonObject sorts keys
// alphabetically and cannot keep the contract's order.

namespace phasebox {

namespace {

class Writer {
public:
    QByteArray take() {
        out_ += '\n';
        return std::move(out_);
    }

    void beginObject() { open('{'); }
    void endObject() { close('}'); }
    void beginArray(bool inlined = false) { open('[', inlined); }
    void endArray() { close(']'); }

    void key(std::string_view name) {
        separate();
        quoted(name);
        out_ += ": ";
        afterKey_ = true;
    }

    void string(std::string_view s) {
        separate();
        quoted(s);
    }

    void number(double v) {
        separate();
        // JSON has no inf or nan; null reads back as a type error instead of a wrong value.
        if (!std::isfinite(v)) {
            out_ += "null";
            return;
        }
        char buf[32];
        const auto result = std::to_chars(buf, buf + sizeof buf, v);  // shortest round trip
        out_.append(buf, result.ptr - buf);
    }
    void integer(int v) {
        separate();
        out_ += QByteArray::number(v);
    }
    void boolean(bool v) {
        separate();
        out_ += v ? "true" : "false";
    }
    void point(const Point2& p) {
        beginArray(true);
        number(p[0]);
        number(p[1]);
        endArray();
    }
    void intPair(const std::array<int, 2>& p) {
        beginArray(true);
        integer(p[0]);
        integer(p[1]);
        endArray();
    }

    // key: value shorthands
    void field(std::string_view k, double v) {
        key(k);
        number(v);
    }
    void field(std::string_view k, int v) {
        key(k);
        integer(v);
    }
    void field(std::string_view k, const std::string& v) {
        key(k);
        string(v);
    }
    template <typename Strings>
    void strings(const Strings& list) {
        beginArray(true);
        for (const std::string& s : list) string(s);
        endArray();
    }

private:
    struct Level {
        bool empty = true;
        bool inlined = false;
    };

    void quoted(std::string_view s) {
        out_ += '"';
        for (const char ch : s) {
            const auto c = static_cast<unsigned char>(ch);
            switch (c) {
                case '"':
                    out_ += "\\\"";
                    break;
                case '\\':
                    out_ += "\\\\";
                    break;
                case '\n':
                    out_ += "\\n";
                    break;
                case '\r':
                    out_ += "\\r";
                    break;
                case '\t':
                    out_ += "\\t";
                    break;
                case '\b':
                    out_ += "\\b";
                    break;
                case '\f':
                    out_ += "\\f";
                    break;
                default:
                    if (c < 0x20) {
                        char buf[8];
                        std::snprintf(buf, sizeof buf, "\\u%04x", c);
                        out_ += buf;
                    } else {
                        out_ += ch;
                    }
            }
        }
        out_ += '"';
    }

    void open(char bracket, bool inlined = false) {
        separate();
        out_ += bracket;
        // An inline array inside another inline one stays on the line.
        levels_.push_back({true, inlined || (!levels_.empty() && levels_.back().inlined)});
    }
    void close(char bracket) {
        const Level level = levels_.back();
        levels_.pop_back();
        if (!level.empty && !level.inlined) newline();
        out_ += bracket;
    }
    // Before every value and key: the comma and line break that separate it from the last.
    void separate() {
        if (afterKey_) {
            afterKey_ = false;
            return;
        }
        if (levels_.empty()) return;
        Level& level = levels_.back();
        if (!level.empty) out_ += level.inlined ? ", " : ",";
        if (!level.inlined) newline();
        level.empty = false;
    }
    void newline() {
        out_ += '\n';
        out_ += QByteArray(2 * static_cast<qsizetype>(levels_.size()), ' ');
    }

    QByteArray out_;
    std::vector<Level> levels_;
    bool afterKey_ = false;
};

// Every field of d that is present, in its table's order.
template <typename D>
void writeFields(Writer& w, const D& d) {
    w.beginObject();
    for (const schema::Field<D>& field : schema::table<D>().fields) {
        if (!schema::isPresent(field, d)) continue;
        w.key(field.key);
        std::visit(
            [&]<typename V>(V D::*member) {
                const V& v = d.*member;
                if constexpr (std::is_same_v<V, double>)
                    w.number(v);
                else if constexpr (std::is_same_v<V, std::optional<double>>)
                    w.number(*v);
                else if constexpr (std::is_same_v<V, int>)
                    w.integer(v);
                else if constexpr (std::is_same_v<V, bool>)
                    w.boolean(v);
                else if constexpr (std::is_same_v<V, std::string>)
                    w.string(v);
                else if constexpr (std::is_same_v<V, std::optional<std::string>>)
                    w.string(*v);
                else if constexpr (std::is_same_v<V, Point2>)
                    w.point(v);
                else if constexpr (std::is_same_v<V, std::optional<Point2>>)
                    w.point(*v);
                else if constexpr (std::is_same_v<V, std::array<int, 2>>)
                    w.intPair(v);
                else if constexpr (std::is_enum_v<V>) {
                    const auto index = static_cast<std::size_t>(v);
                    w.string(index < field.choices.size() ? field.choices[index] : "");
                } else if constexpr (schema::Described<V>)
                    writeFields(w, v);
                else if constexpr (schema::OptionalDescribed<V>)
                    writeFields(w, *v);
                else if constexpr (std::is_same_v<V, std::vector<AttractorDesc>>) {
                    w.beginArray();
                    for (const AttractorDesc& item : v) writeFields(w, item);
                    w.endArray();
                } else if constexpr (std::is_same_v<V, schema::Pinning>) {
                    if (const auto* mode = std::get_if<std::string>(&v)) {
                        w.string(*mode);
                    } else {
                        w.beginArray(true);
                        for (const auto& node : std::get<std::vector<std::array<int, 2>>>(v))
                            w.intPair(node);
                        w.endArray();
                    }
                } else if constexpr (std::is_same_v<V, std::map<std::string, double>>) {
                    w.beginObject();
                    for (const auto& [name, value] : v) w.field(name, value);
                    w.endObject();
                } else if constexpr (std::is_same_v<V, std::vector<Point2>>) {
                    w.beginArray(true);
                    for (const Point2& p : v) w.point(p);
                    w.endArray();
                }
            },
            field.member);
    }
    w.endObject();
}

// CONTRACT §7: only what the lesson uses is written.
void writeInstruments(Writer& w, const InstrumentsDesc& in) {
    namespace key = schema::key;
    w.beginObject();
    if (!in.probes.empty()) {
        w.key(key::probes);
        w.strings(in.probes);
    }
    if (!in.graphs.empty()) {
        w.key(key::graphs);
        w.beginArray();
        for (const GraphDesc& g : in.graphs) {
            w.beginObject();
            w.field(key::y, g.y);
            if (!g.x.empty()) w.field(key::x, g.x);
            w.endObject();
        }
        w.endArray();
    }
    if (!in.timers.empty()) {
        w.key(key::timers);
        w.strings(in.timers);
    }
    if (in.stopwatch) {
        w.key(key::stopwatch);
        w.boolean(true);
    }
    auto instruments = [&](std::string_view k, const auto& list) {
        if (list.empty()) return;
        w.key(k);
        w.beginArray();
        for (const auto& item : list) {
            w.beginObject();
            w.key(key::ends);
            w.strings(item.ends);
            w.endObject();
        }
        w.endArray();
    };
    instruments(key::rulers, in.rulers);
    instruments(key::protractors, in.protractors);
    if (!in.freeBody.empty()) w.field(key::freeBody, in.freeBody);
    if (in.view) {
        w.key(key::view);
        w.beginObject();
        w.key(key::center);
        w.point(in.view->center);
        w.field(key::width, in.view->width);
        w.endObject();
    }
    if (!in.plots.empty()) {
        w.key(key::plots);
        w.strings(in.plots);
    }
    w.endObject();
}

}  // namespace

QByteArray SceneIO::serialize(const SceneDesc& scene) {
    namespace key = schema::key;
    Writer w;
    w.beginObject();
    w.field(key::format, std::string(schema::kFormatName));
    w.field(key::version, scene.formatVersion());
    w.field(key::name, scene.name);
    w.field(key::description, scene.description);
    w.key(key::simulation);
    writeFields(w, scene.simulation);
    w.key(key::effects);
    w.beginObject();
    schema::forEachEffect([&](const auto& table, auto member) {
        if (const auto& effect = scene.effects.*member) {
            w.key(table.key);
            writeFields(w, *effect);
        }
    });
    w.endObject();
    schema::forEachObjectKind([&](const auto& table, auto array) {
        if (table.sinceVersion > 1 && (scene.*array).empty()) return;
        w.key(table.key);
        w.beginArray();
        for (const auto& item : scene.*array) writeFields(w, item);
        w.endArray();
    });
    if (!scene.instruments.empty()) {
        w.key(key::instruments);
        writeInstruments(w, scene.instruments);
    }
    w.endObject();
    return w.take();
}

bool SceneIO::save(const SceneDesc& scene, const QString& path, QString* error) {
    // OutputFile: the old file is replaced only once the new one is complete; a device or
    // FIFO is written in place.
    return OutputFile::writeAll(path, serialize(scene), error);
}

}  // namespace phasebox
