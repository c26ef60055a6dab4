#include "osm/city_builder.h"

#include "model/polygon_ops.h"
#include "osm/building_parts.h"
#include "osm/coastline.h"
#include "model/geos_polygon.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <unordered_set>

namespace urbis {

namespace {

constexpr double kMinArea = 1.0; // m^2

class Builder {
public:
    Builder(const GeoBox& box, CityModel& city) : box_(box), projection_(box.centre()), city_(city) {
        // The local rectangle around the box's projected corners (the box's edges bow a little
        // on the tangent plane; the rectangle holds them all).
        boxMin_ = {HUGE_VAL, HUGE_VAL};
        boxMax_ = {-HUGE_VAL, -HUGE_VAL};
        for (const LonLat corner : {LonLat{box.minLon, box.minLat}, LonLat{box.maxLon, box.minLat},
                                    LonLat{box.minLon, box.maxLat}, LonLat{box.maxLon, box.maxLat}}) {
            const Vec2d p = projection_.project(corner);
            boxMin_ = {std::min(boxMin_.x, p.x), std::min(boxMin_.y, p.y)};
            boxMax_ = {std::max(boxMax_.x, p.x), std::max(boxMax_.y, p.y)};
        }
    }

    /// Projects, checks and repairs one polygon; nullptr when usable, else the drop reason.
    /// `repaired` tells whether GEOS had to make it valid. With `byCentroid`, one whose centroid
    /// lies outside the box is dropped.
    const char* makePolygon(const GeoPolygon& g, Polygon& out, bool& repaired, bool byCentroid = true) {
        out.outer = ring(g.outer);
        if (out.outer.size() < 3) return "degenerate_footprint";
        if (byCentroid && !box_.contains(centroidInDegrees(g.outer))) return "outside_bbox";
        for (const GeoLine& h : g.holes)
            if (Ring hole = ring(h); hole.size() >= 3) out.holes.push_back(std::move(hole));
        orient(out);
        const Validity validity = geos_.makeValid(out);
        if (validity == Validity::Invalid) return "self_intersecting";
        repaired = validity == Validity::Repaired;
        if (area(out) < kMinArea) return "too_small";
        return nullptr;
    }

    void addBuilding(RawBuilding& raw) {
        const PolygonRole role = raw.attributes.isPart ? PolygonRole::Part : PolygonRole::Building;
        const OsmRef id = polygonRef(raw.attributes.osmId);
        if (raw.problem) {
            record(city_.dropped, dropKey(role, raw.problem), id);
            return;
        }
        bool kept = false;
        for (const GeoPolygon& g : raw.polygons) {
            Building b = raw.attributes;
            // Underground objects are counted only where they would otherwise stand, so that
            // one outside the box still counts as outside_bbox.
            bool repaired = false;
            const char* reason = makePolygon(g, b.footprint, repaired);
            if (!reason && raw.underground) reason = "underground";
            if (reason) {
                record(city_.dropped, dropKey(role, reason), id);
                continue;
            }
            if (repaired) record(city_.repaired, dropKey(role, "made_valid"), id);
            city_.buildings.push_back(std::move(b));
            kept = true;
        }
        if (kept)
            for (const auto& [issue, n] : raw.tagIssues) record(city_.repaired, issue, id, n);
    }

    void addArea(const RawArea& raw) {
        const OsmRef id = polygonRef(raw.attributes.osmId);
        if (raw.problem) {
            record(city_.dropped, dropKey(PolygonRole::Area, raw.problem), id);
            return;
        }
        bool kept = false;
        for (const GeoPolygon& g : raw.polygons) {
            Polygon whole;
            bool repaired = false;
            if (const char* reason = makePolygon(g, whole, repaired, false)) {
                record(city_.dropped, dropKey(PolygonRole::Area, reason), id);
                continue;
            }
            // Ground cover is clipped to the box (a landuse can span the whole town, its
            // centroid far outside); a building is kept whole, by its centroid.
            size_t pieces = 0;
            for (Polygon& part : geos_.clipToRectangle(whole, boxMin_, boxMax_)) {
                if (area(part) < kMinArea) continue;
                Area a = raw.attributes;
                a.polygon = std::move(part);
                city_.areas.push_back(std::move(a));
                ++pieces;
            }
            if (pieces == 0) {
                record(city_.dropped, dropKey(PolygonRole::Area, "outside_bbox"), id);
                continue;
            }
            if (repaired) record(city_.repaired, dropKey(PolygonRole::Area, "made_valid"), id);
            kept = true;
        }
        if (kept)
            for (const auto& [issue, n] : raw.tagIssues) record(city_.repaired, issue, id, n);
    }

    /// Clips a road's or railway's pieces to the box and projects them into `out`; drops are
    /// counted under `prefix` + "_outside_bbox", "_degenerate" or "_incomplete_geometry".
    template <typename Way>
    void addLine(const RawLine<Way>& raw, const std::string& prefix, std::vector<Way>& out) {
        const OsmRef id{OsmType::Way, raw.attributes.osmId};
        if (std::none_of(raw.pieces.begin(), raw.pieces.end(), [](const GeoLine& l) { return l.size() >= 2; })) {
            record(city_.dropped, prefix + (raw.pieces.empty() ? "_incomplete_geometry" : "_degenerate"), id);
            return;
        }
        size_t kept = 0;
        for (const GeoLine& piece : raw.pieces)
            for (const GeoLine& clipped : clipPolyline(piece, box_)) {
                Way way = raw.attributes;
                for (const LonLat p : clipped) way.centerline.push_back(projection_.project(p));
                const auto same = [](Vec2d a, Vec2d b) { return a.x == b.x && a.y == b.y; };
                way.centerline.erase(std::unique(way.centerline.begin(), way.centerline.end(), same),
                                     way.centerline.end());
                if (way.centerline.size() < 2) continue;
                out.push_back(std::move(way));
                ++kept;
            }
        if (kept == 0) {
            record(city_.dropped, prefix + "_outside_bbox", id);
            return;
        }
        for (const auto& [issue, n] : raw.tagIssues) record(city_.repaired, issue, id, n);
    }

    /// A river mapped as a line: each piece clipped to the box, projected, and drawn as a water area,
    /// the ribbon of its width around it (clipped to the box), its line kept as the area's flowLine.
    /// Drops: "waterway_incomplete_geometry", "waterway_outside_bbox".
    void addWaterway(const RawWaterway& raw) {
        const OsmRef id{OsmType::Way, raw.osmId};
        size_t kept = 0;
        for (const GeoLine& piece : raw.pieces)
            for (const GeoLine& clipped : clipPolyline(piece, box_)) {
                std::vector<Vec2d> line;
                for (const LonLat p : clipped) line.push_back(projection_.project(p));
                const auto same = [](Vec2d a, Vec2d b) { return a.x == b.x && a.y == b.y; };
                line.erase(std::unique(line.begin(), line.end(), same), line.end());
                if (line.size() < 2) continue;
                for (Polygon& ribbon : geos_.ribbonAround(line, 0.5 * raw.width))
                    for (Polygon& part : geos_.clipToRectangle(ribbon, boxMin_, boxMax_)) {
                        if (area(part) < kMinArea) continue;
                        Area a;
                        a.osmId = raw.osmId;
                        a.kind = AreaKind::Water;
                        a.polygon = std::move(part);
                        a.flowLine = line;
                        city_.areas.push_back(std::move(a));
                        ++kept;
                    }
            }
        if (kept == 0)
            record(city_.dropped, raw.pieces.empty() ? "waterway_incomplete_geometry" : "waterway_outside_bbox", id);
    }

    template <typename T>
    void addPoint(T item, LonLat p, std::vector<T>& out, const char* outsideReason) {
        if (!box_.contains(p)) {
            record(city_.dropped, outsideReason, {OsmType::Node, item.osmId});
            return;
        }
        item.position = projection_.project(p);
        out.push_back(std::move(item));
    }

    /// Closes the coastline against the box into sea polygons (osm/coastline.h), water areas with
    /// no OSM id; repairs and drops are recorded by way and said in CityModel::warnings.
    void addCoastlines(const std::vector<RawCoastline>& coastlines) {
        std::vector<CoastlineWay> ways;
        for (const RawCoastline& c : coastlines)
            for (const GeoLine& piece : c.pieces) {
                CoastlineWay way{c.osmId, {}};
                for (const LonLat p : piece) way.points.push_back(projection_.project(p));
                ways.push_back(std::move(way));
            }
        SeaPolygons sea = seaPolygons(ways, boxMin_, boxMax_);
        for (Polygon& polygon : sea.sea) {
            Area a;
            a.kind = AreaKind::Water;
            a.polygon = std::move(polygon);
            city_.areas.push_back(std::move(a));
        }
        for (const int64_t id : sea.extendedWays) record(city_.repaired, "coastline_extended_to_box", {OsmType::Way, id});
        for (const int64_t id : sea.droppedWays) record(city_.dropped, "coastline_not_closed", {OsmType::Way, id});
        for (std::string& w : sea.warnings) city_.warnings.push_back(std::move(w));
    }

    const GeosContext& geos() const { return geos_; }

private:
    Ring ring(const GeoLine& line) const {
        Ring r;
        r.reserve(line.size());
        for (const LonLat p : line) r.push_back(projection_.project(p));
        removeDuplicatePoints(r);
        return r;
    }

    static LonLat centroidInDegrees(const GeoLine& line) {
        Ring r;
        r.reserve(line.size());
        for (const LonLat p : line) r.push_back({p.lon, p.lat});
        removeDuplicatePoints(r);
        const Vec2d c = centroid(r);
        return {c.x, c.y};
    }

    GeoBox box_;
    GeoProjection projection_;
    Vec2d boxMin_, boxMax_; ///< the box in local metres, for clipping areas
    GeosContext geos_;
    CityModel& city_;
};

/// The crossing nodes, then each node of a footway=crossing way that a carriageway shares and
/// no crossing node (or earlier crossing way) already stands on.
std::vector<RawCrossing> crossingsOf(const RawFeatures& raw) {
    std::vector<RawCrossing> crossings = raw.crossings;
    std::unordered_set<int64_t> taken;
    for (const RawCrossing& c : crossings) taken.insert(c.attributes.osmId);
    for (const RawCrossing& c : raw.crossingWayNodes)
        if (raw.carriagewayNodes.contains(c.attributes.osmId) && taken.insert(c.attributes.osmId).second)
            crossings.push_back(c);
    return crossings;
}

} // namespace

CityModel buildCityModel(RawFeatures&& raw, const GeoBox& box) {
    CityModel city;
    const LonLat centre = box.centre();
    city.origin = {true, centre.lat, centre.lon};
    city.dropped = std::move(raw.dropped);
    Builder builder(box, city);
    for (RawBuilding& b : raw.buildings) builder.addBuilding(b);
    for (const RawArea& a : raw.areas) builder.addArea(a);
    builder.addCoastlines(raw.coastlines);
    for (const RawWaterway& w : raw.waterways) builder.addWaterway(w);
    for (const RawRoad& r : raw.roads) builder.addLine(r, "road", city.roads);
    for (const RawRailway& r : raw.railways) builder.addLine(r, "railway", city.railways);
    for (const RawCrossing& c : crossingsOf(raw))
        builder.addPoint(c.attributes, c.position, city.crossings, "crossing_outside_bbox");
    for (auto& [lamp, p] : raw.lamps) builder.addPoint(std::move(lamp), p, city.lamps, "lamp_outside_bbox");
    for (auto& [tree, p] : raw.trees) builder.addPoint(std::move(tree), p, city.trees, "tree_outside_bbox");
    replaceOutlinesByParts(city.buildings, builder.geos(), city.dropped);
    return city;
}

} // namespace urbis
