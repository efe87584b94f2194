#include "physics/effects/GravityEffect.h"

namespace phasebox {

double GravityEffect::addForces(double, const Vec&, const Vec&, Vec& force) {
    const StateLayout& layout = *view_.layout;
    const double* __restrict m = view_.mass->data();
    double* __restrict f = force.data();
    const double gx = g_.x(), gy = g_.y();
    const int particleEnd = layout.rigidBase();
    for (int i = 0; i < particleEnd; i += 2) {
        f[i] += m[i] * gx;
        f[i + 1] += m[i + 1] * gy;
    }
    for (int b = 0; b < layout.dynamicRigidBodies; ++b) {
        const int i = layout.rigidDof(b);
        f[i] += m[i] * gx;
        f[i + 1] += m[i + 1] * gy;
    }
    return 0.0;
}

void GravityEffect::addAccelerations(double, const Vec&, const Vec&, Vec& accel, bool overwrite) {
    const StateLayout& layout = *view_.layout;
    double* __restrict a = accel.data();
    const double gx = g_.x(), gy = g_.y();
    const int particleEnd = layout.rigidBase();
    if (overwrite) {
        for (int i = 0; i < particleEnd; i += 2) {
            a[i] = gx;
            a[i + 1] = gy;
        }
        for (int b = 0; b < layout.dynamicRigidBodies; ++b) {
            const int i = layout.rigidDof(b);
            a[i] = gx;
            a[i + 1] = gy;
            a[i + 2] = 0.0;
        }
        return;
    }
    for (int i = 0; i < particleEnd; i += 2) {
        a[i] += gx;
        a[i + 1] += gy;
    }
    for (int b = 0; b < layout.dynamicRigidBodies; ++b) {
        const int i = layout.rigidDof(b);
        a[i] += gx;
        a[i + 1] += gy;
    }
}

double GravityEffect::potentialEnergy(const Vec& q) const {
    const StateLayout& layout = *view_.layout;
    const double* m = view_.mass->data();
    const double gx = g_.x(), gy = g_.y();
    double sum = 0.0;
    const int particleEnd = layout.rigidBase();
    for (int i = 0; i < particleEnd; i += 2) sum += m[i] * (gx * q[i] + gy * q[i + 1]);
    for (int b = 0; b < layout.dynamicRigidBodies; ++b) {
        const int i = layout.rigidDof(b);
        sum += m[i] * (gx * q[i] + gy * q[i + 1]);
    }
    return -sum;
}

}  // namespace phasebox
