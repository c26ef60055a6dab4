#include "nature/tree_placement.h"

#include "math/hash.h"
#include "model/polygon_ops.h"

#include <algorithm>
#include <cmath>

namespace urbis {

namespace {

/// Metres of the grids the ground's queries go through.
constexpr double kGroundCell = 32.0;
/// The most trees filled into one city: a bound on memory (52 bytes each in the scene) and build time.
constexpr size_t kMaxFilledTrees = 4'000'000;
/// A filled tree keeps this share of its grid cell away from any mapped tree or one filled into an earlier area.
constexpr double kFillSpacing = 0.6;

std::array<Vec2d, 2> grown(std::array<Vec2d, 2> box, double by) {
    return {Vec2d{box[0].x - by, box[0].y - by}, Vec2d{box[1].x + by, box[1].y + by}};
}

bool isPaved(AreaKind kind) {
    return kind == AreaKind::Pedestrian || kind == AreaKind::Parking || kind == AreaKind::Pitch ||
           kind == AreaKind::Playground;
}

bool isCarriageway(HighwayClass h) {
    return h != HighwayClass::Footway && h != HighwayClass::Cycleway && h != HighwayClass::Path &&
           h != HighwayClass::Steps && h != HighwayClass::Track && h != HighwayClass::Pedestrian;
}

/// Distance from `p` to a ring's edges.
double distanceToRing(const Ring& ring, Vec2d p) {
    double d = INFINITY;
    for (size_t i = 0; i < ring.size(); ++i) d = std::min(d, distanceToSegment(p, ring[i], ring[(i + 1) % ring.size()]));
    return d;
}

/// Whether `p` lies in `polygon` or within `clearance` of its outline.
bool nearPolygon(const Polygon& polygon, Vec2d p, double clearance) {
    if (contains(polygon, p)) return true;
    if (clearance <= 0) return false;
    if (distanceToRing(polygon.outer, p) < clearance) return true;
    for (const Ring& hole : polygon.holes)
        if (distanceToRing(hole, p) < clearance) return true;
    return false;
}

/// A grid of tree positions, for "is there a tree within r of p".
class TreeGrid {
public:
    explicit TreeGrid(double cell) : grid_(cell) {}
    void add(Vec2d p) {
        grid_.insert(uint32_t(points_.size()), {p, p});
        points_.push_back(p);
    }
    bool near(Vec2d p, double r) const {
        bool found = false;
        grid_.query({Vec2d{p.x - r, p.y - r}, Vec2d{p.x + r, p.y + r}}, [&](uint32_t i) {
            found = found || std::hypot(points_[i].x - p.x, points_[i].y - p.y) < r;
        });
        return found;
    }

private:
    CellGrid grid_;
    std::vector<Vec2d> points_;
};

/// The leaf type of a tree whose tags and area leave it open: a conifer with `coniferShare`.
LeafType drawLeafType(uint32_t key, float coniferShare) {
    return hashToUnit(key) < coniferShare ? LeafType::Needleleaved : LeafType::Broadleaved;
}

} // namespace

TreeGround::TreeGround(const CityModel& city)
    : roadGrid_(kGroundCell), buildingGrid_(kGroundCell), waterGrid_(kGroundCell), pavedGrid_(kGroundCell) {
    for (const Road& r : city.roads) {
        if (r.tunnel || r.underground) continue;
        for (size_t i = 0; i + 1 < r.centerline.size(); ++i) {
            const Segment s{r.centerline[i], r.centerline[i + 1], 0.5 * r.width, isCarriageway(r.highway)};
            const double reach = s.halfWidth + kTreeSidewalkAllowance + 10.0;
            roadGrid_.insert(uint32_t(roads_.size()),
                             grown({Vec2d{std::min(s.a.x, s.b.x), std::min(s.a.y, s.b.y)},
                                    Vec2d{std::max(s.a.x, s.b.x), std::max(s.a.y, s.b.y)}}, reach));
            roads_.push_back(s);
        }
    }
    for (const Building& b : city.buildings) {
        if (b.footprint.outer.size() < 3) continue;
        buildingGrid_.insert(uint32_t(buildings_.size()), grown(bounds(b.footprint.outer), 10.0));
        buildings_.push_back(&b.footprint);
    }
    for (const Area& a : city.areas) {
        if (a.polygon.outer.size() < 3) continue;
        if (a.kind == AreaKind::Water) {
            waterGrid_.insert(uint32_t(water_.size()), grown(bounds(a.polygon.outer), 10.0));
            water_.push_back(&a.polygon);
        } else if (isPaved(a.kind)) {
            pavedGrid_.insert(uint32_t(paved_.size()), grown(bounds(a.polygon.outer), 10.0));
            paved_.push_back(&a.polygon);
        }
    }
}

bool TreeGround::onRoad(Vec2d p, double clearance, bool sidewalks) const {
    bool on = false;
    roadGrid_.query({p, p}, [&](uint32_t i) {
        const Segment& s = roads_[i];
        if (on || (!s.carriageway && !sidewalks)) return;
        const double reach = s.halfWidth + clearance + (sidewalks && s.carriageway ? kTreeSidewalkAllowance : 0.0);
        on = distanceToSegment(p, s.a, s.b) < reach;
    });
    return on;
}

bool TreeGround::inPolygons(const std::vector<const Polygon*>& polygons, const CellGrid& grid, Vec2d p,
                            double clearance) const {
    bool in = false;
    grid.query({p, p}, [&](uint32_t i) { in = in || nearPolygon(*polygons[i], p, clearance); });
    return in;
}

bool TreeGround::inBuilding(Vec2d p, double clearance) const { return inPolygons(buildings_, buildingGrid_, p, clearance); }

bool TreeGround::inWater(Vec2d p, double clearance) const { return inPolygons(water_, waterGrid_, p, clearance); }

bool TreeGround::inPaved(Vec2d p, double clearance) const { return inPolygons(paved_, pavedGrid_, p, clearance); }

float fillDensity(AreaKind kind, const TreeOptions& options) {
    switch (kind) {
    case AreaKind::Forest: return options.forestDensity;
    case AreaKind::Park: return options.parkDensity;
    case AreaKind::Scrub: return options.scrubDensity;
    default: return 0.0f;
    }
}

std::vector<Tree> placeTrees(const CityModel& city, const TreeOptions& options, std::map<std::string, uint64_t>& dropped) {
    std::vector<Tree> trees;
    if (!options.enabled) return trees;
    const TreeGround ground(city);
    TreeGrid placed(16.0);
    for (size_t i = 0; i < city.trees.size(); ++i) {
        const Tree& t = city.trees[i];
        const char* reason = ground.onRoad(t.position, 0.0, false) ? "tree_on_road"
                             : ground.inBuilding(t.position, 0.0)   ? "tree_in_building"
                             : ground.inWater(t.position, 0.0)      ? "tree_in_water"
                                                                    : nullptr;
        if (reason) {
            ++dropped[reason];
            continue;
        }
        trees.push_back(t);
        if (trees.back().leafType == LeafType::Unknown)
            trees.back().leafType = drawLeafType(hash3(options.seed, 0x7ee5u, uint32_t(i)), 0.1f * options.coniferShare);
        placed.add(t.position);
    }
    size_t filled = 0;
    for (size_t a = 0; a < city.areas.size(); ++a) {
        const Area& area = city.areas[a];
        const float density = fillDensity(area.kind, options);
        if (!(density > 0.0f) || area.polygon.outer.size() < 3) continue;
        const double cell = 100.0 / std::sqrt(double(density));
        const std::array<Vec2d, 2> box = bounds(area.polygon.outer);
        const int64_t x0 = int64_t(std::floor(box[0].x / cell)), x1 = int64_t(std::floor(box[1].x / cell));
        const int64_t y0 = int64_t(std::floor(box[0].y / cell)), y1 = int64_t(std::floor(box[1].y / cell));
        const bool scrub = area.kind == AreaKind::Scrub;
        // The jittered grid spaces an area's own trees; the spacing test is against the trees before it.
        const size_t areaFirst = trees.size();
        for (int64_t cy = y0; cy <= y1; ++cy)
            for (int64_t cx = x0; cx <= x1; ++cx) {
                if (filled >= kMaxFilledTrees) {
                    ++dropped["tree_fill_limit"];
                    continue;
                }
                HashStream rng{hash3(hash2(options.seed, uint32_t(a)), uint32_t(cx), uint32_t(cy))};
                const Vec2d p{(double(cx) + rng.uniform()) * cell, (double(cy) + rng.uniform()) * cell};
                if (!contains(area.polygon, p) || placed.near(p, kFillSpacing * cell)) continue;
                if (ground.onRoad(p, options.clearance, true) || ground.inBuilding(p, options.clearance) ||
                    ground.inWater(p, options.clearance) || ground.inPaved(p, options.clearance))
                    continue;
                Tree t;
                t.position = p;
                t.height = scrub ? 2.0f : options.defaultHeight;
                if (scrub) t.crownDiameter = 2.4f, t.crownTagged = true;
                t.leafType = scrub ? LeafType::Broadleaved : area.leafType;
                if (t.leafType == LeafType::Unknown)
                    t.leafType = drawLeafType(rng.next(), area.kind == AreaKind::Forest ? options.coniferShare
                                                                                      : 0.1f * options.coniferShare);
                trees.push_back(t);
                ++filled;
            }
        for (size_t i = areaFirst; i < trees.size(); ++i) placed.add(trees[i].position);
    }
    return trees;
}

} // namespace urbis
