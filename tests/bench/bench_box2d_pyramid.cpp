// bench_box2d_pyramid: the library's 20-, 40- and 100-row pyramids in Phasebox and in Box2D
// 2.4.1, timed in the same run, and how well each keeps them standing for 10 s.
//
// Box2D gets the very scene Phasebox gets: its boxes, sizes, masses, frictions, restitutions,
// gravity and ground are read from scenes::pyramid(rows) (ground plane → a two-sided edge
// wider than the base). Box2D runs at its defaults: dt = 1/60, 8 velocity and 3 position
// iterations, continuous collision on, single precision. Phasebox runs at the format's
// defaults: dt = 1/60, one step per frame, in which its contact solver takes 4 inner sub-steps
// of 3 soft iterations and 1 relax iteration, in double.
//
// Box2D puts resting bodies to sleep (after 0.5 s below its sleep tolerances), after which a
// settled pyramid costs almost nothing per step. Phasebox sleeps only when a scene asks for it
// (simulation.sleep, off by default; bench_sleeping measures it), and runs awake here. The
// ratio that compares the same work is therefore against Box2D with sleeping off; Box2D with
// sleeping on (its default) is shown beside it. "Box2D 24 it" runs 24 velocity iterations per step,
// as the velocity passes Phasebox makes (4 inner sub-steps × (3 + 1) = 16, and 24 when this was
// written), to separate the cost of an iteration from the number of iterations.
//
// The engines take turns inside each repeat, so a disturbance from another process hits all
// of them alike; the median then drops it.
//
//   bench_box2d_pyramid [--steps N] [--repeat N] [--json] [--quick] [--no-100]
//
// --quick runs the 20-row pyramid only; --no-100 leaves out the 100-row one (5,050 boxes, most
// of the run's time). With --json the table goes to stderr and stdout
// carries one JSON object.

#include "AllocationCounter.h"
#include "BenchCommon.h"

#include "physics/contacts/ContactSolver.h"
#include "physics/contacts/ContactStage.h"
#include "physics/scene/BuildWorld.h"
#include "physics/scene/SceneDesc.h"
#include "physics/scene/SceneLibrary.h"
#include "physics/world/World.h"

#include <box2d/box2d.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

namespace {

using namespace phasebox;
using namespace phasebox::bench;

constexpr int kDefaultSteps = 60;
constexpr int kDefaultRepeat = 7;
constexpr int kWarmup = 300;            // 5 s: settled, warm start primed
constexpr double kStandSeconds = 10.0;  // tst_contacts: every box within 5 cm after 10 s

// ---- Box2D, built from the scene description ----------------------------------------------

struct Box2dOptions {
    bool allowSleeping = false;
    int velocityIterations = 8;  // Box2D 2.4's documented defaults
    int positionIterations = 3;
};

b2Vec2 toB2(double x, double y) {
    return b2Vec2(static_cast<float>(x), static_cast<float>(y));
}

// Box2D's rows and columns: 1 m boxes at its resting gap (Box2dWorld).
constexpr double kBox2dPitch = 1.0 + (2.0 * b2_polygonRadius - b2_linearSlop);

class Box2dWorld {
public:
    Box2dWorld(const SceneDesc& scene, const Box2dOptions& options)
        : options_(options), dt_(static_cast<float>(scene.simulation.dt)) {
        const Point2 g = scene.effects.gravity ? scene.effects.gravity->g : Point2{0.0, 0.0};
        world_ = std::make_unique<b2World>(toB2(g[0], g[1]));
        world_->SetAllowSleeping(options.allowSleeping);

        // The ground plane as a two-sided edge, far wider than any pyramid's base.
        b2BodyDef groundDef;
        b2Body* ground = world_->CreateBody(&groundDef);
        for (const PlaneDesc& plane : scene.planes) {
            const b2Vec2 point = toB2(plane.point[0], plane.point[1]);
            const b2Vec2 along = toB2(plane.normal[1], -plane.normal[0]);
            b2EdgeShape edge;
            edge.SetTwoSided(point - 1000.0f * along, point + 1000.0f * along);
            b2FixtureDef fixture;
            fixture.shape = &edge;
            fixture.friction = static_cast<float>(plane.friction);
            fixture.restitution = static_cast<float>(plane.restitution);
            ground->CreateFixture(&fixture);
        }
        // Box2D 2.4's polygons carry a skin (b2_polygonRadius each) and its solver rests them
        // b2_linearSlop into each other: boxes set touching are pushed 1.5 cm apart, its pyramid
        // spreads, and its step pays for that for hundreds of steps (the 40-row one 1.71 ms a step
        // against 1.43 ms set apart). Set at its resting gap (the centres spread about the
        // ground's origin), as ../shared/peers' harness sets them, so that the ratio compares the
        // two engines holding the same standing pyramid.
        const double pitch = kBox2dPitch;
        for (const BoxDesc& box : scene.boxes) {
            b2BodyDef def;
            def.type = box.isStatic ? b2_staticBody : b2_dynamicBody;
            def.position = toB2(pitch * box.position[0], pitch * box.position[1]);
            def.angle = static_cast<float>(box.angle);
            b2Body* body = world_->CreateBody(&def);
            b2PolygonShape shape;
            const b2Vec2 half = toB2(0.5 * box.size[0], 0.5 * box.size[1]);
            shape.SetAsBox(half.x, half.y);
            b2FixtureDef fixture;
            fixture.shape = &shape;
            // Box2D wants a density: the scene's mass spread over the box's area.
            fixture.density = static_cast<float>(box.resolvedMass() / (box.size[0] * box.size[1]));
            fixture.friction = static_cast<float>(box.friction);
            fixture.restitution = static_cast<float>(box.restitution);
            body->CreateFixture(&fixture);
            bodies_.push_back(body);
        }
    }

    void step() { world_->Step(dt_, options_.velocityIterations, options_.positionIterations); }
    const b2Profile& profile() const { return world_->GetProfile(); }

    Point2 position(int i) const {
        const b2Vec2 p = bodies_[static_cast<std::size_t>(i)]->GetPosition();
        return {p.x, p.y};
    }
    double angle(int i) const { return bodies_[static_cast<std::size_t>(i)]->GetAngle(); }
    int bodyCount() const { return static_cast<int>(bodies_.size()); }
    int awakeCount() const {
        return static_cast<int>(std::count_if(bodies_.begin(), bodies_.end(),
                                              [](const b2Body* b) { return b->IsAwake(); }));
    }
    // Touching contacts and their manifold points (Box2D also keeps contacts whose fattened
    // bounds overlap but whose shapes do not touch; those are not counted).
    void contactCounts(long long& pairs, long long& points) const {
        pairs = points = 0;
        for (const b2Contact* c = world_->GetContactList(); c; c = c->GetNext()) {
            if (!c->IsTouching()) continue;
            ++pairs;
            points += c->GetManifold()->pointCount;
        }
    }

private:
    Box2dOptions options_;
    float dt_;
    std::unique_ptr<b2World> world_;
    std::vector<b2Body*> bodies_;
};

// ---- the same questions asked of either engine ---------------------------------------------

// Positions and angles of the dynamic boxes, in scene order.
struct Pose {
    std::vector<Point2> position;
    std::vector<double> angle;
};

Pose poseOf(const World& world) {
    Pose pose;
    for (int i = 0; i < static_cast<int>(world.rigidBodies().size()); ++i) {
        const Vec2 p = world.bodyPosition(i);
        pose.position.push_back({p.x(), p.y()});
        pose.angle.push_back(world.bodyAngle(i));
    }
    return pose;
}

Pose poseOf(const Box2dWorld& world) {
    Pose pose;
    for (int i = 0; i < world.bodyCount(); ++i) {
        pose.position.push_back(world.position(i));
        pose.angle.push_back(world.angle(i));
    }
    return pose;
}

// Box2D 2.4's polygons carry a skin (b2_polygonRadius = 0.01 m each) and its solvers stop
// at b2_linearSlop (0.005 m) of overlap, so touching boxes are pushed apart until their cores
// are ~0.015 m apart: a pyramid set up with touching boxes spreads sideways and rises as it
// settles, symmetrically. The displacement alone cannot tell that from a collapse; the lean
// (how far a row's centre moved sideways) and the tilt can, since the spreading moves neither.
struct Standing {
    double displacement = 0.0;  // largest |Δp| from the setup position (tst_contacts' measure)
    double sideways = 0.0;      // largest |Δx| from the setup position
    double lean = 0.0;          // largest sideways shift of a row's mean x
    double tilt = 0.0;          // largest |angle| at the end
    double topRise = 0.0;       // Δy of the top box (settling into or out of the contacts)
};

Standing standing(const Pose& setup, const Pose& end, double pitch) {
    Standing s;
    std::vector<double> rowShift, rowCount;
    for (std::size_t i = 0; i < setup.position.size(); ++i) {
        const double dx = end.position[i][0] - setup.position[i][0];
        const double dy = end.position[i][1] - setup.position[i][1];
        s.displacement = std::max(s.displacement, std::hypot(dx, dy));
        s.sideways = std::max(s.sideways, std::abs(dx));
        s.tilt = std::max(s.tilt, std::abs(end.angle[i]));
        // Rows by setup height (row r's boxes stand at (0.5 + r)·pitch).
        const long rowIndex = std::max(0L, std::lround(setup.position[i][1] / pitch - 0.5));
        const auto row = static_cast<std::size_t>(rowIndex);
        if (row >= rowShift.size()) {
            rowShift.resize(row + 1, 0.0);
            rowCount.resize(row + 1, 0.0);
        }
        rowShift[row] += dx;
        rowCount[row] += 1.0;
    }
    for (std::size_t r = 0; r < rowShift.size(); ++r)
        if (rowCount[r] > 0.0) s.lean = std::max(s.lean, std::abs(rowShift[r] / rowCount[r]));
    // The scene lists boxes row by row, so the last is the top.
    s.topRise = end.position.back()[1] - setup.position.back()[1];
    return s;
}

// Steps a fresh world for kStandSeconds and reports how well the pyramid stood, from where
// the engine set it up.
template <class Engine>
Standing standFor10s(Engine& engine, double dt, double pitch, long long& failed) {
    const Pose setup = poseOf(engine.world());
    const int total = static_cast<int>(std::lround(kStandSeconds / dt));
    for (int k = 0; k < total; ++k)
        if (!engine.step()) ++failed;
    return standing(setup, poseOf(engine.world()), pitch);
}

// Uniform handles on the two engines, for the loops above and the timing below.
struct PhaseboxEngine {
    std::unique_ptr<World> w;
    // One worker unless told (the ratios to Box2D are of one thread each).
    explicit PhaseboxEngine(const SceneDesc& scene, int workers = 1) : w(buildWorld(scene).world) {
        w->setWorkers(workers);
    }
    bool step() { return w->step(); }
    const World& world() const { return *w; }
};

struct Box2dEngine {
    Box2dWorld w;
    Box2dEngine(const SceneDesc& scene, const Box2dOptions& options) : w(scene, options) {}
    bool step() {
        w.step();
        return true;
    }
    const Box2dWorld& world() const { return w; }
};

// ---- measuring ----------------------------------------------------------------------------

enum Candidate { kPhasebox, kBox2d, kBox2d24, kBox2dSleeping, kPhaseboxTwo, kCandidates };
constexpr const char* kCandidateLabel[kCandidates] = {
    "Phasebox (format defaults, 1 worker)",
    "Box2D 2.4.1, 8 vel + 3 pos it, no sleeping",
    "Box2D 2.4.1, 24 vel + 3 pos it, no sleeping",
    "Box2D 2.4.1, 8 + 3, sleeping on (its default)",
    "Phasebox, 2 workers",
};
constexpr const char* kCandidateKey[kCandidates] = {"phasebox", "box2d", "box2d_24_iterations",
                                                    "box2d_sleeping", "phasebox_2_workers"};
bool isPhasebox(int c) {
    return c == kPhasebox || c == kPhaseboxTwo;
}

struct Timing {
    double msPerStep = 0.0;  // median over repeats
    AllocationCounts allocations;
    long long timedSteps = 0;
    long long pairs = 0, points = 0;  // touching contacts after the timed steps
    // Box2D's own profile (ms per step, median): collide = narrow phase, solve = islands.
    double collideMs = 0.0, solveMs = 0.0, broadphaseMs = 0.0, toiMs = 0.0;
    double contactShare = 0.0;  // Phasebox: its "contacts" profile entry over the wall time
    int awake = 0;              // Box2D: awake bodies at the end
};

struct PyramidResult {
    int rows = 0;
    int boxes = 0;
    Timing timing[kCandidates];
    Standing stand[3];  // Phasebox, Box2D no sleeping, Box2D sleeping
    long long failedSteps = 0;
};

double contactSeconds(const World& world) {
    for (const EffectCost& cost : world.effectCosts())
        if (cost.name == "contacts") return cost.seconds;
    return 0.0;
}

PyramidResult measure(int rows, int steps, int repeat) {
    PyramidResult result;
    result.rows = rows;
    const SceneDesc scene = scenes::pyramid(rows);
    result.boxes = static_cast<int>(scene.boxes.size());
    const double dt = scene.simulation.dt;

    // How well each keeps the pyramid standing, each from a fresh world.
    {
        PhaseboxEngine phasebox(scene);
        result.stand[0] = standFor10s(phasebox, dt, 1.0, result.failedSteps);
        Box2dEngine awake(scene, {false, 8, 3});
        result.stand[1] = standFor10s(awake, dt, kBox2dPitch, result.failedSteps);
        Box2dEngine sleeping(scene, {true, 8, 3});
        result.stand[2] = standFor10s(sleeping, dt, kBox2dPitch, result.failedSteps);
    }

    PhaseboxEngine phasebox(scene);
    PhaseboxEngine phaseboxTwo(scene, 2);
    PhaseboxEngine* phaseboxes[kCandidates] = {&phasebox, nullptr, nullptr, nullptr, &phaseboxTwo};
    Box2dEngine box2d(scene, {false, 8, 3});
    Box2dEngine box2d24(scene, {false, 24, 3});
    Box2dEngine box2dSleeping(scene, {true, 8, 3});
    Box2dEngine* box2ds[kCandidates] = {nullptr, &box2d, &box2d24, &box2dSleeping, nullptr};
    for (int k = 0; k < kWarmup; ++k) {
        if (!phasebox.step()) ++result.failedSteps;
        phaseboxTwo.step();
        for (Box2dEngine* b : box2ds)
            if (b) b->step();
    }

    std::vector<double> ms[kCandidates], share, collide, solve, broadphase, toi;
    for (int r = 0; r < repeat; ++r) {
        for (int c = 0; c < kCandidates; ++c) {
            Timing& t = result.timing[c];
            double b2Collide = 0.0, b2Solve = 0.0, b2Broadphase = 0.0, b2Toi = 0.0;
            if (isPhasebox(c)) phaseboxes[c]->w->resetProfile();
            startCountingAllocations();
            const auto start = Clock::now();
            if (isPhasebox(c)) {
                for (int s = 0; s < steps; ++s)
                    if (!phaseboxes[c]->step()) ++result.failedSteps;
            } else {
                for (int s = 0; s < steps; ++s) {
                    box2ds[c]->step();
                    const b2Profile& p = box2ds[c]->w.profile();
                    b2Collide += p.collide;
                    b2Solve += p.solve;
                    b2Broadphase += p.broadphase;
                    b2Toi += p.solveTOI;
                }
            }
            const double wall = secondsBetween(start, Clock::now());
            const AllocationCounts counts = stopCountingAllocations();
            t.allocations.operatorNew += counts.operatorNew;
            t.allocations.malloc += counts.malloc;
            t.timedSteps += steps;
            ms[c].push_back(1e3 * wall / steps);
            if (c == kPhasebox) share.push_back(contactSeconds(*phasebox.w) / wall);
            if (c == kBox2d) {
                collide.push_back(b2Collide / steps);
                solve.push_back(b2Solve / steps);
                broadphase.push_back(b2Broadphase / steps);
                toi.push_back(b2Toi / steps);
            }
        }
    }
    for (int c = 0; c < kCandidates; ++c) result.timing[c].msPerStep = median(ms[c]);
    Timing& p = result.timing[kPhasebox];
    p.contactShare = median(share);
    p.pairs = static_cast<long long>(phasebox.w->contacts()->contacts().size());
    p.points = phasebox.w->contacts()->pointCount();
    Timing& b = result.timing[kBox2d];
    b.collideMs = median(collide);
    b.solveMs = median(solve);
    b.broadphaseMs = median(broadphase);
    b.toiMs = median(toi);
    Timing& two = result.timing[kPhaseboxTwo];
    two.pairs = static_cast<long long>(phaseboxTwo.w->contacts()->contacts().size());
    two.points = phaseboxTwo.w->contacts()->pointCount();
    for (int c = kBox2d; c <= kBox2dSleeping; ++c) {
        box2ds[c]->w.contactCounts(result.timing[c].pairs, result.timing[c].points);
        result.timing[c].awake = box2ds[c]->w.awakeCount();
    }
    return result;
}

// ---- reporting ----------------------------------------------------------------------------

const char* instructionSetName() {
    static const char* const names[] = {"no SIMD (rows one by one)", "AVX2", "AVX-512"};
    return names[ContactSolver::instructions()];
}

void printTable(std::FILE* out, const std::vector<PyramidResult>& results, int steps, int repeat) {
    std::fprintf(out,
                 "bench_box2d_pyramid: scenes::pyramid(rows), dt = 1/60, after %d warm-up "
                 "steps; %d steps x %d repeats (median); Phasebox's contact rows on %s\n",
                 kWarmup, steps, repeat, instructionSetName());
    for (const PyramidResult& r : results) {
        std::fprintf(out, "\n%d rows (%d boxes)%32s%12s%12s%12s\n", r.rows, r.boxes, "ms/step",
                     "contacts", "points", "allocs/step");
        for (int c = 0; c < kCandidates; ++c) {
            const Timing& t = r.timing[c];
            std::fprintf(out, "  %-46s%10.3f%12lld%12lld%12.2f\n", kCandidateLabel[c], t.msPerStep,
                         t.pairs, t.points, double(t.allocations.total()) / t.timedSteps);
        }
        const Timing& p = r.timing[kPhasebox];
        const Timing& b = r.timing[kBox2d];
        std::fprintf(out, "  Phasebox contact share of the step           %9.1f%%\n",
                     100.0 * p.contactShare);
        std::fprintf(out,
                     "  Box2D profile, ms/step: collide %.3f, solve %.3f (of which broad phase "
                     "%.3f), TOI %.3f\n",
                     b.collideMs, b.solveMs, b.broadphaseMs, b.toiMs);
        std::fprintf(out, "  Box2D awake bodies at the end: no sleeping %d, sleeping on %d\n",
                     r.timing[kBox2d].awake, r.timing[kBox2dSleeping].awake);
        std::fprintf(out, "  ratio Phasebox / Box2D (no sleeping, 8 + 3) %10.2fx\n",
                     p.msPerStep / b.msPerStep);
        std::fprintf(out, "  ratio Phasebox / Box2D (24 velocity it)      %10.2fx\n",
                     p.msPerStep / r.timing[kBox2d24].msPerStep);
        std::fprintf(out, "  ratio Phasebox / Box2D (sleeping on)         %10.2fx\n",
                     p.msPerStep / r.timing[kBox2dSleeping].msPerStep);
        std::fprintf(out, "  ratio Phasebox 2 workers / 1 worker          %10.2fx\n",
                     r.timing[kPhaseboxTwo].msPerStep / p.msPerStep);
        std::fprintf(out,
                     "\n  after %.0f s from rest, metres (radians for tilt)%9s%10s%10s%10s%10s\n",
                     kStandSeconds, "|dp|max", "|dx|max", "lean", "tilt", "top dy");
        const char* labels[3] = {"Phasebox", "Box2D, no sleeping", "Box2D, sleeping on"};
        for (int k = 0; k < 3; ++k) {
            const Standing& s = r.stand[k];
            std::fprintf(out, "  %-48s%10.4f%10.4f%10.4f%10.4f%10.4f\n", labels[k], s.displacement,
                         s.sideways, s.lean, s.tilt, s.topRise);
        }
        if (r.failedSteps)
            std::fprintf(out, "  Phasebox steps that diverged: %lld\n", r.failedSteps);
    }
    std::fprintf(out,
                 "\n|dp|max is tst_contacts' measure (Phasebox must stay within 0.05 m). lean = "
                 "largest sideways shift of a row's\nmean x. Box2D's boxes are set 0.015 m apart "
                 "(its polygons' skins less its slop, as ../shared/peers'\nharness sets them), "
                 "and its displacements are measured from there.\n");
}

std::string toJson(const std::vector<PyramidResult>& results, int steps, int repeat) {
    Json json;
    json.beginObject();
    json.value("benchmark", "box2d_pyramid");
    json.value("warmup_steps", kWarmup);
    json.value("steps", steps);
    json.value("repeat", repeat);
    json.value("contact_instructions", instructionSetName());
    json.value("statistic", "median");
    json.value("unit", "ms_per_step");
    json.beginArray("pyramids");
    for (const PyramidResult& r : results) {
        json.beginObject();
        json.value("rows", r.rows);
        json.value("boxes", r.boxes);
        for (int c = 0; c < kCandidates; ++c) {
            const Timing& t = r.timing[c];
            json.beginObject(kCandidateKey[c]);
            json.value("ms_per_step", t.msPerStep);
            json.value("contacts", t.pairs);
            json.value("points", t.points);
            json.value("allocations_per_step", double(t.allocations.total()) / t.timedSteps);
            if (c == kPhasebox) json.value("contact_share", t.contactShare);
            if (c == kBox2d) {
                json.value("collide_ms", t.collideMs);
                json.value("solve_ms", t.solveMs);
                json.value("broadphase_ms", t.broadphaseMs);
                json.value("toi_ms", t.toiMs);
            }
            if (!isPhasebox(c)) json.value("awake_bodies", t.awake);
            json.endObject();
        }
        json.value("ratio_phasebox_box2d",
                   r.timing[kPhasebox].msPerStep / r.timing[kBox2d].msPerStep);
        json.value("ratio_phasebox_box2d_24_iterations",
                   r.timing[kPhasebox].msPerStep / r.timing[kBox2d24].msPerStep);
        json.value("ratio_phasebox_box2d_sleeping",
                   r.timing[kPhasebox].msPerStep / r.timing[kBox2dSleeping].msPerStep);
        json.value("ratio_phasebox_2_workers_1_worker",
                   r.timing[kPhaseboxTwo].msPerStep / r.timing[kPhasebox].msPerStep);
        const char* keys[3] = {"stand_phasebox", "stand_box2d", "stand_box2d_sleeping"};
        for (int k = 0; k < 3; ++k) {
            const Standing& s = r.stand[k];
            json.beginObject(keys[k]);
            json.value("seconds", kStandSeconds);
            json.value("largest_displacement", s.displacement);
            json.value("largest_sideways", s.sideways);
            json.value("largest_row_lean", s.lean);
            json.value("largest_tilt", s.tilt);
            json.value("top_rise", s.topRise);
            json.endObject();
        }
        json.value("failed_steps", r.failedSteps);
        json.endObject();
    }
    json.endArray();
    json.endObject();
    return json.str();
}

}  // namespace

int main(int argc, char** argv) {
    const Options options =
        parseOptions(argc, argv, "[--steps N] [--repeat N] [--json] [--quick] [--no-100]",
                     {"--quick", "--no-100"});
    const int steps = options.steps ? options.steps : kDefaultSteps;
    const int repeat = options.repeat ? options.repeat : (options.quick ? 3 : kDefaultRepeat);
    std::vector<int> rows{20, 40, 100};
    if (options.has("--no-100")) rows.resize(2);
    if (options.quick) rows.resize(1);

    std::vector<PyramidResult> results;
    for (const int r : rows) results.push_back(measure(r, steps, repeat));

    printTable(options.json ? stderr : stdout, results, steps, repeat);
    if (options.json) std::printf("%s\n", toJson(results, steps, repeat).c_str());
    return 0;
}
