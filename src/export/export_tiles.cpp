#include "export/export_tiles.h"

#include <cmath>
#include <map>
#include <utility>

namespace urbis {

namespace {

using TileKey = std::pair<int, int>;  // (z, x): the map's order is the files' order

TileKey tileOf(Vec3f p, float size) { return {int(std::floor(p.z / size)), int(std::floor(p.x / size))}; }

/// Adds a copy of `node` without its primitives to `tile`, or returns the one already there (the last).
ExportNode& nodeIn(ExportScene& tile, const ExportNode& node, std::map<const ExportNode*, size_t>& placed) {
    auto [it, inserted] = placed.try_emplace(&node, tile.nodes.size());
    if (inserted) tile.nodes.push_back(ExportNode{node.name, node.extras, {}, node.whole});
    return tile.nodes[it->second];
}

/// The primitive of `material` (the whole scene's index) in `node` of `tile`, the material copied in.
ExportPrimitive& primitiveIn(ExportScene& tile, std::map<uint32_t, uint32_t>& remap, const ExportScene& scene,
                             ExportNode& node, uint32_t material) {
    auto [it, inserted] = remap.try_emplace(material, uint32_t(tile.materials.size()));
    if (inserted) tile.materials.push_back(scene.materials[material]);
    for (ExportPrimitive& p : node.primitives)
        if (p.material == it->second) return p;
    node.primitives.push_back({it->second, {}});
    return node.primitives.back();
}

} // namespace

std::vector<ExportTile> splitIntoTiles(const ExportScene& scene, float size) {
    struct Tile {
        ExportScene scene;
        std::map<uint32_t, uint32_t> remap;                // whole scene's material -> tile's
        std::map<const ExportNode*, size_t> placed;        // whole scene's node -> tile's
    };
    std::map<TileKey, Tile> tiles;
    for (const ExportNode& node : scene.nodes) {
        const TileKey whole = tileOf(node.bounds().centre(), size);
        for (const ExportPrimitive& p : node.primitives)
            for (const Triangle& t : p.triangles) {
                Tile& tile = tiles[node.whole ? whole : tileOf((t.p0 + t.p1 + t.p2) * (1.0f / 3.0f), size)];
                ExportNode& into = nodeIn(tile.scene, node, tile.placed);
                primitiveIn(tile.scene, tile.remap, scene, into, p.material).triangles.push_back(t);
            }
    }
    std::vector<ExportTile> out;
    for (auto& [key, tile] : tiles) {
        ExportTile t{key.second, key.first, std::move(tile.scene)};
        t.scene.camera = scene.camera;
        t.scene.sunDirection = scene.sunDirection;
        t.scene.sunIrradiance = scene.sunIrradiance;
        t.scene.extras = scene.extras;
        t.scene.extras["tile"] = {{"x", t.x}, {"z", t.z}, {"size", size}};
        out.push_back(std::move(t));
    }
    return out;
}

} // namespace urbis
