#pragma once
// The contact stage of the world's step: finds contacts once per step (broad phase, narrow
// phase, matching last step's contacts for warm starting) and hands them to the solver for
// every sub-step. It exists only while the scene holds two things that can touch.

#include "physics/contacts/BroadPhase.h"
#include "physics/contacts/ContactSolver.h"

#include <cstdint>
#include <vector>

namespace phasebox {

struct Bodies;
class WorkerPool;

// Two shapes that overlap at a state, as the penalty and kinematic models see them: the bodies'
// first state indices (−1 static or the world), the normal from A to B, the pair's material and
// the overlapping points with their lever arms from each centre.
struct TouchingManifold {
    int dofA = -1, dofB = -1;
    bool rotatesA = false, rotatesB = false;
    Vec2 normal = Vec2::Zero();
    double friction = 0.0;
    double restitution = 0.0;
    int pointCount = 0;
    struct Point {
        Vec2 rA = Vec2::Zero(), rB = Vec2::Zero();
        double depth = 0.0;  // overlap along the normal, > 0
    } points[2];
};

class ContactStage {
public:
    // Whether a world of these bodies needs a contact stage at all: two things that can touch, one
    // of them dynamic. Particle–particle pairs count only with particleCollisions.
    static bool needed(const Bodies& bodies, bool particleCollisions);

    ContactStage(bool particleCollisions, double particleRestitution)
        : particleCollisions_(particleCollisions), particleRestitution_(particleRestitution) {}

    // The threads the stage's loops share (the world's; null: the calling thread alone). Every
    // result is bit-identical with or without it: each pair's manifold is found into its own
    // slot and the contacts are then made from the slots in pair order. The solver reaches the
    // same pool through pool().
    void setPool(WorkerPool* pool) {
        pool_ = pool;
        solver_.setPool(pool);
    }
    WorkerPool* pool() const { return pool_; }

    // Rebuilds the collider list after the world's objects changed.
    void bind(const Bodies& bodies);
    // Rebuilds it after islands fell asleep or woke (World, simulation.sleep), keeping the
    // contacts' impulses: those an awake body takes part in warm-start the next collide(), the
    // others are kept aside until their island wakes, so that a woken pile holds as it held.
    void rebind(const Bodies& bodies);

    // Finds the contacts of the state (q, u) for a frame of length dt. uNext is the velocity
    // after the frame's first smooth sub-step, which is frameFraction of the frame: bounds grow by
    // how far each body can move in the frame, so that fast bodies find what lies ahead.
    void collide(const Bodies& bodies, const Vec& inverseMass, const Vec& q, const Vec& u,
                 const Vec& uNext, double frameFraction, double dt,
                 const ContactSettings& settings);

    // The broad phase alone (collide() begins with it): the pairs whose bounds, grown by how far
    // each body can move in the frame, overlap. The penalty model calls it once per frame
    // before the smooth step and then asks overlaps() at every force evaluation.
    void findPairs(const Bodies& bodies, const Vec& q, const Vec& u, const Vec& uNext,
                   double frameFraction, double dt, const ContactSettings& settings);
    // The pairs of the last findPairs() that overlap at the state q (margin 0: touching only),
    // with their overlapping points. Allocation-free once the buffer has grown.
    const std::vector<TouchingManifold>& overlaps(const Bodies& bodies, const Vec& q);

    // One step of h after the smooth step (ContactSolver::solveStep).
    void solveStep(double h, const Vec& q0, const Vec& u0, Vec& q, Vec& u,
                   const ContactSettings& settings, double positionWeight, bool holding) {
        solver_.solveStep(h, q0, u0, q, u, settings, positionWeight, holding);
    }
    // The relax where contacts meet joints (ContactSolver::relaxJoined).
    void relaxJoined(Vec& u, const TangentProjection& joints) { solver_.relaxJoined(u, joints); }
    void keepImpulses() { solver_.keepImpulses(); }
    void primeHeld() { solver_.primeHeld(); }
    void setWeightField(double strength) { solver_.setWeightField(strength); }
    // Whether some contact overlaps deeper than its deepOverlap (bodies started inside each
    // other).
    bool anyDeepOverlap() const {
        for (const ContactConstraint& c : solver_.constraints())
            for (int k = 0; k < c.pointCount; ++k)
                if (c.points[k].baseSeparation < -c.deepOverlap) return true;
        return false;
    }
    // Drops the impulse solver's constraints and warm start (another contact model runs).
    void forgetSolver() {
        solver_.constraints().clear();
        solver_.bodies().clear();
        previous_.clear();
        heldCarried_ = false;
    }
    // The last collide() carried every point that held a force over to a point it found: the
    // solver's contacts hold what the method's step held.
    bool heldCarried() const { return heldCarried_; }
    bool touching() const { return !solver_.empty(); }
    // Adds scale times the last step's position correction to q.
    void addPushOut(Vec& q, double scale) const { solver_.addPushOut(q, scale); }

    const ConstraintList& contacts() const { return solver_.constraints(); }

    // Sleeping. A body asleep collides like a static one. The bodies asleep that an awake body
    // could reach within two frames, found by the last collide() or findReachedSleepers() (a
    // body index: particles first, then rigid bodies), are the ones to wake: a frame ahead of
    // the contacts, so that a body arriving meets a pile that moves, not a wall.
    void findReachedSleepers(const Bodies& bodies, const ContactSettings& settings);
    const std::vector<int>& reachedSleepers() const { return reached_; }
    // Calls fn(a, b) with the body indices of every pair in contact: the solver's contacts
    // (fromSolver, the impulse model) or the last broad phase's pairs. Planes are left out.
    template <class Fn>
    void forEachTouchingPair(bool fromSolver, Fn&& fn) const {
        const std::uint64_t count = colliders_.size();
        if (fromSolver) {
            for (const ContactConstraint& c : solver_.constraints()) {
                const std::uint64_t a = c.key >> 32, b = c.key & 0xffffffffu;
                if (a < count && b < count) fn(colliders_[a].body, colliders_[b].body);
            }
            return;
        }
        for (const auto& [i, j] : pairs_) fn(colliders_[i].body, colliders_[j].body);
    }
    const ContactSolver& solver() const { return solver_; }
    int pointCount() const;
    // Of the last collide()'s contacts, those kept from the frame before as they were (a pair of
    // colliders that have not moved: ContactSettings::keepStillContacts).
    int keptContacts() const { return keptCount_; }

    // The most overlapping pairs a dynamic body takes part in with other dynamic bodies
    // (partners at least half its size; see PairCap; a box's size is its circumscribed circle).
    // A disk in a pile overlaps at most six, a box in a brick wall six and in a grid eight;
    // thousands started at one point would otherwise make a quadratic number of contacts
    // (3,000 disks: 4.5 million; 1,000 boxes: half a million).
    static constexpr int kOverlappingPairCap = 16;
    // And the most near ones (within the speculative margin or a swept box, not overlapping):
    // about six at rest, a few dozen for a fast body entering a dense pile.
    static constexpr int kNearPairCap = 32;
    const BroadPhase& broadPhase() const { return broadPhase_; }

private:
    struct Collider {
        enum class Kind : unsigned char { Disk, Box, Polygon } kind;
        int object;  // particle index, or rigid body index when rigid
        int dof;     // −1 static
        double friction;
        double restitution;
        bool rigid = false;    // object indexes the rigid bodies (boxes, rigid disks): it turns
        bool jointed = false;  // a joint holds it
        bool asleep = false;   // its island sleeps: it collides as a static body
        int body = -1;         // particle index, or particles + rigid body index
    };

    // A pair's narrow phase: a = the constraint's body A (a collider, or −1 − k for plane k),
    // b its body B, and the pair's combined material.
    struct PairContact {
        int a = -1, b = -1;
        double friction = 0.0, restitution = 0.0;
    };
    void updateShapes(const Bodies& bodies, const Vec& q);
    // collide()'s narrow phase: the contacts of the pairs found and of the planes.
    void findContacts(const Bodies& bodies, const Vec& inverseMass, double dt,
                      const ContactSettings& settings);
    // collide()'s contacts [begin, end) from their slots, and the warm start of those contacts
    // (returns the points carried that held a force; heldBefore: those of previous_ passed).
    void buildContacts(int begin, int end);
    std::size_t carryChunk(int begin, int end, std::size_t& heldBefore);
    void updateShapes(const Bodies& bodies, const Vec& q, int begin, int end);
    bool narrowPhase(const Bodies& bodies, int i, int j, double margin, Manifold& m,
                     PairContact& pair) const;
    bool narrowPhasePlane(int k, int i, double margin, Manifold& m, PairContact& pair) const;
    Vec2 colliderCenter(int i) const;
    // The solver body of a collider in this step, numbered as the contacts come (−1: static);
    // findContacts() makes the bodies after, in parallel (bodyColliders_).
    int solverBodyFor(int collider);
    // A contact's key, material and points from its manifold (colliderA −1: a plane).
    void fillConstraint(ContactConstraint& c, std::uint64_t key, int colliderA, int colliderB,
                        const Manifold& m, double friction, double restitution) const;

    bool particleCollisions_;
    double particleRestitution_;
    std::vector<Collider> colliders_;
    std::vector<Disk> disks_;                // per collider, when a disk
    std::vector<OrientedBox> boxes_;         // per collider, when a box
    std::vector<OrientedPolygon> polygons_;  // per collider, when a polygon (vertices: its body's)
    std::vector<Aabb> bounds_;
    std::vector<double> sweep_;  // per collider: how far it can move in this step
    // Per collider, for a pair's margin: its velocity at the step's start and at its end (the
    // smooth forces' change extrapolated), and how far a point of it can move by turning.
    struct Motion {
        Vec2 start = Vec2::Zero(), end = Vec2::Zero();
        double turn = 0.0;
    };
    std::vector<Motion> motion_;
    std::vector<std::pair<int, int>> pairs_;
    // The broad phase on bounds grown further, by kFatMargin of each one's smaller extent, and
    // its pairs: while every collider's bounds stay inside its fat ones (a stack at rest, step
    // after step), this step's pairs are the fat pairs whose bounds overlap, the same pairs in
    // the same order as the broad phase would find (findPairs()), for a pass over the pairs
    // instead of a sweep. Not where the caps bind (a pile): then the pairs depend on which
    // candidates the sweep met, and the broad phase runs on this step's bounds.
    static constexpr double kFatMargin = 0.1;
    std::vector<Aabb> fatBounds_;
    std::vector<std::pair<int, int>> fatPairs_;
    bool fatValid_ = false;  // fatPairs_ are the pairs of fatBounds_, with no cap bound
    bool capsBound_ = true;  // the last broad phase's caps bound (or none ran since bind())
    // After a sweep of fat bounds whose caps bound where the frame's own did not (a dense heap
    // near its caps), the frames until the next try: the sweep runs on the frame's bounds alone,
    // not on both every frame.
    static constexpr int kFatRetryFrames = 60;
    int fatRetryIn_ = 0;
    // Per candidate pair, then per plane and collider: the narrow phase's answer, found in
    // parallel and turned into contacts in order.
    struct Found {
        Manifold m;
        PairContact pair;
        bool hit = false;
        // Its bodies may meet faster than a bounce's threshold in this step (ContactConstraint).
        bool fast = false;
        int kept = -1;  // the contact of previous_ it keeps as it was, or −1 (found anew)
    };
    LargeVector<Found> found_;
    // Per contact of this step: its slot in found_, solver bodies and key; and whether the
    // keys came in ascending order.
    struct Made {
        int slot = 0;
        int bodyA = -1, bodyB = -1;
        std::uint64_t key = 0;
    };
    std::vector<Made> madeFrom_;
    bool keysAscending_ = true;
    WorkerPool* pool_ = nullptr;
    // Runs fn(begin, end) over [0, count) in chunks of grain, shared when a pool is set and
    // there are enough chunks to be worth waking a helper (kLeastSharedChunks).
    template <class Fn>
    void forRange(int count, int grain, Fn&& fn);
    std::vector<unsigned char> pairLimited_;  // per collider: disk pairs capped (PairCap)
    std::vector<double> pairSize_;            // per collider: disk radius, for the cap
    std::vector<HalfPlane> planes_;
    std::vector<double> planeFriction_, planeRestitution_;
    // Where each collider's contacts are measured from: the solver's collidePosition and
    // collideAngle, its place when last seen moving (ContactSolver measures each point's
    // separation from there, its anchors turned with the body). A collider that is still there,
    // within kStillShare of its least half extent (at most kStillMost) and kStillTurn, counting
    // what it can move in the frame, keeps it; a pair of two such colliders (or one and a plane
    // or a static body) keeps last frame's contact as it was instead of a narrow phase, as a
    // contact cache does; a contact found anew is written in its colliders' frames.
    static constexpr double kStillShare = 1e-3;
    static constexpr double kStillMost = 5e-4;  // m
    static constexpr double kStillTurn = 1e-3;  // rad
    struct Frame {
        Vec2 position = Vec2::Zero();
        double angle = 0.0;
        Vec2 offset = Vec2::Zero();  // where the collider is now, from position
        double turn = 0.0;           // and its angle (0 for a disk)
        bool valid = false;          // set at a collide() since bind()
        bool still = false;          // kept at this collide()
    };
    std::vector<Frame> frames_;
    // Each collider's frame kept or moved to where it is (keep false: all moved).
    void updateFrames(const Vec& q, const Vec& u, const Vec& uNext, double dt, bool keep);
    int keptCount_ = 0;  // contacts the last collide() kept
    // The pair (i, j) as narrowPhase() orders it: the contact's body A first.
    std::pair<int, int> pairOrder(int i, int j) const;
    // The contact of previous_ with this key, or −1; next: where the next one is looked for
    // first (updated).
    int keptContact(std::uint64_t key, int& next) const;
    std::vector<std::uint64_t> previousKeys_;  // previous_'s keys, in its order (ascending)
    std::vector<int> bodyOfCollider_;          // solver body index in this step, −1 none yet
    std::vector<int> bodyColliders_;           // per solver body in this step, its collider
    ConstraintList previous_;
    bool heldCarried_ = false;
    // Sleeping: previous_ was filled by rebind() (collide() keeps it), the contacts of islands
    // asleep, the colliders asleep and awake, and the sleepers reached.
    bool carried_ = false;
    ConstraintList asleep_;
    int asleepColliders_ = 0, awakeColliders_ = 0;
    std::vector<int> reached_;
    void reachSleeper(const Bodies& bodies, int i, int j, double margin);
    // Sorts constraints by key (the pair), for matching them with previous_.
    void sortByKey(ConstraintList& constraints);
    std::vector<std::pair<std::uint64_t, int>> keyOrder_;
    ConstraintList sorted_;
    std::vector<TouchingManifold> touching_;
    // Collider pairs (lower index first, as one key) held by a joint: they never collide.
    std::vector<std::uint64_t> jointedPairs_;
    BroadPhase broadPhase_;
    ContactSolver solver_;
};

}  // namespace phasebox
