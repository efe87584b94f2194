#pragma once
// Factories of the concrete methods; only the registry calls them.

#include "physics/integrators/Integrator.h"

#include <limits>

namespace phasebox::methods {

// The stability bound of a method stable at any step (IntegratorInfo::stabilityBound).
inline constexpr double kInfinity = std::numeric_limits<double>::infinity();

std::unique_ptr<Integrator> makeExplicitEuler();
std::unique_ptr<Integrator> makeSymplecticEuler();
std::unique_ptr<Integrator> makeMidpoint();
std::unique_ptr<Integrator> makeHeun();
std::unique_ptr<Integrator> makeRungeKutta4();
std::unique_ptr<Integrator> makeVelocityVerlet();
std::unique_ptr<Integrator> makeImplicitEuler();
std::unique_ptr<Integrator> makeImplicitMidpoint();
std::unique_ptr<Integrator> makeAdaptiveEuler();
std::unique_ptr<Integrator> makeDormandPrince();

// Registry entries, so each method's file states its own facts.
extern const IntegratorInfo kExplicitEulerInfo;
extern const IntegratorInfo kSymplecticEulerInfo;
extern const IntegratorInfo kMidpointInfo;
extern const IntegratorInfo kHeunInfo;
extern const IntegratorInfo kRungeKutta4Info;
extern const IntegratorInfo kVelocityVerletInfo;
extern const IntegratorInfo kImplicitEulerInfo;
extern const IntegratorInfo kImplicitMidpointInfo;
extern const IntegratorInfo kAdaptiveEulerInfo;
extern const IntegratorInfo kDormandPrinceInfo;

}  // namespace phasebox::methods
