// The app library's precompiled header (app/CMakeLists.txt): Qt's widgets and files, the standard
// library, and the engine's and the document's headers that most of its sources include, parsed
// once for the library's 80 sources instead of once each. A source's own includes still say what
// it uses.
#pragma once

#include <QAction>
#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QMessageBox>
#include <QSettings>
#include <QString>
#include <QWidget>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <utility>
#include <vector>

#include "app/document/Document.h"
#include "app/sim/SimulationController.h"
#include "physics/scene/BuildWorld.h"
#include "physics/world/World.h"
