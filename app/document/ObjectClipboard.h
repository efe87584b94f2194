#pragma once
// Copy and paste of objects. What is copied is a scene of its own: the setup with only the
// chosen objects (and the springs whose ends all come along), so the clipboard's text is a
// scene file that another Phasebox, a text editor or `phasebox-cli` can use as it is; pasting
// any valid scene's text adds its objects. Pasted objects take fresh ids, and springs follow
// their ends to the new ids.

#include "app/document/PropertyTable.h"
#include "physics/scene/SceneDesc.h"

#include <QStringList>

#include <vector>

namespace phasebox {

// The MIME type of copied objects (the same text also goes out as plain text).
inline constexpr const char* kSceneMimeType = "application/x-phasebox-scene+json";

// The setup with only these objects (a node id copies its cloth) and the connectors (springs,
// joints) whose bodies are each copied or the world (one chosen without its bodies stays
// behind). Simulation settings and effects are kept.
SceneDesc copyObjects(const SceneDesc& scene, const QStringList& ids);

// The fragment's objects ready to add to target: each with an id no object of target uses,
// springs renamed with their ends (cloth nodes included), everything shifted by offset.
std::vector<ObjectDesc> pastedObjects(const SceneDesc& target, const SceneDesc& fragment,
                                      const Point2& offset);

}  // namespace phasebox
