// Edits of a scene description as the viewer makes them: a part of a scene file laid over the
// description (the panel, scripts), and how far a change reaches (what must be redone).
#pragma once

#include "description/scene_description.h"
#include "description/scene_field.h"

#include <nlohmann/json.hpp>

#include <string>

namespace urbis {

/// `d` with `patch` (an object shaped like a scene file, holding only the keys to change; null
/// unsets an optional key) laid over it (RFC 7386 merge patch) and read back as a scene file is
/// (sceneFromJson): every problem is an InputError naming `where` and the key.
SceneDescription patchedScene(const SceneDescription& d, const nlohmann::ordered_json& patch, const std::string& where);

/// How far the change from `before` to `after` reaches: the furthest of the changed keys' own reach
/// (Field::change, description/scene_fields.h), Relight taken as Rebuild.
SceneChange sceneChangeOf(const SceneDescription& before, const SceneDescription& after);

} // namespace urbis
