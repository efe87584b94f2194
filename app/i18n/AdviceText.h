#pragma once
// The stability advisor's sentences in the window's language. physics/ has no Qt and writes its
// advice in English for the command line (CONTRACT §4); the window composes the same sentences
// here from the advice's numbers (ω, the sub-step, each method's largest stable step), with
// its numbers in the locale. A sentence this file does not know is shown as the engine wrote it.

#include <QString>

#include <string>

namespace phasebox {

struct StabilityAdvice;
struct SimulationSettings;

namespace i18n {

// advice.message for a world with these settings, translated (the engine's "omega*h" as "ω·h").
QString adviceText(const StabilityAdvice& advice, const SimulationSettings& settings);

// advice.contactWarning (contactModelWarning()), translated; empty for none.
QString contactWarningText(const std::string& warning);

}  // namespace i18n
}  // namespace phasebox
