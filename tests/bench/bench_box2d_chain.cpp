// bench_box2d_chain: a chain of 100 hinged boxes swinging down from the horizontal in Phasebox
// and in Box2D 2.4.1, timed in the same run, and how far each lets its hinges come apart
// (issue 17, item 6).
//
// The chain: N = 100 boxes of 0.5 m × 0.125 m (density 20, friction 0.2) laid end to end along
// y = 25 m, box i centred at x = 0.25 + 0.5·i, each hinged to the next at their shared end and
// the first hinged to the fixed world at x = 0. Released from rest under g = (0, −9.81) it
// swings down and whips; 10 s = 600 steps of 1/60 s. Nothing else is in the scene; boxes that
// are not neighbours in the chain may touch as it folds.
//
// Phasebox gets the chain as a SceneDesc at the format's defaults (symplectic_euler,
// dt = 1/60, one sub-step; its joints take sub-steps of their own where a link turns fast).
// Box2D gets the same geometry as bodies and b2RevoluteJoints (collideConnected false) at its
// defaults: 8 velocity and 3 position iterations, continuous collision on, single precision.
// Box2D's sleeping hardly matters for a chain that never comes to rest, but the ratio that
// compares the same work is against Box2D with sleeping off; sleeping on (its default) is
// shown beside it. At 8 velocity iterations Box2D 2.4.1 lets this chain come apart in the
// whip (its hinges open by metres from t ≈ 3.5 s on; the links never touch, so that is its
// joint solver alone); "Box2D 24 it" runs 24 velocity iterations, as the pyramid bench does,
// at which it holds the chain, to show what holding it costs.
//
// Each repeat rebuilds every world outside the timed region and times the full 600-step swing
// from rest; the engines take turns inside each repeat, so a disturbance from another process
// hits them alike, and the median drops it. The hinge gaps are measured in a separate,
// untimed run of each engine (the runs are deterministic: the timed runs end in the very same
// state, which is checked): for Phasebox World::jointErrors().position after each step, for
// Box2D |GetAnchorA() − GetAnchorB()| over all joints after each step.
//
//   bench_box2d_chain [--steps N] [--repeat N] [--json] [--quick]
//
// --steps shortens or lengthens the swing (default 600), --quick runs one repeat. With --json
// the table goes to stderr and stdout carries one JSON object.

#include "AllocationCounter.h"
#include "BenchCommon.h"

#include "physics/contacts/ContactStage.h"
#include "physics/scene/BuildWorld.h"
#include "physics/scene/SceneDesc.h"
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

constexpr int kLinks = 100;
constexpr double kLinkLength = 0.5;
constexpr double kLinkHeight = 0.125;
constexpr double kDensity = 20.0;
constexpr double kFriction = 0.2;
constexpr double kHeight = 25.0;  // y of the chain at rest
constexpr double kGravity = -9.81;
constexpr double kDt = 1.0 / 60.0;
constexpr int kDefaultSteps = 600;  // 10 s
constexpr int kDefaultRepeat = 5;

// ---- Phasebox -----------------------------------------------------------------------------

std::string linkId(int i) {
    std::string id(1, 'b');
    id += std::to_string(i);
    return id;
}

SceneDesc chainScene() {
    SceneDesc scene;
    scene.name = "box2d_chain";
    scene.simulation.dt = kDt;  // the format's default, said aloud
    scene.effects.gravity = GravityDesc{{0.0, kGravity}};
    for (int i = 0; i < kLinks; ++i) {
        BoxDesc box;
        box.id = linkId(i);
        box.position = {0.5 * kLinkLength + kLinkLength * i, kHeight};
        box.size = {kLinkLength, kLinkHeight};
        box.density = kDensity;
        box.friction = kFriction;
        scene.boxes.push_back(box);

        JointDesc hinge;
        hinge.type = JointType::Hinge;
        hinge.a = i == 0 ? box.id : linkId(i - 1);
        if (i > 0) hinge.b = box.id;  // the first link's hinge holds it to the world
        hinge.anchor = Point2{kLinkLength * i, kHeight};
        scene.joints.push_back(hinge);
    }
    return scene;
}

// ---- Box2D, the same chain ----------------------------------------------------------------

b2Vec2 toB2(double x, double y) {
    return b2Vec2(static_cast<float>(x), static_cast<float>(y));
}

struct Box2dOptions {
    bool allowSleeping = false;
    int velocityIterations = 8;  // Box2D 2.4's documented defaults
    int positionIterations = 3;
};

class Box2dChain {
public:
    explicit Box2dChain(const Box2dOptions& options)
        : options_(options), world_(toB2(0.0, kGravity)) {
        world_.SetAllowSleeping(options.allowSleeping);
        b2BodyDef groundDef;
        b2Body* previous = world_.CreateBody(&groundDef);
        b2PolygonShape shape;
        shape.SetAsBox(static_cast<float>(0.5 * kLinkLength),
                       static_cast<float>(0.5 * kLinkHeight));
        for (int i = 0; i < kLinks; ++i) {
            b2BodyDef def;
            def.type = b2_dynamicBody;
            def.position = toB2(0.5 * kLinkLength + kLinkLength * i, kHeight);
            b2Body* body = world_.CreateBody(&def);
            b2FixtureDef fixture;
            fixture.shape = &shape;
            fixture.density = static_cast<float>(kDensity);
            fixture.friction = static_cast<float>(kFriction);
            body->CreateFixture(&fixture);
            bodies_.push_back(body);

            b2RevoluteJointDef hinge;
            hinge.Initialize(previous, body, toB2(kLinkLength * i, kHeight));
            hinge.collideConnected = false;
            joints_.push_back(world_.CreateJoint(&hinge));
            previous = body;
        }
    }

    void step() {
        world_.Step(static_cast<float>(kDt), options_.velocityIterations,
                    options_.positionIterations);
    }
    const b2Profile& profile() const { return world_.GetProfile(); }

    // The largest distance between a joint's two anchor points (m).
    double largestGap() const {
        double gap = 0.0;
        for (const b2Joint* joint : joints_)
            gap = std::max(gap, double((joint->GetAnchorA() - joint->GetAnchorB()).Length()));
        return gap;
    }
    Point2 position(int i) const {
        const b2Vec2 p = bodies_[static_cast<std::size_t>(i)]->GetPosition();
        return {p.x, p.y};
    }
    double angle(int i) const { return bodies_[static_cast<std::size_t>(i)]->GetAngle(); }
    // Touching contacts (Box2D also keeps contacts whose fattened bounds overlap but whose
    // shapes do not touch; those are not counted).
    int touchingContacts() const {
        int pairs = 0;
        for (const b2Contact* c = world_.GetContactList(); c; c = c->GetNext())
            if (c->IsTouching()) ++pairs;
        return pairs;
    }
    int awakeCount() const {
        return static_cast<int>(std::count_if(bodies_.begin(), bodies_.end(),
                                              [](const b2Body* b) { return b->IsAwake(); }));
    }

private:
    Box2dOptions options_;
    b2World world_;
    std::vector<b2Body*> bodies_;
    std::vector<b2Joint*> joints_;
};

// ---- the same questions asked of either engine ---------------------------------------------

// Uniform handles on the two engines, for the runs below.
struct PhaseboxEngine {
    std::unique_ptr<World> w;
    long long failedSteps = 0;
    // One worker: the ratios to Box2D are of one thread each.
    explicit PhaseboxEngine(const SceneDesc& scene) : w(buildWorld(scene).world) {
        w->setWorkers(1);
    }
    void step() {
        if (!w->step()) ++failedSteps;
    }
    double largestGap() const { return w->jointErrors().position; }
    // The contact solver's pairs: touching ones and those within its speculative margin.
    int contactPairs() const {
        return w->contacts() ? static_cast<int>(w->contacts()->contacts().size()) : 0;
    }
    Point2 position(int i) const {
        const Vec2 p = w->bodyPosition(i);
        return {p.x(), p.y()};
    }
    double angle(int i) const { return w->bodyAngle(i); }
};

struct Box2dEngine {
    Box2dChain w;
    explicit Box2dEngine(const Box2dOptions& options) : w(options) {}
    void step() { w.step(); }
    double largestGap() const { return w.largestGap(); }
    int contactPairs() const { return w.touchingContacts(); }
    Point2 position(int i) const { return w.position(i); }
    double angle(int i) const { return w.angle(i); }
};

// Positions and angles of the links at the end of a run, to check that the timed runs took
// the same course as the measured one.
struct Pose {
    std::vector<double> values;
    bool operator==(const Pose&) const = default;
};

template <class Engine>
Pose poseOf(const Engine& engine) {
    Pose pose;
    for (int i = 0; i < kLinks; ++i) {
        const Point2 p = engine.position(i);
        pose.values.insert(pose.values.end(), {p[0], p[1], engine.angle(i)});
    }
    return pose;
}

struct Swing {
    double maxGap = 0.0;     // largest hinge gap after any step (m)
    double finalGap = 0.0;   // after the last step (m)
    double tornAt = -1.0;    // time the largest gap first exceeded a link's length (s); −1 never
    double tipLowest = 0.0;  // lowest y the free end's centre reached (m); ~ −25 hanging
    int mostContacts = 0;    // contact pairs after any step (see contactPairs())
    long long firstStepAllocations = 0;
    long long laterAllocations = 0;  // in steps 2…n
    Pose end;
};

// Runs a fresh engine through the swing, asking after every step; the allocations are those
// of the steps alone.
template <class Engine>
Swing swing(Engine& engine, int steps) {
    Swing s;
    s.tipLowest = engine.position(kLinks - 1)[1];
    for (int k = 0; k < steps; ++k) {
        startCountingAllocations();
        engine.step();
        (k == 0 ? s.firstStepAllocations : s.laterAllocations) += stopCountingAllocations().total();
        const double gap = engine.largestGap();
        s.maxGap = std::max(s.maxGap, gap);
        if (gap > kLinkLength && s.tornAt < 0.0) s.tornAt = (k + 1) * kDt;
        s.tipLowest = std::min(s.tipLowest, engine.position(kLinks - 1)[1]);
        s.mostContacts = std::max(s.mostContacts, engine.contactPairs());
    }
    s.finalGap = engine.largestGap();
    s.end = poseOf(engine);
    return s;
}

// ---- measuring ----------------------------------------------------------------------------

enum Candidate { kPhasebox, kBox2d, kBox2d24, kBox2dSleeping, kCandidates };
constexpr Box2dOptions kBox2dOptions[kCandidates] = {
    {}, {false, 8, 3}, {false, 24, 3}, {true, 8, 3}};
constexpr const char* kCandidateLabel[kCandidates] = {
    "Phasebox (format defaults, 1 step)",
    "Box2D 2.4.1, 8 vel + 3 pos it, no sleeping",
    "Box2D 2.4.1, 24 vel + 3 pos it, no sleeping",
    "Box2D 2.4.1, 8 + 3, sleeping on (its default)",
};

struct Timing {
    double msPerStep = 0.0;  // median over repeats
    AllocationCounts allocations;
    long long timedSteps = 0;
    bool sameCourse = true;  // every timed run ended where the measured run did
    // Phasebox: its stages, ms per step (median). Box2D: its profile, ms per step (median).
    double stageMs[StepProfile::kStageCount] = {};
    double collideMs = 0.0, solveMs = 0.0, toiMs = 0.0;
    int awake = 0;  // Box2D: awake bodies at the end of the last timed run
};

struct ChainResult {
    int steps = 0;
    int repeat = 0;
    Timing timing[kCandidates];
    Swing swing[kCandidates];
    long long failedSteps = 0;  // Phasebox steps that diverged, over all runs
};

ChainResult measure(int steps, int repeat) {
    ChainResult result;
    result.steps = steps;
    result.repeat = repeat;
    const SceneDesc scene = chainScene();

    // The hinge gaps, each engine from rest, untimed.
    {
        PhaseboxEngine phasebox(scene);
        result.swing[kPhasebox] = swing(phasebox, steps);
        result.failedSteps += phasebox.failedSteps;
        for (int c = kBox2d; c < kCandidates; ++c) {
            Box2dEngine box2d(kBox2dOptions[c]);
            result.swing[c] = swing(box2d, steps);
        }
    }

    std::vector<double> ms[kCandidates], stage[StepProfile::kStageCount], collide, solve, toi;
    for (int r = 0; r < repeat; ++r) {
        for (int c = 0; c < kCandidates; ++c) {
            Timing& t = result.timing[c];
            // A fresh world from rest, built outside the timed region.
            std::unique_ptr<PhaseboxEngine> phasebox;
            std::unique_ptr<Box2dEngine> box2d;
            if (c == kPhasebox) {
                phasebox = std::make_unique<PhaseboxEngine>(scene);
                phasebox->w->resetProfile();
            } else {
                box2d = std::make_unique<Box2dEngine>(kBox2dOptions[c]);
            }
            double b2Collide = 0.0, b2Solve = 0.0, b2Toi = 0.0;
            startCountingAllocations();
            const auto start = Clock::now();
            if (c == kPhasebox) {
                for (int s = 0; s < steps; ++s) phasebox->step();
            } else {
                for (int s = 0; s < steps; ++s) {
                    box2d->step();
                    const b2Profile& p = box2d->w.profile();
                    b2Collide += p.collide;
                    b2Solve += p.solve;
                    b2Toi += p.solveTOI;
                }
            }
            const double wall = secondsBetween(start, Clock::now());
            const AllocationCounts counts = stopCountingAllocations();
            t.allocations.operatorNew += counts.operatorNew;
            t.allocations.malloc += counts.malloc;
            t.timedSteps += steps;
            ms[c].push_back(1e3 * wall / steps);
            if (c == kPhasebox) {
                result.failedSteps += phasebox->failedSteps;
                const StepProfile& profile = phasebox->w->stepProfile();
                for (int i = 0; i < StepProfile::kStageCount; ++i)
                    stage[i].push_back(profile.msPerStep(i));
                t.sameCourse = t.sameCourse && poseOf(*phasebox) == result.swing[c].end;
            } else {
                if (c == kBox2d) {
                    collide.push_back(b2Collide / steps);
                    solve.push_back(b2Solve / steps);
                    toi.push_back(b2Toi / steps);
                }
                t.awake = box2d->w.awakeCount();
                t.sameCourse = t.sameCourse && poseOf(*box2d) == result.swing[c].end;
            }
        }
    }
    for (int c = 0; c < kCandidates; ++c) result.timing[c].msPerStep = median(ms[c]);
    for (int i = 0; i < StepProfile::kStageCount; ++i)
        result.timing[kPhasebox].stageMs[i] = median(stage[i]);
    Timing& b = result.timing[kBox2d];
    b.collideMs = median(collide);
    b.solveMs = median(solve);
    b.toiMs = median(toi);
    return result;
}

double allocationsPerStep(const Timing& t) {
    return t.timedSteps ? double(t.allocations.total()) / double(t.timedSteps) : 0.0;
}

// ---- reporting ----------------------------------------------------------------------------

void printTable(std::FILE* out, const ChainResult& r) {
    std::fprintf(out,
                 "bench_box2d_chain: %d hinged boxes %.3g x %.3g m (density %g, friction %g) "
                 "from rest at y = %g m,\ng = 9.81, dt = 1/60; %d steps (%.3g s) from rest x %d "
                 "repeats (median)\n",
                 kLinks, kLinkLength, kLinkHeight, kDensity, kFriction, kHeight, r.steps,
                 r.steps * kDt, r.repeat);
    std::fprintf(out, "\n%-48s%10s%12s\n", "", "ms/step", "allocs/step");
    for (int c = 0; c < kCandidates; ++c) {
        const Timing& t = r.timing[c];
        std::fprintf(out, "  %-46s%10.3f%12.2f\n", kCandidateLabel[c], t.msPerStep,
                     allocationsPerStep(t));
    }
    const Timing& p = r.timing[kPhasebox];
    const Timing& b = r.timing[kBox2d];
    std::fprintf(out, "  Phasebox stages, ms/step:");
    for (int i = 0; i < StepProfile::kStageCount; ++i)
        std::fprintf(out, "%s %.*s %.3f", i ? "," : "",
                     static_cast<int>(StepProfile::kStageNames[i].size()),
                     StepProfile::kStageNames[i].data(), p.stageMs[i]);
    std::fprintf(out, "\n  Box2D profile (8 + 3), ms/step: collide %.3f, solve %.3f, TOI %.3f\n",
                 b.collideMs, b.solveMs, b.toiMs);
    std::fprintf(
        out, "  Phasebox allocations, untimed run: first step %lld, steps 2-%d %lld in all\n",
        r.swing[kPhasebox].firstStepAllocations, r.steps, r.swing[kPhasebox].laterAllocations);
    std::fprintf(out, "  Box2D awake bodies at the end: no sleeping %d, sleeping on %d\n",
                 r.timing[kBox2d].awake, r.timing[kBox2dSleeping].awake);
    std::fprintf(out, "  ratio Phasebox / Box2D (no sleeping, 8 + 3) %10.2fx\n",
                 p.msPerStep / b.msPerStep);
    std::fprintf(out, "  ratio Phasebox / Box2D (24 velocity it)      %10.2fx\n",
                 p.msPerStep / r.timing[kBox2d24].msPerStep);
    std::fprintf(out, "  ratio Phasebox / Box2D (sleeping on)         %10.2fx\n",
                 p.msPerStep / r.timing[kBox2dSleeping].msPerStep);

    std::fprintf(out, "\n  %-46s%12s%12s%10s%10s%10s\n", "the swing, untimed run from rest",
                 "max gap m", "end gap m", "torn s", "tip y min", "contacts");
    for (int c = 0; c < kCandidates; ++c) {
        const Swing& s = r.swing[c];
        char torn[16] = "-";
        if (s.tornAt >= 0.0) std::snprintf(torn, sizeof torn, "%.2f", s.tornAt);
        std::fprintf(out, "  %-46s%12.3e%12.3e%10s%10.3f%10d\n", kCandidateLabel[c], s.maxGap,
                     s.finalGap, torn, s.tipLowest, s.mostContacts);
    }
    if (r.failedSteps) std::fprintf(out, "  Phasebox steps that diverged: %lld\n", r.failedSteps);
    for (int c = 0; c < kCandidates; ++c)
        if (!r.timing[c].sameCourse)
            std::fprintf(out,
                         "  warning: a timed run of %s ended elsewhere than the measured one\n",
                         kCandidateLabel[c]);
    std::fprintf(out,
                 "\ngap = the largest distance between a hinge's two attachment points after a "
                 "step (Phasebox's\nWorld::jointErrors().position, Box2D's |anchor A - anchor "
                 "B|); torn = when it first exceeded\na link's length (0.5 m); tip y min = the "
                 "lowest the free end's centre went (-24.75 m hanging\nstraight down); contacts "
                 "= the most contact pairs after a step (Phasebox: touching or within its\n"
                 "speculative margin; Box2D: touching).\n");
}

std::string toJson(const ChainResult& r) {
    const Timing& p = r.timing[kPhasebox];
    Json json;
    json.beginObject();
    json.value("benchmark", "box2d_chain");
    json.value("links", kLinks);
    json.value("steps", r.steps);
    json.value("repeat", r.repeat);
    json.value("statistic", "median");
    json.value("phasebox_ms_per_step", p.msPerStep);
    json.value("box2d_ms_per_step", r.timing[kBox2d].msPerStep);
    json.value("box2d_sleep_ms_per_step", r.timing[kBox2dSleeping].msPerStep);
    json.value("box2d_24_iterations_ms_per_step", r.timing[kBox2d24].msPerStep);
    json.value("ratio", p.msPerStep / r.timing[kBox2d].msPerStep);
    json.value("ratio_24_iterations", p.msPerStep / r.timing[kBox2d24].msPerStep);
    json.value("ratio_sleeping", p.msPerStep / r.timing[kBox2dSleeping].msPerStep);
    json.value("phasebox_max_gap_m", r.swing[kPhasebox].maxGap);
    json.value("box2d_max_gap_m", r.swing[kBox2d].maxGap);
    json.value("box2d_sleep_max_gap_m", r.swing[kBox2dSleeping].maxGap);
    json.value("box2d_24_iterations_max_gap_m", r.swing[kBox2d24].maxGap);
    json.value("phasebox_final_gap_m", r.swing[kPhasebox].finalGap);
    json.value("box2d_final_gap_m", r.swing[kBox2d].finalGap);
    // Time the largest gap first exceeded a link's length: null when it never did.
    json.value("phasebox_torn_at_s",
               r.swing[kPhasebox].tornAt >= 0.0 ? r.swing[kPhasebox].tornAt : std::nan(""));
    json.value("box2d_torn_at_s",
               r.swing[kBox2d].tornAt >= 0.0 ? r.swing[kBox2d].tornAt : std::nan(""));
    json.value("box2d_24_iterations_torn_at_s",
               r.swing[kBox2d24].tornAt >= 0.0 ? r.swing[kBox2d24].tornAt : std::nan(""));
    json.value("phasebox_allocations_per_step", allocationsPerStep(p));
    json.value("phasebox_first_step_allocations", r.swing[kPhasebox].firstStepAllocations);
    json.value("phasebox_later_step_allocations", r.swing[kPhasebox].laterAllocations);
    json.value("box2d_allocations_per_step", allocationsPerStep(r.timing[kBox2d]));
    json.value("phasebox_tip_lowest_y_m", r.swing[kPhasebox].tipLowest);
    json.value("box2d_tip_lowest_y_m", r.swing[kBox2d].tipLowest);
    json.value("phasebox_most_contacts", r.swing[kPhasebox].mostContacts);
    json.value("box2d_most_touching_contacts", r.swing[kBox2d].mostContacts);
    json.value("box2d_sleep_awake_bodies", r.timing[kBox2dSleeping].awake);
    json.value("failed_steps", r.failedSteps);
    bool sameCourse = true;
    for (const Timing& t : r.timing) sameCourse = sameCourse && t.sameCourse;
    json.value("timed_runs_match", sameCourse);
    json.endObject();
    return json.str();
}

}  // namespace

int main(int argc, char** argv) {
    const Options options =
        parseOptions(argc, argv, "[--steps N] [--repeat N] [--json] [--quick]", {"--quick"});
    const int steps = options.steps ? options.steps : kDefaultSteps;
    const int repeat = options.repeat ? options.repeat : (options.quick ? 1 : kDefaultRepeat);

    const ChainResult result = measure(steps, repeat);

    printTable(options.json ? stderr : stdout, result);
    if (options.json) std::printf("%s\n", toJson(result).c_str());
    return 0;
}
