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

/// The empty value of T that a SceneInputs member left out refers to.
template <typename T>
inline const T kNoSceneInput{};

/// What Scene::build makes a scene of, each input by name (designated initializers, in this order):
/// every primitive kind's records in world space and the materials they index. The record members
/// refer to the caller's arrays, which are not copied (a braced list written in the call lives until
/// it returns); a member left out is none of its kind.
struct SceneInputs {
    const TriangleMesh& mesh = kNoSceneInput<TriangleMesh>;
    std::vector<Material> materials = {};   ///< what TriangleInfo::material and the records' materials index
    const std::vector<WallRecord>& walls = kNoSceneInput<std::vector<WallRecord>>;   ///< procedural walls, whole
    WallTileSize tileSize = {};             ///< the walls' tiles (splitWallsIntoTiles); zero: each wall whole
    const std::vector<GroundRecord>& grounds = kNoSceneInput<std::vector<GroundRecord>>;
    const std::vector<LampRecord>& lamps = kNoSceneInput<std::vector<LampRecord>>;
    const std::vector<TreeRecord>& trees = kNoSceneInput<std::vector<TreeRecord>>;
    const TerrainField& terrain = kNoSceneInput<TerrainField>;   ///< empty: no terrain
    const std::vector<PlanetRecord>& planets = kNoSceneInput<std::vector<PlanetRecord>>;
    const std::vector<ForestRecord>& forests = kNoSceneInput<std::vector<ForestRecord>>;
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

    /// Builds one BVH over the triangles of `in.mesh`, the tiles of the procedural `in.walls`
    /// (splitWallsIntoTiles), the `in.grounds` (hung from its root) and the analytic street `in.lamps`,
    /// `in.trees`, `in.planets` and `in.forests`, and stores each kind's records in leaf order, the slots of
    /// each kind after those of the kinds before it (SceneView::kindEnd). A street triangle (within half a
    /// metre of the ground) may have several references, one per piece (accel/split_references.h), and is
    /// stored once per slot. A terrain, where given, hangs from the root beside the grounds, its samples
    /// in terrainData.
    static Scene build(SceneInputs in);
    SceneView view() const;
    SceneMemory memory() const;
};

} // namespace urbis
