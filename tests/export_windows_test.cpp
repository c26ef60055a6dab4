// Lit rooms in the export carry the renderer's per-window decisions (citygen/lit_room_palette.h): at
// the same hour the twin lights the very cells the procedural walls light, each lit room's parts in
// the palette entry of its window's look, whose colour and mean intensity lie within half a palette
// step of the look's (lights/window_light.h).
#include "citygen/city_mesher.h"
#include "citygen/lit_room_palette.h"
#include "geometry/wall_parts.h"
#include "osm/osm_import.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <vector>

using namespace urbis;

namespace {

const std::string kVillage = URBIS_OSMNX_DATA "/planet_10.068,48.135_10.071,48.137.osm";

/// The village at 21 h: its procedural walls (what the renderer decides by) and its export's twin.
struct NightVillage {
    CityMesh procedural, twin;
    uint32_t palette = 0;   ///< the twin's first palette material
    std::map<uint32_t, std::vector<size_t>> paletteTriangles;   ///< the twin's, by material
};

bool inPalette(const NightVillage& v, uint32_t material) {
    return material >= v.palette && material < v.palette + kLitRoomPaletteSize;
}

const NightVillage& nightVillage() {
    static const NightVillage v = [] {
        NightVillage n;
        const CityModel city = importOsm(kVillage, ImportOptions{});
        CityMeshOptions options;
        options.hour = 21;
        options.streets = false;
        n.procedural = meshCity(city, options);
        options.geometry.walls = Representation::Triangles;
        options.litRoomLooks = true;
        n.twin = meshCity(city, options);
        n.palette = n.procedural.walls.at(0).facadeMaterials + uint32_t(FacadeMaterial::Count);
        for (size_t k = 0; k < n.twin.mesh.size(); ++k)
            if (inPalette(n, n.twin.mesh.info[k].material)) n.paletteTriangles[n.twin.mesh.info[k].material].push_back(k);
        return n;
    }();
    return v;
}

/// A point of a part's surface (wall coordinates): a box's face at its lowest w.
Vec3f pointOn(const WallPart& p) {
    Vec3f q = p.lo + (p.hi - p.lo) * 0.3f;
    if (p.axis == kWallPartBox) q.z = p.lo.z;
    return q;
}

/// Whether a triangle of the twin of `material` contains world point `p` (1 mm).
bool twinHasAt(const NightVillage& v, uint32_t material, Vec3f p) {
    const auto triangles = v.paletteTriangles.find(material);
    if (triangles == v.paletteTriangles.end()) return false;
    for (size_t k : triangles->second) {
        const Triangle& t = v.twin.mesh.triangles[k];
        const Vec3f e1 = t.p1 - t.p0, e2 = t.p2 - t.p0, n = cross(e1, e2);
        const float area2 = length(n);
        if (!(area2 > 0.0f) || std::fabs(dot(p - t.p0, n)) > 1e-3f * area2) continue;
        const float b1 = dot(cross(p - t.p0, e2), n) / (area2 * area2), b2 = dot(cross(e1, p - t.p0), n) / (area2 * area2);
        if (b1 >= -1e-4f && b2 >= -1e-4f && b1 + b2 <= 1.0001f) return true;
    }
    return false;
}

} // namespace

TEST(ExportWindows, TheTwinLightsTheRenderersCellsInTheirLooks) {
    const NightVillage& v = nightVillage();
    const uint32_t lit = v.palette - uint32_t(FacadeMaterial::Count) + uint32_t(FacadeMaterial::RoomLit);
    size_t litCells = 0, cells = 0, expectedTriangles = 0, checkedLit = 0, checkedDark = 0;
    const float stepIntensity = (kLitRoomLevelHigh - kLitRoomLevelLow) / float(kLitRoomLevels - 1);
    const float stepCoolness = 1.0f / float(kLitRoomColours - 1);
    for (const WallRecord& wall : v.procedural.walls)
        for (uint32_t f = 0; f < wall.floors; ++f)
            for (uint32_t s = 0; s < wall.slots; ++s) {
                ++cells;
                const bool isLit = cellDraws(wall, f, s).lit;
                CellParts parts;
                cellParts(wall, f, s, CellSide::Both, parts);
                const WindowLook look = windowLook(wall, f, s);
                const uint32_t entry = litRoomPaletteEntry(look);
                if (isLit) {
                    ++litCells;
                    // The entry is the nearest to the look: within half a step (the lowest level clamps up).
                    EXPECT_LE(std::fabs(litRoomEntryCoolness(entry) - look.coolness), 0.5f * stepCoolness + 1e-6f);
                    EXPECT_LE(std::fabs(litRoomEntryIntensity(entry) - std::fmax(windowMeanIntensity(look), kLitRoomLevelLow)),
                              0.5f * stepIntensity + 1e-6f);
                }
                for (int k = 0; k < parts.count; ++k) {
                    const WallPart& p = parts.parts[k];
                    if (p.material != lit) continue;
                    EXPECT_TRUE(isLit);
                    expectedTriangles += p.axis == kWallPartBox ? 12 : 2;
                    // A few positions: every part of the first 40 lit cells in its entry's material.
                    const Vec3f q = pointOn(p);
                    if (checkedLit < 40) {
                        EXPECT_TRUE(twinHasAt(v, v.palette + entry, wall.worldFromWall(q.x, q.y, q.z)));
                    }
                }
                if (isLit) checkedLit += checkedLit < 40;
                if (!isLit && checkedDark < 40) {
                    // A dark room's back: no lit-room triangle there.
                    for (int k = 0; k < parts.count; ++k)
                        if (parts.parts[k].part == SurfacePart::Room) {
                            const Vec3f q = pointOn(parts.parts[k]);
                            for (uint32_t e = 0; e < kLitRoomPaletteSize; ++e)
                                EXPECT_FALSE(twinHasAt(v, v.palette + e, wall.worldFromWall(q.x, q.y, q.z)));
                            break;
                        }
                    ++checkedDark;
                }
            }
    size_t paletteTriangles = 0, uniformLit = 0;
    for (const TriangleInfo& info : v.twin.mesh.info) {
        paletteTriangles += inPalette(v, info.material);
        uniformLit += info.material == lit;
    }
    std::printf("[ COUNTS   ] village at 21 h: %zu of %zu cells lit, %zu lit-room triangles\n", litCells, cells, paletteTriangles);
    EXPECT_GT(litCells, 50u);
    EXPECT_LT(litCells, cells);
    EXPECT_EQ(checkedLit, 40u);
    EXPECT_EQ(paletteTriangles, expectedTriangles) << "the renderer's lit cells, each room's every part";
    EXPECT_EQ(uniformLit, 0u) << "no lit room keeps the one lit-room material";
}

TEST(ExportWindows, PaletteEntriesEmitTheirLooksRadiance) {
    const NightVillage& v = nightVillage();
    const Material& room = v.twin.materials.at(v.palette - uint32_t(FacadeMaterial::Count) + uint32_t(FacadeMaterial::RoomLit));
    for (uint32_t e = 0; e < kLitRoomPaletteSize; ++e) {
        const Vec3f expected = windowColour(litRoomEntryCoolness(e)) * (luminance(room.emission) * litRoomEntryIntensity(e));
        const Vec3f got = v.twin.materials.at(v.palette + e).emission;
        for (int c = 0; c < 3; ++c) EXPECT_FLOAT_EQ(got[c], expected[c]) << "entry " << e;
        EXPECT_NEAR(luminance(got), luminance(room.emission) * litRoomEntryIntensity(e), 1e-6f);
    }
}
