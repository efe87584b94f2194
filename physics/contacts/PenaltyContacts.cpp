#include "physics/contacts/PenaltyContacts.h"

#include <algorithm>
#include <cmath>

namespace phasebox {

namespace {

double cross(const Vec2& r, const Vec2& e) {
    return r.x() * e.y() - r.y() * e.x();
}

// A contact point's generalised directions: the state indices it moves and, per index, how the
// relative velocity of B's point against A's along the normal (gn) and the tangent (gt)
// depends on that velocity. A force f along the normal then acts on the state as f·gn.
struct PointDirections {
    int dof[6];
    double gn[6], gt[6];
    int count = 0;

    void add(int index, double n, double t) {
        dof[count] = index;
        gn[count] = n;
        gt[count] = t;
        ++count;
    }
    void addBody(int first, bool rotates, const Vec2& r, const Vec2& n, const Vec2& t,
                 double sign) {
        if (first < 0) return;
        add(first, sign * n.x(), sign * t.x());
        add(first + 1, sign * n.y(), sign * t.y());
        if (rotates) add(first + 2, sign * cross(r, n), sign * cross(r, t));
    }
};

}  // namespace

PenaltyContacts::Sums PenaltyContacts::evaluate(const Vec& q, const Vec* u, Vec* force,
                                                ForceJacobians* jacobians, int only) const {
    Sums sums;
    if (!stage_ || !bodies_) return sums;
    const Vec& mass = *view_.mass;
    const double k = stiffness_, c = damping_;
    for (const TouchingManifold& m : stage_->overlaps(*bodies_, q)) {
        const Vec2 n = m.normal, t(-n.y(), n.x());
        for (int p = 0; p < m.pointCount; ++p) {
            const TouchingManifold::Point& point = m.points[p];
            const double d = point.depth;
            sums.potential += 0.5 * k * d * d;
            if (!u) continue;
            PointDirections g;
            g.addBody(m.dofA, m.rotatesA, point.rA, n, t, -1.0);
            g.addBody(m.dofB, m.rotatesB, point.rB, n, t, 1.0);
            double vn = 0.0, vt = 0.0, tangentInverseMass = 0.0;
            for (int i = 0; i < g.count; ++i) {
                vn += g.gn[i] * (*u)[g.dof[i]];
                vt += g.gt[i] * (*u)[g.dof[i]];
                tangentInverseMass += g.gt[i] * g.gt[i] / mass[g.dof[i]];
            }
            // The overlap grows at −vn (B moving into A along the normal).
            const double normal = k * d - c * vn;
            // Regularised Coulomb: μ·F_n·vt/√(vt² + ε²). Its slope at zero slip, μ·F_n/ε, is a
            // damping the step must resolve: ε is at least μ·F_n·h/m_t so that an explicit
            // step never overshoots the sticking point.
            const double limit = m.friction * std::max(normal, 0.0);
            const double slip =
                std::max(kMinSlip, limit * step_ * std::max(tangentInverseMass, 0.0));
            const double root = std::sqrt(vt * vt + slip * slip);
            const double tangent = -limit * vt / root;
            sums.power += -c * vn * vn + tangent * vt;
            if (force)
                for (int i = 0; i < g.count; ++i)
                    if (only < 0 || g.dof[i] == only || g.dof[i] == only + 1)
                        (*force)[only < 0 ? g.dof[i] : g.dof[i] - only] +=
                            normal * g.gn[i] + tangent * g.gt[i];
            if (jacobians) {
                // K = −k·gn·gnᵀ (the overlap shrinks as B moves along n); D = −c·gn·gnᵀ and the
                // friction's slope along the tangent. The normal's turning and the lever arms'
                // change are left out: what remains is symmetric and negative semi-definite.
                const double frictionSlope = limit * slip * slip / (root * root * root);
                for (int i = 0; i < g.count; ++i)
                    for (int j = 0; j < g.count; ++j) {
                        jacobians->addStiffness(g.dof[i], g.dof[j], -k * g.gn[i] * g.gn[j]);
                        const double damping =
                            c * g.gn[i] * g.gn[j] + frictionSlope * g.gt[i] * g.gt[j];
                        if (damping != 0.0) jacobians->addDamping(g.dof[i], g.dof[j], -damping);
                    }
            }
        }
    }
    return sums;
}

double PenaltyContacts::addForces(double, const Vec& q, const Vec& u, Vec& force) {
    return evaluate(q, &u, &force, nullptr).power;
}

double PenaltyContacts::nonConservativePower(double, const Vec& q, const Vec& u) {
    return evaluate(q, &u, nullptr, nullptr).power;
}

void PenaltyContacts::addJacobians(double, const Vec& q, const Vec& u, ForceJacobians& jacobians) {
    evaluate(q, &u, nullptr, &jacobians);
}

double PenaltyContacts::addForcesAndJacobians(double, const Vec& q, const Vec& u, Vec& force,
                                              ForceJacobians& jacobians) {
    return evaluate(q, &u, &force, &jacobians).power;
}

Vec2 PenaltyContacts::forceOn(const Vec& q, const Vec& u, int dof) const {
    Vec force = Vec::Zero(2);
    evaluate(q, &u, &force, nullptr, dof);
    return force;
}

int PenaltyContacts::overlappingPoints(const Vec& q) const {
    int points = 0;
    if (stage_ && bodies_)
        for (const TouchingManifold& m : stage_->overlaps(*bodies_, q)) points += m.pointCount;
    return points;
}

double PenaltyContacts::potentialEnergy(const Vec& q) const {
    return evaluate(q, nullptr, nullptr, nullptr).potential;
}

}  // namespace phasebox
