#include "physics/contacts/ContactStage.h"

#include "physics/core/Bodies.h"
#include "physics/core/WorkerPool.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <limits>

namespace phasebox {

namespace {
// Contacts reserved a collider at bind(), up to kMostReservedContacts in all (a larger scene
// grows its buffers in its first steps, a few doublings among thousands of contacts).
constexpr std::size_t kReservedContacts = 4;
constexpr std::size_t kMostReservedContacts = 4096;
// Items a chunk of a shared loop (WorkerPool): a narrow-phase test costs a fraction of a
// microsecond, a collider's shape and bounds a few tens of nanoseconds, handing a chunk to
// another thread about a microsecond; a chunk is made worth tens of those. (With 2,048
// colliders a chunk, the 100-row pyramid's 5,050 made three chunks, too few to share: its
// shapes and bounds were the caller's alone.)
constexpr int kPairGrain = 512;
constexpr int kColliderGrain = 512;
// A loop is shared from this many chunks on. Waking a helper that went to sleep during the
// solve costs tens of microseconds, about what a few chunks save: with loops of two or three
// chunks shared, the 20-row pyramid (about 600 contacts) took 1.06-1.12x its one-worker step
// on two workers in bench_box2d_pyramid, and 0.97-1.04x without; the 40-row one (about 2,400
// contacts) took 1.02-1.09x from four chunks on and 0.99-1.04x from eight.
constexpr int kLeastSharedChunks = 8;

bool holds(const ContactPoint& p) {
    return p.heldNormal != 0.0 || p.heldTangent != 0.0;
}

std::size_t heldPoints(const ContactConstraint& c) {
    std::size_t held = 0;
    for (int k = 0; k < c.pointCount; ++k) held += holds(c.points[k]);
    return held;
}

// A contact's key: its pair of colliders (a plane's number after the colliders' as the first).
std::uint64_t pairKey(int first, int second) {
    return (static_cast<std::uint64_t>(first) << 32) | static_cast<std::uint64_t>(second);
}

// The impulses of the points of old that the points of c continue (same feature ids), and
// how many of those held a force (World::releaseHeldForces).
void carryImpulses(const ContactConstraint& old, ContactConstraint& c, std::size_t& heldCarried) {
    for (int k = 0; k < c.pointCount; ++k)
        for (int l = 0; l < old.pointCount; ++l)
            if (c.points[k].id == old.points[l].id) {
                const ContactPoint& o = old.points[l];
                ContactPoint& p = c.points[k];
                heldCarried += holds(o);
                p.normalImpulse = o.normalImpulse;
                p.tangentImpulse = o.tangentImpulse;
                p.solvedNormal = o.solvedNormal;
                p.solvedTangent = o.solvedTangent;
                p.lastNormal = o.lastNormal;
                p.lastTangent = o.lastTangent;
                p.heldNormal = o.heldNormal;
                p.heldTangent = o.heldTangent;
            }
}

}  // namespace

template <class Fn>
void ContactStage::forRange(int count, int grain, Fn&& fn) {
    if (pool_ && count > (kLeastSharedChunks - 1) * grain)
        pool_->parallelFor(count, grain, [&fn](int begin, int end, int) { fn(begin, end); });
    else if (count > 0)
        fn(0, count);
}

bool ContactStage::needed(const Bodies& bodies, bool particleCollisions) {
    int dynamicBodies = 0, disks = 0, boxes = static_cast<int>(bodies.rigidBodies.size());
    for (const Particle& p : bodies.particles) {
        if (p.radius <= 0.0) continue;
        ++disks;
        dynamicBodies += !p.pinned;
    }
    for (const RigidBody& b : bodies.rigidBodies) dynamicBodies += !b.isStatic;
    if (dynamicBodies == 0) return false;
    if (!bodies.planes.empty()) return true;
    if (boxes >= 2 || (boxes >= 1 && disks >= 1)) return true;
    return particleCollisions && disks >= 2;
}

void ContactStage::bind(const Bodies& bodies) {
    colliders_.clear();
    const auto& particles = bodies.particles;
    for (int i = 0; i < static_cast<int>(particles.size()); ++i) {
        const Particle& p = particles[i];
        if (p.radius > 0.0)
            colliders_.push_back({Collider::Kind::Disk, i, p.dof, p.friction, p.restitution, false,
                                  false, p.asleep, i});
    }
    const auto& boxes = bodies.rigidBodies;
    for (int i = 0; i < static_cast<int>(boxes.size()); ++i) {
        const RigidBody& b = boxes[i];
        // A rigid disk collides as a disk but turns: its contacts have lever arms.
        const Collider::Kind kind = b.shape == RigidShape::Disk      ? Collider::Kind::Disk
                                    : b.shape == RigidShape::Polygon ? Collider::Kind::Polygon
                                                                     : Collider::Kind::Box;
        colliders_.push_back({kind, i, b.dof, b.friction, b.restitution, true, false, b.asleep,
                              static_cast<int>(particles.size()) + i});
    }
    asleepColliders_ = awakeColliders_ = 0;
    for (const Collider& c : colliders_) {
        asleepColliders_ += c.asleep;
        awakeColliders_ += c.dof >= 0;
    }
    // Two bodies a joint holds do not collide (CONTRACT §6).
    jointedPairs_.clear();
    if (!bodies.joints.empty()) {
        std::vector<int> particleCollider(particles.size(), -1), rigidCollider(boxes.size(), -1);
        for (int c = 0; c < static_cast<int>(colliders_.size()); ++c)
            (colliders_[c].rigid ? rigidCollider : particleCollider)[colliders_[c].object] = c;
        const auto colliderOf = [&](const JointBody& body) {
            switch (body.kind) {
                case JointBody::Kind::Particle:
                    return particleCollider[body.index];
                case JointBody::Kind::Rigid:
                    return rigidCollider[body.index];
                case JointBody::Kind::World:
                    break;
            }
            return -1;
        };
        for (const Joint& j : bodies.joints) {
            const int a = colliderOf(j.a), b = colliderOf(j.b);
            if (a >= 0) colliders_[a].jointed = true;
            if (b >= 0) colliders_[b].jointed = true;
            if (a < 0 || b < 0) continue;
            jointedPairs_.push_back((static_cast<std::uint64_t>(std::min(a, b)) << 32) |
                                    static_cast<std::uint64_t>(std::max(a, b)));
        }
        std::sort(jointedPairs_.begin(), jointedPairs_.end());
    }
    planes_.clear();
    planeFriction_.clear();
    planeRestitution_.clear();
    for (const Plane& p : bodies.planes) {
        planes_.push_back({p.point, p.normal});
        planeFriction_.push_back(p.friction);
        planeRestitution_.push_back(p.restitution);
    }
    disks_.assign(colliders_.size(), Disk{Vec2::Zero(), 0.0});
    boxes_.assign(colliders_.size(), OrientedBox{});
    polygons_.assign(colliders_.size(), OrientedPolygon{});
    bounds_.resize(colliders_.size());
    bodyOfCollider_.assign(colliders_.size(), -1);
    frames_.assign(colliders_.size(), Frame{});  // found anew: previous_ is not this list's
    bodyColliders_.reserve(colliders_.size());
    // Contacts for kReservedContacts a collider (a stack, a chain folding on itself, a pile's
    // inside) before any buffer grows in the step.
    const std::size_t contacts =
        std::min(kReservedContacts * colliders_.size(), kMostReservedContacts);
    broadPhase_.reserve(colliders_.size(), contacts);
    solver_.reserve(colliders_.size(), contacts);
    pairs_.reserve(contacts);
    fatPairs_.reserve(contacts);
    fatBounds_.reserve(colliders_.size());
    previous_.reserve(contacts);
    touching_.reserve(contacts);
    // Pairs between dynamic bodies are capped per body (a static one meets only dynamic ones,
    // a linear number); pairs of disks are left out entirely when particles do not collide.
    pairLimited_.assign(colliders_.size(), PairCap::kFree);
    pairSize_.assign(colliders_.size(), 0.0);
    for (int i = 0; i < static_cast<int>(colliders_.size()); ++i) {
        const Collider& c = colliders_[i];
        if (c.kind == Collider::Kind::Disk && !c.rigid) {
            pairLimited_[i] = !particleCollisions_ ? PairCap::kApart
                              : c.dof >= 0         ? PairCap::kCapped
                                                   : PairCap::kFree;
            pairSize_[i] = particles[c.object].radius;
        } else if (c.kind == Collider::Kind::Disk && c.dof >= 0) {
            pairLimited_[i] = PairCap::kCapped;
            pairSize_[i] = boxes[c.object].radius;
        } else if (c.kind == Collider::Kind::Polygon && c.dof >= 0) {
            pairLimited_[i] = PairCap::kCapped;
            pairSize_[i] = 0.5 * boxes[c.object].size.x();  // the farthest corner
        } else if (c.kind == Collider::Kind::Box && c.dof >= 0) {
            // A box's size for the cap is the radius of its circumscribed circle.
            pairLimited_[i] = PairCap::kCapped;
            pairSize_[i] = 0.5 * boxes[c.object].size.norm();
        }
    }
    previous_.clear();
    fatValid_ = false;
    capsBound_ = true;
    fatRetryIn_ = 0;
    heldCarried_ = false;
    carried_ = false;
    solver_.constraints().clear();
    asleep_.clear();
    reached_.clear();
}

void ContactStage::rebind(const Bodies& bodies) {
    // The contacts of the last collide() and those kept asleep, by the shape pair: a key names
    // colliders, which stay where they are (only their dofs change).
    ConstraintList kept = std::move(solver_.constraints());
    kept.insert(kept.end(), asleep_.begin(), asleep_.end());
    bind(bodies);
    const std::uint64_t count = colliders_.size();
    const auto awake = [&](std::uint64_t c) { return c < count && colliders_[c].dof >= 0; };
    for (ContactConstraint& c : kept)
        (awake(c.key >> 32) || awake(c.key & 0xffffffffu) ? previous_ : asleep_)
            .push_back(std::move(c));
    sortByKey(previous_);
    carried_ = true;
}

void ContactStage::reachSleeper(const Bodies& bodies, int i, int j, double margin) {
    const Collider& a = colliders_[i];
    const Collider& b = colliders_[j];
    if (a.asleep == b.asleep) return;
    const int awake = a.asleep ? j : i, sleeper = a.asleep ? i : j;
    if (colliders_[awake].dof < 0) return;
    Manifold m;
    PairContact pair;
    // A frame further than the contacts look: a body arriving is met by a pile already awake.
    if (narrowPhase(bodies, i, j, margin + 2.0 * sweep_[awake], m, pair))
        reached_.push_back(colliders_[sleeper].body);
}

void ContactStage::findReachedSleepers(const Bodies& bodies, const ContactSettings& settings) {
    reached_.clear();
    if (asleepColliders_ == 0) return;
    for (const auto& [i, j] : pairs_) reachSleeper(bodies, i, j, settings.speculativeDistance);
}

int ContactStage::solverBodyFor(int collider) {
    if (colliders_[collider].dof < 0) return -1;
    int& index = bodyOfCollider_[collider];
    if (index >= 0) return index;
    index = static_cast<int>(bodyColliders_.size());
    bodyColliders_.push_back(collider);
    return index;
}

void ContactStage::fillConstraint(ContactConstraint& c, std::uint64_t key, int colliderA,
                                  int colliderB, const Manifold& m, double friction,
                                  double restitution) const {
    c.key = key;
    c.normal = m.normal;
    c.friction = friction;
    c.restitution = restitution;
    // Each collider's centre, and its least half extent (a disk's radius, a polygon's
    // inradius): a tenth of the smaller one is an overlap no contact reaches in a resting
    // scene.
    struct Extent {
        Vec2 center;
        double size;
    };
    const auto extent = [&](int i) -> Extent {
        switch (colliders_[i].kind) {
            case Collider::Kind::Disk:
                return {disks_[i].center, disks_[i].radius};
            case Collider::Kind::Polygon:
                return {polygons_[i].center, polygons_[i].inradius};
            case Collider::Kind::Box:
                break;
        }
        return {boxes_[i].center, boxes_[i].halfExtents.minCoeff()};
    };
    const Extent b = extent(colliderB);
    const Extent a = colliderA >= 0 ? extent(colliderA)
                                    : Extent{Vec2::Zero(), std::numeric_limits<double>::infinity()};
    const Vec2 centerA = a.center, centerB = b.center;
    c.deepOverlap = ContactConstraint::kDeepOverlapFraction * std::min(a.size, b.size);
    c.pointCount = m.pointCount;
    // A point x found now, on a collider that has moved by (offset, turn) from its frame: its
    // anchor r in the frame, R(turn)·r = x − centre, and the separation the solver would measure
    // from there, s₀ = s − n·(d_B − d_A), d = offset + R(turn)·r − r, so that it measures s now.
    const auto inFrame = [&](int collider, const Vec2& center, const Vec2& x, Vec2& anchor) {
        const Vec2 arm = x - center;
        const Frame& frame = frames_[collider];
        if (frame.turn == 0.0 && frame.offset.x() == 0.0 && frame.offset.y() == 0.0) {
            anchor = arm;
            return Vec2(Vec2::Zero());
        }
        const double cosine = std::cos(frame.turn), sine = std::sin(frame.turn);
        anchor = Vec2(cosine * arm.x() + sine * arm.y(), cosine * arm.y() - sine * arm.x());
        return Vec2(frame.offset + (arm - anchor));
    };
    for (int k = 0; k < m.pointCount; ++k) {
        ContactPoint& p = c.points[k];
        const Vec2& x = m.points[k].position;
        const Vec2 movedA =
            colliderA >= 0 ? inFrame(colliderA, centerA, x, p.anchorA) : Vec2(Vec2::Zero());
        if (colliderA < 0) p.anchorA = Vec2::Zero();
        const Vec2 movedB = inFrame(colliderB, centerB, x, p.anchorB);
        p.baseSeparation = m.points[k].separation;
        if (movedA.x() != 0.0 || movedA.y() != 0.0 || movedB.x() != 0.0 || movedB.y() != 0.0)
            p.baseSeparation -= c.normal.dot(movedB - movedA);
        p.id = m.points[k].id;
    }
}

void ContactStage::updateShapes(const Bodies& bodies, const Vec& q) {
    forRange(static_cast<int>(colliders_.size()), kColliderGrain,
             [&](int begin, int end) { updateShapes(bodies, q, begin, end); });
}

void ContactStage::updateShapes(const Bodies& bodies, const Vec& q, int begin, int end) {
    for (int i = begin; i < end; ++i) {
        const Collider& c = colliders_[i];
        if (c.kind == Collider::Kind::Disk) {
            const Vec2 position = c.rigid ? bodies.rigidBodies[c.object].position
                                          : bodies.particles[c.object].position;
            const double radius =
                c.rigid ? bodies.rigidBodies[c.object].radius : bodies.particles[c.object].radius;
            disks_[i] = {c.dof >= 0 ? Vec2(q.segment<2>(c.dof)) : position, radius};
        } else if (c.kind == Collider::Kind::Polygon) {
            const RigidBody& b = bodies.rigidBodies[c.object];
            OrientedPolygon& p = polygons_[i];
            p.center = c.dof >= 0 ? Vec2(q.segment<2>(c.dof)) : b.position;
            p.rotation = rotation(c.dof >= 0 ? q[c.dof + 2] : b.angle);
            p.count = static_cast<int>(b.vertices.size());
            p.vertices = b.vertices.data();
            p.normals = b.normals.data();
            p.inradius = b.inradius;
        } else {
            const RigidBody& b = bodies.rigidBodies[c.object];
            boxes_[i] = c.dof >= 0 ? OrientedBox{q.segment<2>(c.dof), q[c.dof + 2], 0.5 * b.size}
                                   : OrientedBox{b.position, b.angle, 0.5 * b.size};
        }
    }
}

void ContactStage::findPairs(const Bodies& bodies, const Vec& q, const Vec& u, const Vec& uNext,
                             double frameFraction, double dt, const ContactSettings& settings) {
    // Nothing awake (every body asleep or static): no pair can change anything.
    if (awakeColliders_ == 0) {
        pairs_.clear();
        return;
    }
    // Shapes and bounds. A body's bounds grow by the distance it can travel in this step, so
    // that a fast body finds what lies ahead of it (the speculative contacts then stop it).
    updateShapes(bodies, q);
    const int count = static_cast<int>(colliders_.size());
    std::vector<double>& sweep = sweep_;
    sweep.assign(count, 0.0);
    motion_.assign(count, Motion{});
    forRange(count, kColliderGrain, [&](int begin, int end) {
        for (int i = begin; i < end; ++i) {
            const Collider& c = colliders_[i];
            bounds_[i] = c.kind == Collider::Kind::Disk      ? boundingBox(disks_[i])
                         : c.kind == Collider::Kind::Polygon ? boundingBox(polygons_[i])
                                                             : boundingBox(boxes_[i]);
            if (c.dof >= 0) {
                // The fastest the body moves in this frame: at its start, or at its end, the smooth
                // forces' velocity change extrapolated from the first sub-step over the frame (a
                // ball dropped from rest at dt = 1 s falls 9.81 m·s⁻¹·dt, not 0).
                const double extrapolate = 1.0 / frameFraction;
                auto reach = [&](int k) {
                    return std::max(std::abs(u[k]),
                                    std::abs(u[k] + extrapolate * (uNext[k] - u[k])));
                };
                const double reachX = reach(c.dof), reachY = reach(c.dof + 1);
                double speed = std::sqrt(reachX * reachX + reachY * reachY);
                if (!std::isfinite(speed)) speed = std::hypot(reachX, reachY);  // no overflow
                Motion& motion = motion_[i];
                motion.start = u.segment<2>(c.dof);
                motion.end = motion.start + extrapolate * (uNext.segment<2>(c.dof) - motion.start);
                if (c.kind == Collider::Kind::Box)
                    motion.turn = reach(c.dof + 2) * boxes_[i].halfExtents.norm() * dt;
                if (c.kind == Collider::Kind::Polygon)
                    motion.turn =
                        reach(c.dof + 2) * 0.5 * bodies.rigidBodies[c.object].size.x() * dt;
                sweep[i] = speed * dt + motion.turn;
            }
            // With bodies asleep an awake one looks two frames ahead (findReachedSleepers()).
            const double reach = asleepColliders_ > 0 ? 2.0 * sweep[i] : sweep[i];
            const Vec2 grow = Vec2::Constant(settings.speculativeDistance + reach);
            bounds_[i].lower -= grow;
            bounds_[i].upper += grow;
        }
    });
    const PairCap cap{&pairLimited_, &pairSize_, kOverlappingPairCap, kNearPairCap};
    bool reuse = fatValid_;  // bind() drops the kept pairs whenever the colliders change
    for (int i = 0; reuse && i < count; ++i) reuse = fatBounds_[i].contains(bounds_[i]);
    if (!reuse) {
        fatValid_ = false;
        // Where the last sweep's caps bound, this one's would too: the plain sweep.
        if (capsBound_ || fatRetryIn_ > 0) {
            fatRetryIn_ = std::max(fatRetryIn_ - 1, 0);
            broadPhase_.findPairs(bounds_, pairs_, cap, pool_);
            capsBound_ = broadPhase_.capBound();
            return;
        }
        fatBounds_.resize(bounds_.size());
        bool finite = true;
        for (int i = 0; i < count; ++i) {
            const Aabb& box = bounds_[i];
            const Vec2 extent = box.upper - box.lower;
            const Vec2 grow = Vec2::Constant(kFatMargin * extent.minCoeff());
            fatBounds_[i] = {box.lower - grow, box.upper + grow};
            finite = finite && fatBounds_[i].lower.allFinite() && fatBounds_[i].upper.allFinite();
        }
        if (finite) broadPhase_.findPairs(fatBounds_, fatPairs_, cap, pool_);
        if (!finite || broadPhase_.capBound()) {
            fatRetryIn_ = kFatRetryFrames;
            broadPhase_.findPairs(bounds_, pairs_, cap, pool_);
            capsBound_ = broadPhase_.capBound();
            return;
        }
        fatValid_ = true;
    }
    // The broad phase's own test (the bounds are finite here): they overlap on both axes.
    pairs_.clear();
    for (const auto& [i, j] : fatPairs_) {
        if (bounds_[i].overlaps(bounds_[j])) pairs_.push_back({i, j});
    }
#if PHASEBOX_EXPENSIVE_CHECKS
    // The broad phase on this step's bounds finds the very same pairs, in the same order.
    static thread_local std::vector<std::pair<int, int>> direct;
    broadPhase_.findPairs(bounds_, direct, cap, pool_);
    if (direct != pairs_ || broadPhase_.capBound()) {
        std::fprintf(stderr, "phasebox: invariant violated: %s\n",
                     "the pairs of the fat bounds are not the broad phase's");
        std::abort();
    }
#endif
}

bool ContactStage::narrowPhase(const Bodies& bodies, int i, int j, double margin, Manifold& m,
                               PairContact& pair) const {
    const Collider& a = colliders_[i];
    const Collider& b = colliders_[j];
    if (a.dof < 0 && b.dof < 0) return false;
    if (!jointedPairs_.empty() &&
        std::binary_search(jointedPairs_.begin(), jointedPairs_.end(),
                           (static_cast<std::uint64_t>(std::min(i, j)) << 32) |
                               static_cast<std::uint64_t>(std::max(i, j))))
        return false;
    pair.friction = std::sqrt(a.friction * b.friction);
    pair.restitution = std::max(a.restitution, b.restitution);
    pair.a = i;
    pair.b = j;
    // Bodies started at one point: a direction per pair (computed only then).
    const auto whenCoincident = [i, j](const Vec2& x, const Vec2& y) {
        return coincident(x, y)
                   ? coincidentNormal(static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j))
                   : Vec2(0.0, 1.0);
    };
    const bool diskA = a.kind == Collider::Kind::Disk, diskB = b.kind == Collider::Kind::Disk;
    const bool polygonA = a.kind == Collider::Kind::Polygon,
               polygonB = b.kind == Collider::Kind::Polygon;
    // A polygon's pairs: it is body A of the constraint unless both are polygons.
    if (polygonA || polygonB) {
        const int polygon = polygonA ? i : j, other = polygonA ? j : i;
        pair.a = polygon;
        pair.b = other;
        const Collider& o = colliders_[other];
        if (o.kind == Collider::Kind::Polygon)
            return collidePolygons(
                polygons_[polygon], polygons_[other], margin, m,
                whenCoincident(polygons_[polygon].center, polygons_[other].center));
        if (o.kind == Collider::Kind::Box)
            return collidePolygonBox(
                polygons_[polygon], boxes_[other], margin, m,
                whenCoincident(polygons_[polygon].center, boxes_[other].center));
        return collidePolygonDisk(polygons_[polygon], disks_[other], margin, m);
    }
    if (diskA && diskB) {
        // Two particles meet only with particle_collisions (then with its restitution);
        // a rigid disk meets everything.
        if (!a.rigid && !b.rigid) {
            if (!particleCollisions_) return false;
            const Particle& pa = bodies.particles[a.object];
            const Particle& pb = bodies.particles[b.object];
            if (pa.cloth >= 0 && pa.cloth == pb.cloth) return false;  // no cloth self-collision
            pair.restitution = particleRestitution_;
        }
        return collideDisks(disks_[i], disks_[j], margin, m,
                            whenCoincident(disks_[i].center, disks_[j].center));
    }
    if (!diskA && !diskB)
        return collideBoxes(boxes_[i], boxes_[j], margin, m,
                            whenCoincident(boxes_[i].center, boxes_[j].center));
    const int box = diskA ? j : i, disk = diskA ? i : j;
    pair.a = box;
    pair.b = disk;
    return collideBoxDisk(boxes_[box], disks_[disk], margin, m);
}

bool ContactStage::narrowPhasePlane(int k, int i, double margin, Manifold& m,
                                    PairContact& pair) const {
    const Collider& c = colliders_[i];
    if (c.dof < 0) return false;
    pair.a = -1 - k;
    pair.b = i;
    pair.friction = std::sqrt(planeFriction_[k] * c.friction);
    pair.restitution = std::max(planeRestitution_[k], c.restitution);
    const HalfPlane& plane = planes_[k];
    return c.kind == Collider::Kind::Disk      ? collidePlaneDisk(plane, disks_[i], margin, m)
           : c.kind == Collider::Kind::Polygon ? collidePlanePolygon(plane, polygons_[i], margin, m)
                                               : collidePlaneBox(plane, boxes_[i], margin, m);
}

void ContactStage::sortByKey(ConstraintList& constraints) {
    // By their keys alone, then each constraint moved once: a constraint is a few hundred bytes,
    // which the sort itself would move a dozen times each.
    keyOrder_.clear();
    for (std::size_t i = 0; i < constraints.size(); ++i)
        keyOrder_.emplace_back(constraints[i].key, static_cast<int>(i));
    if (std::is_sorted(keyOrder_.begin(), keyOrder_.end())) return;
    std::sort(keyOrder_.begin(), keyOrder_.end());
    sorted_.clear();
    for (const auto& entry : keyOrder_) sorted_.push_back(constraints[entry.second]);
    std::swap(constraints, sorted_);
}

void ContactStage::updateFrames(const Vec& q, const Vec& u, const Vec& uNext, double dt,
                                bool keep) {
    // After bind() and rebind() no frame is valid (previous_ then holds what rebind() carried,
    // in no frame kept here): every collider's is set anew.
    forRange(static_cast<int>(colliders_.size()), kColliderGrain, [&](int begin, int end) {
        for (int i = begin; i < end; ++i) {
            const Collider& c = colliders_[i];
            Frame& frame = frames_[i];
            if (c.dof < 0) {  // static (or asleep): never moves while bound
                frame.still = true;
                continue;
            }
            const Vec2 position = q.segment<2>(c.dof);
            const double speed =
                std::max(u.segment<2>(c.dof).norm(), uNext.segment<2>(c.dof).norm());
            double size = boxes_[i].halfExtents.minCoeff();
            if (c.kind == Collider::Kind::Disk) size = disks_[i].radius;
            if (c.kind == Collider::Kind::Polygon) size = polygons_[i].inradius;
            const double reach = std::min(kStillShare * size, kStillMost);
            bool still =
                keep && frame.valid && (position - frame.position).norm() + speed * dt <= reach;
            double angle = 0.0;
            if (c.rigid) {
                angle = q[c.dof + 2];
                const double spin = std::max(std::abs(u[c.dof + 2]), std::abs(uNext[c.dof + 2]));
                still = still && std::abs(angle - frame.angle) + spin * dt <= kStillTurn;
            }
            frame.still = still;
            if (!still) {
                frame.position = position;
                frame.angle = angle;
                frame.valid = true;
            }
            frame.offset = position - frame.position;
            // A disk's separations move with its centre alone (the solver does not turn its
            // anchors: ContactSolver::updateMotion), so a contact found anew is not turned back.
            frame.turn = c.kind == Collider::Kind::Disk ? 0.0 : angle - frame.angle;
        }
    });
}

std::pair<int, int> ContactStage::pairOrder(int i, int j) const {
    // narrowPhase()'s: a polygon is body A unless both are, a box before a disk.
    const Collider::Kind a = colliders_[i].kind, b = colliders_[j].kind;
    using K = Collider::Kind;
    const bool swap = (a != K::Polygon && b == K::Polygon) || (a == K::Disk && b == K::Box);
    return swap ? std::pair{j, i} : std::pair{i, j};
}

int ContactStage::keptContact(std::uint64_t key, int& next) const {
    // Pairs come in much the order of last frame's contacts: the one after the last found first.
    const auto count = static_cast<int>(previousKeys_.size());
    if (next < count && previousKeys_[next] == key) return next++;
    const auto at = std::lower_bound(previousKeys_.begin(), previousKeys_.end(), key);
    if (at == previousKeys_.end() || *at != key) return -1;
    next = static_cast<int>(at - previousKeys_.begin()) + 1;
    return next - 1;
}

void ContactStage::findContacts(const Bodies& bodies, const Vec& inverseMass, double dt,
                                const ContactSettings& settings) {
    // Every candidate pair's manifold into its own slot, in parallel, then every plane against
    // every collider; the contacts are then made from the slots in order, serially (they number
    // the solver's bodies as they come), so that nothing depends on how the loops were shared.
    const int count = static_cast<int>(colliders_.size());
    const int pairCount = static_cast<int>(pairs_.size());
    const int planeTests = count * static_cast<int>(planes_.size());
    found_.resize(static_cast<std::size_t>(pairCount + planeTests));
    const std::vector<double>& sweep = sweep_;
    forRange(pairCount, kPairGrain, [&](int begin, int end) {
        int next = 0;  // keptContact()'s guess
        for (int p = begin; p < end; ++p) {
            const auto [i, j] = pairs_[p];
            Found& f = found_[p];
            f.kept = -1;
            f.fast = false;
            if (frames_[i].still && frames_[j].still) {
                // Neither has moved since its contacts were found: last frame's stands (with
                // its materials: they change only with a new bind()).
                const auto [a, b] = pairOrder(i, j);
                f.kept = keptContact(pairKey(a, b), next);
                if (f.kept >= 0) {
                    f.pair.a = a;
                    f.pair.b = b;
                    f.hit = true;
                    continue;
                }
            }
            // How much closer the two can come in this step: their relative velocity (largest
            // at the step's start or end, the change being linear in between) and their turns,
            // not the sum of their speeds. Bodies moving together (a pile spreading out, boxes
            // falling side by side) need no speculative contact with each other.
            const Motion& a = motion_[i];
            const Motion& b = motion_[j];
            const double closing = std::sqrt(
                std::max((b.start - a.start).squaredNorm(), (b.end - a.end).squaredNorm()));
            const double reach = closing * dt + a.turn + b.turn;
            const double margin =
                settings.speculativeDistance + std::min(sweep[i] + sweep[j], reach);
            f.fast = reach > settings.restitutionThreshold * dt;
            f.hit = narrowPhase(bodies, i, j, margin, f.m, f.pair);
        }
    });
    // Planes against every dynamic body (planes are infinite: not in the broad phase).
    forRange(planeTests, kColliderGrain, [&](int begin, int end) {
        int next = 0;
        for (int t = begin; t < end; ++t) {
            const int k = t / count, i = t % count;
            Found& f = found_[pairCount + t];
            const double margin = settings.speculativeDistance + sweep[i];
            f.kept = -1;
            const Motion& motion = motion_[i];
            f.fast =
                std::sqrt(std::max(motion.start.squaredNorm(), motion.end.squaredNorm())) * dt +
                    motion.turn >
                settings.restitutionThreshold * dt;
            if (frames_[i].still) {
                f.kept = keptContact(pairKey(count + k, i), next);
                if (f.kept >= 0) {
                    f.pair.a = -1 - k;
                    f.pair.b = i;
                    f.hit = true;
                    continue;
                }
            }
            f.hit = narrowPhasePlane(k, i, margin, f.m, f.pair);
        }
    });
    // The contacts in slot order: numbered, with their solver bodies and keys, here; built
    // from their slots in parallel.
    madeFrom_.clear();
    // Room for every slot before the loop; when the room must grow, it at least doubles (an
    // exact reserve allocated again at each new largest count of candidate pairs: a swinging
    // chain's or a row of falling dominoes', one more pair every few steps).
    if (madeFrom_.capacity() < found_.size())
        madeFrom_.reserve(std::max(found_.size(), 2 * madeFrom_.capacity()));
    std::uint64_t lastKey = 0;
    keysAscending_ = true;
    keptCount_ = 0;
    for (int s = 0; s < pairCount + planeTests; ++s) {
        Found& f = found_[s];
        if (!f.hit) continue;
        if (s >= pairCount) f.pair.a = -1;  // a plane: the world is body A
        keptCount_ += f.kept >= 0;
        Made made;
        made.slot = s;
        made.bodyA = f.pair.a >= 0 ? solverBodyFor(f.pair.a) : -1;
        made.bodyB = solverBodyFor(f.pair.b);
        made.key = s < pairCount ? pairKey(f.pair.a, f.pair.b)
                                 : pairKey(count + (s - pairCount) / count, f.pair.b);
        if (!madeFrom_.empty() && made.key <= lastKey) keysAscending_ = false;
        lastKey = made.key;
        madeFrom_.push_back(made);
    }
    // The solver bodies in the order numbered, each made whole from its collider (the vector
    // keeps last step's elements, so that only its growth is constructed serially: a body is a
    // few hundred bytes, the 100-row pyramid's 5,050 were a serial megabyte and a half).
    std::vector<SolverBody>& solverBodies = solver_.bodies();
    solverBodies.resize(bodyColliders_.size());
    forRange(static_cast<int>(bodyColliders_.size()), kColliderGrain, [&](int begin, int end) {
        for (int k = begin; k < end; ++k) {
            const Collider& c = colliders_[bodyColliders_[k]];
            SolverBody& b = solverBodies[k];
            b = SolverBody{};
            b.dof = c.dof;
            b.rotates = c.rigid;
            b.round = c.kind == Collider::Kind::Disk;
            b.jointed = c.jointed;
            const Frame& frame = frames_[bodyColliders_[k]];
            b.collidePosition = frame.position;
            if (b.rotates) b.collideAngle = frame.angle;
            b.invMass = inverseMass[b.dof];
            b.invInertia = b.rotates ? inverseMass[b.dof + 2] : 0.0;
        }
    });
    // Every element is rebuilt whole below: those the vector holds already are not cleared
    // first (a contact is a few hundred bytes; one pass over them instead of two).
    ConstraintList& constraints = solver_.constraints();
    constraints.resize(madeFrom_.size());
}

void ContactStage::buildContacts(int begin, int end) {
    ConstraintList& constraints = solver_.constraints();
    for (int k = begin; k < end; ++k) {
        const Made& made = madeFrom_[k];
        const Found& f = found_[made.slot];
        ContactConstraint& c = constraints[k];
        if (f.kept < 0) {
            c = ContactConstraint{};
            c.bodyA = made.bodyA;
            c.bodyB = made.bodyB;
            c.fast = f.fast;
            fillConstraint(c, made.key, f.pair.a, f.pair.b, f.m, f.pair.friction,
                           f.pair.restitution);
            continue;
        }
        // As last frame found it, in the same frames, with its masses (ContactSolver::prepare()
        // keeps them) and impulses (carryChunk() finds the same).
        c = previous_[static_cast<std::size_t>(f.kept)];
        c.bodyA = made.bodyA;
        c.bodyB = made.bodyB;
        c.kept = true;
        c.fast = false;  // neither body has moved
    }
}

std::size_t ContactStage::carryChunk(int begin, int end, std::size_t& heldBefore) {
    // Each contact finds its predecessor by its key (both lists are sorted by key). The chunk
    // owns the contacts of previous_ from its first key up to the next chunk's first key, and
    // counts those that held a force on the way.
    ConstraintList& now = solver_.constraints();
    const int count = static_cast<int>(now.size());
    const auto byKey = [](const ContactConstraint& c, std::uint64_t key) { return c.key < key; };
    auto old = std::lower_bound(previous_.begin(), previous_.end(), now[begin].key, byKey);
    // The next chunk's first key (from madeFrom_ while that chunk may still be building).
    const auto last =
        end == count ? previous_.end()
                     : std::lower_bound(old, previous_.end(),
                                        keysAscending_ ? madeFrom_[end].key : now[end].key, byKey);
    std::size_t carried = 0;
    heldBefore = 0;
    for (int n = begin; n < end; ++n) {
        ContactConstraint& c = now[n];
        while (old != last && old->key < c.key) heldBefore += heldPoints(*old++);
        if (old == last || old->key != c.key) continue;
        if (c.kept)  // a copy of old, its impulses with it
            carried += heldPoints(c);
        else
            carryImpulses(*old, c, carried);
    }
    while (old != last) heldBefore += heldPoints(*old++);
    return carried;
}

void ContactStage::collide(const Bodies& bodies, const Vec& inverseMass, const Vec& q, const Vec& u,
                           const Vec& uNext, double frameFraction, double dt,
                           const ContactSettings& settings) {
    // Last step's constraints, with their accumulated impulses, for warm starting (or those
    // rebind() carried over a change of islands). The new ones are written over what the
    // vector holds (findContacts()).
    if (!carried_) std::swap(previous_, solver_.constraints());
    carried_ = false;
    bodyColliders_.clear();  // the solver's bodies are made anew in findContacts()
    std::fill(bodyOfCollider_.begin(), bodyOfCollider_.end(), -1);

    findPairs(bodies, q, u, uNext, frameFraction, dt, settings);
    updateFrames(q, u, uNext, dt, settings.keepStillContacts);
    // Their keys side by side, for keptContact()'s search (a search through the contacts
    // themselves reads a line of a different contact at every probe).
    previousKeys_.resize(previous_.size());
    for (std::size_t k = 0; k < previous_.size(); ++k) previousKeys_[k] = previous_[k].key;
    findReachedSleepers(bodies, settings);
    findContacts(bodies, inverseMass, dt, settings);

    // The contacts are built from their slots, and carry the impulses of persisting contacts
    // (same shapes, same features) for the warm start: in the same pass when they come sorted
    // by key (pairs in order, each its lower collider first), else after sorting them. Whether
    // every point that held a force found its successor: then the contacts account for all the
    // forces the method's step held (World::releaseHeldForces). Both counts are sums of
    // integers, the same in any order.
    ConstraintList& now = solver_.constraints();
    const int made = static_cast<int>(now.size());
    std::atomic<std::size_t> carried{0}, heldBefore{0};
    const auto carry = [&](int begin, int end) {
        std::size_t held = 0;
        carried += carryChunk(begin, end, held);
        heldBefore += held;
    };
    if (keysAscending_) {
        forRange(made, kPairGrain, [&](int begin, int end) {
            buildContacts(begin, end);
            carry(begin, end);
        });
    } else {
        forRange(made, kPairGrain, [&](int begin, int end) { buildContacts(begin, end); });
        sortByKey(now);
        forRange(made, kPairGrain, carry);
    }
    // The contacts of previous_ before the first key found (all of them when none was).
    const auto beforeFirst =
        made == 0 ? previous_.end()
                  : std::lower_bound(
                        previous_.begin(), previous_.end(), now.front().key,
                        [](const ContactConstraint& c, std::uint64_t key) { return c.key < key; });
    for (auto old = previous_.begin(); old != beforeFirst; ++old) heldBefore += heldPoints(*old);
    heldCarried_ = carried.load() == heldBefore.load();
    solver_.prepare();
}

Vec2 ContactStage::colliderCenter(int i) const {
    switch (colliders_[i].kind) {
        case Collider::Kind::Disk:
            return disks_[i].center;
        case Collider::Kind::Polygon:
            return polygons_[i].center;
        case Collider::Kind::Box:
            break;
    }
    return boxes_[i].center;
}

const std::vector<TouchingManifold>& ContactStage::overlaps(const Bodies& bodies, const Vec& q) {
    updateShapes(bodies, q);
    touching_.clear();
    // As collide(): each pair's and each plane test's manifold into its slot, in parallel,
    // then the overlaps in slot order.
    const int count = static_cast<int>(colliders_.size());
    const int pairCount = static_cast<int>(pairs_.size());
    const int planeTests = count * static_cast<int>(planes_.size());
    found_.resize(static_cast<std::size_t>(pairCount + planeTests));
    forRange(pairCount, kPairGrain, [&](int begin, int end) {
        for (int p = begin; p < end; ++p) {
            Found& f = found_[p];
            f.hit = narrowPhase(bodies, pairs_[p].first, pairs_[p].second, 0.0, f.m, f.pair);
        }
    });
    forRange(planeTests, kColliderGrain, [&](int begin, int end) {
        for (int t = begin; t < end; ++t) {
            Found& f = found_[pairCount + t];
            f.hit = narrowPhasePlane(t / count, t % count, 0.0, f.m, f.pair);
        }
    });
    const auto add = [&](const Manifold& m, const PairContact& pair) {
        TouchingManifold t;
        const bool world = pair.a < 0;
        t.dofA = world ? -1 : colliders_[pair.a].dof;
        t.rotatesA = !world && colliders_[pair.a].rigid && t.dofA >= 0;
        t.dofB = colliders_[pair.b].dof;
        t.rotatesB = colliders_[pair.b].rigid && t.dofB >= 0;
        t.normal = m.normal;
        t.friction = pair.friction;
        t.restitution = pair.restitution;
        const Vec2 centerA = world ? Vec2::Zero() : colliderCenter(pair.a);
        const Vec2 centerB = colliderCenter(pair.b);
        for (int k = 0; k < m.pointCount; ++k) {
            if (m.points[k].separation >= 0.0) continue;
            TouchingManifold::Point& p = t.points[t.pointCount++];
            p.rA = m.points[k].position - centerA;
            p.rB = m.points[k].position - centerB;
            p.depth = -m.points[k].separation;
        }
        if (t.pointCount > 0) touching_.push_back(t);
    };
    for (const Found& f : found_)
        if (f.hit) add(f.m, f.pair);
    return touching_;
}

int ContactStage::pointCount() const {
    int n = 0;
    for (const ContactConstraint& c : solver_.constraints()) n += c.pointCount;
    return n;
}

}  // namespace phasebox
