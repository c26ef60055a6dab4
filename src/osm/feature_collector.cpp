#include "osm/feature_collector.h"

#include "osm/building_tags.h"
#include "osm/lamp_tags.h"
#include "osm/level_tags.h"
#include "osm/nature_tags.h"
#include "osm/railway_tags.h"
#include "osm/street_tags.h"
#include "osm/tag_parsing.h"
#include "osm/tree_rows.h"
#include "osm/underground_tags.h"

#include <algorithm>
#include <cstring>

namespace urbis {

namespace {

TagLookup lookupIn(const osmium::TagList& tags) {
    return [&tags](const char* key) { return tags.get_value_by_key(key); };
}

bool hasYesish(const osmium::TagList& tags, const char* key) {
    const char* value = tags.get_value_by_key(key);
    return value && std::strcmp(value, "no") != 0;
}

/// A way or relation with `building` is a building outline, unless it also has
/// `building:part`: then it is its own part. `building:part` alone is a part.
PolygonRole roleOf(const osmium::TagList& tags) {
    if (hasYesish(tags, "building:part")) return PolygonRole::Part;
    if (hasYesish(tags, "building")) return PolygonRole::Building;
    return areaKindFromTags(lookupIn(tags)) ? PolygonRole::Area : PolygonRole::None;
}

LonLat lonLatOf(const osmium::Location& location) { return {location.lon(), location.lat()}; }

/// The locations of a ring or way; false when one is missing.
template <typename NodeRefs>
bool locationsOf(const NodeRefs& nodes, GeoLine& out) {
    out.clear();
    out.reserve(nodes.size());
    for (const osmium::NodeRef& node : nodes) {
        if (!node.location().valid()) return false;
        out.push_back(lonLatOf(node.location()));
    }
    return true;
}

/// The pieces of a way's line between missing nodes; true when a node was missing.
bool piecesOf(const osmium::WayNodeList& nodes, std::vector<GeoLine>& pieces) {
    GeoLine piece;
    bool missing = false;
    for (const osmium::NodeRef& node : nodes) {
        if (node.location().valid()) {
            piece.push_back(lonLatOf(node.location()));
            continue;
        }
        missing = true;
        if (!piece.empty()) pieces.push_back(std::move(piece));
        piece.clear();
    }
    if (!piece.empty()) pieces.push_back(std::move(piece));
    return missing;
}

/// A node where pedestrians cross: highway=crossing, railway=crossing or footway=crossing.
bool isCrossingNode(const osmium::TagList& tags) {
    return tags.has_tag("highway", "crossing") || tags.has_tag("railway", "crossing") ||
           tags.has_tag("footway", "crossing");
}

} // namespace

osmium::TagsFilter polygonTagsFilter() {
    osmium::TagsFilter filter{false};
    for (const char* key : {"building", "building:part", "leisure", "landuse", "natural", "waterway", "water",
                            "amenity", "area:highway", "place", "highway"})
        filter.add_rule(true, osmium::TagMatcher{key});
    return filter;
}

void RelationCatalogue::relation(const osmium::Relation& relation) {
    const char* type = relation.tags().get_value_by_key("type");
    if (!type || std::strcmp(type, "multipolygon") != 0) return;
    const PolygonRole role = roleOf(relation.tags());
    if (role != PolygonRole::None) roles_[relation.id()] = role;
}

FeatureCollector::FeatureCollector(const ImportOptions& options, RawFeatures& out)
    : options_(options), out_(out) {}

void FeatureCollector::node(const osmium::Node& node) {
    if (!node.location().valid()) return;
    const LonLat p = lonLatOf(node.location());
    GeoBox& e = out_.dataExtent;
    e = {std::min(e.minLon, p.lon), std::min(e.minLat, p.lat), std::max(e.maxLon, p.lon), std::max(e.maxLat, p.lat)};
    if (node.tags().empty()) return;
    const TagLookup tags = lookupIn(node.tags());
    if (node.tags().has_tag("highway", "street_lamp")) out_.lamps.emplace_back(lampFromTags(tags, node.id()), p);
    if (node.tags().has_tag("natural", "tree")) out_.trees.emplace_back(treeFromTags(tags, node.id()), p);
    if (isCrossingNode(node.tags()))
        if (const std::optional<CrossingKind> kind = crossingKindFromTags(tags))
            out_.crossings.push_back({{node.id(), {}, *kind}, p});
}

void FeatureCollector::way(const osmium::Way& way) {
    const osmium::TagList& tags = way.tags();
    if (tags.has_tag("natural", "tree_row")) addTreeRow(way);
    if (const std::optional<RailKind> kind = railKindOf(tags.get_value_by_key("railway"))) addRailway(way, *kind);
    if (tags.has_tag("natural", "coastline")) {
        RawCoastline coast{way.id(), {}};
        piecesOf(way.nodes(), coast.pieces);
        out_.coastlines.push_back(std::move(coast));
        return;
    }
    PolygonRole role = roleOf(tags);
    if (const std::optional<float> width = waterwayWidthFromTags(lookupIn(tags)); width && role == PolygonRole::None) {
        RawWaterway river{way.id(), *width, {}};
        piecesOf(way.nodes(), river.pieces);
        out_.waterways.push_back(std::move(river));
        return;
    }
    // A highway tagged area=yes that is no ring (unclosed, or fewer than 4 nodes) is a
    // mistagged road: kept as one. (is_closed() reads the last node, so the size comes first.)
    if (role == PolygonRole::Area && tags.has_key("highway") && (way.nodes().size() < 4 || !way.is_closed()))
        role = PolygonRole::None;
    if (role != PolygonRole::None) {
        std::vector<GeoPolygon> polygons(1);
        const char* problem = nullptr;
        if (way.nodes().empty()) problem = "degenerate_footprint";
        else if (!way.is_closed()) problem = "unclosed_way";
        else if (!locationsOf(way.nodes(), polygons[0].outer)) problem = "incomplete_geometry";
        if (problem) polygons.clear();
        addPolygonFeature(role, tags, way.id(), std::move(polygons), problem);
        return;
    }
    if (tags.has_key("highway")) addRoad(way);
}

void FeatureCollector::addRoad(const osmium::Way& way) {
    const TagLookup tags = lookupIn(way.tags());
    RawRoad road;
    bool reversed = false;
    road.attributes = roadFromTags(tags, way.id(), reversed, road.tagIssues);
    if (piecesOf(way.nodes(), road.pieces)) ++road.tagIssues["road_missing_nodes"];
    if (reversed)
        for (GeoLine& p : road.pieces) std::reverse(p.begin(), p.end());
    if (road.attributes.footway == FootwayKind::Crossing) {
        if (const std::optional<CrossingKind> kind = crossingKindFromTags(tags))
            for (const osmium::NodeRef& node : way.nodes())
                if (node.location().valid())
                    out_.crossingWayNodes.push_back({{node.ref(), {}, *kind}, lonLatOf(node.location())});
    } else if (isCarriageway(road.attributes.highway)) {
        for (const osmium::NodeRef& node : way.nodes()) out_.carriagewayNodes.insert(node.ref());
    }
    out_.roads.push_back(std::move(road));
}

void FeatureCollector::addTreeRow(const osmium::Way& way) {
    GeoLine line;
    if (!locationsOf(way.nodes(), line)) return;
    // The row's own tags size its trees; they stand a crown apart (8 m when untagged).
    Tree tree = treeFromTags(lookupIn(way.tags()), way.id());
    tree.inRow = true;
    for (const LonLat& p : treeRowPoints(line, tree.crownTagged ? std::max(2.0f, tree.crownDiameter) : 8.0))
        out_.trees.emplace_back(tree, p);
}

void FeatureCollector::addRailway(const osmium::Way& way, RailKind kind) {
    RawRailway railway;
    railway.attributes = railwayFromTags(lookupIn(way.tags()), kind, way.id(), railway.tagIssues);
    if (piecesOf(way.nodes(), railway.pieces)) ++railway.tagIssues["railway_missing_nodes"];
    out_.railways.push_back(std::move(railway));
}

void FeatureCollector::area(const osmium::Area& area) {
    assembled_.insert(area.orig_id());
    const PolygonRole role = roleOf(area.tags());
    if (role == PolygonRole::None) return;
    std::vector<GeoPolygon> polygons;
    const char* problem = nullptr;
    for (const osmium::OuterRing& outer : area.outer_rings()) {
        GeoPolygon polygon;
        bool complete = locationsOf(outer, polygon.outer);
        for (const osmium::InnerRing& inner : area.inner_rings(outer)) {
            polygon.holes.emplace_back();
            complete = complete && locationsOf(inner, polygon.holes.back());
        }
        if (!complete) problem = "incomplete_geometry";
        polygons.push_back(std::move(polygon));
    }
    if (polygons.empty() && !problem) problem = "invalid_multipolygon";
    if (problem) polygons.clear();
    addPolygonFeature(role, area.tags(), -area.orig_id(), std::move(polygons), problem);
}

void FeatureCollector::addPolygonFeature(PolygonRole role, const osmium::TagList& tags, int64_t osmId,
                                         std::vector<GeoPolygon> polygons, const char* problem) {
    const TagLookup lookup = lookupIn(tags);
    if (role == PolygonRole::Area) {
        RawArea a{{}, std::move(polygons), problem, {}};
        a.attributes.osmId = osmId;
        a.attributes.kind = *areaKindFromTags(lookup);
        if (const char* surface = lookup("surface")) a.attributes.surface = parseRoadSurface(surface);
        a.attributes.layer = levelFromTags(lookup, "area_bad_layer_tag", a.tagIssues).layer;
        a.attributes.leafType = leafTypeFromTags(lookup);
        if (const char* ele = lookup("ele"); ele && a.attributes.kind == AreaKind::Water)
            if (const std::optional<double> metres = parseElevation(ele)) a.attributes.ele = float(*metres);
        out_.areas.push_back(std::move(a));
        return;
    }
    RawBuilding b{{}, std::move(polygons), problem, {}, isUnderground(lookup)};
    b.attributes = buildingFromTags(lookup, options_, osmId, b.tagIssues);
    b.attributes.isPart = role == PolygonRole::Part;
    out_.buildings.push_back(std::move(b));
}

void countUnassembledRelations(const RelationCatalogue& catalogue, const FeatureCollector& collector,
                               RawFeatures& out) {
    for (const auto& [id, role] : catalogue.roles())
        if (!collector.assembledRelations().contains(id))
            record(out.dropped, dropKey(role, "incomplete_geometry"), {OsmType::Relation, id});
}

} // namespace urbis
