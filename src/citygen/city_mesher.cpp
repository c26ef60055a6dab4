#include "citygen/city_mesher.h"

#include "citygen/building_mesher.h"

#include <tbb/parallel_for.h>

#include <tuple>

namespace urbis {

namespace {

/// One material per distinct colour, so a million buildings share a small table.
class MaterialTable {
public:
    uint32_t indexOf(Rgb c) {
        auto key = std::make_tuple(c.r, c.g, c.b);
        auto [it, inserted] = index_.try_emplace(key, uint32_t(materials.size()));
        if (inserted) materials.push_back(Material{Vec3f{c.r, c.g, c.b}});
        return it->second;
    }
    std::vector<Material> materials;

private:
    std::map<std::tuple<float, float, float>, uint32_t> index_;
};

struct Chunk {
    TriangleMesh mesh;
    BuildingTriangleCounts counts;
    uint64_t failed = 0;
};

} // namespace

CityMesh meshCity(const CityModel& city) {
    CityMesh out;
    MaterialTable table;
    uint32_t groundMaterial = table.indexOf(Rgb{0.10f, 0.11f, 0.09f});
    std::vector<TriangleInfo> wallInfo(city.buildings.size()), roofInfo(city.buildings.size());
    for (size_t i = 0; i < city.buildings.size(); ++i) {
        const Building& b = city.buildings[i];
        wallInfo[i] = {table.indexOf(b.wallColour), uint32_t(i + 1)};
        roofInfo[i] = {table.indexOf(b.roofColour), uint32_t(i + 1)};
    }

    constexpr size_t kChunk = 256;
    std::vector<Chunk> chunks((city.buildings.size() + kChunk - 1) / kChunk);
    tbb::parallel_for(size_t(0), chunks.size(), [&](size_t c) {
        GEOSContextHandle_t geos = GEOS_init_r();
        Chunk& chunk = chunks[c];
        size_t end = std::min(city.buildings.size(), (c + 1) * kChunk);
        for (size_t i = c * kChunk; i < end; ++i)
            if (!meshBuilding(geos, city.buildings[i], wallInfo[i], roofInfo[i], chunk.mesh, chunk.counts))
                ++chunk.failed;
        GEOS_finish_r(geos);
    });

    size_t walls = 0, roofs = 0;
    uint64_t failed = 0;
    for (const Chunk& chunk : chunks) {
        out.mesh.append(chunk.mesh);
        walls += chunk.counts.walls;
        roofs += chunk.counts.roofs;
        failed += chunk.failed;
        for (const auto& [reason, n] : chunk.counts.roofFallbacks) out.roofFallbacks[reason] += n;
    }
    for (const Triangle& t : out.mesh.triangles) {
        out.cityBounds.extend(t.p0);
        out.cityBounds.extend(t.p1);
        out.cityBounds.extend(t.p2);
    }
    out.groundMaterial = groundMaterial;
    out.materials = std::move(table.materials);
    out.trianglesByKind = {{"walls", walls}, {"roofs", roofs}};
    if (failed) out.dropped["triangulation_failed"] = failed;
    return out;
}

} // namespace urbis
