#include "app/io/SceneIO.h"

#include <QSaveFile>

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

constexpr std::string_view kFormatName = "phasebox-scene";

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
    void field(std::string_view k, bool v) {
        key(k);
        boolean(v);
    }
    void field(std::string_view k, const std::string& v) {
        key(k);
        string(v);
    }
    void field(std::string_view k, const Point2& v) {
        key(k);
        point(v);
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

void writeSimulation(Writer& w, const SimulationDesc& sim) {
    w.beginObject();
    w.field("integrator", sim.integrator);
    w.field("dt", sim.dt);
    w.field("substeps", sim.substeps);
    w.field("tolerance", sim.tolerance);
    w.field("newton_iterations", sim.newtonIterations);
    w.field("duration", sim.duration);
    if (!sim.solver.empty()) {
        w.key("solver");
        w.beginObject();
        for (const auto& [name, value] : sim.solver) w.field(name, value);
        w.endObject();
    }
    w.endObject();
}

void writeEffects(Writer& w, const EffectsDesc& fx) {
    w.beginObject();
    if (fx.gravity) {
        w.key("gravity");
        w.beginObject();
        w.field("g", fx.gravity->g);
        w.endObject();
    }
    if (fx.drag) {
        w.key("drag");
        w.beginObject();
        w.field("linear", fx.drag->linear);
        w.field("quadratic", fx.drag->quadratic);
        w.field("angular", fx.drag->angular);
        w.endObject();
    }
    if (fx.newtonianGravity) {
        const NewtonianGravityDesc& ng = *fx.newtonianGravity;
        w.key("newtonian_gravity");
        w.beginObject();
        w.field("G", ng.G);
        w.key("attractors");
        w.beginArray();
        for (const AttractorDesc& a : ng.attractors) {
            w.beginObject();
            w.field("position", a.position);
            w.field("mass", a.mass);
            w.endObject();
        }
        w.endArray();
        w.field("mutual", ng.mutual);
        w.field("softening", ng.softening);
        w.endObject();
    }
    if (fx.buoyancy) {
        w.key("buoyancy");
        w.beginObject();
        w.field("fluid_density", fx.buoyancy->fluidDensity);
        w.field("surface_y", fx.buoyancy->surfaceY);
        w.field("drag", fx.buoyancy->drag);
        w.endObject();
    }
    if (fx.wind) {
        w.key("wind");
        w.beginObject();
        w.field("velocity", fx.wind->velocity);
        w.field("drag", fx.wind->drag);
        w.endObject();
    }
    if (fx.flocking) {
        w.key("flocking");
        w.beginObject();
        w.field("radius", fx.flocking->radius);
        w.field("separation", fx.flocking->separation);
        w.field("alignment", fx.flocking->alignment);
        w.field("cohesion", fx.flocking->cohesion);
        w.field("max_speed", fx.flocking->maxSpeed);
        w.endObject();
    }
    if (fx.particleCollisions) {
        w.key("particle_collisions");
        w.beginObject();
        w.field("restitution", fx.particleCollisions->restitution);
        w.endObject();
    }
    if (fx.coulomb) {
        w.key("coulomb");
        w.beginObject();
        w.field("k", fx.coulomb->k);
        w.field("softening", fx.coulomb->softening);
        w.endObject();
    }
    w.endObject();
}

void writeId(Writer& w, const std::string& id) {
    if (!id.empty()) w.field("id", id);
}

void writeParticle(Writer& w, const ParticleDesc& p) {
    w.beginObject();
    writeId(w, p.id);
    w.field("position", p.position);
    w.field("velocity", p.velocity);
    w.field("mass", p.mass);
    w.field("radius", p.radius);
    w.field("pinned", p.pinned);
    w.field("restitution", p.restitution);
    w.field("friction", p.friction);
    w.field("charge", p.charge);
    w.endObject();
}

void writeBox(Writer& w, const BoxDesc& b) {
    w.beginObject();
    writeId(w, b.id);
    w.field("position", b.position);
    w.field("size", b.size);
    w.field("angle", b.angle);
    w.field("velocity", b.velocity);
    w.field("angular_velocity", b.angularVelocity);
    if (b.mass)
        w.field("mass", *b.mass);
    else
        w.field("density", b.density);
    w.field("static", b.isStatic);
    w.field("friction", b.friction);
    w.field("restitution", b.restitution);
    w.endObject();
}

void writePlane(Writer& w, const PlaneDesc& p) {
    w.beginObject();
    writeId(w, p.id);
    w.field("point", p.point);
    w.field("normal", p.normal);
    w.field("friction", p.friction);
    w.field("restitution", p.restitution);
    w.endObject();
}

void writeSpring(Writer& w, const SpringDesc& s) {
    w.beginObject();
    writeId(w, s.id);
    w.field("a", s.a);
    if (s.b) w.field("b", *s.b);
    if (s.anchor) w.field("anchor", *s.anchor);
    w.field("a_point", s.aPoint);
    w.field("b_point", s.bPoint);
    w.field("stiffness", s.stiffness);
    w.field("damping", s.damping);
    if (s.restLength) w.field("rest_length", *s.restLength);
    w.endObject();
}

void writeCloth(Writer& w, const ClothDesc& c) {
    w.beginObject();
    w.field("id", c.id);
    w.field("origin", c.origin);
    w.field("size", c.size);
    w.key("resolution");
    w.intPair(c.resolution);
    w.field("mass", c.mass);
    w.key("stiffness");
    w.beginObject();
    w.field("structural", c.stiffness.structural);
    w.field("shear", c.stiffness.shear);
    w.field("bend", c.stiffness.bend);
    w.endObject();
    w.field("damping", c.damping);
    w.field("radius", c.radius);
    if (const auto* mode = std::get_if<std::string>(&c.pinned)) {
        w.field("pinned", *mode);
    } else {
        w.key("pinned");
        w.beginArray(true);
        for (const auto& node : std::get<std::vector<std::array<int, 2>>>(c.pinned))
            w.intPair(node);
        w.endArray();
    }
    w.endObject();
}

template <typename Desc, typename WriteOne>
void writeArray(Writer& w, std::string_view key, const std::vector<Desc>& items,
                WriteOne writeOne) {
    w.key(key);
    w.beginArray();
    for (const Desc& item : items) writeOne(w, item);
    w.endArray();
}

}  // namespace

QByteArray SceneIO::serialize(const SceneDesc& scene) {
    Writer w;
    w.beginObject();
    w.field("format", std::string(kFormatName));
    w.field("version", SceneDesc::kFormatVersion);
    w.field("name", scene.name);
    w.field("description", scene.description);
    w.key("simulation");
    writeSimulation(w, scene.simulation);
    w.key("effects");
    writeEffects(w, scene.effects);
    writeArray(w, "particles", scene.particles, writeParticle);
    writeArray(w, "boxes", scene.boxes, writeBox);
    writeArray(w, "planes", scene.planes, writePlane);
    writeArray(w, "springs", scene.springs, writeSpring);
    writeArray(w, "cloths", scene.cloths, writeCloth);
    w.endObject();
    return w.take();
}

bool SceneIO::save(const SceneDesc& scene, const QString& path, QString* error) {
    const QByteArray bytes = serialize(scene);
    QSaveFile file(path);
    auto fail = [&](const QString& reason) {
        if (error) *error = path + QStringLiteral(": cannot write the file: ") + reason;
        return false;
    };
    if (!file.open(QIODevice::WriteOnly)) return fail(file.errorString());
    if (const qint64 written = file.write(bytes); written != bytes.size()) {
        // A full disk or a file-size limit gives a short write with no error set, and Qt's
        // error string is then "Unknown error": say what happened instead.
        const QString reason =
            file.error() != QFileDevice::NoError
                ? file.errorString()
                : QStringLiteral("only %1 of %2 bytes could be written (is the disk full?)")
                      .arg(std::max<qint64>(written, 0))
                      .arg(bytes.size());
        file.cancelWriting();
        return fail(reason);
    }
    // Until commit() the old file is untouched; commit renames the finished copy over it.
    if (!file.commit()) return fail(file.errorString());
    return true;
}


}  // namespace phasebox
