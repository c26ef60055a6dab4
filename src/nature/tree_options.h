// What a scene says about its trees (the scene file's `trees` object, docs/scene_files.md): where
// they are filled in, how big untagged trees are, how rough their crowns and what colour.
#pragma once

#include "math/vec.h"

#include <cstdint>
#include <string>

namespace urbis {

/// The choices of TreeOptions::season.
inline constexpr const char* kTreeSeasons[] = {"summer", "autumn"};

struct TreeOptions {
    bool enabled = true;             ///< false: no trees at all (mapped or filled)
    uint32_t seed = 1;               ///< of the filled-in trees' places and of every tree's variation
    /// Trees per hectare filled into areas (seeded jittered grid, kept off roads, buildings, water and
    /// paved or sports areas, and away from mapped trees): landuse=forest and natural=wood, parks
    /// (leisure=park|garden), natural=scrub|heath (bushes). 0: none.
    float forestDensity = 300.0f;
    float parkDensity = 30.0f;
    float scrubDensity = 200.0f;
    /// Metres of forest around the city: a ring beyond its extent, by domain repetition (a ForestRecord:
    /// cells of outerForestCell metres, each holding a hashed, jittered tree with a probability that
    /// makes outerForestDensity trees per hectare, at most one a cell). 0: none.
    float outerForest = 0.0f;
    float outerForestCell = 6.0f;
    float outerForestDensity = 250.0f;
    float clearance = 1.0f;          ///< m from a filled tree's trunk to a road's edge (sidewalks included), a building or water
    float defaultHeight = 10.0f;     ///< m, of a filled-in tree (a mapped tree without `height` keeps the import's)
    float sizeVariation = 0.25f;     ///< relative: untagged heights and crowns vary by up to this, seeded
    float coniferShare = 0.3f;       ///< of trees whose leaf_type is unknown (forests; 0.1 of that elsewhere)
    /// The crown's noise: its amplitude as a share of the crown's radius, and its lumps per crown radius.
    float roughness = 0.18f;
    float lumps = 1.5f;
    std::string season = "summer";   ///< one of kTreeSeasons: autumn turns deciduous broadleaves' leaves
    Vec3f barkAlbedo{0.10f, 0.075f, 0.055f};
    Vec3f leafAlbedo{0.055f, 0.12f, 0.035f};      ///< broadleaves in summer (each tree varies it by +-20 %)
    Vec3f needleAlbedo{0.03f, 0.07f, 0.035f};     ///< conifers
    Vec3f autumnAlbedo{0.28f, 0.13f, 0.03f};      ///< deciduous broadleaves in autumn
};

} // namespace urbis
