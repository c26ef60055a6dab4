// Edits of a scene description as the viewer makes them: a part of a scene file laid over the
// description (the panel, scripts), and how far a change reaches (what must be redone).
#pragma once

#include "description/scene_description.h"

#include <nlohmann/json.hpp>

#include <string>

namespace urbis {

/// `d` with `patch` (an object shaped like a scene file, holding only the keys to change; null
/// unsets an optional key) laid over it (RFC 7386 merge patch) and read back as a scene file is
/// (sceneFromJson): every problem is an InputError naming `where` and the key.
SceneDescription patchedScene(const SceneDescription& d, const nlohmann::ordered_json& patch, const std::string& where);

/// What a change of the description asks of the viewer, least first.
enum class SceneChange {
    None,      ///< nothing that shows
    Display,   ///< the exposure or the denoiser: the same samples shown otherwise
    Restart,   ///< the camera or the integrator: the same scene, the image starts over
    Resize,    ///< the film's size: a new film
    Rebuild,   ///< anything else (the city, its geometry, materials, the sky and the sun): the scene is built again
};

/// How far the change from `before` to `after` reaches. Sections no rule names (keys other branches
/// add) rebuild the scene: always right, if slower than need be.
SceneChange sceneChangeOf(const SceneDescription& before, const SceneDescription& after);

} // namespace urbis
