// The engine library's precompiled header (physics/CMakeLists.txt): Eigen and the standard library
// headers most of its sources include, parsed once for the library's sources instead of once
// each. Only headers that rarely change: a change here compiles the whole engine again.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "physics/core/Types.h"
