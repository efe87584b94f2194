#include "physics/scene/InstrumentValidation.h"

#include "physics/scene/SceneSchema.h"
#include "physics/world/Probes.h"

#include <cmath>

namespace phasebox {

namespace {

namespace key = schema::key;

std::string at(std::string_view k) {
    return std::string(key::instruments) + "." + std::string(k);
}
std::string at(std::string_view k, std::size_t i) {
    return at(k) + "[" + std::to_string(i) + "]";
}

// The parser's message without the vocabulary it lists after "; known:" (a file's reader
// wants the reason; the list is in the docs and in `run --probe`'s message).
std::string reason(const std::string& message) {
    const std::size_t known = message.find("; known");
    return known == std::string::npos ? message : message.substr(0, known);
}

template <typename Ends>
std::string call(std::string_view name, const Ends& ends) {
    std::string text(name);
    text += '(';
    for (std::size_t i = 0; i < ends.size(); ++i) text += (i ? "," : "") + ends[i];
    return text + ')';
}

}  // namespace

std::string rulerProbe(const RulerDesc& ruler) {
    return call("distance", ruler.ends);
}
std::string protractorProbe(const ProtractorDesc& protractor) {
    return call("angle", protractor.ends);
}

void validateInstrumentValues(const InstrumentsDesc& in, std::vector<SceneIssue>& issues) {
    if (!in.view) return;
    const double far = SceneLimits::kMaxLength;
    for (std::size_t i = 0; i < 2; ++i)
        if (!(std::abs(in.view->center[i]) <= far))
            issues.push_back(
                {at(key::view) + "." + std::string(key::center) + "[" + std::to_string(i) + "]",
                 "must be within ±1e6"});
    if (!(in.view->width > 0.0 && in.view->width <= 2.0 * far))
        issues.push_back(
            {at(key::view) + "." + std::string(key::width), "must be > 0 and at most 2e6"});
}

std::vector<SceneIssue> checkInstruments(const InstrumentsDesc& in, const World& world) {
    std::vector<SceneIssue> issues;
    auto probe = [&](const std::string& text, std::string path) {
        if (const ProbeParse parsed = parseProbe(world, text); !parsed)
            issues.push_back({std::move(path), reason(parsed.error)});
    };
    for (std::size_t i = 0; i < in.probes.size(); ++i) probe(in.probes[i], at(key::probes, i));
    for (std::size_t i = 0; i < in.graphs.size(); ++i) {
        probe(in.graphs[i].y, at(key::graphs, i) + "." + std::string(key::y));
        if (!in.graphs[i].x.empty())
            probe(in.graphs[i].x, at(key::graphs, i) + "." + std::string(key::x));
    }
    for (std::size_t i = 0; i < in.timers.size(); ++i) probe(in.timers[i], at(key::timers, i));
    for (std::size_t i = 0; i < in.rulers.size(); ++i)
        probe(rulerProbe(in.rulers[i]), at(key::rulers, i) + "." + std::string(key::ends));
    for (std::size_t i = 0; i < in.protractors.size(); ++i)
        probe(protractorProbe(in.protractors[i]),
              at(key::protractors, i) + "." + std::string(key::ends));
    if (!in.freeBody.empty() && !findProbeObject(world, in.freeBody))
        issues.push_back({at(key::freeBody), "no object \"" + in.freeBody + "\""});
    return issues;
}

}  // namespace phasebox
