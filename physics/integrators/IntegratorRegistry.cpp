#include "physics/integrators/Integrator.h"
#include "physics/integrators/Methods.h"

#include <array>

namespace phasebox {

namespace {
struct Entry {
    const IntegratorInfo* info;
    std::unique_ptr<Integrator> (*make)();
};

const std::array<Entry, 10>& entries() {
    using namespace methods;
    static const std::array<Entry, 10> table{{
        {&kExplicitEulerInfo, makeExplicitEuler},
        {&kSymplecticEulerInfo, makeSymplecticEuler},
        {&kMidpointInfo, makeMidpoint},
        {&kHeunInfo, makeHeun},
        {&kRungeKutta4Info, makeRungeKutta4},
        {&kVelocityVerletInfo, makeVelocityVerlet},
        {&kImplicitEulerInfo, makeImplicitEuler},
        {&kImplicitMidpointInfo, makeImplicitMidpoint},
        {&kAdaptiveEulerInfo, makeAdaptiveEuler},
        {&kDormandPrinceInfo, makeDormandPrince},
    }};
    return table;
}

const std::array<IntegratorInfo, 10>& infos() {
    static const std::array<IntegratorInfo, 10> table = [] {
        std::array<IntegratorInfo, 10> out{};
        for (std::size_t i = 0; i < out.size(); ++i) out[i] = *entries()[i].info;
        return out;
    }();
    return table;
}
}  // namespace

std::span<const IntegratorInfo> integratorRegistry() {
    return infos();
}

const IntegratorInfo* findIntegrator(std::string_view name) {
    for (const IntegratorInfo& info : infos())
        if (info.name == name) return &info;
    return nullptr;
}

std::string knownIntegratorNames() {
    std::string out;
    for (const IntegratorInfo& info : infos()) {
        if (!out.empty()) out += ", ";
        out += info.name;
    }
    return out;
}

std::unique_ptr<Integrator> makeIntegrator(std::string_view name,
                                           const IntegratorSettings& settings) {
    for (const Entry& entry : entries()) {
        if (entry.info->name != name) continue;
        auto integrator = entry.make();
        integrator->setSettings(settings);
        return integrator;
    }
    return nullptr;
}

}  // namespace phasebox
