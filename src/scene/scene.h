// The host-side scene: the arrays of scene_arrays.h (each kind's records in BVH leaf order), the BVH
// itself, lights, and what it all costs.
#pragma once

#include "accel/bvh_build.h"
#include "scene/scene_view.h"
#include "scene/terrain_field.h"
#include "scene/triangle_mesh.h"
#include "scene/wall_tiles.h"

#include <cstddef>
#include <vector>

namespace urbis {

/// Bytes of each array of a scene (scene_arrays.h), host or device.
struct SceneMemory {
#define URBIS_MEMORY_MEMBER(Type, name, key) size_t name = 0;
    URBIS_SCENE_ARRAYS(URBIS_MEMORY_MEMBER)
#undef URBIS_MEMORY_MEMBER

    /// f(const char* statsKey, size_t bytes) for every array.
    template <typename F>
    void forEach(F&& f) const {
#define URBIS_MEMORY_EACH(Type, name, key) f(key, name);
        URBIS_SCENE_ARRAYS(URBIS_MEMORY_EACH)
#undef URBIS_MEMORY_EACH
    }
    size_t total() const {
        size_t sum = 0;
        forEach([&](const char*, size_t bytes) { sum += bytes; });
        return sum;
    }
};

/// Every array here is mirrored to the device as it is (DeviceScene).
struct Scene {
#define URBIS_SCENE_MEMBER(Type, name, key) std::vector<Type> name;
    URBIS_SCENE_ARRAYS(URBIS_SCENE_MEMBER)
#undef URBIS_SCENE_MEMBER
    Sun sun;
    Sky sky;
    NightSky night;         ///< the moon and the stars
    LightListInfo lights;   ///< beside the light arrays, which buildLights (lights/light_build.h) fills from the rest

    /// Builds one BVH over the triangles of `mesh`, the tiles of the procedural `walls`
    /// (splitWallsIntoTiles), the `grounds` (hung from its root) and the analytic street `lamps`, `trees`, `planets`
    /// and `forests`,
    /// and stores each kind's records in leaf order, the slots of each kind after those of the kinds
    /// before it (SceneView::kindEnd). A street triangle (within half a metre of the ground) may have
    /// several references, one per piece (accel/split_references.h), and is stored once per slot.
    /// A `terrain`, where given, hangs from the root beside the grounds, its samples in terrainData.
    static Scene build(const TriangleMesh& mesh, std::vector<Material> materials,
                       const std::vector<WallRecord>& walls = {}, WallTileSize tileSize = {},
                       const std::vector<GroundRecord>& grounds = {}, const std::vector<LampRecord>& lamps = {},
                       const std::vector<TreeRecord>& trees = {}, const TerrainField& terrain = {},
                       const std::vector<PlanetRecord>& planets = {}, const std::vector<ForestRecord>& forests = {});
    SceneView view() const;
    SceneMemory memory() const;
};

} // namespace urbis
