// The precompiled header of the engine's suites (physics/ and stability/): Qt Test, the standard
// library and the engine's most included headers, parsed once for all of them
// (tests/CMakeLists.txt). A suite's own includes still say what it uses; this only makes them
// cheap. (Each suite parsed these headers for 6 to 10 of its 10 to 15 seconds of compiling.)
#pragma once

#include <QObject>
#include <QString>
#include <QTest>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "physics/scene/BuildWorld.h"
#include "physics/scene/SceneLibrary.h"
#include "physics/world/World.h"
