#include "physics/world/Probes.h"

#include "physics/contacts/ContactStage.h"
#include "physics/world/World.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <numbers>

namespace phasebox {

namespace {

constexpr std::string_view kVocabulary =
    "ID.x, ID.y, ID.vx, ID.vy, ID.speed, ID.angle, ID.omega, ID.kinetic, ID.px, ID.py, ID.L, "
    "system.kinetic, system.potential, system.total, system.work_nc, system.drift, "
    "system.correction, system.px, system.py, system.L, system.com_x, system.com_y, "
    "distance(A,B), angle(A,B,C) (A, B, C: ids or points X:Y, the vertex B), force(JOINT), "
    "JOINT.angle, contact_force(ID)";

struct Field {
    std::string_view name;
    ProbeKind kind;
};

constexpr Field kObjectFields[] = {
    {"x", ProbeKind::X},
    {"y", ProbeKind::Y},
    {"vx", ProbeKind::Vx},
    {"vy", ProbeKind::Vy},
    {"speed", ProbeKind::Speed},
    {"angle", ProbeKind::Angle},
    {"omega", ProbeKind::Omega},
    {"kinetic", ProbeKind::Kinetic},
    {"px", ProbeKind::Px},
    {"py", ProbeKind::Py},
    {"L", ProbeKind::AngularMomentum},
};

constexpr Field kSystemFields[] = {
    {"kinetic", ProbeKind::SystemKinetic},
    {"potential", ProbeKind::SystemPotential},
    {"total", ProbeKind::SystemTotal},
    {"work_nc", ProbeKind::SystemWorkNc},
    {"drift", ProbeKind::SystemDrift},
    {"correction", ProbeKind::SystemCorrection},
    {"px", ProbeKind::SystemPx},
    {"py", ProbeKind::SystemPy},
    {"L", ProbeKind::SystemAngularMomentum},
    {"com_x", ProbeKind::SystemComX},
    {"com_y", ProbeKind::SystemComY},
};

template <std::size_t N>
std::optional<ProbeKind> findField(const Field (&fields)[N], std::string_view name) {
    for (const Field& f : fields)
        if (f.name == name) return f.kind;
    return std::nullopt;
}

std::string_view trim(std::string_view s) {
    const auto space = [](char c) { return c == ' ' || c == '\t'; };
    while (!s.empty() && space(s.front())) s.remove_prefix(1);
    while (!s.empty() && space(s.back())) s.remove_suffix(1);
    return s;
}

// The arguments of an instrument, split at the commas outside brackets (a cloth node's id,
// `flag[1,2]`, holds one).
std::vector<std::string_view> splitArguments(std::string_view text) {
    std::vector<std::string_view> args;
    int depth = 0;
    std::size_t start = 0;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text[i] == '[') ++depth;
        if (text[i] == ']') depth = std::max(0, depth - 1);
        if (text[i] == ',' && depth == 0) {
            args.push_back(trim(text.substr(start, i - start)));
            start = i + 1;
        }
    }
    args.push_back(trim(text.substr(start)));
    return args;
}

ProbeParse refuse(std::string_view text, const std::string& reason = {}) {
    ProbeParse result;
    result.error = "unknown probe \"" + std::string(text) + "\"";
    if (!reason.empty()) result.error += ": " + reason;
    result.error += "; known: ";
    result.error += kVocabulary;
    return result;
}

std::string quoted(std::string_view s) {
    std::string text;  // not "\"" + … + "\"": GCC 12 warns falsely (-Wrestrict) on that
    text.reserve(s.size() + 2);
    text += '"';
    text += s;
    text += '"';
    return text;
}

int findJoint(const World& world, std::string_view id) {
    const auto& joints = world.joints();
    for (std::size_t j = 0; j < joints.size(); ++j)
        if (joints[j].id == id) return static_cast<int>(j);
    return -1;
}

bool measuresAngle(const Joint& joint) {
    return joint.type == Joint::Type::Hinge || joint.type == Joint::Type::Rod ||
           joint.type == Joint::Type::Rope;
}

// An instrument: distance(A,B), angle(A,B,C), force(JOINT), contact_force(ID). nullopt when
// the name is none of them (the text may still be an object's field: an id may hold brackets).
std::optional<ProbeParse> parseInstrument(const World& world, std::string_view text,
                                          std::string_view name, std::string_view inside) {
    struct Instrument {
        std::string_view name;
        ProbeKind kind;
        std::size_t arguments;
        std::string_view form;
    };
    static constexpr Instrument kInstruments[] = {
        {"distance", ProbeKind::Distance, 2, "distance(A,B)"},
        {"angle", ProbeKind::AngleAt, 3, "angle(A,B,C)"},
        {"force", ProbeKind::JointForce, 1, "force(JOINT)"},
        {"contact_force", ProbeKind::ContactForce, 1, "contact_force(ID)"},
    };
    const Instrument* instrument = nullptr;
    for (const Instrument& i : kInstruments)
        if (i.name == name) instrument = &i;
    if (!instrument) return std::nullopt;
    const std::vector<std::string_view> args = splitArguments(inside);
    if (args.size() != instrument->arguments)
        return refuse(text, "takes " + std::to_string(instrument->arguments) + " argument" +
                                (instrument->arguments == 1 ? "" : "s") + ": " +
                                std::string(instrument->form));
    Probe probe;
    probe.text = std::string(text);
    probe.kind = instrument->kind;
    if (instrument->kind == ProbeKind::JointForce) {
        probe.joint = findJoint(world, args[0]);
        if (probe.joint < 0) return refuse(text, "no joint " + quoted(args[0]));
        return ProbeParse{std::move(probe), {}};
    }
    const bool points = instrument->kind != ProbeKind::ContactForce;
    for (std::size_t k = 0; k < args.size(); ++k) {
        // An object's id first: ids are free text, so "1:2" may name one.
        if (const std::optional<ProbeObject> object = findProbeObject(world, args[k]))
            probe.objects[k] = *object;
        else if (const std::optional<Vec2> point = parseProbePoint(args[k]); points && point)
            probe.points[k] = *point;
        else
            return refuse(text, "no object " + quoted(args[k]) +
                                    (points ? " (nor a point X:Y in metres)" : ""));
    }
    if (instrument->kind == ProbeKind::ContactForce) {
        const ProbeObject& o = probe.objects[0];
        const bool fixed =
            o.rigid ? world.rigidBodies()[o.index].isStatic : world.particles()[o.index].pinned;
        // The world takes the reaction of what it holds still; it is not summed anywhere.
        if (fixed)
            return refuse(text, quoted(args[0]) +
                                    " is static or pinned: the contact force is measured on "
                                    "moving bodies");
    }
    return ProbeParse{std::move(probe), {}};
}

// The state of one object; fixed objects rest at their place.
struct ObjectState {
    Vec2 position{0.0, 0.0}, velocity{0.0, 0.0};
    double angle = 0.0, omega = 0.0;
    double mass = 0.0, inertia = 0.0;
};

ObjectState stateOf(const World& world, const ProbeObject& o) {
    ObjectState s;
    if (o.rigid) {
        const RigidBody& b = world.rigidBodies()[o.index];
        s.position = world.bodyPosition(o.index);
        s.angle = world.bodyAngle(o.index);
        if (b.dof >= 0) {
            s.velocity = world.bodyVelocity(o.index);
            s.omega = world.bodyAngularVelocity(o.index);
            s.mass = b.mass;
            s.inertia = b.inertia;
        }
    } else {
        const Particle& p = world.particles()[o.index];
        s.position = world.particlePosition(o.index);
        if (p.dof >= 0) {
            s.velocity = world.particleVelocity(o.index);
            s.mass = p.mass;
        }
    }
    return s;
}

// Where argument k of distance or angle is now: its object or its fixed point.
Vec2 argumentPosition(const World& world, const Probe& probe, int k) {
    return probe.points[k] ? *probe.points[k] : probeObjectPosition(world, probe.objects[k]);
}

// Where a joint's point on one of its bodies is now (in the world frame).
Vec2 jointPoint(const World& world, const JointBody& body) {
    switch (body.kind) {
        case JointBody::Kind::Particle:
            return world.particlePosition(body.index);
        case JointBody::Kind::Rigid:
            return world.bodyPosition(body.index) +
                   rotation(world.bodyAngle(body.index)) * body.point;
        case JointBody::Kind::World:
            break;
    }
    return body.point;
}

// The angle of the line from `from` to `to` measured from straight down (−y), counter-clockwise
// positive, in (−π, π].
double angleFromDown(const Vec2& from, const Vec2& to) {
    const Vec2 r = to - from;
    const double angle = std::atan2(r.x(), -r.y());
    return angle <= -std::numbers::pi ? std::numbers::pi : angle;
}

}  // namespace

std::optional<Vec2> parseProbePoint(std::string_view text) {
    const std::size_t colon = text.find(':');
    if (colon == std::string_view::npos) return std::nullopt;
    double xy[2];
    const std::string_view parts[2] = {trim(text.substr(0, colon)), trim(text.substr(colon + 1))};
    for (int k = 0; k < 2; ++k) {
        std::string_view part = parts[k];
        // from_chars takes no leading '+'; a number written "+1" is still a number.
        if (!part.empty() && part.front() == '+') part.remove_prefix(1);
        const char* end = part.data() + part.size();
        const auto [last, status] = std::from_chars(part.data(), end, xy[k]);
        if (part.empty() || status != std::errc() || last != end || !std::isfinite(xy[k]))
            return std::nullopt;
    }
    return Vec2(xy[0], xy[1]);
}

std::optional<double> jointAngle(const World& world, int j) {
    if (j < 0 || j >= static_cast<int>(world.joints().size())) return std::nullopt;
    const Joint& joint = world.joints()[j];
    if (!measuresAngle(joint)) return std::nullopt;
    const bool hinge = joint.type == Joint::Type::Hinge;
    if (joint.b.kind != JointBody::Kind::World) {
        if (!hinge) return angleFromDown(jointPoint(world, joint.b), jointPoint(world, joint.a));
        const auto angleOf = [&](const JointBody& body) {
            return body.kind == JointBody::Kind::Rigid ? world.bodyAngle(body.index) : 0.0;
        };
        return angleOf(joint.b) - angleOf(joint.a) - joint.referenceAngle;
    }
    // Held to the world: b's point is the anchor. A hinge's a-point sits on the anchor, so the
    // pendulum's line runs to a's centre; a rod or rope pulls on a's point.
    const Vec2 end =
        hinge ? (joint.a.kind == JointBody::Kind::Rigid ? world.bodyPosition(joint.a.index)
                                                        : world.particlePosition(joint.a.index))
              : jointPoint(world, joint.a);
    return angleFromDown(joint.b.point, end);
}

std::optional<ProbeObject> findProbeObject(const World& world, std::string_view id) {
    for (std::size_t i = 0; i < world.particles().size(); ++i)
        if (world.particles()[i].id == id) return ProbeObject{false, static_cast<int>(i)};
    for (std::size_t i = 0; i < world.rigidBodies().size(); ++i)
        if (world.rigidBodies()[i].id == id) return ProbeObject{true, static_cast<int>(i)};
    return std::nullopt;
}

Vec2 probeObjectPosition(const World& world, const ProbeObject& o) {
    return o.rigid ? world.bodyPosition(o.index) : world.particlePosition(o.index);
}

double signedAngle(const Vec2& a, const Vec2& vertex, const Vec2& c) {
    const Vec2 ba = a - vertex, bc = c - vertex;
    // atan2 answers in [−π, π]; −π (BC exactly opposite BA, approached from below) is reported
    // as π so that the range is (−π, π] as CONTRACT §7 says.
    const double angle = std::atan2(cross(ba, bc), ba.dot(bc));
    return angle <= -std::numbers::pi ? std::numbers::pi : angle;
}

// From the flat state: particles (x, y) then rigid bodies (x, y, θ), with the per-coordinate
// masses (m, m, I).
SystemMotion systemMotion(const World& world) {
    SystemMotion s;
    const Vec& q = world.positions();
    const Vec& u = world.velocities();
    const Vec& m = world.mass();
    const int paired = world.layout().rigidBase(), dimension = world.layout().dimension();
    if (q.size() < dimension || u.size() < dimension || m.size() < dimension) return s;
    const auto add = [&](int i) {
        const Vec2 x = q.segment<2>(i), v = u.segment<2>(i);
        s.momentum += m[i] * v;
        s.massMoment += m[i] * x;
        s.angularMomentum += m[i] * cross(x, v);
        s.mass += m[i];
    };
    for (int i = 0; i < paired; i += 2) add(i);
    for (int i = paired; i < dimension; i += 3) {
        add(i);
        s.angularMomentum += m[i + 2] * u[i + 2];
    }
    if (world.sleepingBodies() == 0) return s;
    // Bodies asleep are out of the state; their records hold their state.
    const auto addAsleep = [&](const Vec2& x, const Vec2& v, double mass) {
        s.momentum += mass * v;
        s.massMoment += mass * x;
        s.angularMomentum += mass * cross(x, v);
        s.mass += mass;
    };
    for (const Particle& p : world.particles())
        if (p.asleep) addAsleep(p.position, p.velocity, p.mass);
    for (const RigidBody& b : world.rigidBodies()) {
        if (!b.asleep) continue;
        addAsleep(b.position, b.velocity, b.mass);
        s.angularMomentum += b.inertia * b.angularVelocity;
    }
    return s;
}

std::string_view probeVocabulary() {
    return kVocabulary;
}

ProbeParse parseProbe(const World& world, std::string_view text) {
    const std::string_view t = trim(text);
    if (t.empty()) return refuse(text);
    const std::size_t open = t.find('(');
    if (open != std::string_view::npos && t.back() == ')') {
        std::optional<ProbeParse> instrument = parseInstrument(
            world, t, trim(t.substr(0, open)), t.substr(open + 1, t.size() - open - 2));
        if (instrument) return std::move(*instrument);
    }
    // ID.FIELD at the last dot: ids may hold dots, fields do not.
    const std::size_t dot = t.rfind('.');
    if (dot == std::string_view::npos) return refuse(t);
    const std::string_view id = t.substr(0, dot), field = t.substr(dot + 1);
    Probe probe;
    probe.text = std::string(t);
    // system.FIELD is the system's even in a scene with an object called "system" (its own
    // fields stay reachable where the names differ: system.x, system.omega).
    if (id == "system") {
        if (const std::optional<ProbeKind> kind = findField(kSystemFields, field)) {
            probe.kind = *kind;
            return ProbeParse{std::move(probe), {}};
        }
    }
    const std::optional<ProbeObject> object = findProbeObject(world, id);
    if (const int joint = findJoint(world, id); !object && joint >= 0 && field == "angle") {
        if (!measuresAngle(world.joints()[joint]))
            return refuse(t, quoted(id) +
                                 " is not a hinge, rod or rope: JOINT.angle is a "
                                 "pendulum's angle");
        probe.kind = ProbeKind::JointAngle;
        probe.joint = joint;
        return ProbeParse{std::move(probe), {}};
    }
    const std::optional<ProbeKind> kind = findField(kObjectFields, field);
    if (!kind) return refuse(t);
    if (!object) return refuse(t, "no object " + quoted(id));
    if (!object->rigid && (*kind == ProbeKind::Angle || *kind == ProbeKind::Omega))
        return refuse(t, quoted(id) + " is a particle: angle and omega are of rigid bodies");
    probe.kind = *kind;
    probe.objects[0] = *object;
    return ProbeParse{std::move(probe), {}};
}

double evaluateProbe(const World& world, const Probe& probe) {
    const EnergyLedger& e = world.energy();
    switch (probe.kind) {
        case ProbeKind::X:
            return probeObjectPosition(world, probe.objects[0]).x();
        case ProbeKind::Y:
            return probeObjectPosition(world, probe.objects[0]).y();
        case ProbeKind::Vx:
            return stateOf(world, probe.objects[0]).velocity.x();
        case ProbeKind::Vy:
            return stateOf(world, probe.objects[0]).velocity.y();
        case ProbeKind::Speed:
            return stateOf(world, probe.objects[0]).velocity.norm();
        case ProbeKind::Angle:
            return stateOf(world, probe.objects[0]).angle;
        case ProbeKind::Omega:
            return stateOf(world, probe.objects[0]).omega;
        case ProbeKind::Kinetic: {
            const ObjectState s = stateOf(world, probe.objects[0]);
            return 0.5 * s.mass * s.velocity.squaredNorm() + 0.5 * s.inertia * s.omega * s.omega;
        }
        case ProbeKind::Px: {
            const ObjectState s = stateOf(world, probe.objects[0]);
            return s.mass * s.velocity.x();
        }
        case ProbeKind::Py: {
            const ObjectState s = stateOf(world, probe.objects[0]);
            return s.mass * s.velocity.y();
        }
        case ProbeKind::AngularMomentum: {
            const ObjectState s = stateOf(world, probe.objects[0]);
            return s.mass * cross(s.position, s.velocity) + s.inertia * s.omega;
        }
        case ProbeKind::SystemKinetic:
            return e.kinetic;
        case ProbeKind::SystemPotential:
            return e.potential;
        case ProbeKind::SystemTotal:
            return e.kinetic + e.potential;
        case ProbeKind::SystemWorkNc:
            return e.workNc;
        case ProbeKind::SystemDrift:
            return e.drift;
        case ProbeKind::SystemCorrection:
            return e.correction;
        case ProbeKind::SystemPx:
            return systemMotion(world).momentum.x();
        case ProbeKind::SystemPy:
            return systemMotion(world).momentum.y();
        case ProbeKind::SystemAngularMomentum:
            return systemMotion(world).angularMomentum;
        case ProbeKind::SystemComX:
        case ProbeKind::SystemComY: {
            // 0 when nothing is dynamic: there is no centre of mass to follow.
            const std::optional<Vec2> com = systemMotion(world).centreOfMass();
            if (!com) return 0.0;
            return probe.kind == ProbeKind::SystemComX ? com->x() : com->y();
        }
        case ProbeKind::Distance:
            return (argumentPosition(world, probe, 1) - argumentPosition(world, probe, 0)).norm();
        case ProbeKind::AngleAt:
            return signedAngle(argumentPosition(world, probe, 0), argumentPosition(world, probe, 1),
                               argumentPosition(world, probe, 2));
        case ProbeKind::JointAngle:
            return jointAngle(world, probe.joint).value_or(0.0);
        case ProbeKind::JointForce: {
            const JointSolver* joints = world.jointSolver();
            if (!joints || probe.joint >= static_cast<int>(world.joints().size())) return 0.0;
            return joints->force(probe.joint);
        }
        case ProbeKind::ContactForce: {
            const ProbeObject& o = probe.objects[0];
            const int dof =
                o.rigid ? world.rigidBodies()[o.index].dof : world.particles()[o.index].dof;
            return dof < 0 ? 0.0 : world.contactForce(dof).norm();
        }
    }
    return 0.0;
}

// ---- listing the probes a world has ----------------------------------------------------------

std::vector<std::string> objectProbes(const World& world, std::string_view id) {
    std::vector<std::string> texts;
    const std::optional<ProbeObject> object = findProbeObject(world, id);
    if (!object) return texts;
    const std::string prefix = std::string(id) + '.';
    for (const Field& f : kObjectFields) {
        const bool turns = f.kind == ProbeKind::Angle || f.kind == ProbeKind::Omega;
        if (turns && !object->rigid) continue;
        texts.push_back(prefix + std::string(f.name));
    }
    const bool fixed = object->rigid ? world.rigidBodies()[object->index].isStatic
                                     : world.particles()[object->index].pinned;
    if (!fixed) texts.push_back("contact_force(" + std::string(id) + ')');
    return texts;
}

std::vector<std::string> listProbes(const World& world) {
    std::vector<std::string> texts;
    for (const Field& f : kSystemFields) texts.push_back("system." + std::string(f.name));
    const auto add = [&](const std::string& id) {
        const std::vector<std::string> fields = objectProbes(world, id);
        texts.insert(texts.end(), fields.begin(), fields.end());
    };
    for (const Particle& p : world.particles())
        if (p.cloth < 0) add(p.id);
    for (const RigidBody& b : world.rigidBodies()) add(b.id);
    for (const Joint& j : world.joints()) {
        const std::vector<std::string> fields = jointProbes(world, j.id);
        texts.insert(texts.end(), fields.begin(), fields.end());
    }
    return texts;
}

std::vector<std::string> jointProbes(const World& world, std::string_view id) {
    const int joint = findJoint(world, id);
    if (joint < 0) return {};
    std::vector<std::string> texts{"force(" + std::string(id) + ')'};
    if (measuresAngle(world.joints()[joint])) texts.push_back(std::string(id) + ".angle");
    return texts;
}

std::vector<double> upwardCrossings(std::span<const double> times, std::span<const double> values,
                                    double level) {
    std::vector<double> crossings;
    const std::size_t n = std::min(times.size(), values.size());
    for (std::size_t i = 1; i < n; ++i) {
        const double a = values[i - 1], b = values[i];
        if (!std::isfinite(a) || !std::isfinite(b) || !(a < level && b >= level)) continue;
        crossings.push_back(times[i - 1] + (level - a) / (b - a) * (times[i] - times[i - 1]));
    }
    return crossings;
}

// ---- PeriodTracker ----------------------------------------------------------------------

void PeriodTracker::Crossings::add(const Sample& a, const Sample& b, double level) {
    if (!(a.value < level && b.value >= level)) return;
    const double t = a.t + (level - a.value) / (b.value - a.value) * (b.t - a.t);
    if (count == 0) first = t;
    last = t;
    ++count;
}

PeriodTracker::PeriodTracker(std::size_t capacity) : capacity_(std::max<std::size_t>(capacity, 4)) {
    series_.reserve(capacity_ + 1);
}

void PeriodTracker::add(double t, double value) {
    if (!std::isfinite(value) || !std::isfinite(t)) return;
    const Sample sample{t, value};
    if (added_ == 0) {
        min_ = max_ = value;
    } else {
        min_ = std::min(min_, value);
        max_ = std::max(max_, value);
    }
    // Neumaier's compensated sum: a million steps of a slowly varying probe lose no digits.
    const double sum = sum_ + value;
    compensation_ +=
        std::abs(sum_) >= std::abs(value) ? (sum_ - sum) + value : (value - sum) + sum_;
    sum_ = sum;
    if (frozen_) {
        crossings_.add(last_, sample, level_);
        ++sinceFreeze_;
    }
    if (added_ % stride_ == 0) series_.push_back(sample);
    ++added_;
    last_ = sample;
    if (series_.size() > capacity_) {
        if (!frozen_) freeze();  // while the series is still complete: exact
        decimate();
    }
    if (frozen_) {
        const double mid = 0.5 * (min_ + max_);
        if (std::abs(mid - level_) > kLevelTolerance * (max_ - min_) &&
            sinceFreeze_ >= static_cast<long long>(capacity_ / 4))
            freeze();
    }
}

PeriodTracker::Crossings PeriodTracker::crossingsOfSeries(double level) const {
    Crossings c;
    for (std::size_t i = 1; i < series_.size(); ++i) c.add(series_[i - 1], series_[i], level);
    // The newest sample is not stored when the stride skips it.
    if (!series_.empty() && series_.back().t < last_.t) c.add(series_.back(), last_, level);
    return c;
}

void PeriodTracker::freeze() {
    level_ = 0.5 * (min_ + max_);
    crossings_ = crossingsOfSeries(level_);
    frozen_ = true;
    sinceFreeze_ = 0;
}

void PeriodTracker::decimate() {
    // Sample i is stored when i is a multiple of the stride, so keeping the even positions
    // keeps the multiples of twice the stride.
    std::size_t kept = 0;
    for (std::size_t i = 0; i < series_.size(); i += 2) series_[kept++] = series_[i];
    series_.resize(kept);
    stride_ *= 2;
}

ProbeSummary PeriodTracker::summary() const {
    ProbeSummary s;
    s.samples = added_;
    if (added_ == 0) return s;
    s.final = last_.value;
    s.min = min_;
    s.max = max_;
    s.mean = (sum_ + compensation_) / static_cast<double>(added_);
    const double mid = 0.5 * (min_ + max_);
    const bool useFrozen = frozen_ && std::abs(mid - level_) <= kLevelTolerance * (max_ - min_);
    const Crossings c = useFrozen ? crossings_ : crossingsOfSeries(mid);
    if (c.count >= 2) s.period = (c.last - c.first) / static_cast<double>(c.count - 1);
    return s;
}

}  // namespace phasebox
