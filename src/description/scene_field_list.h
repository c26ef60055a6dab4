// Every key of the scene file as a flat list, with its key path: what the viewer looks a change's
// reach up in (viewer/scene_edit.h), and what the tests check every key against.
#pragma once

#include "description/scene_field.h"

#include <string>
#include <vector>

namespace urbis {

/// A key of the scene file and where it is: "integrator.max_depth".
struct FieldAtPath {
    std::string path;
    Field field;
};

/// Every Field of visitSceneFields in file order, the optional objects (camera.geo, planet) and their
/// keys included as if they were set.
const std::vector<FieldAtPath>& sceneFieldList();

} // namespace urbis
