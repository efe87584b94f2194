#include "app/io/SceneIO.h"

#include "app/io/JsonText.h"

#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QJsonValue>
#include <QLocale>

#include <algorithm>
#include <cmath>
#include <cstdlib>
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

constexpr std::string_view kFormatName = "phasebox-scene";

// The keys of every object the format defines, in the contract's order. Keys outside these
// lists are ignored unless they look like a misspelling of one of them.
using KeyList = std::span<const std::string_view>;
constexpr std::string_view kTopKeys[] = {"format",     "version", "name",      "description",
                                         "simulation", "effects", "particles", "boxes",
                                         "planes",     "springs", "cloths"};
constexpr std::string_view kSimulationKeys[] = {
    "integrator", "dt", "substeps", "tolerance", "newton_iterations", "duration", "solver"};
constexpr std::string_view kEffectKeys[] = {
    "gravity", "drag", "newtonian_gravity", "buoyancy", "wind", "flocking", "particle_collisions",
    "coulomb"};
constexpr std::string_view kGravityKeys[] = {"g"};
constexpr std::string_view kDragKeys[] = {"linear", "quadratic", "angular"};
constexpr std::string_view kNewtonianKeys[] = {"G", "attractors", "mutual", "softening"};
constexpr std::string_view kAttractorKeys[] = {"position", "mass"};
constexpr std::string_view kBuoyancyKeys[] = {"fluid_density", "surface_y", "drag"};
constexpr std::string_view kWindKeys[] = {"velocity", "drag"};
constexpr std::string_view kFlockingKeys[] = {"radius", "separation", "alignment", "cohesion",
                                              "max_speed"};
constexpr std::string_view kCollisionKeys[] = {"restitution"};
constexpr std::string_view kCoulombKeys[] = {"k", "softening"};
constexpr std::string_view kParticleKeys[] = {
    "id", "position", "velocity", "mass", "radius", "pinned", "restitution", "friction", "charge"};
constexpr std::string_view kBoxKeys[] = {"id",       "position",         "size",       "angle",
                                         "velocity", "angular_velocity", "mass",       "density",
                                         "static",   "friction",         "restitution"};
constexpr std::string_view kPlaneKeys[] = {"id", "point", "normal", "friction", "restitution"};
constexpr std::string_view kSpringKeys[] = {
    "id", "a", "b", "anchor", "a_point", "b_point", "stiffness", "damping", "rest_length"};
constexpr std::string_view kClothKeys[] = {"id",        "origin",  "size",   "resolution", "mass",
                                           "stiffness", "damping", "radius", "pinned"};
constexpr std::string_view kClothStiffnessKeys[] = {"structural", "shear", "bend"};

const char* const kXY = "[x, y]";
const char* const kWH = "[w, h]";

QString toQString(std::string_view s) {
    return QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size()));
}

QString join(const QString& path, const QString& key) {
    return path.isEmpty() ? key : path + QLatin1Char('.') + key;
}

QString join(const QString& path, std::string_view key) {
    return join(path, toQString(key));
}

QString index(const QString& path, qsizetype i) {
    return path + QLatin1Char('[') + QString::number(i) + QLatin1Char(']');
}

// Optimal string alignment distance (Levenshtein plus transposition of neighbours), ignoring
// case, so that "Stifness", "stiffnes" and "stiffnses" all count as close to "stiffness".
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
// edits, but not a complete replacement of the known key: "x" is two edits from "id" and
// shares nothing with it, and without that rule every short key would be rejected next to the
// short keys "id", "a" and "b".
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
    QStringList takeErrors() { return std::exchange(errors_, {}); }

    // A key that is close to a known one is a typo that would silently drop a value (a
    // teacher's spring losing its stiffness), so it is an error; anything further away is an
    // extension and is ignored.
    void checkKeys(const QJsonObject& object, const QString& path, KeyList known) {
        for (auto it = object.begin(); it != object.end(); ++it) {
            const QString key = it.key();
            const bool isKnown = std::any_of(known.begin(), known.end(), [&](std::string_view k) {
                return key == toQString(k);
            });
            if (isKnown) continue;
            if (const auto guess = misspeltKey(key, known))
                fail(join(path, key),
                     QStringLiteral("unknown key; did you mean \"%1\"?").arg(toQString(*guess)));
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
    Fields(Reader& reader, QJsonObject object, QString path, KeyList known)
        : r_(reader), object_(std::move(object)), path_(std::move(path)) {
        r_.checkKeys(object_, path_, known);
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
    void point(std::string_view key, std::optional<Point2>& out) {
        const QJsonValue v = get(key);
        Point2 p{0.0, 0.0};
        if (!v.isUndefined() && r_.pair(v, at(key), p, kXY)) out = p;
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

// Reads every element of an optional array of objects with readOne(fields, desc).
template <typename Desc, typename ReadOne>
void readObjects(Fields& top, std::string_view key, KeyList known, std::vector<Desc>& out,
                 ReadOne readOne) {
    const QJsonValue v = top.get(key);
    QJsonArray array;
    if (v.isUndefined() || !top.reader().array(v, top.at(key), array)) return;
    out.reserve(static_cast<std::size_t>(array.size()));
    for (qsizetype i = 0; i < array.size(); ++i) {
        const QString path = index(top.at(key), i);
        QJsonObject object;
        Desc desc;
        if (top.reader().object(array[i], path, object)) {
            Fields fields(top.reader(), object, path, known);
            readOne(fields, desc);
        }
        out.push_back(std::move(desc));
    }
}

void readSimulation(Fields& f, SimulationDesc& sim) {
    f.string("integrator", sim.integrator);
    f.number("dt", sim.dt);
    f.integer("substeps", sim.substeps);
    f.number("tolerance", sim.tolerance);
    f.integer("newton_iterations", sim.newtonIterations);
    f.number("duration", sim.duration);
    // The solver's keys belong to the engine (SceneDesc.h lists the ones it reads); a near miss
    // of one is a typo like any other, and the rest are kept so that they round-trip.
    const QJsonValue solver = f.get("solver");
    QJsonObject object;
    if (solver.isUndefined() || !f.reader().object(solver, f.at("solver"), object)) return;
    f.reader().checkKeys(object, f.at("solver"), kSolverKeys);
    for (auto it = object.begin(); it != object.end(); ++it) {
        double value = 0.0;
        if (f.reader().number(it.value(), join(f.at("solver"), it.key()), value))
            sim.solver[it.key().toStdString()] = value;
    }
}

// An effect is present when given as an object (its fields) or as true (all defaults); false
// and null mean absent, so that a file (or a script writing one) can switch an effect off
// without deleting its key.
template <typename Desc, typename ReadFields>
void readEffect(Fields& effects, std::string_view key, KeyList known, std::optional<Desc>& out,
                ReadFields readFields) {
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
    Fields fields(effects.reader(), v.toObject(), effects.at(key), known);
    readFields(fields, desc);
    out = std::move(desc);
}

void readEffects(Fields& fx, EffectsDesc& out) {
    readEffect(fx, "gravity", kGravityKeys, out.gravity,
               [](Fields& f, GravityDesc& d) { f.point("g", d.g); });
    readEffect(fx, "drag", kDragKeys, out.drag, [](Fields& f, DragDesc& d) {
        f.number("linear", d.linear);
        f.number("quadratic", d.quadratic);
        f.number("angular", d.angular);
    });
    readEffect(fx, "newtonian_gravity", kNewtonianKeys, out.newtonianGravity,
               [](Fields& f, NewtonianGravityDesc& d) {
                   f.number("G", d.G);
                   readObjects(f, "attractors", kAttractorKeys, d.attractors,
                               [](Fields& a, AttractorDesc& attractor) {
                                   a.point("position", attractor.position);
                                   a.number("mass", attractor.mass);
                               });
                   f.boolean("mutual", d.mutual);
                   f.number("softening", d.softening);
               });
    readEffect(fx, "buoyancy", kBuoyancyKeys, out.buoyancy, [](Fields& f, BuoyancyDesc& d) {
        f.number("fluid_density", d.fluidDensity);
        f.number("surface_y", d.surfaceY);
        f.number("drag", d.drag);
    });
    readEffect(fx, "wind", kWindKeys, out.wind, [](Fields& f, WindDesc& d) {
        f.point("velocity", d.velocity);
        f.number("drag", d.drag);
    });
    readEffect(fx, "flocking", kFlockingKeys, out.flocking, [](Fields& f, FlockingDesc& d) {
        f.number("radius", d.radius);
        f.number("separation", d.separation);
        f.number("alignment", d.alignment);
        f.number("cohesion", d.cohesion);
        f.number("max_speed", d.maxSpeed);
    });
    readEffect(
        fx, "particle_collisions", kCollisionKeys, out.particleCollisions,
        [](Fields& f, ParticleCollisionsDesc& d) { f.number("restitution", d.restitution); });
    readEffect(fx, "coulomb", kCoulombKeys, out.coulomb, [](Fields& f, CoulombDesc& d) {
        f.number("k", d.k);
        f.number("softening", d.softening);
    });
}

void readParticle(Fields& f, ParticleDesc& p) {
    f.string("id", p.id);
    f.point("position", p.position, Need::Required);
    f.point("velocity", p.velocity);
    f.number("mass", p.mass);
    f.number("radius", p.radius);
    f.boolean("pinned", p.pinned);
    f.number("restitution", p.restitution);
    f.number("friction", p.friction);
    f.number("charge", p.charge);
}

void readBox(Fields& f, BoxDesc& b) {
    f.string("id", b.id);
    f.point("position", b.position, Need::Required);
    f.point("size", b.size, Need::Required, kWH);
    f.number("angle", b.angle);
    f.point("velocity", b.velocity);
    f.number("angular_velocity", b.angularVelocity);
    // Which one the author gave is part of the scene: a file that states a density should
    // still state a density after resizing the box and saving.
    if (f.has("mass") && f.has("density"))
        f.reader().fail(f.path(), QStringLiteral("give mass or density, not both"));
    f.number("mass", b.mass);
    f.number("density", b.density);
    f.boolean("static", b.isStatic);
    f.number("friction", b.friction);
    f.number("restitution", b.restitution);
}

void readPlane(Fields& f, PlaneDesc& p) {
    f.string("id", p.id);
    f.point("point", p.point, Need::Required);
    f.point("normal", p.normal, Need::Required);
    f.number("friction", p.friction);
    f.number("restitution", p.restitution);
}

void readSpring(Fields& f, SpringDesc& s) {
    f.string("id", s.id);
    f.string("a", s.a, Need::Required);
    f.string("b", s.b);
    f.point("anchor", s.anchor);
    f.point("a_point", s.aPoint);
    f.point("b_point", s.bPoint);
    f.number("stiffness", s.stiffness, Need::Required);
    f.number("damping", s.damping);
    f.number("rest_length", s.restLength);
}

void readClothPinned(Fields& f, ClothDesc& c) {
    const QJsonValue v = f.get("pinned");
    if (v.isUndefined()) return;
    Reader& r = f.reader();
    if (v.isString()) {
        c.pinned = v.toString().toStdString();
        return;
    }
    if (!v.isArray()) {
        r.fail(f.at("pinned"), QStringLiteral("must be a string (top, top_corners, left, none) "
                                              "or an array of [i, j] pairs"));
        return;
    }
    const QJsonArray array = v.toArray();
    std::vector<std::array<int, 2>> nodes;
    nodes.reserve(static_cast<std::size_t>(array.size()));
    for (qsizetype k = 0; k < array.size(); ++k) {
        std::array<int, 2> node{0, 0};
        r.intPair(array[k], index(f.at("pinned"), k), node, "[i, j]");
        nodes.push_back(node);
    }
    c.pinned = std::move(nodes);
}

void readCloth(Fields& f, ClothDesc& c) {
    f.string("id", c.id, Need::Required);
    f.point("origin", c.origin);
    f.point("size", c.size, Need::Optional, kWH);
    if (const QJsonValue v = f.get("resolution"); !v.isUndefined())
        f.reader().intPair(v, f.at("resolution"), c.resolution, "[nx, ny]");
    f.number("mass", c.mass);
    if (auto stiffness = f.object("stiffness", kClothStiffnessKeys)) {
        stiffness->number("structural", c.stiffness.structural);
        stiffness->number("shear", c.stiffness.shear);
        stiffness->number("bend", c.stiffness.bend);
    }
    f.number("damping", c.damping);
    f.number("radius", c.radius);
    readClothPinned(f, c);
}

// format and version decide whether the rest can be read at all; false = stop here.
bool readHeader(Reader& r, const QJsonObject& top) {
    const QJsonValue format = top.value(QStringLiteral("format"));
    if (format.isUndefined()) {
        r.fail(QStringLiteral("format"), QStringLiteral("is required"));
    } else if (format.toString() != toQString(kFormatName)) {
        QString what = QStringLiteral("must be \"%1\"").arg(toQString(kFormatName));
        if (format.isString()) what += QStringLiteral(" (got \"%1\")").arg(format.toString());
        r.fail(QStringLiteral("format"), what);
    }

    const QJsonValue version = top.value(QStringLiteral("version"));
    const QString path = QStringLiteral("version");
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

// ---- writing ----

// A JSON writer that keeps the contract's key order (QJsonObject sorts its keys) and prints
// numbers in their shortest form that reads back as the same double.
}  // namespace

SceneLoadResult SceneIO::load(const QString& path) {
    SceneLoadResult result;
    auto fail = [&](const QString& what) {
        result.errors << path + QStringLiteral(": ") + what;
        return result;
    };
    // QFile refuses a directory with "Unknown error", which tells the user nothing.
    if (QFileInfo(path).isDir())
        return fail(QStringLiteral("cannot read the file: it is a folder"));
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return fail(QStringLiteral("cannot read the file: ") + file.errorString());
    const QString tooLarge =
        QStringLiteral("the file is larger than 64 MiB, too large for a scene");
    if (file.size() > kMaxFileBytes) return fail(tooLarge);
    // Read one byte past the limit rather than trusting size(), which is 0 for pipes and
    // files under /proc.
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
    if (const auto problem = jsontext::parse(json, document)) {
        const auto [line, column] = jsontext::lineAndColumn(json, problem->offset);
        result.errors << QStringLiteral("%1:%2:%3: %4")
                             .arg(sourceName, QString::number(line), QString::number(column),
                                  problem->what);
        return result;
    }

    Reader r(sourceName);
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
    Fields fields(r, top, QString(), kTopKeys);
    fields.string("name", scene.name);
    fields.string("description", scene.description);
    if (auto simulation = fields.object("simulation", kSimulationKeys))
        readSimulation(*simulation, scene.simulation);
    if (auto effects = fields.object("effects", kEffectKeys)) readEffects(*effects, scene.effects);
    readObjects(fields, "particles", kParticleKeys, scene.particles, readParticle);
    readObjects(fields, "boxes", kBoxKeys, scene.boxes, readBox);
    readObjects(fields, "planes", kPlaneKeys, scene.planes, readPlane);
    readObjects(fields, "springs", kSpringKeys, scene.springs, readSpring);
    readObjects(fields, "cloths", kClothKeys, scene.cloths, readCloth);

    // Ranges and references are checked only on a fully read scene: after a type error the
    // description holds defaults in that place, and checking them would report made-up values.
    if (r.clean()) {
        for (const SceneIssue& issue : validateScene(scene))
            r.fail(QString::fromStdString(issue.path), QString::fromStdString(issue.message));
    }
    result.errors = r.takeErrors();
    if (result.errors.isEmpty()) result.scene = std::move(scene);
    return result;
}

}  // namespace phasebox
