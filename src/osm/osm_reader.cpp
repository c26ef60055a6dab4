#include "osm/osm_reader.h"

#include "osm/feature_collector.h"

// GCC 12 sees a false strlen over-read in osmium's AreaBuilder::set_user() once
// MultipolygonManager::complete_relation() is inlined (the user name of an object read
// with read_meta::no is an empty string in the buffer); the header is not ours to fix.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wstringop-overread"
#include <osmium/area/assembler.hpp>
#include <osmium/area/multipolygon_manager.hpp>
#pragma GCC diagnostic pop
#include <osmium/handler/node_locations_for_ways.hpp>
#include <osmium/index/map/flex_mem.hpp>
#include <osmium/io/any_input.hpp>
#include <osmium/visitor.hpp>

#include <unordered_set>

namespace urbis {

RawFeatures readOsm(const std::string& path, const ImportOptions& options) {
    RawFeatures features;
    const osmium::io::File file{path};

    osmium::area::Assembler::config_type assemblerConfig;
    assemblerConfig.create_way_polygons = false; // closed ways: FeatureCollector::way()
    assemblerConfig.create_empty_areas = true;   // so that failures are seen and counted
    osmium::area::MultipolygonManager<osmium::area::Assembler> multipolygons{assemblerConfig,
                                                                             polygonTagsFilter()};
    RelationCatalogue catalogue;
    {
        osmium::io::Reader reader{file, osmium::osm_entity_bits::relation, osmium::io::read_meta::no};
        const osmium::Box box = reader.header().box();
        if (box.valid())
            features.headerBox = {box.bottom_left().lon(), box.bottom_left().lat(),
                                  box.top_right().lon(), box.top_right().lat()};
        // libosmium's relations database reads outside its stash when two relations share an id
        // (the second one's members point at the first once it is complete and removed): each id
        // goes to it once, and the repeats are counted.
        std::unordered_set<osmium::object_id_type> relationIds;
        while (osmium::memory::Buffer buffer = reader.read())
            for (const osmium::Relation& relation : buffer.select<osmium::Relation>()) {
                if (!relationIds.insert(relation.id()).second) {
                    record(features.dropped, "relation_duplicate_id", {OsmType::Relation, relation.id()});
                    continue;
                }
                multipolygons.relation(relation);
                catalogue.relation(relation);
            }
        reader.close();
    }
    multipolygons.prepare_for_lookup();

    using Index = osmium::index::map::FlexMem<osmium::unsigned_object_id_type, osmium::Location>;
    Index index;
    osmium::handler::NodeLocationsForWays<Index> locations{index};
    locations.ignore_errors(); // missing nodes leave invalid locations, counted per object
    FeatureCollector collector{options, features};
    osmium::io::Reader reader{file, osmium::osm_entity_bits::node | osmium::osm_entity_bits::way,
                              osmium::io::read_meta::no};
    osmium::apply(reader, locations, collector,
                  multipolygons.handler([&collector](osmium::memory::Buffer&& areas) {
                      osmium::apply(areas, collector);
                  }));
    reader.close();
    countUnassembledRelations(catalogue, collector, features);
    return features;
}

} // namespace urbis
