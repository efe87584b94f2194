#include "app/io/SceneIO.h"

#include "app/io/InputFile.h"
#include "app/io/JsonText.h"
#include "physics/scene/SceneSchema.h"

#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QJsonValue>
#include <QLocale>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <span>
#include <string_view>
#include <utility>
#include <vector>

namespace phasebox {

namespace {

// No scene a person writes comes near this; refusing bigger files keeps a wrongly chosen
// multi-gigabyte file from being read into memory.
constexpr qint64 kMaxFileBytes = qint64(64) * 1024 * 1024;

// Keys outside a table are ignored unless they look like a misspelling of one of its keys.
using KeyList = std::span<const std::string_view>;
namespace key = schema::key;

const char* const kXY = "[x, y]";
const char* const kWH = "[w, h]";

// What the two numbers of a pair are called in messages.
const char* pairHint(schema::Type type) {
    switch (type) {
        case schema::Type::Size:
            return kWH;
        case schema::Type::Grid:
            return "[nx, ny]";
        case schema::Type::Pinning:
            return "[i, j]";
        case schema::Type::Interval:
            return "[lower, upper]";
        default:
            return kXY;
    }
}

QString toQString(std::string_view s) {
    return QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size()));
}

// A key from the file is cut for the path in a message (jsontext::shortened).
QString join(const QString& path, const QString& key) {
    const QString shown = jsontext::shortened(key);
    return path.isEmpty() ? shown : path + QLatin1Char('.') + shown;
}

QString join(const QString& path, std::string_view key) {
    return join(path, toQString(key));
}

QString index(const QString& path, qsizetype i) {
    return path + QLatin1Char('[') + QString::number(i) + QLatin1Char(']');
}

// Optimal string alignment distance (Levenshtein plus transposition of neighbours), ignoring
// case, so that "Stifness", "stiffnes" and "stiffnses" all count as close to stiffness.
int editDistance(const QString& a, const QString& b) {
    const QString s = a.toCaseFolded();
    const QString t = b.toCaseFolded();
    const qsizetype n = s.size();
    const qsizetype m = t.size();
    std::vector<std::vector<int>> d(n + 1, std::vector<int>(m + 1, 0));
    for (qsizetype i = 0; i <= n; ++i) d[i][0] = static_cast<int>(i);
    for (qsizetype j = 0; j <= m; ++j) d[0][j] = static_cast<int>(j);
    for (qsizetype i = 1; i <= n; ++i) {
        for (qsizetype j = 1; j <= m; ++j) {
            const int cost = s[i - 1] == t[j - 1] ? 0 : 1;
            d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
            if (i > 1 && j > 1 && s[i - 1] == t[j - 2] && s[i - 2] == t[j - 1])
                d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
        }
    }
    return d[n][m];
}

// The known key that an unknown one is most likely a misspelling of, or nothing. Within two
// edits, but not a complete replacement of the known key: `x` is two edits from `id` and
// shares nothing with it, and without that rule every short key would be rejected next to the
// short keys `id`, `a` and `b`.
std::optional<std::string_view> misspeltKey(const QString& key, KeyList known) {
    constexpr int kMaxEdits = 2;
    std::optional<std::string_view> best;
    int bestDistance = kMaxEdits + 1;
    for (std::string_view candidate : known) {
        const QString name = toQString(candidate);
        if (std::abs(key.size() - name.size()) > kMaxEdits) continue;
        const int distance = editDistance(key, name);
        if (distance < bestDistance && distance < std::max(key.size(), name.size())) {
            best = candidate;
            bestDistance = distance;
        }
    }
    return best;
}

QString describeVersion(double v) {
    if (std::abs(v) < 1e15) return QString::number(static_cast<qint64>(v));
    return QString::number(v, 'g', QLocale::FloatingPointShortest);
}

// Collects every problem of one file as "SOURCE: PATH: what".
class Reader {
public:
    explicit Reader(QString source) : source_(std::move(source)) {}

    void fail(const QString& path, const QString& what) {
        errors_ << source_ + QStringLiteral(": ") + path + QStringLiteral(": ") + what;
    }
    void failFile(const QString& what) { errors_ << source_ + QStringLiteral(": ") + what; }

    bool clean() const { return errors_.isEmpty(); }
    qsizetype errorCount() const { return errors_.size(); }
    QStringList takeErrors() { return std::exchange(errors_, {}); }

    // A key that is close to a known one is a typo that would silently drop a value (a
    // teacher's spring losing its stiffness), so it is an error; anything further away is an
    // extension and is ignored, unless the object is strict (the instruments, the app's own
    // section: there an instrument misspelt would vanish from a lesson without a word).
    enum class Unknown { Ignored, Refused };
    void checkKeys(const QJsonObject& object, const QString& path, KeyList known,
                   Unknown unknown = Unknown::Ignored) {
        for (auto it = object.begin(); it != object.end(); ++it) {
            const QString key = it.key();
            const bool isKnown = std::any_of(known.begin(), known.end(), [&](std::string_view k) {
                return key == toQString(k);
            });
            if (isKnown) continue;
            if (const auto guess = misspeltKey(key, known)) {
                fail(join(path, key),
                     QStringLiteral("unknown key; did you mean \"%1\"?").arg(toQString(*guess)));
            } else if (unknown == Unknown::Refused) {
                QStringList names;
                for (std::string_view k : known) names << toQString(k);
                fail(join(path, key),
                     QStringLiteral("unknown key; known: ") + names.join(QStringLiteral(", ")));
            }
        }
    }

    // Each reader reports a type error at path and returns false, leaving out unchanged.
    bool number(const QJsonValue& v, const QString& path, double& out) {
        if (!v.isDouble()) return typeError(path, "must be a number");
        out = v.toDouble();
        return true;
    }
    bool integer(const QJsonValue& v, const QString& path, int& out) {
        if (!v.isDouble()) return typeError(path, "must be an integer");
        const double d = v.toDouble();
        if (!std::isfinite(d) || std::trunc(d) != d) return typeError(path, "must be an integer");
        if (d < std::numeric_limits<int>::min() || d > std::numeric_limits<int>::max())
            return typeError(path, QStringLiteral("is out of range (got %1)").arg(d));
        out = static_cast<int>(d);
        return true;
    }
    bool boolean(const QJsonValue& v, const QString& path, bool& out) {
        if (!v.isBool()) return typeError(path, "must be true or false");
        out = v.toBool();
        return true;
    }
    bool string(const QJsonValue& v, const QString& path, std::string& out) {
        if (!v.isString()) return typeError(path, "must be a string");
        out = v.toString().toStdString();
        return true;
    }
    bool object(const QJsonValue& v, const QString& path, QJsonObject& out) {
        if (!v.isObject()) return typeError(path, "must be an object");
        out = v.toObject();
        return true;
    }
    bool array(const QJsonValue& v, const QString& path, QJsonArray& out) {
        if (!v.isArray()) return typeError(path, "must be an array");
        out = v.toArray();
        return true;
    }
    // [x, y], [w, h]: hint names the two numbers in the message.
    bool pair(const QJsonValue& v, const QString& path, Point2& out, const char* hint) {
        if (!v.isArray() || v.toArray().size() != 2)
            return typeError(path, QStringLiteral("must be an array of 2 numbers %1").arg(hint));
        const QJsonArray a = v.toArray();
        Point2 p = out;
        const bool ok0 = number(a[0], index(path, 0), p[0]);
        const bool ok1 = number(a[1], index(path, 1), p[1]);
        if (!ok0 || !ok1) return false;
        out = p;
        return true;
    }
    bool intPair(const QJsonValue& v, const QString& path, std::array<int, 2>& out,
                 const char* hint) {
        if (!v.isArray() || v.toArray().size() != 2)
            return typeError(path, QStringLiteral("must be an array of 2 integers %1").arg(hint));
        const QJsonArray a = v.toArray();
        std::array<int, 2> p = out;
        const bool ok0 = integer(a[0], index(path, 0), p[0]);
        const bool ok1 = integer(a[1], index(path, 1), p[1]);
        if (!ok0 || !ok1) return false;
        out = p;
        return true;
    }

private:
    bool typeError(const QString& path, const QString& what) {
        fail(path, what);
        return false;
    }

    QString source_;
    QStringList errors_;
};

enum class Need { Optional, Required };

// One JSON object of the scene, read field by field with paths for the messages. Absent
// fields keep the value already in the description, which holds the contract's default.
class Fields {
public:
    Fields(Reader& reader, QJsonObject object, QString path, KeyList known,
           Reader::Unknown unknown = Reader::Unknown::Ignored)
        : r_(reader), object_(std::move(object)), path_(std::move(path)) {
        r_.checkKeys(object_, path_, known, unknown);
    }

    bool has(std::string_view key) const { return object_.contains(toQString(key)); }
    QString at(std::string_view key) const { return join(path_, key); }
    const QString& path() const { return path_; }

    // The value, or undefined when absent; a required absent field is reported.
    QJsonValue get(std::string_view key, Need need = Need::Optional) {
        const QJsonValue v = object_.value(toQString(key));
        if (v.isUndefined() && need == Need::Required)
            r_.fail(at(key), QStringLiteral("is required"));
        return v;
    }

    void number(std::string_view key, double& out, Need need = Need::Optional) {
        const QJsonValue v = get(key, need);
        if (!v.isUndefined()) r_.number(v, at(key), out);
    }
    void number(std::string_view key, std::optional<double>& out) {
        const QJsonValue v = get(key);
        double x = 0.0;
        if (!v.isUndefined() && r_.number(v, at(key), x)) out = x;
    }
    void integer(std::string_view key, int& out) {
        const QJsonValue v = get(key);
        if (!v.isUndefined()) r_.integer(v, at(key), out);
    }
    void boolean(std::string_view key, bool& out) {
        const QJsonValue v = get(key);
        if (!v.isUndefined()) r_.boolean(v, at(key), out);
    }
    void string(std::string_view key, std::string& out, Need need = Need::Optional) {
        const QJsonValue v = get(key, need);
        if (!v.isUndefined()) r_.string(v, at(key), out);
    }
    void string(std::string_view key, std::optional<std::string>& out) {
        const QJsonValue v = get(key);
        std::string s;
        if (!v.isUndefined() && r_.string(v, at(key), s)) out = std::move(s);
    }
    void point(std::string_view key, Point2& out, Need need = Need::Optional,
               const char* hint = kXY) {
        const QJsonValue v = get(key, need);
        if (!v.isUndefined()) r_.pair(v, at(key), out, hint);
    }
    void point(std::string_view key, std::optional<Point2>& out, const char* hint = kXY) {
        const QJsonValue v = get(key);
        Point2 p{0.0, 0.0};
        if (!v.isUndefined() && r_.pair(v, at(key), p, hint)) out = p;
    }
    // One of choices by name, stored as the enum value of its index.
    template <typename E>
    void choice(std::string_view key, E& out, std::span<const std::string_view> choices,
                Need need) {
        const QJsonValue v = get(key, need);
        if (v.isUndefined()) return;
        const std::string name = v.toString().toStdString();
        const auto it = std::find(choices.begin(), choices.end(), name);
        if (v.isString() && it != choices.end()) {
            out = static_cast<E>(it - choices.begin());
            return;
        }
        QStringList names;
        for (std::string_view c : choices) names << toQString(c);
        QString what = QStringLiteral("must be one of ") + names.join(QStringLiteral(", "));
        if (v.isString())
            what += QStringLiteral(" (got \"%1\")").arg(jsontext::shortened(v.toString()));
        r_.fail(at(key), what);
    }
    // A nested object with its own keys; nullopt when absent or not an object.
    std::optional<Fields> object(std::string_view key, KeyList known) {
        const QJsonValue v = get(key);
        QJsonObject o;
        if (v.isUndefined() || !r_.object(v, at(key), o)) return std::nullopt;
        return Fields(r_, o, at(key), known);
    }

    Reader& reader() { return r_; }

private:
    Reader& r_;
    QJsonObject object_;
    QString path_;
};

template <typename D>
void readFields(Fields& f, D& d);

// Reads every element of an optional array of objects by their table.
template <typename Desc>
void readObjects(Fields& top, std::string_view key, std::vector<Desc>& out) {
    const QJsonValue v = top.get(key);
    QJsonArray array;
    if (v.isUndefined() || !top.reader().array(v, top.at(key), array)) return;
    const std::vector<std::string_view> known = schema::keysOf(schema::table<Desc>());
    out.reserve(static_cast<std::size_t>(array.size()));
    for (qsizetype i = 0; i < array.size(); ++i) {
        const QString path = index(top.at(key), i);
        QJsonObject object;
        Desc desc;
        if (top.reader().object(array[i], path, object)) {
            Fields fields(top.reader(), object, path, known);
            readFields(fields, desc);
        }
        out.push_back(std::move(desc));
    }
}

// The contact solver's settings belong to the engine (schema::solverSettings() lists the ones
// it reads); a near miss of one is a typo like any other, and the rest are kept so that they
// round-trip.
void readSolver(Fields& f, std::string_view key, std::map<std::string, double>& solver) {
    const QJsonValue v = f.get(key);
    QJsonObject object;
    if (v.isUndefined() || !f.reader().object(v, f.at(key), object)) return;
    std::vector<std::string_view> known;
    for (const schema::SolverSetting& setting : schema::solverSettings())
        known.push_back(setting.key);
    f.reader().checkKeys(object, f.at(key), known);
    for (auto it = object.begin(); it != object.end(); ++it) {
        double value = 0.0;
        if (f.reader().number(it.value(), join(f.at(key), it.key()), value))
            solver[it.key().toStdString()] = value;
    }
}

void readPinning(Fields& f, std::string_view key, schema::Pinning& pinned) {
    const QJsonValue v = f.get(key);
    if (v.isUndefined()) return;
    Reader& r = f.reader();
    if (v.isString()) {
        pinned = v.toString().toStdString();
        return;
    }
    if (!v.isArray()) {
        r.fail(f.at(key), QStringLiteral("must be a string (top, top_corners, left, none) "
                                         "or an array of [i, j] pairs"));
        return;
    }
    const QJsonArray array = v.toArray();
    std::vector<std::array<int, 2>> nodes;
    nodes.reserve(static_cast<std::size_t>(array.size()));
    for (qsizetype k = 0; k < array.size(); ++k) {
        std::array<int, 2> node{0, 0};
        r.intPair(array[k], index(f.at(key), k), node, pairHint(schema::Type::Pinning));
        nodes.push_back(node);
    }
    pinned = std::move(nodes);
}

// Every field of d's table, in its order. Absent fields keep d's value, the default. A field
// that d does not use (Field::uses, decided by the fields before it) is not required, and is
// refused when given.
template <typename D>
void readFields(Fields& f, D& d) {
    const qsizetype errorsBefore = f.reader().errorCount();
    for (const schema::Field<D>& field : schema::table<D>().fields) {
        const std::string_view key = field.key;
        const bool used = !field.uses || field.uses(d);
        const Need need =
            field.need == schema::Need::Required && used ? Need::Required : Need::Optional;
        if (!field.exclusiveWith.empty() && f.has(key) && f.has(field.exclusiveWith))
            f.reader().fail(f.path(), QStringLiteral("give %1 or %2, not both")
                                          .arg(toQString(key), toQString(field.exclusiveWith)));
        std::visit(
            [&]<typename V>(V D::*member) {
                V& v = d.*member;
                if constexpr (std::is_same_v<V, double> || std::is_same_v<V, std::string>) {
                    if constexpr (std::is_same_v<V, double>)
                        f.number(key, v, need);
                    else
                        f.string(key, v, need);
                } else if constexpr (std::is_same_v<V, std::optional<double>>) {
                    f.number(key, v);
                } else if constexpr (std::is_same_v<V, std::optional<std::string>>) {
                    f.string(key, v);
                } else if constexpr (std::is_same_v<V, int>) {
                    f.integer(key, v);
                } else if constexpr (std::is_same_v<V, bool>) {
                    f.boolean(key, v);
                } else if constexpr (std::is_same_v<V, Point2>) {
                    f.point(key, v, need, pairHint(field.type));
                } else if constexpr (std::is_same_v<V, std::optional<Point2>>) {
                    f.point(key, v, pairHint(field.type));
                } else if constexpr (std::is_same_v<V, std::array<int, 2>>) {
                    if (const QJsonValue value = f.get(key); !value.isUndefined())
                        f.reader().intPair(value, f.at(key), v, pairHint(field.type));
                } else if constexpr (std::is_enum_v<V>) {
                    f.choice(key, v, field.choices, need);
                } else if constexpr (schema::Described<V>) {
                    if (auto nested = f.object(key, schema::keysOf(schema::table<V>())))
                        readFields(*nested, v);
                } else if constexpr (schema::OptionalDescribed<V>) {
                    using Nested = typename V::value_type;
                    if (auto nested = f.object(key, schema::keysOf(schema::table<Nested>()))) {
                        Nested value;
                        readFields(*nested, value);
                        v = std::move(value);
                    }
                } else if constexpr (std::is_same_v<V, std::vector<AttractorDesc>>) {
                    readObjects(f, key, v);
                } else if constexpr (std::is_same_v<V, schema::Pinning>) {
                    readPinning(f, key, v);
                } else if constexpr (std::is_same_v<V, std::map<std::string, double>>) {
                    readSolver(f, key, v);
                } else if constexpr (std::is_same_v<V, std::vector<Point2>>) {
                    QJsonArray array;
                    const QJsonValue value = f.get(key, need);
                    if (value.isUndefined() || !f.reader().array(value, f.at(key), array)) return;
                    v.assign(static_cast<std::size_t>(array.size()), Point2{0.0, 0.0});
                    for (qsizetype k = 0; k < array.size(); ++k)
                        f.reader().pair(array[k], index(f.at(key), k), v[k], kXY);
                }
            },
            field.member);
    }
    // What d uses depends on fields read above (a joint's type); after an error there they
    // hold defaults, which would make a correct key look out of place.
    if (f.reader().errorCount() != errorsBefore) return;
    for (const schema::Field<D>& field : schema::table<D>().fields)
        if (field.uses && f.has(field.key) && !field.uses(d))
            f.reader().fail(f.at(field.key),
                            QStringLiteral("is only for ") + toQString(field.usedBy));
}

// An effect is present when given as an object (its fields) or as true (all defaults); false
// and null mean absent, so that a file (or a script writing one) can switch an effect off
// without deleting its key.
template <typename Desc>
void readEffect(Fields& effects, std::string_view key, std::optional<Desc>& out) {
    const QJsonValue v = effects.get(key);
    if (v.isUndefined() || v.isNull() || (v.isBool() && !v.toBool())) return;
    if (v.isBool()) {
        out.emplace();
        return;
    }
    if (!v.isObject()) {
        effects.reader().fail(effects.at(key), QStringLiteral("must be an object, true or false"));
        return;
    }
    Desc desc;
    Fields fields(effects.reader(), v.toObject(), effects.at(key),
                  schema::keysOf(schema::table<Desc>()));
    readFields(fields, desc);
    out = std::move(desc);
}

// ---- instruments (CONTRACT §7): every key checked strictly (Reader::checkKeys) ----

// An array of non-empty strings (exactly count of them when count > 0).
void readStrings(Reader& r, const QJsonValue& v, const QString& path, std::vector<std::string>& out,
                 qsizetype count = 0) {
    QJsonArray array;
    if (!r.array(v, path, array)) return;
    if (count > 0 && array.size() != count) {
        r.fail(path, QStringLiteral("must be an array of %1 strings").arg(count));
        return;
    }
    out.clear();
    for (qsizetype i = 0; i < array.size(); ++i) {
        std::string s;
        if (!r.string(array[i], index(path, i), s)) continue;
        if (s.empty())
            r.fail(index(path, i), QStringLiteral("must not be empty"));
        else
            out.push_back(std::move(s));
    }
}

// Each element of an array of objects with the given keys, read by one(object, path).
template <typename One>
void readInstrumentList(Reader& r, const QJsonValue& v, const QString& path, KeyList known,
                        One one) {
    QJsonArray array;
    if (!r.array(v, path, array)) return;
    for (qsizetype i = 0; i < array.size(); ++i) {
        QJsonObject object;
        if (!r.object(array[i], index(path, i), object)) continue;
        r.checkKeys(object, index(path, i), known, Reader::Unknown::Refused);
        one(object, index(path, i));
    }
}

template <std::size_t N>
void readEnds(Reader& r, const QJsonObject& object, const QString& path,
              std::vector<std::array<std::string, N>>& out) {
    const QJsonValue v = object.value(toQString(key::ends));
    if (v.isUndefined()) {
        r.fail(join(path, key::ends), QStringLiteral("is required"));
        return;
    }
    std::vector<std::string> ends;
    readStrings(r, v, join(path, key::ends), ends, N);
    if (ends.size() != N) return;
    std::array<std::string, N> e;
    std::move(ends.begin(), ends.end(), e.begin());
    out.push_back(std::move(e));
}

void readInstruments(Fields& top, InstrumentsDesc& in) {
    const QJsonValue value = top.get(key::instruments);
    QJsonObject o;
    Reader& r = top.reader();
    const QString path = top.at(key::instruments);
    if (value.isUndefined() || !r.object(value, path, o)) return;
    static constexpr std::string_view kKeys[] = {key::probes,    key::graphs, key::timers,
                                                 key::stopwatch, key::rulers, key::protractors,
                                                 key::freeBody,  key::view,   key::plots};
    r.checkKeys(o, path, kKeys, Reader::Unknown::Refused);
    auto at = [&](std::string_view k) { return join(path, k); };
    auto has = [&](std::string_view k) { return o.contains(toQString(k)); };
    auto get = [&](std::string_view k) { return o.value(toQString(k)); };

    if (has(key::probes)) readStrings(r, get(key::probes), at(key::probes), in.probes);
    if (has(key::timers)) readStrings(r, get(key::timers), at(key::timers), in.timers);
    if (has(key::stopwatch)) r.boolean(get(key::stopwatch), at(key::stopwatch), in.stopwatch);
    if (has(key::graphs)) {
        static constexpr std::string_view kGraphKeys[] = {key::y, key::x};
        readInstrumentList(r, get(key::graphs), at(key::graphs), kGraphKeys,
                           [&](const QJsonObject& g, const QString& p) {
                               GraphDesc graph;
                               const QJsonValue y = g.value(toQString(key::y));
                               if (y.isUndefined())
                                   r.fail(join(p, key::y), QStringLiteral("is required"));
                               else
                                   r.string(y, join(p, key::y), graph.y);
                               if (g.contains(toQString(key::x)))
                                   r.string(g.value(toQString(key::x)), join(p, key::x), graph.x);
                               in.graphs.push_back(std::move(graph));
                           });
    }
    static constexpr std::string_view kEndKeys[] = {key::ends};
    std::vector<std::array<std::string, 2>> rulers;
    std::vector<std::array<std::string, 3>> protractors;
    if (has(key::rulers))
        readInstrumentList(
            r, get(key::rulers), at(key::rulers), kEndKeys,
            [&](const QJsonObject& e, const QString& p) { readEnds(r, e, p, rulers); });
    if (has(key::protractors))
        readInstrumentList(
            r, get(key::protractors), at(key::protractors), kEndKeys,
            [&](const QJsonObject& e, const QString& p) { readEnds(r, e, p, protractors); });
    for (auto& e : rulers) in.rulers.push_back({std::move(e)});
    for (auto& e : protractors) in.protractors.push_back({std::move(e)});
    if (has(key::freeBody)) r.string(get(key::freeBody), at(key::freeBody), in.freeBody);
    if (has(key::view)) {
        QJsonObject v;
        if (r.object(get(key::view), at(key::view), v)) {
            static constexpr std::string_view kViewKeys[] = {key::center, key::width};
            ViewDesc view;
            Fields fields(r, v, at(key::view), kViewKeys, Reader::Unknown::Refused);
            fields.point(key::center, view.center, Need::Required);
            fields.number(key::width, view.width, Need::Required);
            in.view = view;
        }
    }
    if (has(key::plots)) {
        readStrings(r, get(key::plots), at(key::plots), in.plots);
        for (std::size_t i = 0; i < in.plots.size(); ++i) {
            if (std::find(std::begin(kPlotNames), std::end(kPlotNames), in.plots[i]) !=
                std::end(kPlotNames))
                continue;
            QStringList names;
            for (std::string_view n : kPlotNames) names << toQString(n);
            r.fail(index(at(key::plots), qsizetype(i)),
                   QStringLiteral("must be one of %1 (got \"%2\")")
                       .arg(names.join(QStringLiteral(", ")),
                            jsontext::shortened(QString::fromStdString(in.plots[i]))));
        }
    }
}

// format and version decide whether the rest can be read at all; false = stop here.
bool readHeader(Reader& r, const QJsonObject& top) {
    const QString formatKey = toQString(key::format);
    const QJsonValue format = top.value(formatKey);
    if (format.isUndefined()) {
        r.fail(formatKey, QStringLiteral("is required"));
    } else if (format.toString() != toQString(schema::kFormatName)) {
        QString what = QStringLiteral("must be \"%1\"").arg(toQString(schema::kFormatName));
        if (format.isString())
            what += QStringLiteral(" (got \"%1\")").arg(jsontext::shortened(format.toString()));
        r.fail(formatKey, what);
    }

    const QString path = toQString(key::version);
    const QJsonValue version = top.value(path);
    const double v = version.toDouble();
    if (version.isUndefined()) {
        r.fail(path, QStringLiteral("is required"));
    } else if (!version.isDouble() || !std::isfinite(v) || std::trunc(v) != v) {
        r.fail(path, QStringLiteral("must be an integer"));
    } else if (v > SceneDesc::kFormatVersion) {
        r.fail(path, QStringLiteral("the file is scene format version %1, but this Phasebox reads "
                                    "version %2 at most; please update Phasebox")
                         .arg(describeVersion(v))
                         .arg(SceneDesc::kFormatVersion));
    } else if (v < 1) {
        r.fail(path, QStringLiteral("must be >= 1 (got %1)").arg(describeVersion(v)));
    }
    return r.clean();
}

}  // namespace

SceneLoadResult SceneIO::load(const QString& path) {
    SceneLoadResult result;
    auto fail = [&](const QString& what) {
        result.errors << path + QStringLiteral(": ") + what;
        return result;
    };
    QFile file;
    if (const QString refused = inputfile::open(path, file); !refused.isEmpty())
        return fail(refused);
    const QString tooLarge =
        QStringLiteral("the file is larger than 64 MiB, too large for a scene");
    if (file.size() > kMaxFileBytes) return fail(tooLarge);
    // Read one byte past the limit rather than trusting size(), which is 0 for files under
    // /proc.
    const QByteArray bytes = file.read(kMaxFileBytes + 1);
    if (file.error() != QFileDevice::NoError)
        return fail(QStringLiteral("cannot read the file: ") + file.errorString());
    if (bytes.size() > kMaxFileBytes) return fail(tooLarge);
    if (bytes.trimmed().isEmpty()) return fail(QStringLiteral("the file is empty"));
    return parse(bytes, path);
}

SceneLoadResult SceneIO::parse(const QByteArray& text, const QString& sourceName) {
    SceneLoadResult result;
    // Editors on Windows start UTF-8 files with a byte order mark. Qt skips it, but the columns
    // of the first line would then count it as a character.
    const QByteArray json = text.startsWith("\xEF\xBB\xBF") ? text.mid(3) : text;
    QJsonDocument document;
    jsontext::ScanResult scanned;
    if (const auto problem = jsontext::parse(json, document, &scanned)) {
        const auto [line, column] = jsontext::lineAndColumn(json, problem->offset);
        result.errors << QStringLiteral("%1:%2:%3: %4")
                             .arg(sourceName, QString::number(line), QString::number(column),
                                  problem->what);
        return result;
    }

    Reader r(sourceName);
    // Qt keeps the last of two equal keys; which one the author meant is theirs to say.
    if (!scanned.duplicates.empty()) {
        auto place = [&](qsizetype offset) {
            const auto [line, column] = jsontext::lineAndColumn(json, offset);
            return QStringLiteral("%1:%2").arg(line).arg(column);
        };
        for (const jsontext::DuplicateKey& d : scanned.duplicates)
            r.fail(d.path, QStringLiteral("duplicate key (at %1 and again at %2); JSON keeps only "
                                          "one of them, so give it once")
                               .arg(place(d.first), place(d.second)));
        if (const long long more = scanned.duplicateCount - scanned.duplicates.size(); more > 0)
            r.failFile(QStringLiteral("and %1 more duplicate keys").arg(more));
        result.errors = r.takeErrors();
        return result;
    }
    if (!document.isObject()) {
        r.failFile(QStringLiteral("the top level must be a JSON object {...}"));
        result.errors = r.takeErrors();
        return result;
    }
    const QJsonObject top = document.object();
    // A newer file may hold keys this version does not know, and reading it would either
    // report them as typos or drop their data, so only the version is reported.
    if (!readHeader(r, top)) {
        result.errors = r.takeErrors();
        return result;
    }

    SceneDesc scene;
    Fields fields(r, top, QString(), schema::topKeys());
    fields.string(key::name, scene.name);
    fields.string(key::description, scene.description);
    if (auto simulation =
            fields.object(key::simulation, schema::keysOf(schema::table<SimulationDesc>()))) {
        readFields(*simulation, scene.simulation);
    }
    if (auto effects = fields.object(key::effects, schema::effectKeys())) {
        schema::forEachEffect([&](const auto& table, auto member) {
            readEffect(*effects, table.key, scene.effects.*member);
        });
    }
    schema::forEachObjectKind(
        [&](const auto& table, auto array) { readObjects(fields, table.key, scene.*array); });
    readInstruments(fields, scene.instruments);

    // Ranges and references are checked only on a fully read scene: after a type error the
    // description holds defaults in that place, and checking them would report made-up values.
    if (r.clean()) {
        for (const SceneIssue& issue : validateScene(scene))
            r.fail(QString::fromStdString(issue.path), QString::fromStdString(issue.message));
    }
    // A polygon's state is its centroid's (CONTRACT §6); saving then writes the centred form.
    if (r.clean()) recentrePolygons(scene);
    result.errors = r.takeErrors();
    if (result.errors.isEmpty()) result.scene = std::move(scene);
    return result;
}

}  // namespace phasebox
