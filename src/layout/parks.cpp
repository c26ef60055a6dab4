#include "layout/parks.h"

#include "layout/street_furniture.h"
#include "model/polygon_ops.h"
#include "math/hash.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace urbis {

namespace {

constexpr float kDiagonalPathChance = 0.5f;
constexpr double kTreeFromPath = 1.5;  // m between a trunk and a path's edge

Road path(HighwayClass highway, float width, RoadSurface surface, Vec2d from, Vec2d centre, Vec2d to) {
    Road r;
    r.highway = highway;
    r.width = width;
    r.lanes = 1;
    r.sidewalk = Sidewalk::None;
    r.surface = surface;
    r.laneMarkings = false;
    r.centerline = {from, centre, to};
    return r;
}

bool onPath(Vec2d p, const std::vector<Road>& paths) {
    for (const Road& r : paths)
        for (size_t i = 0; i + 1 < r.centerline.size(); ++i)
            if (distanceToSegment(p, r.centerline[i], r.centerline[i + 1]) < 0.5 * r.width + kTreeFromPath) return true;
    return false;
}

} // namespace

void layOutPark(const Rect2d& block, uint32_t key, double areaPerTree, CityModel& city) {
    Area area;
    area.kind = AreaKind::Park;
    area.polygon.outer = ringOf(block);
    city.areas.push_back(std::move(area));

    const Vec2d c = block.centre();  // one point, shared by every path: their junction
    std::vector<Road> paths = {
        path(HighwayClass::Footway, 3.0f, RoadSurface::PavingStones, {block.x0, c.y}, c, {block.x1, c.y}),
        path(HighwayClass::Footway, 3.0f, RoadSurface::PavingStones, {c.x, block.y0}, c, {c.x, block.y1})};
    if (hashToUnit(hash2(key, 0xd1a6u)) < kDiagonalPathChance) {
        paths.push_back(path(HighwayClass::Path, 2.0f, RoadSurface::Gravel, {block.x0, block.y0}, c, {block.x1, block.y1}));
        paths.push_back(path(HighwayClass::Path, 2.0f, RoadSurface::Gravel, {block.x1, block.y0}, c, {block.x0, block.y1}));
    }
    std::vector<Tree> trees;
    plantPark(block, areaPerTree, key, trees);
    for (const Tree& t : trees)
        if (!onPath(t.position, paths)) city.trees.push_back(t);
    for (Road& r : paths) city.roads.push_back(std::move(r));
}

Area plazaOn(const Rect2d& block, uint32_t key) {
    Area area;
    area.kind = AreaKind::Pedestrian;
    area.surface = hashToUnit(hash2(key, 0x91a2au)) < 0.5f ? RoadSurface::Sett : RoadSurface::PavingStones;
    area.polygon.outer = ringOf(block);
    return area;
}

} // namespace urbis
