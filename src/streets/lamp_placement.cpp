#include "streets/lamp_placement.h"

#include "model/cell_grid.h"
#include "model/polygon_ops.h"
#include "streets/polyline.h"
#include "streets/road_elevation.h"
#include "streets/road_fitting.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <utility>

namespace urbis {

namespace {

constexpr double kCurbSetback = 0.5;         // m from the curb onto the sidewalk, or beyond a bare edge
constexpr double kCarriagewayMargin = 0.2;   // m beyond a carriageway's half width that stays clear
constexpr double kPathClearance = 0.5;       // m from a footway's or path's centerline
constexpr double kBuildingClearance = 0.5;   // m from a footprint's outline
constexpr double kJunctionRadius = 8.0;      // m around a junction node, at least
constexpr double kWideRoad = 10.0;           // m of carriageway from which both sides are lit
constexpr double kPlacedSpacing = 0.4;       // of a spacing: the least distance between placed lamps
constexpr double kMappedReach = 0.5;         // of a spacing: a mapped lamp this near stands for a placed one
constexpr double kTurnReach = 30.0;          // m within which a mapped lamp turns to a road
constexpr double kCell = 32.0;               // m, the query grids' cells

/// Classes that carry traffic: lamps keep off them, and their shared nodes make junctions.
bool isCarriageway(HighwayClass h) { return !isPath(h); }

bool finite(Vec2d p) { return std::isfinite(p.x) && std::isfinite(p.y); }

double distance(Vec2d a, Vec2d b) { return std::hypot(a.x - b.x, a.y - b.y); }

std::array<Vec2d, 2> around(Vec2d p, double r) { return {Vec2d{p.x - r, p.y - r}, Vec2d{p.x + r, p.y + r}}; }

/// Degrees clockwise from north of the direction (dx, dy).
float bearing(double dx, double dy) {
    const double deg = std::atan2(dx, dy) * 180.0 / std::numbers::pi;
    return float(deg < 0.0 ? deg + 360.0 : deg);
}

/// The surface roads' segments, for the nearest road and the carriageway test.
class RoadIndex {
public:
    explicit RoadIndex(const std::vector<Road>& roads) : roads_(roads), grid_(kCell) {
        for (uint32_t r = 0; r < roads.size(); ++r) {
            if (!atSurface(roads[r])) continue;
            const auto& line = roads[r].centerline;
            for (uint32_t i = 0; i + 1 < line.size(); ++i) {
                if (!finite(line[i]) || !finite(line[i + 1])) continue;
                const double reach = reachOf(roads[r]);
                const Vec2d a = line[i], b = line[i + 1];
                grid_.insert(uint32_t(segments_.size()), {Vec2d{std::min(a.x, b.x) - reach, std::min(a.y, b.y) - reach},
                                                          Vec2d{std::max(a.x, b.x) + reach, std::max(a.y, b.y) + reach}});
                segments_.push_back({r, i});
            }
        }
    }

    /// Whether p lies on a carriageway (within its half width + margin), or near a path's centerline.
    bool blocked(Vec2d p) const {
        bool hit = false;
        grid_.query({p, p}, [&](uint32_t s) {
            const auto [r, i] = segments_[s];
            if (hit) return;
            const auto& line = roads_[r].centerline;
            hit = distanceToSegment(p, line[i], line[i + 1]) < reachOf(roads_[r]);
        });
        return hit;
    }

    /// The nearest point of a carriageway's centerline within kTurnReach of p, if any.
    bool nearestCarriageway(Vec2d p, Vec2d& nearest) const {
        double best = kTurnReach;
        bool found = false;
        grid_.query(around(p, kTurnReach), [&](uint32_t s) {
            const auto [r, i] = segments_[s];
            if (!isCarriageway(roads_[r].highway)) return;
            const auto& line = roads_[r].centerline;
            const Vec2d q = nearestOnSegment(p, line[i], line[i + 1]);
            if (const double d = distance(p, q); d < best) {
                best = d;
                nearest = q;
                found = true;
            }
        });
        return found;
    }

private:
    static double reachOf(const Road& r) {
        return isCarriageway(r.highway) ? 0.5 * std::max(0.0f, r.width) + kCarriagewayMargin : kPathClearance;
    }
    const std::vector<Road>& roads_;
    CellGrid grid_;
    std::vector<std::pair<uint32_t, uint32_t>> segments_;
};

/// Nodes where three or more carriageway edges meet (shared nodes are bit-identical points), each
/// with the radius kept clear around it.
class Junctions {
public:
    explicit Junctions(const std::vector<Road>& roads) : grid_(kCell) {
        std::map<std::pair<double, double>, std::pair<int, double>> nodes;   // degree, widest half width
        for (const Road& r : roads) {
            if (!atSurface(r) || !isCarriageway(r.highway)) continue;
            for (size_t i = 0; i < r.centerline.size(); ++i) {
                auto& [degree, halfWidth] = nodes[{r.centerline[i].x, r.centerline[i].y}];
                degree += i == 0 || i + 1 == r.centerline.size() ? 1 : 2;
                halfWidth = std::max(halfWidth, 0.5 * double(r.width));
            }
        }
        for (const auto& [p, node] : nodes) {
            if (node.first < 3 || !finite({p.first, p.second})) continue;
            const double radius = std::max(kJunctionRadius, node.second + 4.0);
            grid_.insert(uint32_t(points_.size()), around({p.first, p.second}, radius));
            points_.push_back({{p.first, p.second}, radius});
        }
    }

    bool near(Vec2d p) const {
        bool hit = false;
        grid_.query({p, p}, [&](uint32_t j) { hit |= distance(p, points_[j].first) < points_[j].second; });
        return hit;
    }

private:
    CellGrid grid_;
    std::vector<std::pair<Vec2d, double>> points_;
};

/// Building footprints, for "inside or against a building".
class Footprints {
public:
    explicit Footprints(const std::vector<Building>& buildings) : buildings_(buildings), grid_(kCell) {
        for (uint32_t b = 0; b < buildings.size(); ++b) {
            if (buildings[b].footprint.outer.size() < 3) continue;
            std::array<Vec2d, 2> box = bounds(buildings[b].footprint.outer);
            box[0] = {box[0].x - kBuildingClearance, box[0].y - kBuildingClearance};
            box[1] = {box[1].x + kBuildingClearance, box[1].y + kBuildingClearance};
            grid_.insert(b, box);
        }
    }

    bool near(Vec2d p) const {
        bool hit = false;
        grid_.query({p, p}, [&](uint32_t b) {
            if (hit) return;
            const Polygon& f = buildings_[b].footprint;
            hit = contains(f, p) || ringNear(f.outer, p);
            for (const Ring& hole : f.holes) hit = hit || ringNear(hole, p);
        });
        return hit;
    }

private:
    static bool ringNear(const Ring& ring, Vec2d p) {
        for (size_t i = 0; i < ring.size(); ++i)
            if (distanceToSegment(p, ring[i], ring[(i + 1) % ring.size()]) < kBuildingClearance) return true;
        return false;
    }
    const std::vector<Building>& buildings_;
    CellGrid grid_;
};

/// Lamps so far, for "too near another lamp".
class LampIndex {
public:
    LampIndex() : grid_(kCell) {}
    void add(Vec2d p) {
        grid_.insert(uint32_t(points_.size()), {p, p});
        points_.push_back(p);
    }
    bool near(Vec2d p, double r) const {
        bool hit = false;
        grid_.query(around(p, r), [&](uint32_t i) { hit |= distance(p, points_[i]) < r; });
        return hit;
    }

private:
    CellGrid grid_;
    std::vector<Vec2d> points_;
};

/// One row of lamps along a road: which side (+1 left, -1 right, 0 the centre line), how far from
/// the centerline, where along it the first lamp stands, and for a single row the other side's
/// offset, tried where a station is blocked (0: none).
struct LampRow {
    int side;
    double offset;
    double phase;
    double otherOffset = 0.0;
};

std::vector<LampRow> rowsOf(const Road& road, double spacing) {
    const double half = 0.5 * road.width;
    auto offset = [&](float sidewalk) { return half + (sidewalk > 0.0f ? std::min(kCurbSetback, 0.5 * sidewalk) : kCurbSetback); };
    const double left = offset(road.sidewalkLeftWidth), right = offset(road.sidewalkRightWidth);
    if (road.width >= kWideRoad) return {{-1, right, 0.5 * spacing}, {1, left, spacing}};
    const bool leftOnly = road.sidewalkLeftWidth > 0.0f && !(road.sidewalkRightWidth > 0.0f);
    return {leftOnly ? LampRow{1, left, 0.5 * spacing, right} : LampRow{-1, right, 0.5 * spacing, left}};
}

} // namespace

LampStyle lampStyle(HighwayClass highway) {
    switch (highway) {
    case HighwayClass::Motorway:
    case HighwayClass::Trunk: return {40.0, LampMount::BentMast, LampHead::Cobra, 10.0f, 4000.0f};
    case HighwayClass::Primary: return {30.0, LampMount::BentMast, LampHead::Cobra, 9.0f, 4000.0f};
    case HighwayClass::Secondary: return {30.0, LampMount::BentMast, LampHead::Cobra, 8.0f, 4000.0f};
    case HighwayClass::Tertiary: return {35.0, LampMount::BentMast, LampHead::Flat, 7.0f, 4000.0f};
    case HighwayClass::Unclassified:
    case HighwayClass::Residential: return {38.0, LampMount::Pole, LampHead::Cone, 5.5f, 3000.0f};
    case HighwayClass::LivingStreet:
    case HighwayClass::Pedestrian: return {25.0, LampMount::Pole, LampHead::Lantern, 4.5f, 3000.0f};
    case HighwayClass::Service: return {25.0, LampMount::Pole, LampHead::Globe, 4.0f, 3000.0f};
    default: return {};
    }
}

bool litRoad(const Road& road) {
    return lampStyle(road.highway).spacing > 0.0 && atSurface(road) && !road.area && road.centerline.size() >= 2 &&
           road.width > 0.0f;
}

std::vector<Lamp> streetLamps(const CityModel& city, const std::vector<Road>& roads) {
    const RoadIndex roadIndex(roads);
    const Junctions junctions(roads);
    const Footprints footprints(city.buildings);
    LampIndex mapped, placed;
    std::vector<Lamp> out;
    for (const Lamp& lamp : city.lamps) {
        if (!finite(lamp.position)) continue;
        Lamp kept = lamp;
        Vec2d q;
        if (kept.direction < 0.0f && roadIndex.nearestCarriageway(lamp.position, q) && distance(q, lamp.position) > 0.01)
            kept.direction = bearing(q.x - lamp.position.x, q.y - lamp.position.y);
        mapped.add(lamp.position);
        out.push_back(kept);
    }
    for (uint32_t r = 0; r < roads.size(); ++r) {
        const Road& road = roads[r];
        const std::vector<Vec2d>& line = road.centerline;
        const double length = polylineLength(line);
        if (!litRoad(road) || !std::isfinite(length)) continue;
        const LampStyle style = lampStyle(road.highway);
        for (const LampRow& row : rowsOf(road, style.spacing)) {
            size_t segment = 0;
            double segmentStart = 0.0;
            for (double s = row.phase; s < length; s += style.spacing) {
                // The segment holding station s (zero-length segments are passed over).
                while (segment + 2 < line.size() && segmentStart + distance(line[segment], line[segment + 1]) < s) {
                    segmentStart += distance(line[segment], line[segment + 1]);
                    ++segment;
                }
                const Vec2d a = line[segment], b = line[segment + 1];
                const Vec2d n = leftNormal(a, b);
                if (n.x == 0.0 && n.y == 0.0) continue;
                const double f = std::clamp((s - segmentStart) / distance(a, b), 0.0, 1.0);
                const Vec2d centre{a.x + f * (b.x - a.x), a.y + f * (b.y - a.y)};
                auto clear = [&](Vec2d p) {
                    return !junctions.near(p) && !footprints.near(p) &&
                           !roadIndex.blocked(p) &&
                           !mapped.near(p, kMappedReach * style.spacing) && !placed.near(p, kPlacedSpacing * style.spacing);
                };
                int side = row.side;
                Vec2d p{centre.x + n.x * side * row.offset, centre.y + n.y * side * row.offset};
                if (!clear(p) && row.otherOffset > 0.0) {
                    side = -side;
                    p = {centre.x + n.x * side * row.otherOffset, centre.y + n.y * side * row.otherOffset};
                }
                if (!clear(p)) continue;
                // The head leans to the road.
                const double lean = -side;
                Lamp lamp;
                lamp.position = p;
                lamp.height = style.height;
                lamp.lampType = "LED";
                lamp.mount = style.mount;
                lamp.head = style.head;
                lamp.direction = bearing(n.x * lean, n.y * lean);
                lamp.colourTemperature = style.colourTemperature;
                placed.add(p);
                out.push_back(lamp);
            }
        }
    }
    return out;
}

} // namespace urbis
