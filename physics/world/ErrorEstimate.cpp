#include "physics/world/ErrorEstimate.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace phasebox {

double LocalErrorEstimator::estimate(OdeSystem& system, const Integrator& running, double t,
                                     double h, const Vec& q, const Vec& u) {
    const int n = system.dimension();
    if (n == 0) return 0.0;
    const IntegratorInfo& info = running.info();
    if (!method_ || method_->info().name != info.name) {
        method_ = makeIntegrator(info.name);
        method_->reset(n);
    }
    for (int k = 0; k < 3; ++k) {
        if (q_[k].size() != n) {
            q_[k].resize(n);
            u_[k].resize(n);
            method_->reset(n);
        }
    }
    method_->setSettings(running.settings());
    double work = 0.0;
    bool ok = method_->step(system, t, h, q, u, q_[0], u_[0], work);
    ok = ok && method_->step(system, t, 0.5 * h, q, u, q_[1], u_[1], work);
    ok = ok && method_->step(system, t + 0.5 * h, 0.5 * h, q_[1], u_[1], q_[2], u_[2], work);
    if (!ok) return std::numeric_limits<double>::infinity();
    const double difference = (q_[0] - q_[2]).lpNorm<Eigen::Infinity>();
    const double p = std::max(1, info.order);
    return difference / (1.0 - std::pow(2.0, -p));
}

}  // namespace phasebox
