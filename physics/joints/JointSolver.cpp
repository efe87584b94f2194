// The joint solver (JointSolver.h): binding, J·W·Jᵀ and its block LDLᵀ, the constrained
// dynamics and the stages after the step; SHAKE is in JointShake.cpp, the joints' rows in
// JointRows.cpp and a file per type.

#include "physics/joints/JointSolver.h"
#include "physics/joints/JointTuning.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <set>
#include <type_traits>
#include <utility>

namespace phasebox {

namespace {
// Motor impulses and the velocity projection alternate this many times.
constexpr int kMotorIterations = 4;
// A motor turns b against a, and each end must take its torque: a rigid body, the world or a
// fixed point. A free particle has no angle: a motor on one turned the other body alone, an
// external torque booked as motor work (the validation refuses such a motor, and one left
// here does nothing).
bool takesTorque(const joints::End& e) {
    return e.rigid || e.dof < 0;
}
// Where a joint's end is: a dynamic body's coordinates (and, for a rigid body, its point in the
// body's frame), or a fixed point in the world.
joints::End resolveEnd(const Bodies& bodies, const JointBody& body) {
    joints::End e;
    switch (body.kind) {
        case JointBody::Kind::Particle: {
            const Particle& p = bodies.particles[body.index];
            if (p.dof >= 0)
                e.dof = p.dof;
            else
                e.fixed = p.position;
            break;
        }
        case JointBody::Kind::Rigid: {
            const RigidBody& b = bodies.rigidBodies[body.index];
            e.rigid = true;
            if (b.dof >= 0) {
                e.dof = b.dof;
                e.turns = true;
                e.local = body.point;
            } else {
                e.fixed = b.position + rotation(b.angle) * body.point;
                e.angle0 = b.angle;
            }
            break;
        }
        case JointBody::Kind::World:
            e.rigid = true;  // the world has an angle: 0
            e.fixed = body.point;
            break;
    }
    return e;
}
}  // namespace

// ---- binding: ends and the joint graph ----------------------------------------------------

void JointSolver::bind(const Bodies& bodies, bool carry) {
    std::unique_ptr<JointSolver> old;
    if (carry) old = std::make_unique<JointSolver>(*this);
    const int scene = static_cast<int>(bodies.joints.size());
    joints_.clear();
    active_.assign(scene, -1);
    sceneIndex_.clear();
    idle_.assign(scene, Idle{});
    endA_.clear();
    endB_.clear();
    hasMotors_ = hasInequalities_ = false;
    turningDofs_.clear();
    turningBodies_.clear();
    std::map<int, int> slots;  // dof → slot
    const auto withSlot = [&](End e, const JointBody& body) {
        if (e.turns) {
            const auto [it, added] = slots.try_emplace(e.dof, static_cast<int>(slots.size()));
            if (added) {
                turningDofs_.push_back(e.dof);
                turningBodies_.push_back(body.index);
            }
            e.slot = it->second;
        }
        return e;
    };
    for (int i = 0; i < scene; ++i) {
        const Joint& j = bodies.joints[i];
        const End a = resolveEnd(bodies, j.a), b = resolveEnd(bodies, j.b);
        if (a.dof < 0 && b.dof < 0) {
            idle_[i].a = a;
            idle_[i].b = b;
            continue;
        }
        active_[i] = static_cast<int>(joints_.size());
        sceneIndex_.push_back(i);
        joints_.push_back(j);
        endA_.push_back(withSlot(a, j.a));
        endB_.push_back(withSlot(b, j.b));
        hasMotors_ =
            hasMotors_ || (j.hasMotor && takesTorque(endA_.back()) && takesTorque(endB_.back()));
        hasInequalities_ = hasInequalities_ || j.hasLimits || j.type == Joint::Type::Rope ||
                           j.type == Joint::Type::Pulley;
    }
    // SHAKE's reach: a tenth of the smallest length a joint holds (a rod's, a lever arm).
    double smallest = std::numeric_limits<double>::infinity();
    const auto arm = [](const JointBody& b) {
        return b.kind == JointBody::Kind::Rigid ? b.point.norm() : 0.0;
    };
    // Over every joint of the scene, asleep or not: what the awake ones are solved with does
    // not change when others fall asleep.
    for (const Joint& j : bodies.joints)
        for (const double length : {j.length, j.radius, arm(j.a), arm(j.b)})
            if (length > 0.0) smallest = std::min(smallest, length);
    shakeReach_ = joints::kShakeReach * (std::isfinite(smallest) ? smallest : 1.0);
    // A rope counts as taut within kTautFraction of its length: SHAKE must leave less than
    // that, or a rope it held would read as slack in the next step.
    shakeCeiling_ = joints::kShakeCeiling;
    for (const Joint& j : bodies.joints)
        if (j.type == Joint::Type::Rope)
            shakeCeiling_ = std::min(shakeCeiling_, 0.5 * tautBand(j.length));
    shakeTolerance_ = joints::kProjectionTolerance;
    projectionFloor_ = joints::kProjectionTolerance;
    const int m = jointCount();
    rotations_.assign(turningDofs_.size(), Mat2::Identity());
    heldStiffness_.assign(turningDofs_.size(), 0.0);
    rows_.assign(m, Rows{});
    rhs_.assign(m, Vec3::Zero());
    lambda_.assign(m, Vec3::Zero());
    heldLimit_.assign(m, joints::kNoLimit);
    findLimits_ = true;
    previousStep_.assign(m, Vec3::Zero());
    lastDelta_.assign(m, Vec3::Zero());
    for (int i = 0; i < kAndersonDepth; ++i) {
        andersonDf_[i].assign(m, Vec3::Zero());
        andersonDl_[i].assign(m, Vec3::Zero());
    }
    forces_.assign(m, 0.0);
    forcesKnown_ = false;
    ropeShaken_.assign(m, 0);
    forceOn_.assign(m, {Vec2::Zero(), Vec2::Zero()});
    motorImpulse_.assign(m, 0.0);
    heldMotorTorque_.assign(m, 0.0);

    // The joint graph: two joints are adjacent when they hold a common dynamic body, unless
    // that body holds more than kHubJoints: then it is a node itself (a hub), adjacent to its
    // joints (JointSolver.h).
    std::map<int, std::vector<std::pair<int, int>>> byBody;  // dof → (joint, side)
    for (int k = 0; k < m; ++k) {
        if (endA_[k].dof >= 0) byBody[endA_[k].dof].push_back({k, 0});
        if (endB_[k].dof >= 0) byBody[endB_[k].dof].push_back({k, 1});
    }
    hubs_.clear();
    std::vector<std::set<int>> graph(m);
    for (const auto& [dof, list] : byBody) {
        if (list.size() <= static_cast<std::size_t>(kHubJoints)) {
            for (const auto& [k1, s1] : list)
                for (const auto& [k2, s2] : list)
                    if (k1 != k2) graph[k1].insert(k2);
            continue;
        }
        const int h = static_cast<int>(hubs_.size());
        const auto& [k0, s0] = list.front();
        hubs_.push_back({dof, (s0 == 0 ? endA_[k0] : endB_[k0]).turns ? 3 : 2});
        graph.emplace_back();
        for (const auto& [k, side] : list) {
            (side == 0 ? endA_[k] : endB_[k]).hub = h;
            graph[k].insert(m + h);
            graph[m + h].insert(k);
        }
    }
    // A joint that holds hubs alone has no pivot of its own: it goes after them.
    std::vector<char> late(m + hubs_.size(), 0);
    const auto outsideHubs = [](const End& e) { return e.dof >= 0 && e.hub < 0; };
    for (int k = 0; k < m && !hubs_.empty(); ++k)
        late[k] = !outsideHubs(endA_[k]) && !outsideHubs(endB_[k]);
    pattern_.analyse(std::move(graph), late);
    couplings_.clear();
    hubCouplings_.clear();
    for (const auto& [dof, list] : byBody)
        for (const auto& [k1, s1] : list) {
            const int h = (s1 == 0 ? endA_[k1] : endB_[k1]).hub;
            if (h >= 0) {
                const int pk = pattern_.position(k1), ph = pattern_.position(m + h);
                hubCouplings_.push_back(
                    {pattern_.blockIndex(std::min(pk, ph), std::max(pk, ph)), k1, s1, h, pk > ph});
                continue;
            }
            for (const auto& [k2, s2] : list)
                if (pattern_.position(k1) > pattern_.position(k2))
                    couplings_.push_back(
                        {pattern_.blockIndex(pattern_.position(k2), pattern_.position(k1)), k1, s1,
                         k2, s2});
        }
    // A weld holds the angle too, and a hinge at a limit: those have three rows.
    blockRows_ = 2;
    for (const Joint& j : bodies.joints)
        if (j.type == Joint::Type::Weld || (j.type == Joint::Type::Hinge && j.hasLimits))
            blockRows_ = 3;
    for (const Hub& hub : hubs_)
        if (hub.dofs == 3) blockRows_ = 3;
    const int nodes = pattern_.size();
    const std::size_t blocks = static_cast<std::size_t>(pattern_.blockCount());
    factors2_.resize(blockRows_ == 2 ? nodes : 0, blockRows_ == 2 ? blocks : 0);
    factors3_.resize(blockRows_ == 3 ? nodes : 0, blockRows_ == 3 ? blocks : 0);
    rowsChanged();
    factoredValid_ = false;
    rowsQ_.resize(0);
    rotationsKnown_ = false;
    if (old) carryFrom(*old);
}

void JointSolver::carryFrom(const JointSolver& old) {
    const int scene = static_cast<int>(active_.size());
    for (int i = 0; i < scene && i < static_cast<int>(old.active_.size()); ++i) {
        const int was = old.active_[i], now = active_[i];
        if (now < 0) {  // asleep now: what it held when it fell asleep, or before
            idle_[i].force = old.force(i);
            idle_[i].forceOn = {old.forceOnA(i), old.forceOnB(i)};
            continue;
        }
        if (was < 0) {  // woken: the forces it held when it fell asleep
            forces_[now] = old.idle_[i].force;
            forceOn_[now] = old.idle_[i].forceOn;
            continue;
        }
        forces_[now] = old.forces_[was];
        forceOn_[now] = old.forceOn_[was];
        lambda_[now] = old.lambda_[was];
        ropeShaken_[now] = old.ropeShaken_[was];
        // A motor's island never sleeps (World::fallAsleep), so its held torque carries on
        // when another island falls asleep or wakes.
        heldMotorTorque_[now] = old.heldMotorTorque_[was];
    }
    // A body that kept turning keeps the stiffness it held (one that slept, what it held then).
    // Per rigid body: the stiffness it held at the last bind, as it turned then or slept.
    sleptStiffness_ = old.sleptStiffness_;
    const auto hold = [this](int body, double stiffness) {
        if (body >= static_cast<int>(sleptStiffness_.size()))
            sleptStiffness_.resize(static_cast<std::size_t>(body) + 1, 0.0);
        sleptStiffness_[body] = stiffness;
    };
    for (std::size_t s = 0; s < old.turningBodies_.size(); ++s)
        hold(old.turningBodies_[s], old.heldStiffness_[s]);
    for (std::size_t s = 0; s < turningBodies_.size(); ++s)
        if (turningBodies_[s] < static_cast<int>(sleptStiffness_.size()))
            heldStiffness_[s] = sleptStiffness_[turningBodies_[s]];
    forcesKnown_ = old.forcesKnown_;
}

template <class Add>
void JointSolver::forEachJTranspose(const Vec& invMass, Add&& add) const {
    // Over the B rows a joint can have (where B = 2 the third row is zero).
    const auto over = [&](auto rows) {
        constexpr int B = decltype(rows)::value;
        const auto endOf = [&](const End& e, const Mat3& jac, const Vec3& lambda) {
            if (e.dof < 0) return;
            double f[3];
            for (int c = 0; c < 3; ++c) {
                f[c] = jac(0, c) * lambda[0];
                for (int i = 1; i < B; ++i) f[c] += jac(i, c) * lambda[i];
            }
            add(e.dof, invMass[e.dof], f[0]);
            add(e.dof + 1, invMass[e.dof + 1], f[1]);
            if (e.turns) add(e.dof + 2, invMass[e.dof + 2], f[2]);
        };
        for (int k = 0; k < jointCount(); ++k) {
            const Rows& r = rows_[k];
            if (r.count == 0) continue;
            endOf(endA_[k], r.ja, lambda_[k]);
            endOf(endB_[k], r.jb, lambda_[k]);
        }
    };
    if (blockRows_ == 2)
        over(std::integral_constant<int, 2>{});
    else
        over(std::integral_constant<int, 3>{});
}

void JointSolver::addJTranspose(const Vec& invMass, double scale, Vec& x) const {
    forEachJTranspose(invMass, [&](int dof, double w, double f) { x[dof] += scale * w * f; });
}

void JointSolver::applyShakeImpulse(double h, const Vec& weights, Vec& q, Vec& u) {
    // The same impulse moves the positions and the velocities: summed over the joints per body
    // once, then applied to both.
    impulse_.setZero(weights.size());
    forEachJTranspose(weights, [&](int dof, double, double f) { impulse_[dof] += f; });
    impulse_.array() *= weights.array();
    q += impulse_;
    u += impulse_ * (1.0 / h);  // a product: the vector division cost 1% of the whip's step
}

// ---- J·W·Jᵀ and its block LDLᵀ ------------------------------------------------------------------

void JointSolver::factor(const Vec& invMass) {
    // The same rows as the last factorization: the factors stand.
    if (factoredValid_ && &invMass == factoredMass_ && factoredVersion_ == rowsVersion_) return;
    factoredVersion_ = rowsVersion_;
    factoredMass_ = &invMass;
    factoredValid_ = true;
    if (blockRows_ == 2)
        factorBlocks(factors2_, invMass);
    else
        factorBlocks(factors3_, invMass);
}

template <int B>
void JointSolver::factorBlocks(BlockLdlt<B>& f, const Vec& invMass) {
    using MatB = Eigen::Matrix<double, B, B>;
    const auto weights = [&](const End& e) {
        Vec3 w = Vec3::Zero();
        if (e.dof < 0) return w;
        w[0] = invMass[e.dof];
        w[1] = invMass[e.dof + 1];
        if (e.turns) w[2] = invMass[e.dof + 2];
        return w;
    };
    // J_i·W·J_kᵀ of B rows each.
    const auto product = [](const Mat3& ji, const Vec3& w, const Mat3& jk) {
        MatB out;
        for (int i = 0; i < B; ++i)
            for (int j = 0; j < B; ++j)
                out(i, j) = ji(i, 0) * w[0] * jk(j, 0) + ji(i, 1) * w[1] * jk(j, 1) +
                            ji(i, 2) * w[2] * jk(j, 2);
        return out;
    };
    const int m = jointCount();
    for (int p = 0; p < pattern_.size(); ++p) {
        const int k = pattern_.node(p);
        MatB& d = f.diag(p);
        if (k >= m) {  // a hub: −M over its degrees of freedom
            const Hub& hub = hubs_[k - m];
            d.setIdentity();
            for (int i = 0; i < hub.dofs; ++i) {
                const double w = invMass[hub.dof + i];
                d(i, i) = w > 0.0 ? -1.0 / w : -1.0;
            }
            continue;
        }
        const Rows& r = rows_[k];
        const End& a = endA_[k];
        const End& b = endB_[k];
        const bool viaHub = a.hub >= 0 || b.hub >= 0;
        const auto outside = [&](const End& e) { return e.hub < 0 ? weights(e) : Vec3::Zero(); };
        d = product(r.ja, outside(a), r.ja) + product(r.jb, outside(b), r.jb);
        // The whole diagonal, hubs included, scales the regularization below.
        const MatB whole =
            viaHub ? MatB(product(r.ja, weights(a), r.ja) + product(r.jb, weights(b), r.jb)) : d;
        for (int i = 0; i < B; ++i) {
            if (i >= r.count) {  // an unused row: the identity keeps the block invertible
                d.row(i).setZero();
                d.col(i).setZero();
                d(i, i) = 1.0;
            } else if (!viaHub) {
                // Redundant joints (a closed loop held twice) would make the system singular:
                // a relative 1e-10 on the diagonal picks the least-norm answer among equals.
                d(i, i) = d(i, i) > 0.0 ? d(i, i) * (1.0 + 1e-10) : 1.0;
            } else {
                d(i, i) = whole(i, i) > 0.0 ? d(i, i) + 1e-10 * whole(i, i) : 1.0;
            }
        }
    }
    f.clearOff();
    for (const Coupling& c : couplings_) {
        const Rows& ri = rows_[c.i];
        const Rows& rk = rows_[c.k];
        const Mat3& ji = c.sideI == 0 ? ri.ja : ri.jb;
        const Mat3& jk = c.sideK == 0 ? rk.ja : rk.jb;
        const End& body = c.sideK == 0 ? endA_[c.k] : endB_[c.k];
        f.off(c.block) += product(ji, weights(body), jk);
    }
    // A joint and its hub couple by the joint's Jacobian on the hub: [J·W·Jᵀ, J_h; J_hᵀ, −M_h]
    // eliminates to J·W·Jᵀ with the hub's W back in (Baraff 1996, "Linear-time dynamics using
    // Lagrange multipliers").
    for (const HubCoupling& c : hubCouplings_) {
        const Rows& r = rows_[c.joint];
        const Mat3& j = c.side == 0 ? r.ja : r.jb;
        const Hub& hub = hubs_[c.hub];
        MatB o = MatB::Zero();
        for (int i = 0; i < std::min(B, r.count); ++i)
            for (int x = 0; x < hub.dofs; ++x) {
                const double v = invMass[hub.dof + x] > 0.0 ? j(i, x) : 0.0;
                if (c.jointLater)
                    o(i, x) = v;
                else
                    o(x, i) = v;
            }
        f.off(c.block) += o;
    }
    f.factor(pattern_);
}

void JointSolver::solve() {
    if (blockRows_ == 2)
        solveBlocks(factors2_);
    else
        solveBlocks(factors3_);
}

template <int B>
void JointSolver::solveBlocks(BlockLdlt<B>& f) {
    f.solve(
        pattern_,
        [&](int p) {
            const int k = pattern_.node(p);
            using Column = typename BlockLdlt<B>::Column;
            return k < jointCount() ? Column(rhs_[k].template head<B>()) : Column::Zero();
        },
        [&](int p, const std::array<double, B>& x) {
            const int k = pattern_.node(p);
            if (k >= jointCount()) return;  // a hub's velocity change: not needed
            Vec3& lambda = lambda_[k];
            for (int i = 0; i < B; ++i) lambda[i] = x[i];
            if constexpr (B == 2) lambda[2] = 0.0;
        });
}

// ---- constrained dynamics --------------------------------------------------------------------

void JointSolver::solveDynamics(const Vec& q, const Vec& u, const Vec& invMass, const Vec& accel) {
    evaluateRows(Mode::Dynamics, q, u);
    // A taut rope that would have to push goes slack, and a pulley's stop or a hinge's limit
    // that would have to pull lets go, and the system is solved again. A limit the step holds
    // stays for the step (found at its start: the derivative must not switch within it).
    for (int pass = 0; pass < 3; ++pass) {
        factor(invMass);
        for (int k = 0; k < jointCount(); ++k) {
            const Rows& r = rows_[k];
            rhs_[k] = -(jTimes(k, accel) + r.bias);
            joints::zeroFrom(rhs_[k], r.count);
        }
        solve();
        if (!hasInequalities_) break;
        bool slackened = false;
        // Joint k's rows from `from` on let go: the count cut there, their Jacobian zeroed.
        const auto letGo = [&](int k, int from) {
            Rows& r = rows_[k];
            r.count = from;
            for (int i = from; i < 3; ++i) {
                r.ja.row(i).setZero();
                r.jb.row(i).setZero();
            }
            rowsChanged();
            slackened = true;
        };
        for (int k = 0; k < jointCount(); ++k) {
            const Joint::Type type = joints_[k].type;
            const int count = rows_[k].count;
            const Vec3& lambda = lambda_[k];
            if (type == Joint::Type::Rope && count > 0 && lambda[0] > 0.0)
                letGo(k, 0);
            else if (type == Joint::Type::Pulley && count > 1 && lambda[1] < 0.0)
                letGo(k, 1);
            else if (findLimits_ && type == Joint::Type::Hinge && count > 2 && lambda[2] < 0.0)
                letGo(k, 2);
        }
        if (!slackened) break;
    }
    forcesKnown_ = true;
    if (findLimits_) {
        for (int k = 0; k < jointCount(); ++k)
            heldLimit_[k] = rows_[k].count > 2 && joints_[k].type == Joint::Type::Hinge
                                ? static_cast<int>(rows_[k].target[2])
                                : joints::kNoLimit;
        findLimits_ = false;
    }
    for (int k = 0; k < jointCount(); ++k) {
        const Rows& r = rows_[k];
        joints::zeroFrom(lambda_[k], r.count);
        const Joint::Type type = joints_[k].type;
        forces_[k] = type == Joint::Type::Hinge || type == Joint::Type::Weld
                         ? lambda_[k].head<2>().norm()
                         : std::abs(lambda_[k][0]);
        forceOn_[k][0] = (r.ja.transpose() * lambda_[k]).head<2>();
        forceOn_[k][1] = (r.jb.transpose() * lambda_[k]).head<2>();
    }
}

void JointSolver::constrainAccelerations(const Vec& q, const Vec& u, const Vec& invMass,
                                         Vec& accel) {
    solveDynamics(q, u, invMass, accel);
    addJTranspose(invMass, 1.0, accel);
}

void JointSolver::constrainForces(const Vec& q, const Vec& u, const Vec& invMass, Vec& force,
                                  Vec& scratch) {
    scratch.array() = invMass.array() * force.array();
    solveDynamics(q, u, invMass, scratch);
    for (int k = 0; k < jointCount(); ++k) {
        const Rows& r = rows_[k];
        for (const auto& [end, jac] : {std::pair{&endA_[k], &r.ja}, std::pair{&endB_[k], &r.jb}}) {
            if (end->dof < 0) continue;
            const Vec3 f = jac->transpose() * lambda_[k];
            const int dofs = end->turns ? 3 : 2;
            for (int i = 0; i < dofs; ++i) force[end->dof + i] += f[i];
        }
    }
}

// ---- after the step --------------------------------------------------------------------------

void JointSolver::dropInequalities() {
    if (!hasInequalities_) return;  // the rows are all equalities, those past count zero
    rowsChanged();
    for (int k = 0; k < jointCount(); ++k) {
        Rows& r = rows_[k];
        const Joint::Type type = joints_[k].type;
        // A hinge keeps the limit the step holds: SHAKE holds it as the derivative did.
        if (type == Joint::Type::Hinge)
            r.count = std::min(r.count, heldLimit_[k] != joints::kNoLimit ? 3 : 2);
        if (type == Joint::Type::Pulley) r.count = std::min(r.count, 1);
        for (int i = r.count; i < 3; ++i) {
            r.ja.row(i).setZero();
            r.jb.row(i).setZero();
        }
    }
}

double JointSolver::worstViolation() const {
    double worst = 0.0;
    for (const Rows& r : rows_)
        for (int i = 0; i < r.count; ++i) worst = std::max(worst, std::abs(r.c[i]));
    return worst;
}

void JointSolver::solveFor(const Vec& invMass, Vec& x, double scale, Target target, const Vec& u) {
    factor(invMass);
    for (int k = 0; k < jointCount(); ++k) {
        rhs_[k] = target == Target::Violation ? Vec3(-rows_[k].c)
                  : target == Target::Rate    ? Vec3(rows_[k].target - jTimes(k, u))
                                              : Vec3(-jTimes(k, u));
        joints::zeroFrom(rhs_[k], rows_[k].count);
    }
    solve();
    addJTranspose(invMass, scale, x);
}

void JointSolver::correctPositions(Vec& q, const Vec& u, const Vec& invMass) {
    // What the last SHAKE left is the method's: its equalities are within shakeTolerance_ (at
    // least projectionFloor_).
    for (int it = 0; it < joints::kProjectionIterations; ++it) {
        // Equalities' C depend on q alone, whatever mode evaluated them: at the same q (the
        // velocity projection's, where the contacts moved nothing) they stand.
        if (it > 0 || hasInequalities_ || !rowsAreAt(q)) evaluateRows(Mode::Position, q, u);
        if (worstViolation() <= shakeTolerance_) return;
        Vec& target = q;
        solveFor(invMass, target, 1.0, Target::Violation, u);
    }
}

bool JointSolver::projectVelocities(const Vec& q, Vec& u, const Vec& invMass, bool sameQ) {
    // Without inequalities the rows' J depends on q alone, whatever mode evaluated them (a
    // position projection that has just ended at q): at the same q they stand.
    const bool rowsOfQ = sameQ || rowsAreAt(q);
    if (!rowsOfQ || hasInequalities_) evaluateRows(Mode::Velocity, q, u);
    // An inequality's row here is a catch, unless the step held it (a rope or a hinge limit
    // SHAKE held through the step is the method's equality).
    const auto catches = [&](int k) {
        const Joint::Type type = joints_[k].type;
        return (type == Joint::Type::Rope && rows_[k].count > 0 && !ropeShaken_[k]) ||
               (type == Joint::Type::Hinge && rows_[k].count > 2 &&
                heldLimit_[k] == joints::kNoLimit) ||
               (type == Joint::Type::Pulley && rows_[k].count > 1);
    };
    bool inequality = false;
    for (int k = 0; k < jointCount(); ++k) inequality = inequality || catches(k);
    const Vec& v = u;
    solveFor(invMass, u, 1.0, Target::Rate, v);
    // Stopping one inequality can send another out of its bound (an arm stopped at its limit
    // swings the forearm out past the elbow's): again at the new velocities, the rows of the
    // passes before kept, until no further row moves out.
    for (int pass = 0; hasInequalities_ && pass < kVelocityPasses; ++pass) {
        keptRows_ = rows_;  // same size after the first: no allocation
        evaluateRows(Mode::Velocity, q, u);
        bool more = false;
        for (int k = 0; k < jointCount(); ++k) {
            if (rows_[k].count < keptRows_[k].count) {
                rows_[k] = keptRows_[k];
            } else if (rows_[k].count > keptRows_[k].count) {
                more = true;
                inequality = inequality || catches(k);
            }
        }
        if (!more) break;
        rowsChanged();
        solveFor(invMass, u, 1.0, Target::Rate, v);
    }
    return inequality;
}

void JointSolver::projectChange(Vec& x, const Vec& invMass) {
    const Vec& v = x;
    solveFor(invMass, x, 1.0, Target::Zero, v);
}

double JointSolver::driveMotors(double h, const Vec& q, Vec& u, const Vec& mass, const Vec& invMass,
                                bool held) {
    lastMotorWork_ = 0.0;
    if (!hasMotors_) return 0.0;
    const auto kinetic = [&] { return 0.5 * (mass.array() * u.array().square()).sum(); };
    const double before = kinetic();
    // What the held torques gave in the method's step (addHeldMotorTorques()).
    for (int k = 0; k < jointCount(); ++k) motorImpulse_[k] = held ? heldTorque(k) * h : 0.0;
    for (int it = 0; it < kMotorIterations; ++it) {
        for (int k = 0; k < jointCount(); ++k) {
            const Joint& j = joints_[k];
            const End& a = endA_[k];
            const End& b = endB_[k];
            if (!j.hasMotor || !takesTorque(a) || !takesTorque(b)) continue;
            const double ia = a.turns ? invMass[a.dof + 2] : 0.0;
            const double ib = b.turns ? invMass[b.dof + 2] : 0.0;
            if (ia + ib <= 0.0) continue;
            const double rate = (b.turns ? u[b.dof + 2] : 0.0) - (a.turns ? u[a.dof + 2] : 0.0);
            const double limit = j.maxMotorTorque * h;
            const double old = motorImpulse_[k];
            motorImpulse_[k] = std::clamp(old + (j.motorSpeed - rate) / (ia + ib), -limit, limit);
            const double impulse = motorImpulse_[k] - old;
            if (a.turns) u[a.dof + 2] -= ia * impulse;
            if (b.turns) u[b.dof + 2] += ib * impulse;
        }
        projectVelocities(q, u, invMass, it > 0);
    }
    for (int k = 0; k < jointCount(); ++k) heldMotorTorque_[k] = motorImpulse_[k] / h;
    lastMotorWork_ = kinetic() - before;
    return lastMotorWork_;
}

double JointSolver::heldTorque(int k) const {
    const Joint& j = joints_[k];
    if (!j.hasMotor || !takesTorque(endA_[k]) || !takesTorque(endB_[k])) return 0.0;
    const double most = j.maxMotorTorque;
    return std::clamp(heldMotorTorque_[k], -most, most);
}

bool JointSolver::addHeldMotorTorques(Vec& force) const {
    bool any = false;
    for (int k = 0; hasMotors_ && k < jointCount(); ++k) {
        const double torque = heldTorque(k);
        if (torque == 0.0) continue;
        const End& a = endA_[k];
        const End& b = endB_[k];
        if (a.turns) force[a.dof + 2] -= torque;
        if (b.turns) force[b.dof + 2] += torque;
        any = any || a.turns || b.turns;
    }
    return any;
}

int JointSolver::substepsFor(double h, const Vec& q, const Vec& u) const {
    double rate = 0.0;
    // The rate at which the direction from a fixed point c to a moving point turns.
    const auto turning = [](const Vec2& d, const Vec2& v) {
        const double len = d.norm();
        return len > 0.0 ? std::abs(cross(d, v)) / (len * len) : 0.0;
    };
    // The rotations of the last rows where those were of this q (the frame's start is the last
    // step's end).
    const bool cached = rotationsAreAt(q);
    for (int k = 0; k < jointCount(); ++k) {
        const Joint& j = joints_[k];
        const EndState a = evaluate(endA_[k], q, u, cached), b = evaluate(endB_[k], q, u, cached);
        for (const EndState* s : {&a, &b})
            if (s->arm.squaredNorm() > 0.0) rate = std::max(rate, std::abs(s->omega));
        switch (j.type) {
            case Joint::Type::Rod:
            case Joint::Type::Rope:
                rate = std::max(rate, turning(a.p - b.p, a.v - b.v));
                break;
            case Joint::Type::Pulley:
                rate =
                    std::max({rate, turning(a.p - j.groundA, a.v), turning(b.p - j.groundB, b.v)});
                break;
            case Joint::Type::Track:
                if (j.circle) rate = std::max(rate, turning(a.p - j.center, a.v));
                break;
            case Joint::Type::Hinge:
            case Joint::Type::Weld:
                break;
        }
    }
    const double n = std::ceil(h * rate / kMaxTurnPerStep);
    return substepCount(n);
}

double JointSolver::geometricFrequency(const Vec& q, const Vec& invMass) {
    // Gershgorin's bound on the largest eigenvalue of W·K, row by row of K: a hinge's or a
    // weld's point row is linear in the positions and curved only in the angle, F·r on the
    // diagonal; a distance row of length d adds F/d on each end's translation and as much
    // again across to the other end, and F·r²/d with F·r on a turning end's angle.
    stiffness_.assign(static_cast<std::size_t>(invMass.size()), 0.0);  // same size: no allocation
    for (int k = 0; k < jointCount(); ++k) {
        const double f = forces_[k];
        if (!(f > 0.0)) continue;
        const Joint& j = joints_[k];
        if (implicitLimit_ > 0.0 && (j.type == Joint::Type::Hinge || j.type == Joint::Type::Weld))
            continue;         // shake() takes their stiffness implicitly
        double length = 0.0;  // a distance row's current length; 0: no distance row
        switch (j.type) {
            case Joint::Type::Rod:
            case Joint::Type::Rope:
                length = (pointA(k, q) - pointB(k, q)).norm();
                break;
            case Joint::Type::Pulley:
                length =
                    std::min((pointA(k, q) - j.groundA).norm(), (pointB(k, q) - j.groundB).norm());
                break;
            case Joint::Type::Track:
                if (j.circle) length = (pointA(k, q) - j.center).norm();
                break;
            case Joint::Type::Hinge:
            case Joint::Type::Weld:
                break;
        }
        const double sideways = length > 0.0 ? f / length : 0.0;
        for (const End* e : {&endA_[k], &endB_[k]}) {
            if (e->dof < 0) continue;
            stiffness_[e->dof] += 2.0 * sideways;
            stiffness_[e->dof + 1] += 2.0 * sideways;
            if (e->turns) {
                const double r = e->local.norm();
                stiffness_[e->dof + 2] += f * r + 2.0 * sideways * r * r;
            }
        }
    }
    double fastest = 0.0;
    for (std::size_t i = 0; i < stiffness_.size(); ++i)
        fastest = std::max(fastest, stiffness_[i] * invMass[static_cast<Eigen::Index>(i)]);
    return std::sqrt(fastest);
}

}  // namespace phasebox
