// The precompiled header of the app's suites (app/, cli/ and gui/): the engine's, Qt's widgets and
// files, and the app's most included headers (tests/CMakeLists.txt, EnginePch.h).
#pragma once

#include "tests/support/EnginePch.h"

#include <QAction>
#include <QApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QStandardPaths>
#include <QTemporaryDir>

#include "app/desktop/MainWindow.h"
#include "app/document/Document.h"
#include "app/io/SceneIO.h"
#include "ui/canvas/SceneView.h"
