#pragma once
// The kinematic contact model (CONTRACT §6): no forces. After the smooth step, two overlapping
// bodies are moved apart along the normal in proportion to their inverse masses; where the
// relative normal velocity at a contact point is approaching, an impulse at that point reflects
// it scaled by e, and another scales the tangential relative velocity by max(0, 1 − μ).

#include "physics/contacts/ContactStage.h"

#include <vector>

namespace phasebox {

// The two halves of the response, apart so that the world can book each (the push-out's energy
// is correction, the impulses' losses work_nc). invMass per state index; the overlaps were
// found at q before the push-out, whose lever arms the impulses use.
void separateKinematically(const std::vector<TouchingManifold>& overlaps, const Vec& invMass,
                           Vec& q);
void reflectKinematically(const std::vector<TouchingManifold>& overlaps, const Vec& invMass,
                          Vec& u);

}  // namespace phasebox
