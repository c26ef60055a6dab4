#include "citygen/city_mesher.h"

#include "citygen/building_mesher.h"
#include "citygen/city_trees.h"
#include "citygen/facade_mesher.h"
#include "citygen/lit_room_palette.h"
#include "citygen/window_schedule.h"
#include "base/input_error.h"
#include "scene/memory_budget.h"
#include "scene/surface_part.h"
#include "streets/street_materials.h"
#include "streets/street_mesher.h"

#include <tbb/parallel_for.h>
#include <tbb/parallel_pipeline.h>
#include <tbb/task_arena.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <cstdio>
#include <exception>
#include <tuple>

namespace urbis {

namespace {

/// Reflectance of real building surfaces: fresh white paint reflects about 85 %, black roofing felt
/// and dark slate about 3 %. A mapped "black" or "white" is such a surface, not a perfect absorber or
/// reflector (a pure black roof renders as a hole in the city).
constexpr float kMinAlbedo = 0.03f, kMaxAlbedo = 0.85f;

/// Buildings' colours are kept to steps of 1/1024 (under a fifth of an 8-bit sRGB step from 0.01 up:
/// invisible), so that buildings whose colours are a palette's with a jitter share materials rather
/// than take one each (72 bytes a building on the device, some 900 MB for 10 million).
constexpr float kColourSteps = 1024.0f;

Rgb inColourSteps(Rgb c) {
    const auto step = [](float v) { return std::round(v * kColourSteps) / kColourSteps; };
    return {step(c.r), step(c.g), step(c.b)};
}

/// One material per distinct colour, so a million buildings share a small table.
class MaterialTable {
public:
    uint32_t indexOf(Rgb c) {
        auto key = std::make_tuple(c.r, c.g, c.b);
        auto [it, inserted] = index_.try_emplace(key, uint32_t(materials.size()));
        const auto clamp = [](float v) { return std::clamp(v, kMinAlbedo, kMaxAlbedo); };
        if (inserted) materials.push_back(Material{Vec3f{clamp(c.r), clamp(c.g), clamp(c.b)}});
        return it->second;
    }
    std::vector<Material> materials;

private:
    std::map<std::tuple<float, float, float>, uint32_t> index_;
};

/// The materials of FacadeMaterial, in its order.
void addFacadeMaterials(const CityMaterials& city, std::vector<Material>& out) {
    Material glass{city.glassTransmittance, MaterialKind::Glass};
    glass.ior = city.glassIor;
    Material roomDark{Vec3f{0.12f, 0.11f, 0.10f}};
    Material roomLit{Vec3f{0.45f, 0.40f, 0.33f}};
    roomLit.emission = city.litRoomEmission;
    Material slab{Vec3f{0.5f, 0.5f, 0.48f}};
    Material railing{Vec3f{0.04f, 0.04f, 0.045f}, MaterialKind::Glossy, Vec3f{0.4f, 0.4f, 0.42f}, 60.0f};
    Material mullion{Vec3f{0.1f, 0.1f, 0.11f}, MaterialKind::Glossy, Vec3f{0.35f, 0.35f, 0.37f}, 120.0f};
    Material spandrel{Vec3f{0.05f, 0.06f, 0.07f}, MaterialKind::Glossy, Vec3f{0.3f, 0.3f, 0.3f}, 400.0f};
    for (const Material& m : {glass, roomDark, roomLit, slab, railing, mullion, spandrel}) out.push_back(m);
    static_assert(uint32_t(FacadeMaterial::Count) == 7, "one material per FacadeMaterial");
}

struct Chunk {
    TriangleMesh mesh;
    std::vector<WallRecord> walls;
    BuildingTriangleCounts counts;
    std::map<std::string, uint64_t> dropped;
};

/// Meshes one building into `chunk`; a building that cannot be meshed, or whose meshing throws
/// (a library's exception, an allocation that fails), leaves nothing in it and is counted: one
/// building never ends a city.
void meshBuildingInto(GEOSContextHandle_t geos, const Building& building, TriangleInfo wallInfo, TriangleInfo roofInfo,
                      const WallContext* facade, Chunk& chunk) {
    const size_t triangles = chunk.mesh.size(), walls = chunk.walls.size();
    const BuildingTriangleCounts counts = chunk.counts;
    const char* reason = nullptr;
    try {
        reason = meshBuilding(geos, building, wallInfo, roofInfo, facade, chunk.mesh, chunk.walls, chunk.counts);
    } catch (const std::exception&) {
        reason = "mesh_failed";
        chunk.mesh.triangles.resize(triangles);
        chunk.mesh.info.resize(triangles);
        chunk.walls.resize(walls);
        chunk.counts = counts;
    }
    if (reason) ++chunk.dropped[reason];
}

constexpr size_t kChunk = 256;
/// Chunks meshed or waiting to be appended at once, per thread: enough that no thread waits on the
/// one being appended.
constexpr size_t kChunksInFlightPerThread = 4;

/// Calls f(p) for every vertex of the city's triangles and two opposite corners of each wall (a wall is
/// an upright rectangle: those two bound it).
template <typename F>
void forEachCityPoint(const CityMesh& mesh, F&& f) {
    for (const Triangle& t : mesh.mesh.triangles) f(t.p0), f(t.p1), f(t.p2);
    for (const WallRecord& w : mesh.walls) f(w.worldFromWall(0, 0, 0)), f(w.worldFromWall(w.width, w.height, 0));
}

/// Columns of the framing grid along x and z.
constexpr int kFramingCells = 8;

/// The bounds of the city's points in each column of a kFramingCells^2 grid over cityBounds.
std::vector<Bounds3f> framingPieces(const CityMesh& mesh) {
    std::vector<Bounds3f> pieces(kFramingCells * kFramingCells);
    if (mesh.cityBounds.empty()) return {};
    const Bounds3f& b = mesh.cityBounds;
    const auto cell = [](float v, float lo, float hi) {
        return hi > lo ? std::clamp(int((v - lo) / (hi - lo) * kFramingCells), 0, kFramingCells - 1) : 0;
    };
    forEachCityPoint(mesh, [&](Vec3f p) {
        pieces[cell(p.x, b.lo.x, b.hi.x) * kFramingCells + cell(p.z, b.lo.z, b.hi.z)].extend(p);
    });
    std::erase_if(pieces, [](const Bounds3f& piece) { return piece.empty(); });
    return pieces;
}

/// Replaces the procedural walls by their triangle twin, after checking that it fits in memory; lit
/// rooms of the palette from `litRoomPalette` (kNoLitRoomPalette: none).
void meshWallTwins(const CityMeshOptions& options, uint32_t litRoomPalette, CityMesh& out) {
    const size_t twinTriangles = tbb::parallel_reduce(
        tbb::blocked_range<size_t>(0, out.walls.size(), 1024), size_t(0),
        [&](const tbb::blocked_range<size_t>& r, size_t n) {
            for (size_t i = r.begin(); i != r.end(); ++i) n += wallTwinTriangleCount(out.walls[i]);
            return n;
        },
        [](size_t a, size_t b) { return a + b; });
    const size_t needed = (twinTriangles + out.mesh.size()) * kBuildBytesPerTriangle;
    const size_t limit = options.memoryLimit ? options.memoryLimit : availableMemoryBytes();
    if (limit && needed > limit) {
        char message[256];
        std::snprintf(message, sizeof message,
                      "--geometry walls=triangles: the facades' triangle twin has %zu triangles and needs about %.1f GB "
                      "to build, more than the %.1f GB available; use --geometry walls=procedural",
                      twinTriangles, double(needed) / 1e9, double(limit) / 1e9);
        throw InputError(message, FailureKind::OutOfMemory);
    }
    std::vector<TriangleMesh> parts((out.walls.size() + kChunk - 1) / kChunk);
    tbb::parallel_for(size_t(0), parts.size(), [&](size_t c) {
        const size_t end = std::min(out.walls.size(), (c + 1) * kChunk);
        for (size_t i = c * kChunk; i < end; ++i) meshWall(out.walls[i], parts[c], litRoomPalette);
    });
    out.mesh.triangles.reserve(out.mesh.size() + twinTriangles);
    out.mesh.info.reserve(out.mesh.size() + twinTriangles);
    for (const TriangleMesh& part : parts) out.mesh.append(part);
    out.trianglesByKind["walls"] += twinTriangles;
    out.walls.clear();
    out.walls.shrink_to_fit();
}

/// Joins the streets (streets/street_mesher.h) to the buildings: their materials after the buildings',
/// their objects after the buildings' ids. Returns the first object id after the streets'.
uint32_t addStreets(const CityModel& city, const CityMeshOptions& options, CityMesh& out) {
    StreetOptions streetOptions;
    streetOptions.lamps = options.geometry.lamps;
    streetOptions.firstMaterial = uint32_t(out.materials.size());
    streetOptions.firstObject = uint32_t(city.buildings.size() + 1);
    streetOptions.americanMarkings = city.origin.valid && city.origin.lon < -30.0;
    streetOptions.leftHandTraffic = options.traffic.value_or(trafficSideOf(city.origin)) == TrafficSide::Left;
    streetOptions.water = options.water;
    for (const Material& m : streetMaterials(options.water)) out.materials.push_back(m);
    StreetMesh streets = meshStreets(city, streetOptions);
    out.mesh.append(streets.mesh);
    out.roadSegments = std::move(streets.roadSegments);
    out.lamps = std::move(streets.lamps);
    out.bridgeSpans = std::move(streets.bridgeSpans);
    out.waterElevations = std::move(streets.waterElevations);
    out.waterFlows = std::move(streets.waterFlows);
    for (const auto& [kind, n] : streets.trianglesByKind) out.trianglesByKind[kind] += n;
    for (const auto& [reason, n] : streets.dropped) out.dropped[reason] += n;
    out.streetCounts = std::move(streets.counts);
    return streetOptions.firstObject + streets.objects;
}

} // namespace

CityMesh meshCity(const CityModel& city, const CityMeshOptions& options) {
    CityMesh out;
    MaterialTable table;
    const Vec3f ground = options.materials.groundAlbedo;
    uint32_t groundMaterial = table.indexOf(Rgb{ground.x, ground.y, ground.z});
    std::vector<TriangleInfo> wallInfo(city.buildings.size()), roofInfo(city.buildings.size());
    for (size_t i = 0; i < city.buildings.size(); ++i) {
        const Building& b = city.buildings[i];
        wallInfo[i] = {table.indexOf(inColourSteps(b.wallColour)), uint32_t(i + 1), uint32_t(SurfacePart::Facade)};
        roofInfo[i] = {table.indexOf(inColourSteps(b.roofColour)), uint32_t(i + 1), uint32_t(SurfacePart::Roof)};
    }
    out.materials = std::move(table.materials);
    const uint32_t facadeMaterials = uint32_t(out.materials.size());
    addFacadeMaterials(options.materials, out.materials);
    uint32_t litRoomPalette = kNoLitRoomPalette;
    if (options.litRoomLooks && options.geometry.walls == Representation::Triangles) {
        litRoomPalette = uint32_t(out.materials.size());
        for (const Material& m : litRoomPaletteMaterials(out.materials[facadeMaterials + uint32_t(FacadeMaterial::RoomLit)]))
            out.materials.push_back(m);
    }
    const auto facadeOf = [&](size_t i) {
        const Building& b = city.buildings[i];
        WallContext f{&b, facadeStyleOf(b), uint32_t(i + 1), wallInfo[i].material, facadeMaterials};
        f.proceduralParapets = options.geometry.roofs == Representation::Procedural;
        f.litChance = chanceByte(litRoomShare(windowUseOf(b.type), options.hour));
        f.shopLitChance = chanceByte(litShopWindowShare(options.hour));
        return f;
    };

    // Streamed: chunks of buildings are meshed in parallel and appended in their order as they come,
    // each released once appended, so that only some chunks per thread are alive at once rather than
    // a second copy of the whole city's mesh; the order keeps the city the same for any thread count.
    const size_t chunkCount = (city.buildings.size() + kChunk - 1) / kChunk;
    size_t nextChunk = 0, walls = 0, roofs = 0;
    const auto nextIndex = [&](tbb::flow_control& control) {
        if (nextChunk == chunkCount) control.stop();
        return nextChunk++;
    };
    const auto meshChunk = [&](size_t c) {
        auto chunk = std::make_shared<Chunk>();
        GEOSContextHandle_t geos = GEOS_init_r();
        const size_t end = std::min(city.buildings.size(), (c + 1) * kChunk);
        for (size_t i = c * kChunk; i < end; ++i) {
            const WallContext facade = facadeOf(i);
            meshBuildingInto(geos, city.buildings[i], wallInfo[i], roofInfo[i],
                             options.geometry.walls != Representation::Plain ? &facade : nullptr, *chunk);
        }
        GEOS_finish_r(geos);
        return chunk;
    };
    const auto appendChunk = [&](const std::shared_ptr<Chunk>& chunk) {
        out.mesh.append(chunk->mesh);
        out.walls.insert(out.walls.end(), chunk->walls.begin(), chunk->walls.end());
        walls += chunk->counts.walls;
        roofs += chunk->counts.roofs;
        out.holesDropped += chunk->counts.holesDropped;
        for (const auto& [reason, n] : chunk->counts.roofFallbacks) out.roofFallbacks[reason] += n;
        for (const auto& [reason, n] : chunk->dropped) out.dropped[reason] += n;
    };
    tbb::parallel_pipeline(kChunksInFlightPerThread * size_t(tbb::this_task_arena::max_concurrency()),
                           tbb::make_filter<void, size_t>(tbb::filter_mode::serial_in_order, nextIndex) &
                               tbb::make_filter<size_t, std::shared_ptr<Chunk>>(tbb::filter_mode::parallel, meshChunk) &
                               tbb::make_filter<std::shared_ptr<Chunk>, void>(tbb::filter_mode::serial_in_order, appendChunk));
    forEachCityPoint(out, [&out](Vec3f p) { out.cityBounds.extend(p); });
    out.framingPieces = framingPieces(out);
    for (const WallRecord& w : out.walls) out.facadeCells += size_t(w.floors) * w.slots;
    out.facadeWalls = out.walls.size();
    out.groundMaterial = groundMaterial;
    out.trianglesByKind = {{"walls", walls}, {"roofs", roofs}};
    if (options.geometry.walls == Representation::Triangles) meshWallTwins(options, litRoomPalette, out);
    if (options.streets) addCityTrees(city, options, addStreets(city, options, out), out);
    return out;
}

} // namespace urbis
