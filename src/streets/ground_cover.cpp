#include "streets/ground_cover.h"

#include "streets/ground_cover_levels.h"
#include "streets/ground_cover_shapes.h"
#include "streets/street_levels.h"
#include "streets/street_materials.h"
#include "streets/water.h"
#include "streets/water_depth.h"

#include <algorithm>

namespace urbis {

namespace {

using Band = CoverStyle::Band;

/// One area on its way to the mesh.
struct CoverItem {
    size_t area = 0;       ///< index into CityModel::areas
    size_t shape = 0;      ///< index into CoverShapes
    CoverStyle style;
    double squareMetres = 0;
    bool kept = true;
    float level = 0;       ///< the surface's height (water: waterSurfaceLevel, its bed below the ground)
};

/// Sorts `order` (indices into items) bottom first: by priority, then larger first, then by OSM
/// id and by place in the city, so that the stack is the same whatever the areas' order.
void sortBottomFirst(std::vector<size_t>& order, const std::vector<CoverItem>& items, const CityModel& city) {
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
        const CoverItem &x = items[a], &y = items[b];
        if (x.style.priority != y.style.priority) return x.style.priority < y.style.priority;
        if (x.squareMetres != y.squareMetres) return x.squareMetres > y.squareMetres;
        const int64_t idX = city.areas[x.area].osmId, idY = city.areas[y.area].osmId;
        return idX != idY ? idX < idY : x.area < y.area;
    });
}

/// Puts the kept items of `band` on the planes from `base`
/// below `ceiling`, piled as stackPlanes says; those whose pile is too deep are dropped.
void stackBand(std::vector<CoverItem>& items, const CoverShapes& shapes, const CityModel& city, Band band, float base,
               float ceiling, StreetMesh& out) {
    std::vector<size_t> order;
    for (size_t i = 0; i < items.size(); ++i)
        if (items[i].kept && items[i].style.band == band) order.push_back(i);
    sortBottomFirst(order, items, city);
    std::vector<PlaneBox> boxes;
    for (const size_t i : order) boxes.push_back(shapes.box(items[i].shape));
    const std::vector<int> plane = stackPlanes(boxes, planesBetween(base, ceiling, kCoverStep), [&](size_t a, size_t b) {
        return shapes.overlap(items[order[a]].shape, items[order[b]].shape);
    });
    for (size_t k = 0; k < order.size(); ++k) {
        CoverItem& item = items[order[k]];
        if (plane[k] < 0) {
            item.kept = false;
            ++out.dropped["area_too_deep"];
        } else {
            item.level = base + float(plane[k]) * kCoverStep;
        }
    }
}

/// Adds flat triangles at world height `level` (world x east, y up, z south).
size_t addFlat(const std::vector<PlaneTriangle>& triangles, float level, TriangleInfo info, TriangleMesh& mesh) {
    auto world = [level](Vec2d p) { return Vec3f{float(p.x), level, float(-p.y)}; };
    for (const PlaneTriangle& t : triangles) mesh.add({world(t[0]), world(t[1]), world(t[2])}, info);
    return triangles.size();
}

} // namespace

CoverStyle coverStyleOf(const Area& area) {
    using M = StreetMaterial;
    const bool surfaced = area.surface != RoadSurface::Unknown;
    switch (area.kind) {
    case AreaKind::Residential: return {Band::Ground, 0, M::ResidentialGround};
    case AreaKind::Commercial: return {Band::Ground, 0, M::CommercialGround};
    case AreaKind::Industrial: return {Band::Ground, 0, M::IndustrialGround};
    case AreaKind::Farmland: return {Band::Ground, 0, M::Farmland};
    case AreaKind::Park: return {Band::Ground, 1, M::Park};
    case AreaKind::Grass: return {Band::Ground, 1, M::Lawn};
    case AreaKind::Forest: return {Band::Ground, 1, M::ForestFloor};
    case AreaKind::Cemetery: return {Band::Ground, 1, M::Cemetery};
    case AreaKind::Scrub: return {Band::Ground, 1, M::Scrub};
    case AreaKind::Sand: return {Band::Ground, 1, M::Sand};
    case AreaKind::Pitch: return {Band::Ground, 2, M::Pitch};
    case AreaKind::Playground: return {Band::Ground, 2, M::Playground};
    case AreaKind::Parking: return {Band::Ground, 3, surfaced ? materialOf(area.surface) : M::Parking};
    case AreaKind::Water: return {Band::Water, 0, M::Water, SurfacePart::Water};
    case AreaKind::Pedestrian:
        return {Band::Paved, 0, surfaced ? materialOf(area.surface) : M::PavingStones, SurfacePart::Sidewalk};
    }
    return {};
}

void meshGroundCover(const CityModel& city, const StreetOptions& options, StreetMesh& out) {
    CoverShapes shapes;
    std::vector<CoverItem> items;
    for (size_t a = 0; a < city.areas.size(); ++a) {
        if (shapes.add(city.areas[a].polygon) == CoverShapes::Added::Degenerate) {
            ++out.dropped["area_degenerate"];
            continue;
        }
        const size_t shape = shapes.size() - 1;
        items.push_back({a, shape, coverStyleOf(city.areas[a]), shapes.area(shape)});
    }
    if (shapes.holesSkipped) out.dropped["area_hole_degenerate"] += shapes.holesSkipped;

    std::vector<size_t> water;
    std::vector<bool> ribbon;
    for (const CoverItem& item : items)
        if (item.style.band == Band::Water) {
            water.push_back(item.shape);
            ribbon.push_back(!city.areas[item.area].flowLine.empty());
        }
    const std::vector<bool> waterLeft = separateWaters(shapes, water, ribbon);
    for (size_t i = 0, w = 0; i < items.size(); ++i)
        if (items[i].style.band == Band::Water && !waterLeft[w++]) {
            items[i].kept = false;
            ++out.dropped["water_covered"];
        }

    // Ground cover under water is cut away: the bed lies below the ground, and its light comes up
    // through the surface, which a park's polygon under a lake would hide.
    for (CoverItem& ground : items) {
        if (ground.style.band != Band::Ground) continue;
        for (size_t i = 0, w = 0; i < items.size() && ground.kept; ++i)
            if (items[i].style.band == Band::Water && waterLeft[w++] && shapes.overlap(ground.shape, items[i].shape) &&
                !shapes.subtract(ground.shape, items[i].shape)) {
                ground.kept = false;
                ++out.dropped["area_under_water"];
            }
    }
    stackBand(items, shapes, city, Band::Ground, kGroundCoverLevel, kWaterLevel, out);
    stackBand(items, shapes, city, Band::Paved, kPavedAreaLevel, kRoadLevel, out);

    uint32_t object = options.firstObject + out.objects;
    size_t groundTriangles = 0, waterTriangles = 0;
    uint64_t groundAreas = 0, waterAreas = 0;
    for (const CoverItem& item : items) {
        if (!item.kept || (item.style.band == Band::Water && !options.water.enabled)) continue;
        const std::vector<PlaneTriangle> triangles = shapes.triangles(item.shape);
        if (triangles.empty()) {
            ++out.dropped["area_triangulation_failed"];
            continue;
        }
        auto infoOf = [&](StreetMaterial m, SurfacePart part) {
            return TriangleInfo{options.firstMaterial + uint32_t(m), object, uint32_t(part)};
        };
        const TriangleInfo info = infoOf(item.style.material, item.style.part);
        if (item.style.band == Band::Water) {
            const TriangleInfo bed = infoOf(StreetMaterial::WaterBed, SurfacePart::Water);
            waterTriangles += addFlat(triangles, waterSurfaceLevel(), info, out.mesh);
            waterTriangles += meshWaterBed(shapes, item.shape, options.water, bed, out.mesh);
            const Area& area = city.areas[item.area];
            if (area.ele) out.waterElevations[object] = *area.ele;
            if (!area.flowLine.empty()) {
                std::vector<Vec2d>& flow = out.waterFlows[object];
                for (const Vec2d p : area.flowLine) flow.push_back({p.x, -p.y});   // world x, z
            }
            ++waterAreas;
        } else {
            groundTriangles += addFlat(triangles, item.level, info, out.mesh);
            ++groundAreas;
        }
        ++object;
    }
    out.counts["ground_cover"] += groundAreas;
    out.counts["water"] += waterAreas;
    out.trianglesByKind["ground_cover"] += groundTriangles;
    out.trianglesByKind["water"] += waterTriangles;
    out.objects = object - options.firstObject;
}

} // namespace urbis
