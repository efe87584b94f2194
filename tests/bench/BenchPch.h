// The precompiled header of the benchmarks that link the engine alone (tests/bench/CMakeLists.txt):
// the standard library, Eigen and the engine's most included headers, parsed once for all of
// them. A benchmark's own includes still say what it uses. Not AllocationCounter.h: it replaces
// the global operator new, which only the benchmarks that count allocations may do.
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "physics/contacts/ContactStage.h"
#include "physics/scene/BuildWorld.h"
#include "physics/scene/SceneDesc.h"
#include "physics/scene/SceneLibrary.h"
#include "physics/world/World.h"
