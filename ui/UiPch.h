// The widget library's precompiled header (ui/CMakeLists.txt): Qt's widgets, painting and charts
// and the standard library headers most of its sources include, parsed once instead of once each.
#pragma once

#include <QChart>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineSeries>
#include <QMenu>
#include <QPainter>
#include <QToolButton>
#include <QVBoxLayout>
#include <QWidget>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "physics/core/Types.h"
