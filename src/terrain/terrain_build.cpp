#include "terrain/terrain_build.h"

#include "base/input_error.h"
#include "osm/geo_projection.h"
#include "terrain/dem_raster.h"
#include "terrain/dual_heightmap.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <optional>

namespace urbis {
namespace {

/// 0 at 0, 1 from 1 on, smooth between.
float smoothStep(float x) {
    x = std::clamp(x, 0.0f, 1.0f);
    return x * x * (3.0f - 2.0f * x);
}

/// The DEM on the city's tangent plane: its raster, the projection, and its local rectangle.
struct DemOnPlane {
    DemRaster raster;
    GeoProjection projection;
    float xa, xb, za, zb;   ///< world metres of the raster's outline's bounding box
};

DemOnPlane placeDem(const std::string& file, const GeoOrigin& origin) {
    DemRaster raster(file);
    double lon, lat;
    raster.lonLatOf(raster.width() * 0.5, raster.height() * 0.5, lon, lat);
    const GeoProjection projection(origin.valid ? LonLat{origin.lon, origin.lat} : LonLat{lon, lat});
    float xa = INFINITY, xb = -INFINITY, za = INFINITY, zb = -INFINITY;
    for (int k = 0; k <= 8; ++k)
        for (int side = 0; side < 4; ++side) {
            const double f = k / 8.0, w = raster.width(), h = raster.height();
            const double col = side == 0 ? f * w : side == 1 ? w : side == 2 ? f * w : 0;
            const double row = side == 0 ? 0 : side == 1 ? f * h : side == 2 ? h : f * h;
            raster.lonLatOf(col, row, lon, lat);
            const Vec2d p = projection.project({lon, lat});
            xa = std::min(xa, float(p.x)), xb = std::max(xb, float(p.x));
            za = std::min(za, float(-p.y)), zb = std::max(zb, float(-p.y));
        }
    return {std::move(raster), projection, xa, xb, za, zb};
}

void checkParams(const TerrainParams& p) {
    auto require = [](bool ok, const char* what) {
        if (!ok) throw InputError(std::string("terrain: ") + what, FailureKind::Usage);
    };
    require(choiceNamed(kTerrainKinds, p.kind).has_value(), "kind must be none or fbm");
    require(choiceNamed(kDemInterpolations, p.interpolation).has_value(), "interpolation must be bilinear or bicubic");
    require(p.size > 0 && p.size <= 200000, "size must be in (0, 200000] metres");
    require(p.cell >= 0 && p.cell <= 1000, "cell must be in [0, 1000] metres");
    require(p.fbm.octaves >= 1 && p.fbm.octaves <= 24, "octaves must be in [1, 24]");
    require(p.fbm.wavelength > 0, "wavelength must be positive");
    require(p.dual.wavelength > 0 && p.dual.maskWavelength > 0, "dual.wavelength and dual.mask_wavelength must be positive");
    require(p.fade >= 0, "fade must not be negative");
}

} // namespace

TerrainMarch terrainMarchOf(const std::string& name) {
    if (const std::optional<TerrainMarch> march = choiceNamed(kTerrainMarches, name)) return *march;
    throw InputError("terrain: unknown march '" + name + "' (hierarchy, lei or reference)", FailureKind::Usage);
}

TerrainField buildTerrain(const TerrainParams& params, const GeoOrigin& origin, float cx, float cz, uint32_t firstMaterial) {
    checkParams(params);
    const TerrainMarch march = terrainMarchOf(params.march);
    std::optional<DemOnPlane> dem;
    if (!params.dem.empty()) dem.emplace(placeDem(params.dem, origin));
    const bool fbm = params.hasFbm();
    const bool bicubic = choiceNamed(kDemInterpolations, params.interpolation) == DemInterpolation::Bicubic;
    const float cell = params.cell > 0 ? params.cell : dem ? 2.0f : 4.0f;
    // The grid: the fBm's square around the city, and the DEM's rectangle; both with the fade border.
    float xa = INFINITY, xb = -INFINITY, za = INFINITY, zb = -INFINITY;
    if (fbm) xa = cx - params.size * 0.5f, xb = cx + params.size * 0.5f, za = cz - params.size * 0.5f, zb = cz + params.size * 0.5f;
    if (dem) xa = std::min(xa, dem->xa), xb = std::max(xb, dem->xb), za = std::min(za, dem->za), zb = std::max(zb, dem->zb);
    const float outer = dem ? params.fade : 0.0f;
    xa -= outer, xb += outer, za -= outer, zb += outer;
    const double samplesX = std::ceil((xb - xa) / cell) + 1, samplesZ = std::ceil((zb - za) / cell) + 1;
    if (samplesX * samplesZ > 1.2e8)
        throw InputError("terrain: " + std::to_string(uint64_t(samplesX)) + "x" + std::to_string(uint64_t(samplesZ)) +
                             " samples; make cell larger or size smaller", FailureKind::Usage);
    const uint32_t nx = uint32_t(samplesX), nz = uint32_t(samplesZ);

    // The DEM's detail: fBm of its pixel's wavelength and `detail` metres, as the landscape's rules.
    FbmParams detail = params.fbm;
    if (dem) {
        detail.wavelength = float(2.0 * dem->raster.pixelMetres());
        detail.amplitude = params.detail;
        detail.octaves = 4;
        detail.offset = 0;
        detail.warp = 0;
        detail.erosion = 0;
    }
    // The DEM's pixel position of every sample: unprojected in parallel, transformed in one call.
    std::vector<double> cols, rows;
    if (dem) {
        cols.resize(size_t(nx) * nz);
        rows.resize(cols.size());
        tbb::parallel_for(uint32_t(0), nz, [&](uint32_t j) {
            for (uint32_t i = 0; i < nx; ++i) {
                const LonLat ll = dem->projection.unproject({double(xa + cell * float(i)), -double(za + cell * float(j))});
                cols[size_t(j) * nx + i] = ll.lon;
                rows[size_t(j) * nx + i] = ll.lat;
            }
        });
        dem->raster.pixelsOf(cols, rows);
    }
    std::vector<float> heights(size_t(nx) * nz);
    tbb::parallel_for(uint32_t(0), nz, [&](uint32_t j) {
        for (uint32_t i = 0; i < nx; ++i) {
            const float x = xa + cell * float(i), z = za + cell * float(j);
            float h = 0.0f;
            // Distance (metres) inside the fade border: the fBm square's, or the DEM's rectangle's.
            float inside = INFINITY;
            if (fbm) {
                h += landscapeHeight(params, {x, z});
                inside = std::min({x - xa, xb - x, z - za, zb - z});
            }
            if (dem) {
                const double col = cols[size_t(j) * nx + i], row = rows[size_t(j) * nx + i];
                h += dem->raster.sample(col, row, bicubic);
                h += fbmTerrainHeight(detail, {x, z});
                const double px = dem->raster.pixelMetres();
                const double outside = std::max({-col, col - dem->raster.width(), -row, row - dem->raster.height(), 0.0}) * px;
                inside = fbm ? inside : float(-outside);
            }
            const float fade = params.fade > 0 ? smoothStep(dem && !fbm ? 1.0f + inside / params.fade : inside / params.fade)
                                               : 1.0f;
            heights[size_t(j) * nx + i] = std::max(0.0f, h * fade);
        }
    });
    TerrainField field = TerrainField::fromSamples(xa, za, cell, nx, nz, std::move(heights));
    TerrainRecord& r = field.record;
    r.material = firstMaterial;
    r.march = march;
    r.leiA = params.leiA, r.leiB = params.leiB, r.leiC = params.leiC, r.leiBisections = params.leiBisections;
    r.referenceStep = params.referenceStep;
    r.sandLevel = params.sandLevel, r.snowLevel = params.snowLevel, r.rockSlope = params.rockSlope;
    r.seed = params.fbm.seed;
    return field;
}

std::vector<Material> terrainMaterials() {
    std::vector<Material> m(uint32_t(TerrainMaterial::Count));
    m[uint32_t(TerrainMaterial::Rock)].albedo = {0.16f, 0.14f, 0.12f};
    m[uint32_t(TerrainMaterial::Grass)].albedo = {0.07f, 0.12f, 0.035f};
    m[uint32_t(TerrainMaterial::Snow)].albedo = {0.8f, 0.82f, 0.85f};
    m[uint32_t(TerrainMaterial::Sand)].albedo = {0.45f, 0.38f, 0.26f};
    return m;
}

} // namespace urbis
