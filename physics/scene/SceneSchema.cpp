// The schema's own part and the simulation's table: the "simulation" section's fields, the
// contact solver's settings, the top-level keys, the effects' keys in order, and what a Range
// says of its lowest value. The effects' tables are in EffectSchema.cpp, the objects' in
// ObjectSchema.cpp, the joints' in JointSchema.cpp.
#include "physics/scene/SceneSchema.h"

#include "physics/scene/SchemaFields.h"

#include <stdexcept>
#include <string>
#include <vector>

namespace phasebox::schema {

namespace {

using namespace fields;

// ---- simulation ----

// The time step's upper bound, for the format, World and the commands alike (a step of more than
// a second skips past every motion a classroom scene has). The editors' lower bound is a
// hundred-thousandth of a second: a valid scene may go below it, and the editor then widens.
constexpr Range kDt = {Bound::PositiveUpTo, 1.0, 0.0};

// The parameters panel's everyday ranges of the settings that the format allows far past them.
constexpr double kLargeSetting = 1e12;

const Field<SimulationDesc> kSimulation[] = {
    {.key = key::integrator,
     .type = T::String,
     .member = &SimulationDesc::integrator,
     .label = "Integrator",
     .description = "one of the registered integrators (CONTRACT §3)",
     .rule = Rule::KnownIntegrator},
    {.key = key::dt,
     .type = T::Number,
     .member = &SimulationDesc::dt,
     .range = kDt,
     .unit = "s",
     .label = "Time step",
     .description = "the frame step: the time one step advances",
     .editor = {.min = 1e-5, .max = kDt.max}},
    {.key = key::substeps,
     .type = T::Integer,
     .member = &SimulationDesc::substeps,
     .range = {Bound::IntegerAtLeast, L::kMaxSubsteps, 1.0},
     .label = "Sub-steps",
     .description = "each step is split into this many equal sub-steps",
     .editor = {.min = 1.0, .max = 1000.0}},
    {.key = key::tolerance,
     .type = T::Number,
     .member = &SimulationDesc::tolerance,
     .range = positive(L::kMaxCoefficient, L::kMinTolerance),
     .label = "Tolerance",
     .description = "local error tolerance of the adaptive integrators",
     .editor = {.min = 1e-15, .max = 1.0}},
    {.key = key::newtonIterations,
     .type = T::Integer,
     .member = &SimulationDesc::newtonIterations,
     .range = {Bound::IntegerAtLeast, L::kMaxNewtonIterations, 1.0},
     .label = "Newton iterations",
     .description = "Newton iterations of implicit_euler (1 = the linearised step)",
     .editor = {.min = 1.0, .max = L::kMaxNewtonIterations}},
    {.key = key::duration,
     .type = T::Number,
     .member = &SimulationDesc::duration,
     .range = positive(L::kMaxDuration),
     .unit = "s",
     .label = "Duration",
     .description = "default run length of phasebox-cli run"},
    {.key = key::solver,
     .type = T::NumberMap,
     .member = &SimulationDesc::solver,
     .label = "Contact solver",
     .description = "contact solver settings, all optional",
     .present = [](const SimulationDesc& s) { return !s.solver.empty(); }},
    {.key = key::contactModel,
     .type = T::Choice,
     .member = &SimulationDesc::contactModel,
     .label = "Contact model",
     .description = "how contacts respond: impulse, penalty or kinematic",
     .present = [](const SimulationDesc& s) { return s.contactModel != ContactModel::Impulse; },
     .choices = kContactModelNames},
    {.key = key::contactStiffness,
     .type = T::Number,
     .member = &SimulationDesc::contactStiffness,
     .range = positive(L::kMaxCoefficient),
     .unit = "N/m",
     .label = "Contact stiffness",
     .description = "penalty stiffness per contact point; absent: the lightest body gets "
                    "omega*h = 0.5",
     .editor = {.min = 1e-3, .max = kLargeSetting}},
    {.key = key::contactDamping,
     .type = T::Number,
     .member = &SimulationDesc::contactDamping,
     .range = nonNegative(L::kMaxCoefficient),
     .unit = "N s/m",
     .label = "Contact damping",
     .description = "penalty damping per contact point",
     .editor = {.min = 0.0, .max = kLargeSetting},
     .present = [](const SimulationDesc& s) { return s.contactDamping != 0.0; }},
    {.key = key::sleep,
     .type = T::Bool,
     .member = &SimulationDesc::sleep,
     .label = "Sleep",
     .description = "islands at rest for 0.5 s stop being stepped until something wakes them",
     .present = [](const SimulationDesc& s) { return s.sleep; }},
};

const SolverSetting kSolverSettings[] = {
    {key::substeps,
     {Bound::IntegerBetween, 64.0, 0.0},
     "inner sub-steps of the contact solver per step; 0: the solver's choice"},
    {key::iterations,
     {Bound::IntegerBetween, 1000.0, 0.0},
     "soft velocity iterations per inner sub-step"},
    {key::relaxIterations,
     {Bound::IntegerBetween, 1000.0, 0.0},
     "relax iterations per inner sub-step"},
    {key::contactHertz, positive(L::kMaxCoefficient), "stiffness of the soft contact, in Hz"},
    {key::dampingRatio, nonNegative(L::kMaxCoefficient), "damping ratio of the soft contact"},
    {key::pushOut, positive(L::kMaxCoefficient), "largest speed that pushes overlaps apart"},
    {key::restitutionThreshold, nonNegative(L::kMaxCoefficient),
     "approach speed below which contacts do not bounce"},
    {key::speculativeDistance, nonNegative(L::kMaxCoefficient),
     "distance at which contacts are created before touching"},
};

}  // namespace

double Range::lowest() const {
    switch (bound) {
        case Bound::Symmetric:
            return -max;
        case Bound::Positive:
        case Bound::IntegerAtLeast:
        case Bound::IntegerBetween:
            return min;
        case Bound::NonNegative:
        case Bound::UnitInterval:
        case Bound::PositiveUpTo:
            return 0.0;
        case Bound::None:
            break;
    }
    return -std::numeric_limits<double>::infinity();
}

bool Range::lowestExcluded() const {
    return (bound == Bound::Positive && min <= 0.0) || bound == Bound::PositiveUpTo;
}

std::span<const SolverSetting> solverSettings() {
    return kSolverSettings;
}
std::span<const std::string_view> topKeys() {
    // The object arrays' keys are their tables'.
    static const std::vector<std::string_view> keys = [] {
        std::vector<std::string_view> out{key::format,      key::version,    key::name,
                                          key::description, key::simulation, key::effects};
        forEachObjectKind([&](const auto& table, auto) { out.push_back(table.key); });
        out.push_back(key::instruments);
        return out;
    }();
    return keys;
}

std::span<const std::string_view> effectKeys() {
    static const std::vector<std::string_view> keys = [] {
        std::vector<std::string_view> out;
        forEachEffect([&](const auto& t, auto) { out.push_back(t.key); });
        return out;
    }();
    return keys;
}

PB_TABLE(SimulationDesc, key::simulation, "how time advances", kSimulation)

const Field<SimulationDesc>& simulationField(std::string_view key) {
    for (const Field<SimulationDesc>& f : kSimulation)
        if (f.key == key) return f;
    throw std::invalid_argument("no simulation setting \"" + std::string(key) + "\"");
}

}  // namespace phasebox::schema
