// The checks of a scene description that span fields (each field's own range is in scene_fields.h).
#pragma once

#include "description/scene_description.h"
#include "scene/scene.h"

#include <optional>
#include <string>

namespace urbis {

/// A problem of a description: the key path it is at, the command-line option that sets it, and
/// what is wrong.
struct SceneProblem {
    std::string key;      ///< "source.bbox"
    std::string option;   ///< "--bbox"
    std::string message;  ///< "crops an OSM file and needs source.osm (--osm)"
};

/// The first problem of `d`, if any: a crop box that is inverted, off the globe or without an OSM
/// file; a height range with min above max; a camera position without a target (or the reverse),
/// at its target, or given with a geographic placement; a geographic camera without an OSM file;
/// wall tiles that are neither "whole" nor SLOTSxFLOORS; a time that is no ISO 8601 time with an
/// offset (astro/civil_time.h); a location off the globe; an animation of a planet, a geo camera
/// keyframe without an OSM file, a camera keyframe with no look where camera.target is unset.
std::optional<SceneProblem> firstSceneProblem(const SceneDescription& d);

/// "whole" -> whole walls ({0, 0}); "SLOTSxFLOORS" -> tiles of at most that many cells (each 1 to
/// 65535); nullopt for anything else.
std::optional<WallTileSize> wallTileSizeOf(const std::string& text);

} // namespace urbis
