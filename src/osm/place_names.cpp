#include "osm/place_names.h"

#include "base/input_error.h"

#include <osmium/handler.hpp>
#include <osmium/handler/node_locations_for_ways.hpp>
#include <osmium/index/map/flex_mem.hpp>
#include <osmium/io/any_input.hpp>
#include <osmium/visitor.hpp>

#include <unordered_map>

namespace urbis {

namespace {

/// A named relation (a forest or a park mapped as a multipolygon): the sums of its member ways' node locations.
struct NamedRelation {
    std::string name;
    double lonSum = 0, latSum = 0;
    size_t located = 0;
};

/// The first pass: named relations, and which relations each member way belongs to.
class RelationCollector : public osmium::handler::Handler {
public:
    RelationCollector(std::vector<NamedRelation>& relations, std::unordered_multimap<osmium::object_id_type, size_t>& memberOf)
        : relations_(relations), memberOf_(memberOf) {}

    void relation(const osmium::Relation& relation) {
        const char* name = relation.tags().get_value_by_key("name");
        if (!name || !*name) return;
        for (const osmium::RelationMember& member : relation.members())
            if (member.type() == osmium::item_type::way) memberOf_.emplace(member.ref(), relations_.size());
        relations_.push_back({name});
    }

private:
    std::vector<NamedRelation>& relations_;
    std::unordered_multimap<osmium::object_id_type, size_t>& memberOf_;
};

/// Collects named nodes and ways (node locations already set on the ways), and adds member ways' nodes to their relations.
class NameCollector : public osmium::handler::Handler {
public:
    NameCollector(std::vector<NamedPlace>& out, std::vector<NamedRelation>& relations,
                  const std::unordered_multimap<osmium::object_id_type, size_t>& memberOf)
        : out_(out), relations_(relations), memberOf_(memberOf) {}

    void node(const osmium::Node& node) {
        const char* name = node.tags().get_value_by_key("name");
        if (name && *name && node.location().valid()) out_.push_back({name, node.location().lon(), node.location().lat()});
    }

    void way(const osmium::Way& way) {
        const char* name = way.tags().get_value_by_key("name");
        const auto relations = memberOf_.equal_range(way.id());
        if ((!name || !*name) && relations.first == relations.second) return;
        double lon = 0, lat = 0;
        size_t located = 0;
        // A closed way repeats its first node: counted once.
        const size_t count = way.nodes().size() - (way.nodes().size() > 1 && way.is_closed() ? 1 : 0);
        for (size_t i = 0; i < count; ++i) {
            const osmium::Location location = way.nodes()[i].location();
            if (!location.valid()) continue;
            lon += location.lon();
            lat += location.lat();
            ++located;
        }
        for (auto it = relations.first; it != relations.second; ++it) {
            NamedRelation& relation = relations_[it->second];
            relation.lonSum += lon;
            relation.latSum += lat;
            relation.located += located;
        }
        if (name && *name && located) out_.push_back({name, lon / double(located), lat / double(located)});
    }

private:
    std::vector<NamedPlace>& out_;
    std::vector<NamedRelation>& relations_;
    const std::unordered_multimap<osmium::object_id_type, size_t>& memberOf_;
};

} // namespace

std::vector<NamedPlace> readPlaceNames(const std::string& path) {
    std::vector<NamedPlace> places;
    try {
        using Index = osmium::index::map::FlexMem<osmium::unsigned_object_id_type, osmium::Location>;
        Index index;
        osmium::handler::NodeLocationsForWays<Index> locations{index};
        locations.ignore_errors();   // a way's missing nodes are left out of its centre
        std::vector<NamedRelation> relations;
        std::unordered_multimap<osmium::object_id_type, size_t> memberOf;
        RelationCollector relationCollector{relations, memberOf};
        osmium::io::Reader relationReader{osmium::io::File{path}, osmium::osm_entity_bits::relation, osmium::io::read_meta::no};
        osmium::apply(relationReader, relationCollector);
        relationReader.close();

        NameCollector collector{places, relations, memberOf};
        osmium::io::Reader reader{osmium::io::File{path}, osmium::osm_entity_bits::node | osmium::osm_entity_bits::way,
                                  osmium::io::read_meta::no};
        osmium::apply(reader, locations, collector);
        reader.close();
        for (const NamedRelation& relation : relations)
            if (relation.located)
                places.push_back({relation.name, relation.lonSum / double(relation.located), relation.latSum / double(relation.located)});
    } catch (const std::exception& e) {
        throw InputError(path + ": cannot read the names of its features: " + e.what());
    }
    return places;
}

} // namespace urbis
