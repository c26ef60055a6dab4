// Where a road or railway lies relative to the ground, from `layer`, `bridge`, `tunnel`,
// `covered` and `location`: one reader for both, so that they agree.
#pragma once

#include "osm/tag_lookup.h"

#include <cstdint>
#include <map>
#include <string>

namespace urbis {

struct LevelTags {
    int layer = 0;            ///< `layer`, clamped to [-5, 5] (the wiki's range)
    bool bridge = false;      ///< `bridge=*` other than no
    bool tunnel = false;      ///< `tunnel=*` other than no
    bool covered = false;     ///< `covered=yes`
    bool underground = false; ///< `location=underground` (also in a `;` list)
};

/// The level tags of a way. A `layer` that is no whole number, or lies outside [-5, 5] (then
/// clamped), is counted in `issues` under `badLayerIssue`.
LevelTags levelFromTags(const TagLookup& tag, const char* badLayerIssue, std::map<std::string, uint64_t>& issues);

/// Copies `level` into a Road or Railway, which carry the same fields.
template <typename Way>
void assignLevel(const LevelTags& level, Way& way) {
    way.layer = level.layer;
    way.bridge = level.bridge;
    way.tunnel = level.tunnel;
    way.covered = level.covered;
    way.underground = level.underground;
}

} // namespace urbis
