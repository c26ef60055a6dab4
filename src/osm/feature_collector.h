// libosmium handlers that turn OSM objects into RawFeatures.
#pragma once

#include "osm/import_options.h"
#include "osm/raw_features.h"

#include <osmium/handler.hpp>
#include <osmium/osm/area.hpp>
#include <osmium/osm/node.hpp>
#include <osmium/osm/relation.hpp>
#include <osmium/osm/way.hpp>
#include <osmium/tags/tags_filter.hpp>

#include <unordered_map>
#include <unordered_set>

namespace urbis {


/// Tags the multipolygon assembler must see on a relation for it to be of interest.
osmium::TagsFilter polygonTagsFilter();

/// First pass: remembers the role of every multipolygon relation, so that those the
/// assembler never completes (members missing from the file) can be counted by role.
class RelationCatalogue : public osmium::handler::Handler {
public:
    /// Records a type=multipolygon relation with a building, part or area role.
    void relation(const osmium::Relation& relation);
    /// Role by relation id.
    const std::unordered_map<osmium::object_id_type, PolygonRole>& roles() const { return roles_; }

private:
    std::unordered_map<osmium::object_id_type, PolygonRole> roles_;
};

/// Second pass: nodes (lamps, trees, data extent), ways (roads, closed building/part/area
/// ways) and assembled multipolygon areas, with node locations already set.
class FeatureCollector : public osmium::handler::Handler {
public:
    /// Collects into `out`, reading tags with `options` (metres per level, building seeds).
    FeatureCollector(const ImportOptions& options, RawFeatures& out);
    /// Street lamps, trees and crossings; extends the data extent.
    void node(const osmium::Node& node);
    /// Highways, railways, and closed ways that are buildings, parts or areas.
    void way(const osmium::Way& way);
    /// Multipolygon relations assembled by osmium::area::MultipolygonManager (configured not
    /// to assemble closed ways: way() reads those, so that GEOS can repair them).
    void area(const osmium::Area& area);
    /// Ids of the relations that reached area().
    const std::unordered_set<osmium::object_id_type>& assembledRelations() const { return assembled_; }

private:
    /// A highway way; a footway=crossing one also gives its nodes as crossing candidates, a
    /// carriageway its node ids.
    void addRoad(const osmium::Way& way);
    void addRailway(const osmium::Way& way, RailKind kind);
    /// The trees of a natural=tree_row way (osm/tree_rows.h), each with the row's tags and id.
    void addTreeRow(const osmium::Way& way);
    void addPolygonFeature(PolygonRole role, const osmium::TagList& tags, int64_t osmId,
                           std::vector<GeoPolygon> polygons, const char* problem);

    const ImportOptions& options_;
    RawFeatures& out_;
    std::unordered_set<osmium::object_id_type> assembled_;
};

/// Counts, by role, the relations of `catalogue` that never reached the collector
/// ("incomplete_geometry": members or node locations missing from the file).
void countUnassembledRelations(const RelationCatalogue& catalogue, const FeatureCollector& collector,
                               RawFeatures& out);

} // namespace urbis
