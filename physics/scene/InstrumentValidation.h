#pragma once
// Checks a scene's instruments (CONTRACT §7), with JSON paths as validateScene() gives them.
//
// What needs only the description (the view's numbers) is part of validateScene(); what names
// the world's objects (every probe, a ruler's or protractor's ends, the free body) is checked
// against the built world by buildWorld(), with the probes' own parser, so an instrument is
// valid exactly when the probe it reads is.

#include "physics/scene/SceneDesc.h"

#include <string>
#include <vector>

namespace phasebox {

class World;

void validateInstrumentValues(const InstrumentsDesc& instruments, std::vector<SceneIssue>& issues);
std::vector<SceneIssue> checkInstruments(const InstrumentsDesc& instruments, const World& world);

// The probe a ruler or protractor reads: distance(A,B), angle(A,B,C).
std::string rulerProbe(const RulerDesc& ruler);
std::string protractorProbe(const ProtractorDesc& protractor);

}  // namespace phasebox
