#include "physics/effects/WindEffect.h"

namespace phasebox {

double WindEffect::addForces(double, const Vec&, const Vec& u, Vec& force) {
    double power = 0.0;
    const int end = view_.layout->rigidBase();
    for (int i = 0; i < end; i += 2) {
        const Vec2 f = drag_ * (wind_ - u.segment<2>(i));
        force.segment<2>(i) += f;
        power += f.dot(u.segment<2>(i));
    }
    return power;
}

double WindEffect::nonConservativePower(double, const Vec&, const Vec& u) {
    double power = 0.0;
    const int end = view_.layout->rigidBase();
    for (int i = 0; i < end; i += 2)
        power += drag_ * (wind_ - u.segment<2>(i)).dot(u.segment<2>(i));
    return power;
}

void WindEffect::addJacobians(double, const Vec&, const Vec&, ForceJacobians& jacobians) {
    const int end = view_.layout->rigidBase();
    for (int i = 0; i < end; ++i) jacobians.addDamping(i, i, -drag_);
}

}  // namespace phasebox
